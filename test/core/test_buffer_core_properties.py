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

"""Property tests (hypothesis) for ``tf_demo.core``: transform algebra and buffer semantics."""

from __future__ import annotations

import math
import random

from hypothesis import assume
from hypothesis import given
from hypothesis import strategies as st
import numpy as np
import numpy.typing as npt
import pytest
from tf_demo.core import BufferCore
from tf_demo.core import ExtrapolationException
from tf_demo.core import math3d
from tf_demo.core import TransformException
from tf_demo.core import TransformResult
from tf_demo.core.exceptions import BackwardExtrapolationException
from tf_demo.core.exceptions import ForwardExtrapolationException
from tf_demo.testing import strategies as tfst

pytestmark = pytest.mark.property

Vec = tuple[float, float, float]
Quat = tuple[float, float, float, float]
Transform = tuple[Vec, Quat]
Tree = tuple[list[str], list[int], list[Transform]]
History = tuple[list[str], list[int], list[list[tuple[int, Transform]]]]

TOL = 1e-9
SECOND = 1_000_000_000
IDENTITY: Transform = ((0.0, 0.0, 0.0), (0.0, 0.0, 0.0, 1.0))


def _quiet_core(cache_time_ns: int = 10 * SECOND) -> BufferCore:
    """Return a buffer whose log texts are discarded."""
    return BufferCore(cache_time_ns, log=lambda level, text: None)


def _assert_vec_close(a: tuple[float, ...], b: tuple[float, ...], tol: float = TOL) -> None:
    """Assert two vectors agree component-wise."""
    assert np.allclose(a, b, rtol=0.0, atol=tol), (a, b)


def _assert_same_rotation(a: tuple[float, ...], b: tuple[float, ...], tol: float = TOL) -> None:
    """Assert two quaternions describe the same rotation (q and -q are equal)."""
    assert np.allclose(a, b, rtol=0.0, atol=tol) or np.allclose(a, [-c for c in b], atol=tol), (
        a,
        b,
    )


def _assert_transform_close(
    a: tuple[tuple[float, ...], tuple[float, ...]],
    b: tuple[tuple[float, ...], tuple[float, ...]],
    tol: float = TOL,
) -> None:
    """Assert two ``(t, q)`` transforms agree."""
    _assert_vec_close(a[0], b[0], tol)
    _assert_same_rotation(a[1], b[1], tol)


def _matrix(t: tuple[float, ...], q: tuple[float, ...]) -> npt.NDArray[np.float64]:
    """Build a 4x4 homogeneous matrix independently of ``math3d`` (textbook formula)."""
    x, y, z, w = q
    rotation = np.array(
        [
            [1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
            [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
            [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)],
        ]
    )
    out = np.eye(4)
    out[:3, :3] = rotation
    out[:3, 3] = t
    return out


def _angle_between(a: tuple[float, ...], b: tuple[float, ...]) -> float:
    """Return the rotation angle between two unit quaternions (0..pi)."""
    dot = abs(sum(x * y for x, y in zip(a, b, strict=True)))
    return 2.0 * math.acos(min(1.0, dot))


# --------------------------------------------------------------------------------------------
# Transform algebra


@given(tfst.transforms())
@tfst.profile_settings(200)
def test_compose_with_inverse_is_identity(transform: Transform) -> None:
    """a ∘ a⁻¹ and a⁻¹ ∘ a are the identity; inverting twice gives a back."""
    t, q = transform
    t_inv, q_inv = math3d.invert(t, q)
    _assert_transform_close(math3d.compose(t, q, t_inv, q_inv), IDENTITY)
    _assert_transform_close(math3d.compose(t_inv, q_inv, t, q), IDENTITY)
    _assert_transform_close(math3d.invert(t_inv, q_inv), (t, q))


@given(tfst.transforms(), tfst.transforms(), tfst.transforms())
@tfst.profile_settings(200)
def test_composition_is_associative(a: Transform, b: Transform, c: Transform) -> None:
    """(a ∘ b) ∘ c equals a ∘ (b ∘ c)."""
    ab = math3d.compose(*a, *b)
    bc = math3d.compose(*b, *c)
    _assert_transform_close(math3d.compose(*ab, *c), math3d.compose(*a, *bc))


@given(tfst.transforms(), tfst.transforms())
@tfst.profile_settings(200)
def test_compose_matches_the_product_of_homogeneous_matrices(a: Transform, b: Transform) -> None:
    """compose(a, b) is the matrix product H(a)·H(b), and the 4x4 helpers round-trip."""
    t, q = math3d.compose(*a, *b)
    product = _matrix(*a) @ _matrix(*b)
    assert np.allclose(_matrix(t, q), product, atol=TOL)
    assert np.allclose(math3d.homogeneous_from_transform(t, q), product, atol=TOL)
    back = math3d.transform_from_homogeneous(product)
    _assert_transform_close(back, (t, q))


@given(tfst.raw_quaternions())
@tfst.profile_settings(200)
def test_matrix_round_trip_normalises_and_canonicalises_the_sign(q: Quat) -> None:
    """quat→matrix→quat gives q/|q| up to sign, with tf2's sign rule (w > 0 if trace > 0)."""
    unit = math3d.quat_normalize(q)
    m = math3d.matrix_from_quat(q)
    back = math3d.quat_from_matrix(m)
    _assert_same_rotation(back, unit)
    assert math.isclose(sum(c * c for c in back), 1.0, abs_tol=TOL)
    trace = m[0][0] + m[1][1] + m[2][2]
    if trace > 0:
        assert back[3] > 0
    else:
        diagonal = [m[0][0], m[1][1], m[2][2]]
        assert back[diagonal.index(max(diagonal))] >= 0


@given(tfst.unit_quaternions(), tfst.unit_quaternions(), st.floats(0.0, 1.0))
@tfst.profile_settings(300)
def test_slerp_takes_the_short_path_and_hits_its_ends(q0: Quat, q1: Quat, ratio: float) -> None:
    """slerp starts at q0, ends at ±q1 in q0's hemisphere and splits the shorter arc by ratio."""
    assume(_angle_between(q0, q1) > 1e-6)
    _assert_vec_close(math3d.slerp(q0, q1, 0.0), q0)
    end = math3d.slerp(q0, q1, 1.0)
    _assert_same_rotation(end, q1)
    assert sum(a * b for a, b in zip(end, q0, strict=True)) >= -TOL  # stays in q0's hemisphere
    middle = math3d.slerp(q0, q1, ratio)
    total = _angle_between(q0, q1)
    assert total <= math.pi + TOL  # the shorter arc: never more than half a turn
    assert math.isclose(_angle_between(q0, middle), ratio * total, abs_tol=1e-7)
    assert math.isclose(_angle_between(middle, q1), (1 - ratio) * total, abs_tol=1e-7)
    # -q1 is the same rotation, so it must give the same interpolated rotation, unless the two
    # arcs are equally short (q0 . q1 == 0: half a turn, both ways valid; tf2 picks by the sign)
    if abs(sum(a * b for a, b in zip(q0, q1, strict=True))) > 1e-9:
        minus_q1 = (-q1[0], -q1[1], -q1[2], -q1[3])
        _assert_same_rotation(math3d.slerp(q0, minus_q1, ratio), middle, 1e-7)


@given(tfst.rpy_angles())
@tfst.profile_settings(300)
def test_rpy_quaternion_and_matrix_agree_with_rz_ry_rx(rpy: Vec) -> None:
    """setRPY's quaternion and matrix are both Rz(yaw)·Ry(pitch)·Rx(roll)."""
    roll, pitch, yaw = rpy
    cr, sr, cp, sp, cy, sy = (
        math.cos(roll),
        math.sin(roll),
        math.cos(pitch),
        math.sin(pitch),
        math.cos(yaw),
        math.sin(yaw),
    )
    rx = np.array([[1, 0, 0], [0, cr, -sr], [0, sr, cr]])
    ry = np.array([[cp, 0, sp], [0, 1, 0], [-sp, 0, cp]])
    rz = np.array([[cy, -sy, 0], [sy, cy, 0], [0, 0, 1]])
    expected = rz @ ry @ rx
    assert np.allclose(np.array(math3d.matrix_from_rpy(roll, pitch, yaw)), expected, atol=TOL)
    q = math3d.quat_from_rpy(roll, pitch, yaw)
    assert np.allclose(_matrix((0, 0, 0), q)[:3, :3], expected, atol=TOL)


@given(tfst.rpy_angles())
@tfst.profile_settings(300)
def test_rpy_round_trip_away_from_gimbal_lock(rpy: Vec) -> None:
    """getRPY(setRPY(r, p, y)) gives the same angles when |pitch| < pi/2 (not at the lock)."""
    roll, pitch, yaw = rpy
    assume(abs(abs(pitch) - math.pi / 2) > 1e-3)
    back = math3d.rpy_from_quat(math3d.quat_from_rpy(roll, pitch, yaw))
    for got, want in zip(back, rpy, strict=True):
        difference = (got - want + math.pi) % (2 * math.pi) - math.pi
        assert abs(difference) < 1e-8, (back, rpy)
    _assert_same_rotation(math3d.quat_from_rpy(*back), math3d.quat_from_rpy(roll, pitch, yaw))


@given(
    st.floats(-3.0, 3.0),
    st.floats(-3.0, 3.0),
    st.sampled_from([math.pi / 2, -math.pi / 2]),
)
@tfst.profile_settings(200)
def test_rpy_at_gimbal_lock_follows_tf2_literally(roll: float, yaw: float, pitch: float) -> None:
    """At |pitch| = pi/2 getRPY gives (roll, ±pi/2, 0): yaw is dropped, as tf2 does (spec §9)."""
    matrix = math3d.matrix_from_rpy(roll, pitch, yaw)
    assert abs(matrix[2][0]) >= 1  # the exact lock tf2 tests for
    got_roll, got_pitch, got_yaw = math3d.rpy_from_matrix(matrix)
    assert got_yaw == 0.0
    assert got_pitch == math.copysign(math.pi / 2, pitch)
    # tf2 takes atan2(R21, R22) = atan2(cos(p)·sin(r), cos(p)·cos(r)) with cos(p) ~ 6e-17 > 0
    assert math.isclose(got_roll, roll, abs_tol=1e-12)
    # The angles rebuild the rotation only when no yaw was lost.
    rebuilt = math3d.matrix_from_rpy(got_roll, got_pitch, got_yaw)
    assert np.allclose(rebuilt, math3d.matrix_from_rpy(roll, pitch, 0.0), atol=1e-12)
    # The quaternion route agrees with the matrix route.
    from_quat = math3d.rpy_from_quat(math3d.quat_from_rpy(roll, pitch, yaw))
    assert abs(from_quat[1]) == pytest.approx(math.pi / 2, abs=1e-7)


def test_rpy_matches_tf2_verified_values() -> None:
    """setRPY(0.1, 0.2, 0.3) and the getRPY round trip of (0.1, 2.0, 0.1) match spec §9."""
    q = math3d.quat_from_rpy(0.1, 0.2, 0.3)
    _assert_vec_close(q, (0.034270799, 0.106020511, 0.143572175, 0.983347443), 1e-9)
    back = math3d.rpy_from_quat(math3d.quat_from_rpy(0.1, 2.0, 0.1))
    _assert_vec_close(back, (-3.0416, 1.1416, -3.0416), 1e-4)


# --------------------------------------------------------------------------------------------
# Buffer semantics


@st.composite
def static_trees(draw: st.DrawFn) -> Tree:
    """Draw a connected tree of frames (parent list) with one transform per link."""
    parents = draw(tfst.parent_lists(min_frames=2, max_frames=7))
    parents = [-1] + [p if p >= 0 else 0 for p in parents[1:]]  # keep it one tree
    names = draw(
        st.lists(tfst.frame_names(), min_size=len(parents), max_size=len(parents), unique=True)
    )
    links = [draw(tfst.transforms(bound=10.0)) for _ in parents]
    return names, parents, links


def _root_T_frame(
    names: list[str], parents: list[int], links: list[Transform], index: int
) -> npt.NDArray[np.float64]:
    """Product of the edge matrices from the root down to ``names[index]``."""
    matrix = np.eye(4)
    while parents[index] >= 0:
        matrix = _matrix(*links[index]) @ matrix
        index = parents[index]
    return matrix


def _fill(
    core: BufferCore,
    names: list[str],
    parents: list[int],
    links: list[Transform],
    *,
    is_static: bool,
    stamp: int = 0,
) -> None:
    """Insert every link of a tree."""
    for index, parent in enumerate(parents):
        if parent >= 0:
            t, q = links[index]
            assert core.set_transform(names[parent], names[index], stamp, t, q, 'prop', is_static)


@given(static_trees(), st.data())
@tfst.profile_settings(150)
def test_a_chain_equals_the_product_of_its_edges(tree: Tree, data: st.DataObject) -> None:
    """lookup(target, source) is H(root→target)⁻¹ · H(root→source) built from the edges."""
    names, parents, links = tree
    core = _quiet_core()
    _fill(core, names, parents, links, is_static=True)
    target = data.draw(st.integers(0, len(names) - 1))
    source = data.draw(st.integers(0, len(names) - 1))
    expected = np.linalg.inv(_root_T_frame(names, parents, links, target)) @ _root_T_frame(
        names, parents, links, source
    )
    result = core.lookup_transform(names[target], names[source], 0)
    assert np.allclose(_matrix(result.translation, result.rotation), expected, atol=1e-8)


@given(static_trees(), st.data(), tfst.stamps_ns(1, 10**12))
@tfst.profile_settings(150)
def test_lookup_there_and_back_is_identity(tree: Tree, data: st.DataObject, stamp: int) -> None:
    """lookup(A, B) ∘ lookup(B, A) is the identity, for dynamic links at their stamp."""
    names, parents, links = tree
    core = _quiet_core()
    _fill(core, names, parents, links, is_static=False, stamp=stamp)
    a = names[data.draw(st.integers(0, len(names) - 1))]
    b = names[data.draw(st.integers(0, len(names) - 1))]
    ab = core.lookup_transform(a, b, stamp)
    ba = core.lookup_transform(b, a, stamp)
    composed = math3d.compose(ab.translation, ab.rotation, ba.translation, ba.rotation)
    _assert_transform_close(composed, IDENTITY, 1e-8)


@given(static_trees(), tfst.stamps_ns(0, 10**15))
@tfst.profile_settings(150)
def test_static_transforms_answer_at_any_time(tree: Tree, stamp: int) -> None:
    """A purely static tree gives the same transform at every time, stamped with that time."""
    names, parents, links = tree
    core = _quiet_core()
    _fill(core, names, parents, links, is_static=True, stamp=123)
    latest = core.lookup_transform(names[-1], names[0], 0)
    at_time = core.lookup_transform(names[-1], names[0], stamp)
    assert at_time.stamp_ns == stamp
    assert latest.stamp_ns == 0
    _assert_transform_close(
        (at_time.translation, at_time.rotation), (latest.translation, latest.rotation)
    )


@st.composite
def dynamic_histories(draw: st.DrawFn) -> History:
    """Draw a tree whose links each carry samples at distinct stamps: (names, parents, samples)."""
    parents = draw(tfst.parent_lists(min_frames=2, max_frames=5))
    names = draw(
        st.lists(tfst.frame_names(), min_size=len(parents), max_size=len(parents), unique=True)
    )
    samples = []
    for _ in parents:
        stamps = draw(st.lists(st.integers(1, 50), min_size=1, max_size=4, unique=True))
        samples.append([(s * SECOND // 10, draw(tfst.transforms(bound=10.0))) for s in stamps])
    return names, parents, samples


@given(
    dynamic_histories(),
    st.randoms(use_true_random=False),
    st.lists(st.integers(0, 60), min_size=1, max_size=8),
)
@tfst.profile_settings(150)
def test_results_do_not_depend_on_insertion_order(
    history: History, rng: random.Random, query_stamps: list[int]
) -> None:
    """Two buffers fed the same samples in different orders answer every query identically."""
    names, parents, samples = history
    inserts = [
        (names[parent], names[i], stamp, transform)
        for i, parent in enumerate(parents)
        if parent >= 0
        for stamp, transform in samples[i]
    ]
    shuffled = list(inserts)
    rng.shuffle(shuffled)
    cores = (_quiet_core(), _quiet_core())
    for core, order in zip(cores, (inserts, shuffled), strict=True):
        for parent, child, stamp, (t, q) in order:
            core.set_transform(parent, child, stamp, t, q, 'prop')
    for query in query_stamps:
        for target in names:
            for source in names:
                outcomes: list[object] = []
                for core in cores:
                    try:
                        r = core.lookup_transform(target, source, query * SECOND // 10)
                        outcomes.append((tuple(r.translation), tuple(r.rotation), r.stamp_ns))
                    except TransformException as exc:
                        outcomes.append((type(exc).__name__, str(exc)))
                assert outcomes[0] == outcomes[1], (target, source, query)


@given(
    st.lists(st.integers(1, 10**6), min_size=2, max_size=6, unique=True),
    st.data(),
)
@tfst.profile_settings(200)
def test_interpolation_hits_samples_and_stays_between_them(
    stamps: list[int], data: st.DataObject
) -> None:
    """Samples come back exactly at their stamps; in between the result lies between."""
    stamps.sort()
    samples = [data.draw(tfst.transforms(bound=10.0)) for _ in stamps]
    core = _quiet_core()
    for stamp, (t, q) in zip(stamps, samples, strict=True):
        core.set_transform('p', 'c', stamp, t, q, 'prop')
    for stamp, (t, q) in zip(stamps, samples, strict=True):
        result = core.lookup_transform('p', 'c', stamp)
        assert tuple(result.translation) == pytest.approx(t, abs=1e-12)
        _assert_same_rotation(result.rotation, q, 1e-12)
        assert result.stamp_ns == stamp
    index = data.draw(st.integers(0, len(stamps) - 2))
    low, high = stamps[index], stamps[index + 1]
    assume(high - low >= 2)
    time_ns = data.draw(st.integers(low + 1, high - 1))
    result = core.lookup_transform('p', 'c', time_ns)
    (t0, q0), (t1, q1) = samples[index], samples[index + 1]
    for axis in range(3):
        assert (
            min(t0[axis], t1[axis]) - TOL
            <= result.translation[axis]
            <= max(t0[axis], t1[axis]) + TOL
        )
    total = _angle_between(q0, q1)
    assert _angle_between(q0, result.rotation) <= total + 1e-7
    assert _angle_between(result.rotation, q1) <= total + 1e-7


@given(
    st.lists(st.integers(2, 10**4), min_size=2, max_size=5, unique=True),
    tfst.transforms(bound=10.0),
)
@tfst.profile_settings(200)
def test_extrapolation_is_detected_exactly_at_the_boundaries(
    stamps: list[int], transform: Transform
) -> None:
    """The oldest and newest stamps answer; one nanosecond outside raises past/future errors."""
    stamps.sort()
    core = _quiet_core()
    for stamp in stamps:
        core.set_transform('p', 'c', stamp, *transform, 'prop')
    assert core.lookup_transform('p', 'c', stamps[0]).stamp_ns == stamps[0]
    assert core.lookup_transform('p', 'c', stamps[-1]).stamp_ns == stamps[-1]
    assert core.can_transform('p', 'c', stamps[0])
    assert not core.can_transform('p', 'c', stamps[0] - 1)
    with pytest.raises(BackwardExtrapolationException, match='into the past'):
        core.lookup_transform('p', 'c', stamps[0] - 1)
    with pytest.raises(ForwardExtrapolationException, match='into the future'):
        core.lookup_transform('p', 'c', stamps[-1] + 1)


@given(
    st.lists(st.integers(0, 400), min_size=1, max_size=30),
    st.integers(1, 50),
)
@tfst.profile_settings(200)
def test_pruning_keeps_the_newest_cache_time_of_data(offsets: list[int], cache_time: int) -> None:
    """Accepted samples within cache_time of the newest stay; older ones go one insert later.

    tf2 prunes with the newest stamp from before each insert (spec §2.1), so after the last insert
    everything older than (newest before that insert) - cache_time is gone.
    """
    core = _quiet_core(cache_time)
    accepted: dict[int, float] = {}
    latest = None
    latest_before_last_insert = None
    for offset in offsets:
        latest_before_last_insert = latest
        stamp = 1000 + offset
        stored = core.set_transform(
            'p', 'c', stamp, (float(stamp), 0.0, 0.0), (0.0, 0.0, 0.0, 1.0), 'prop'
        )
        expected_ok = latest is None or stamp >= latest - cache_time
        assert stored == expected_ok, (stamp, latest)
        if stored:
            accepted.setdefault(stamp, float(stamp))
            latest = stamp if latest is None else max(latest, stamp)
    assert latest is not None
    for stamp in accepted:
        if stamp >= latest - cache_time:
            assert core.lookup_transform('p', 'c', stamp).translation[0] == float(stamp)
    if latest_before_last_insert is None:
        return
    too_old = [s for s in accepted if s < latest_before_last_insert - cache_time]
    for stamp in too_old:
        with pytest.raises(ExtrapolationException):
            core.lookup_transform('p', 'c', stamp)


@given(dynamic_histories(), st.data())
@tfst.profile_settings(100)
def test_lookup_transforms_equals_single_lookups(history: History, data: st.DataObject) -> None:
    """The batch lookup equals single lookups, or raises what the first failing one raises."""
    names, parents, samples = history
    core = _quiet_core()
    for i, parent in enumerate(parents):
        if parent >= 0:
            for stamp, (t, q) in samples[i]:
                core.set_transform(names[parent], names[i], stamp, t, q, 'prop')
    target = data.draw(st.sampled_from(names))
    source = data.draw(st.sampled_from(names))
    times = data.draw(st.lists(st.integers(0, 55 * SECOND // 10), min_size=1, max_size=20))
    singles: list[TransformResult | TransformException] = []
    for time_ns in times:
        try:
            singles.append(core.lookup_transform(target, source, time_ns))
        except TransformException as exc:
            singles.append(exc)
    first_error = next((s for s in singles if isinstance(s, TransformException)), None)
    if first_error is not None:
        with pytest.raises(type(first_error)) as raised:
            core.lookup_transforms(target, source, np.array(times, dtype=np.int64))
        assert str(raised.value) == str(first_error)
        return
    translations, rotations = core.lookup_transforms(
        target, source, np.array(times, dtype=np.int64)
    )
    for row, single in enumerate(singles):
        assert isinstance(single, TransformResult)
        _assert_vec_close(tuple(translations[row]), tuple(single.translation))
        _assert_same_rotation(tuple(rotations[row]), tuple(single.rotation))


def _answers(scenario: tfst.Scenario, offset: int) -> list[object]:
    """Run a scenario's inserts and lookups with every non-zero stamp shifted by ``offset``."""

    def shift(stamp: int) -> int:
        return stamp + offset if stamp else 0

    core = _quiet_core(scenario['cache_time_ns'])
    answers: list[object] = []
    for op in scenario['ops']:
        if op[0] == 'set':
            core.set_transform(
                op[1], op[2], shift(op[3]), tuple(op[4]), tuple(op[5]), op[6], op[7]
            )
        elif op[0] == 'clear':
            core.clear()
        elif op[0] == 'lookup':
            try:
                result = core.lookup_transform(op[1], op[2], shift(op[3]))
                answers.append((result.translation, result.rotation, result.stamp_ns))
            except TransformException as exc:
                answers.append(type(exc))
    return answers


@given(tfst.scenarios(), st.sampled_from([10**9, 1_700_000_000 * SECOND, 2**62]))
@tfst.profile_settings(100)
def test_shifting_every_stamp_changes_nothing_but_the_stamps(
    scenario: tfst.Scenario, offset: int
) -> None:
    """Scenarios at epoch-sized stamps (beyond what the oracle can take) give the same answers."""
    assume(all(op[3] != 0 for op in scenario['ops'] if op[0] == 'set' and not op[7]))
    base = _answers(scenario, 0)
    shifted = _answers(scenario, offset)
    assert len(base) == len(shifted)
    for before, after in zip(base, shifted, strict=True):
        if isinstance(before, tuple) and isinstance(after, tuple):
            _assert_vec_close(after[0], before[0], 1e-9)
            _assert_same_rotation(after[1], before[1], 1e-9)
            assert after[2] == (before[2] + offset if before[2] else 0)
        else:
            assert after == before


@given(
    st.lists(st.integers(1, 6), min_size=1, max_size=12),
    st.randoms(use_true_random=False),
)
@tfst.profile_settings(200)
def test_same_stamp_samples_break_ties_as_tf2_jazzy(grid: list[int], rng: random.Random) -> None:
    """Ties: the newest-inserted sample answers, except at the oldest stamp (first-inserted).

    Jazzy keeps same-stamp samples with different data (spec §1.2) and orders them newest-inserted
    first; findClosest returns the front at the newest stamp, the back at the oldest, and the
    newest-inserted tie (ratio 0) in between (spec §2.2, §10.4).
    """
    core = _quiet_core()
    inserted: dict[int, list[float]] = {}
    for order, point in enumerate(grid):
        stamp = point * SECOND
        x = float(order + 1)  # distinct data, so nothing is an exact duplicate
        q = (0.0, 0.0, math.sin(order * 0.1), math.cos(order * 0.1))
        assert core.set_transform('p', 'c', stamp, (x, 0.0, 0.0), q, 'prop')
        inserted.setdefault(stamp, []).append(x)
    newest, oldest = max(inserted), min(inserted)
    probes = list(inserted)
    rng.shuffle(probes)
    for stamp in probes:
        expected = (
            inserted[stamp][0] if stamp == oldest and stamp != newest else inserted[stamp][-1]
        )
        got = core.lookup_transform('p', 'c', stamp).translation[0]
        assert got == pytest.approx(expected, abs=1e-12), (stamp, inserted)
