# Copyright 2026 The tf_demo Authors
#
# Licensed under the Apache License, Version 2.0 (the "License");
# you may not use this file except in compliance with the License.
# You may obtain a copy of the License at
#
#     http://www.apache.org/licenses/LICENSE-2.0
#
# Unless required by applicable law or agreed to in writing, software
# distributed under the License is distributed on an "AS IS" BASIS,
# WITHOUT WARRANTIES OR CONDITIONS OF ANY KIND, either express or implied.
# See the License for the specific language governing permissions and
# limitations under the License.

"""
The vectorised rotation math, pinned to :mod:`tf_demo.core.math3d`'s scalar functions within 1e-12.

math3d is the one source of the rotation math; the lookup walk calls its functions.  The
vectorised walk (``_batch`` with the interval constants of ``TimeCache.arrays``) does the same
lerp, slerp and composition on numpy arrays, and math3d itself has a fast route
(``canonical_quat`` computes only the matrix entries tf2 reads back, pinned bit for bit) and
array versions (``*_batch``, ``*_lanes``); each test below names the array code it pins and
compares it with the scalar original on drawn inputs (quaternions up to sign where the array
code may flip it). Where a test builds the
newer rotation from the older one, the angle between them is exactly 0 or at least 1e-6 rad:
below about 1e-7 rad math3d's slerp (tf2's, which divides the dot product by the norms) may find
a cosine of exactly 1 and return the older rotation while the walk (which skips that division)
still interpolates, and the two then differ by up to about the angle itself (7e-9 measured at
1e-7 rad).
"""

from __future__ import annotations

from hypothesis import example
from hypothesis import given
from hypothesis import strategies as st
import numpy as np
import numpy.typing as npt
import pytest
from tf_demo.core import _batch
from tf_demo.core import math3d
from tf_demo.core.time_cache import StaticCache
from tf_demo.core.time_cache import TimeCache
from tf_demo.testing import strategies as tfst

pytestmark = pytest.mark.property

Vec3 = tuple[float, float, float]
Quat = tuple[float, float, float, float]
Transform = tuple[Vec3, Quat]

TOL = 1e-12
SECOND = 1_000_000_000
T0 = 1_000 * SECOND
PARENT = 2

quats = tfst.unit_quaternions()
moves = tfst.transforms()
#: Nanoseconds between two samples, and a lane time strictly between them.
spans = st.integers(min_value=2, max_value=100 * SECOND)
fractions = st.floats(min_value=0.0, max_value=1.0, exclude_min=True, exclude_max=True)
#: Rotation angles (rad) between neighbouring samples: 0, or far enough from 0 (module doc).
small_angles = st.one_of(st.just(0.0), st.floats(min_value=1e-6, max_value=2.0))


def _assert_close(actual: tuple[float, ...], expected: tuple[float, ...], what: str) -> None:
    assert np.allclose(actual, expected, rtol=0.0, atol=TOL), (what, actual, expected)


def _assert_identical(actual: tuple[float, ...], expected: tuple[float, ...], what: str) -> None:
    """Assert the same doubles bit for bit (NaN equal to NaN, -0.0 unequal to 0.0)."""
    assert [float(c).hex() for c in actual] == [float(c).hex() for c in expected], (
        what,
        actual,
        expected,
    )


def _assert_same_rotation(actual: tuple[float, ...], expected: tuple[float, ...]) -> None:
    """Assert two quaternions agree within :data:`TOL`, up to sign."""
    plus = np.allclose(actual, expected, rtol=0.0, atol=TOL)
    assert plus or np.allclose(actual, [-c for c in expected], rtol=0.0, atol=TOL), (
        actual,
        expected,
    )


def _dynamic(first: Transform, second: Transform, span: int) -> TimeCache:
    """Return a cache of child 1 holding ``first`` at :data:`T0` and ``second`` ``span`` later."""
    cache = TimeCache(1000 * SECOND, child_id=1)
    for stamp, (t, q) in ((T0, first), (T0 + span, second)):
        cache.insert(stamp, (*t, *q, PARENT))
    return cache


def _static(move: Transform, child: int) -> StaticCache:
    cache = StaticCache(child)
    t, q = move
    cache.insert(0, (*t, *q, child + 1))
    return cache


def _lane_time(span: int, fraction: float) -> int:
    """Return a time strictly inside ``(T0, T0 + span)``."""
    return T0 + min(max(1, round(fraction * span)), span - 1)


def _expected_link(first: Transform, second: Transform, ratio: float) -> tuple[Vec3, Quat]:
    """math3d's tf2 interpolate: lerp of the translations, slerp of the rotations."""
    return math3d.lerp(first[0], second[0], ratio), math3d.slerp(first[1], second[1], ratio)


def _rotated(q: Quat, angle: float, axis: Vec3, flip: bool) -> Quat:
    """Return ``q`` turned by ``angle`` about ``axis`` (negated when ``flip``: same rotation)."""
    turned = math3d.quat_multiply(q, math3d.quat_from_axis_angle(axis, angle))
    if flip:
        turned = (-turned[0], -turned[1], -turned[2], -turned[3])
    return math3d.quat_normalize(turned)


#: Rotation axes: the vector part of a unit quaternion, long enough to normalise (a vector like
#: (0, 0, 1.5e-239) is not zero but its norm underflows: math3d refuses it as a zero axis).
axes = (
    tfst.unit_quaternions()
    .map(lambda q: (q[0], q[1], q[2]))
    .filter(lambda v: v[0] * v[0] + v[1] * v[1] + v[2] * v[2] > 1e-12)
)


# --- TimeCache.arrays + _batch._interpolate_rows: the vectorised slerp ------------------------


def _batch_links(
    cache: TimeCache, span: int, fractions_drawn: list[float]
) -> list[tuple[float, list[float]]]:
    """Read ``cache`` with ``_batch.sample_batch`` at the drawn lane times: (ratio, link)s."""
    times = [_lane_time(span, f) for f in fractions_drawn]
    values, parents, ok = _batch.sample_batch(cache, np.array(times, dtype=np.int64))
    assert ok is None
    assert set(parents.tolist()) == {PARENT}
    return [((t - T0) / span, row) for t, row in zip(times, values.tolist(), strict=True)]


@given(moves, moves, spans, st.lists(fractions, min_size=1, max_size=8))
@example(
    ((0.0, 0.0, 0.0), (0.0, 0.0, 0.0, 1.0)), ((1.0, 0.0, 0.0), (0.0, 0.0, 0.0, 1.0)), 10, [0.5]
)
@tfst.profile_settings(150)
def test_batch_slerp_sine_branch_is_math3d_slerp(
    first: Transform, second: Transform, span: int, lane_fractions: list[float]
) -> None:
    """
    Pins ``TimeCache.arrays``' interval constants and ``_batch._interpolate_rows``' two-sine
    branch (some interval of the cache turns by more than 1 rad, and still intervals) to
    math3d.lerp / math3d.slerp.
    """
    cache = _dynamic(first, second, span)
    far = math3d.quat_multiply(second[1], (1.0, 0.0, 0.0, 0.0))  # a half turn: angle pi/2
    cache.insert(T0 + 2 * span, (*second[0], *far, PARENT))
    assert _batch.cache_arrays(cache).max_theta > _batch._SQRT_COSINE_MAX_THETA
    for ratio, row in _batch_links(cache, span, lane_fractions):
        t, q = _expected_link(first, second, ratio)
        _assert_close(tuple(row[:3]), t, 'lerp')
        _assert_same_rotation(tuple(row[3:]), q)


@given(
    moves,
    st.tuples(tfst.translations(), small_angles, axes, st.booleans()),
    spans,
    st.lists(fractions, min_size=1, max_size=8),
)
@tfst.profile_settings(150)
def test_batch_slerp_cosine_branch_is_math3d_slerp(
    first: Transform,
    turn: tuple[Vec3, float, Vec3, bool],
    span: int,
    lane_fractions: list[float],
) -> None:
    """
    Pins ``TimeCache.arrays``' interval constants and ``_batch._interpolate_rows``' one-sine
    branch (every interval turns by at most 1 rad; either sign of the newer quaternion) to
    math3d.lerp / math3d.slerp.
    """
    translation, angle, axis, flip = turn
    second = (translation, _rotated(first[1], angle, axis, flip))
    cache = _dynamic(first, second, span)
    assert _batch.cache_arrays(cache).max_theta <= _batch._SQRT_COSINE_MAX_THETA
    for ratio, row in _batch_links(cache, span, lane_fractions):
        t, q = _expected_link(first, second, ratio)
        _assert_close(tuple(row[:3]), t, 'lerp')
        _assert_same_rotation(tuple(row[3:]), q)


# --- _batch's composition copies ---------------------------------------------------------------


def _flat(move: Transform) -> tuple[float, ...]:
    return (*move[0], *move[1])


def _expected_compose(link: Transform, acc: Transform) -> tuple[float, ...]:
    t, q = math3d.compose(link[0], link[1], acc[0], acc[1])
    return (*t, *q)


@given(st.lists(st.tuples(moves, moves), min_size=1, max_size=6))
@tfst.profile_settings(150)
def test_batch_compose_is_math3d_compose(pairs: list[tuple[Transform, Transform]]) -> None:
    """Pins ``_batch._compose`` / ``_compose_translation`` (floats and lane arrays) to math3d."""
    for link, acc in pairs:
        one = [
            float(v) for v in _batch._compose(_batch._link(_flat(link)), _batch._link(_flat(acc)))
        ]
        _assert_close(tuple(one[:3]), _expected_compose(link, acc)[:3], 'compose translation')
        _assert_same_rotation(tuple(one[3:]), _expected_compose(link, acc)[3:])
    links = np.array([_flat(link) for link, _ in pairs]).T
    accs = np.array([_flat(acc) for _, acc in pairs]).T
    lanes = np.array(_batch._compose(_batch._link(list(links)), _batch._link(list(accs)))).T
    for (link, acc), row in zip(pairs, lanes.tolist(), strict=True):
        expected = _expected_compose(link, acc)
        _assert_close(tuple(row[:3]), expected[:3], 'compose translation')
        _assert_same_rotation(tuple(row[3:]), expected[3:])


def _check_rows(
    t: npt.NDArray[np.float64],
    q: npt.NDArray[np.float64],
    pairs: list[tuple[Transform, Transform]],
) -> None:
    """Assert row k of ``(t, q)`` is ``math3d.compose(*pairs[k])``."""
    assert t.shape == (len(pairs), 3)
    assert q.shape == (len(pairs), 4)
    for (link, acc), t_row, q_row in zip(pairs, t.tolist(), q.tolist(), strict=True):
        expected = _expected_compose(link, acc)
        _assert_close(tuple(t_row), expected[:3], 'accumulate translation')
        _assert_same_rotation(tuple(q_row), expected[3:])


@given(st.lists(moves, min_size=2, max_size=6), st.lists(moves, min_size=2, max_size=6), moves)
@tfst.profile_settings(150)
def test_batch_accumulate_is_math3d_compose(
    links: list[Transform], accs: list[Transform], fixed: Transform
) -> None:
    """
    Pins every branch of ``_batch._accumulate`` (one row, one fixed accumulated rotation through
    ``_times_fixed``, and row by row) to math3d.compose.
    """
    count = min(len(links), len(accs))
    links, accs = links[:count], accs[:count]
    link_rows = np.array([_flat(m) for m in links])

    one_t, one_q = _batch._accumulate(link_rows[:1], np.array([fixed[0]]), np.array([fixed[1]]))
    _check_rows(one_t, one_q, [(links[0], fixed)])
    fixed_t, fixed_q = _batch._accumulate(link_rows, np.array([fixed[0]]), np.array([fixed[1]]))
    _check_rows(fixed_t, fixed_q, [(link, fixed) for link in links])
    rows_t, rows_q = _batch._accumulate(
        link_rows, np.array([a[0] for a in accs]), np.array([a[1] for a in accs])
    )
    _check_rows(rows_t, rows_q, list(zip(links, accs, strict=True)))
    spread_t, spread_q = _batch._accumulate(
        link_rows[:1], np.array([a[0] for a in accs]), np.array([a[1] for a in accs])
    )
    _check_rows(spread_t, spread_q, [(links[0], acc) for acc in accs])


@given(moves, moves, moves, spans, st.lists(fractions, min_size=1, max_size=8))
@tfst.profile_settings(150)
def test_batch_chain_product_is_math3d_compose(
    below: Transform, first: Transform, second: Transform, span: int, lane_fractions: list[float]
) -> None:
    """Pins ``_batch._chain_product`` (a dynamic link over a static one: ``_times_fixed``)."""
    times = np.array([_lane_time(span, f) for f in lane_fractions], dtype=np.int64)
    dynamic = _dynamic(first, second, span)
    dynamic.insert(T0 + 2 * span, (*second[0], *second[1], PARENT))
    product = _batch._chain_product([_static(below, 0), dynamic], times)
    rows = np.array([np.broadcast_to(v, times.shape) for v in product]).T
    for time_ns, row in zip(times.tolist(), rows.tolist(), strict=True):
        link = _expected_link(first, second, (time_ns - T0) / span)
        expected = _expected_compose(link, below)
        _assert_close(tuple(row[:3]), expected[:3], 'chain translation')
        _assert_same_rotation(tuple(row[3:]), expected[3:])


@given(st.lists(st.tuples(moves, moves), min_size=1, max_size=6))
@tfst.profile_settings(150)
def test_batch_inverse_is_math3d_invert_and_compose(
    pairs: list[tuple[Transform, Transform]],
) -> None:
    """
    Pins ``_batch._inverse`` / ``_inverse_times`` (through ``_rotate``) to math3d.invert and
    math3d.compose: the same operations, so equal to the last bit (floats and lane arrays).
    """
    for target, source in pairs:
        inverse = _batch._inverse(_batch._link(_flat(target)))
        t, q = math3d.invert(*target)
        assert inverse == (*t, *q)
        full = _batch._inverse_times(inverse, _batch._link(_flat(source)))
        assert full == (*math3d.compose(t, q, *source)[0], *math3d.compose(t, q, *source)[1])
    targets = _batch._link(list(np.array([_flat(a) for a, _ in pairs]).T))
    sources = _batch._link(list(np.array([_flat(b) for _, b in pairs]).T))
    lanes = np.array(_batch._inverse_times(_batch._inverse(targets), sources)).T
    for (target, source), row in zip(pairs, lanes.tolist(), strict=True):
        t, q = math3d.invert(*target)
        t, q = math3d.compose(t, q, *source)
        assert tuple(row) == (*t, *q)


# --- math3d's own fast routes and vectorised copies ---------------------------------------------


@given(tfst.raw_quaternions())
@example((0.0, 0.0, 0.0, -2.0))
@example((0.5, 0.5, 0.5, -0.5))
@tfst.profile_settings(200)
def test_canonical_quat_shortcut_is_the_matrix_route(q: Quat) -> None:
    """Pins ``canonical_quat``'s shortcut to tf2's route through the matrix, bit for bit."""
    expected = math3d.quat_from_matrix(math3d.matrix_from_quat(q))
    _assert_identical(math3d.canonical_quat(q), expected, 'canonical quaternion')


@given(st.lists(tfst.raw_quaternions(), min_size=1, max_size=8))
@tfst.profile_settings(150)
def test_batch_rotation_helpers_are_the_scalar_ones(rows: list[Quat]) -> None:
    """
    Pins math3d's vectorised copies row by row to their scalar originals: ``canonical_quat_batch``,
    ``matrix_from_quat_batch`` and ``quat_from_matrix_batch`` (on the matrices of unit rotations).
    """
    quats = np.array(rows)
    canonical = math3d.canonical_quat_batch(quats)
    matrices = math3d.matrix_from_quat_batch(quats)
    unit_matrices = math3d.matrix_from_quat_batch(canonical)
    back = math3d.quat_from_matrix_batch(unit_matrices)
    for index, q in enumerate(rows):
        scalar = math3d.canonical_quat(q)
        _assert_identical(tuple(canonical[index]), scalar, 'canonical_quat_batch')
        matrix = math3d.matrix_from_quat(q)
        _assert_close(tuple(matrices[index].ravel()), sum(matrix, ()), 'matrix_from_quat_batch')
        unit = math3d.matrix_from_quat(math3d.canonical_quat(q))
        _assert_close(tuple(back[index]), math3d.quat_from_matrix(unit), 'quat_from_matrix_batch')


@given(st.lists(st.tuples(quats, quats, fractions), min_size=1, max_size=8))
@tfst.profile_settings(150)
def test_slerp_batch_is_slerp(rows: list[tuple[Quat, Quat, float]]) -> None:
    """Pins ``slerp_batch`` (lane-wise, same special cases) to ``slerp`` row by row."""
    q0 = np.array([row[0] for row in rows])
    q1 = np.array([row[1] for row in rows])
    out = math3d.slerp_batch(q0, q1, np.array([row[2] for row in rows]))
    for index, (a, b, ratio) in enumerate(rows):
        _assert_close(tuple(out[index]), math3d.slerp(a, b, ratio), 'slerp_batch')
