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
Vectorised tree walk for :meth:`BufferCore.lookup_transforms` (many stamps, one call).

Each stamp is a *lane*.  Lanes walk tf2's two-sided path in lock-step; lanes that reach
different frames (a parent change in the history) are processed in groups, one numpy pass per
distinct frame and depth.  Cache reads use ``searchsorted`` and the same interpolation formulas
as :class:`~tf_demo.core.time_cache.TimeCache`, so results equal the scalar walk.  Lanes that
fail are only flagged: the caller replays them through the scalar walk, which raises tf2's exact
exception.  Quaternion products and the full-path steps call :mod:`~tf_demo.core.math3d` on
lanes; the lane-wise lerp, slerp and the walk's translation step are vectorised copies of
math3d's, pinned to it (within 1e-12) by ``test/core/test_math3d_vectorised.py``.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import NamedTuple
from typing import TYPE_CHECKING

from tf_demo.core.lazy_import import lazy_module
from tf_demo.core.math3d import canonical_quat_batch
from tf_demo.core.math3d import canonical_quat_rows
from tf_demo.core.math3d import quat_multiply_batch
from tf_demo.core.math3d import quat_multiply_lanes
from tf_demo.core.math3d import rotate_vector_batch
from tf_demo.core.math3d import rotate_vector_lanes
from tf_demo.core.time_cache import StaticCache
from tf_demo.core.time_cache import TimeCache

if TYPE_CHECKING:
    import numpy as np
    import numpy.typing as npt

    FloatArray = npt.NDArray[np.float64]
    IntArray = npt.NDArray[np.int64]
    BoolArray = npt.NDArray[np.bool_]
    #: A float (the same for every lane) or one value per lane.
    Value = float | FloatArray
    #: A transform as seven values: tx, ty, tz, qx, qy, qz, qw.
    Link = tuple[Value, Value, Value, Value, Value, Value, Value]
else:
    np = lazy_module('numpy')

__all__ = [
    'INTERVAL_COLUMNS',
    'CacheArrays',
    'batch_walk',
    'batch_walk_uniform',
    'cache_arrays',
    'sample_batch',
]

#: Rows of :attr:`CacheArrays.intervals`, one column per interval between samples k and k + 1:
#: older translation (3), newer minus older translation (3), older rotation (4), newer rotation
#: with the slerp sign applied (4), slerp angle, ``1 / sin(angle)`` (0 for a zero angle), the
#: interval length in ns as a float, ``cos(angle) / sin(angle)`` (0 for a zero angle), and
#: ``newer / sin(angle) - older * cot(angle)`` (4; the sine coefficient of the slerp).
INTERVAL_COLUMNS = 22


class CacheArrays(NamedTuple):
    """A :class:`TimeCache`'s live samples as numpy arrays, with per-interval constants."""

    #: ``(K,)`` ascending stamps.
    stamps: npt.NDArray[np.int64]
    #: ``(7, K)``: one contiguous row per component (tx, ty, tz, qx, qy, qz, qw).
    values: npt.NDArray[np.float64]
    #: ``(K,)`` parent ids.
    parents: npt.NDArray[np.int64]
    #: ``(INTERVAL_COLUMNS, K - 1)`` lerp / slerp constants, one contiguous row each.
    intervals: npt.NDArray[np.float64]
    #: Some interval has a zero slerp angle (its rotation is the older one, as tf2).
    any_still: bool
    #: Some interval changes parent (no interpolation across it).
    any_parent_change: bool
    #: Largest slerp angle of any interval (0 when there is none).
    max_theta: float


def cache_arrays(cache: TimeCache) -> CacheArrays:
    """
    Return a time cache's live samples as :class:`CacheArrays`, ascending by stamp.

    Kept in the cache's ``arrays_memo`` until its next change (insert, prune, clear); treat them
    as read-only.  Samples the cache made already keep their bits.  The interval constants are
    the batch walk's slerp, pinned to :func:`math3d.slerp <tf_demo.core.math3d.slerp>` by
    ``test/core/test_math3d_vectorised.py``.
    """
    memo = cache.arrays_memo
    if isinstance(memo, CacheArrays):
        return memo
    stamp_array, value_array, parent_array, samples = cache.live_storage()
    stamps = np.array(stamp_array, dtype=np.int64)
    table = np.array(value_array, dtype=np.float64).reshape(-1, 7)
    canonical_quat_batch(table[:, 3:], out=table[:, 3:])
    for row, sample in enumerate(samples):
        if sample is not None:  # stored as given (insert), or read already: the same bits
            table[row] = sample.as_tuple()[:7]
    values = np.ascontiguousarray(table.T)
    parents = np.array(parent_array, dtype=np.int64)
    count = stamps.shape[0]
    intervals = np.empty((INTERVAL_COLUMNS, max(count - 1, 0)))
    q0 = values[3:, :-1]
    q1 = values[3:, 1:]
    dot = np.einsum('ij,ij->j', q0, q1)
    theta = np.arccos(np.minimum(np.abs(dot), 1.0))
    intervals[0:3] = values[:3, :-1]
    intervals[3:6] = values[:3, 1:] - values[:3, :-1]
    intervals[6:10] = q0
    intervals[10:14] = q1 * np.where(dot < 0, -1.0, 1.0)
    intervals[14] = theta
    with np.errstate(divide='ignore'):
        intervals[15] = np.where(theta != 0.0, 1.0 / np.sin(theta), 0.0)
    intervals[16] = np.diff(stamps).astype(np.float64)
    intervals[17] = np.cos(theta) * intervals[15]
    intervals[18:22] = intervals[10:14] * intervals[15] - q0 * intervals[17]
    arrays = CacheArrays(
        stamps,
        values,
        parents,
        intervals,
        bool((theta == 0.0).any()),
        bool((parents[1:] != parents[:-1]).any()),
        float(theta.max()) if theta.size else 0.0,
    )
    cache.arrays_memo = arrays
    return arrays


_MAX_GRAPH_DEPTH = 1000
_ENDING_NONE = 0
_ENDING_TARGET_PARENT = 1
_ENDING_SOURCE_PARENT = 2
_ENDING_FULL = 3
#: Largest slerp angle for which :func:`_interpolate_rows` derives the cosine from the sine.
_SQRT_COSINE_MAX_THETA = 1.0
#: Most lanes per pass of :func:`batch_walk_uniform` (passes are balanced).
UNIFORM_CHUNK = 4096


def _accumulate(
    link: FloatArray, acc_t: FloatArray, acc_q: FloatArray
) -> tuple[FloatArray, FloatArray]:
    """
    Return ``link * acc`` row-wise, with the same formula as the scalar walk.

    ``link`` is ``(M, 7)``; ``acc_t`` / ``acc_q`` are ``(M, 3)`` / ``(M, 4)`` or one row that
    broadcasts.  The results are column-major views, so each component is contiguous.
    """
    if link.shape[0] == 1 and acc_t.shape[0] == 1 and acc_q.shape[0] == 1:
        one = _compose(_link(link[0].tolist()), _link(acc_t[0].tolist() + acc_q[0].tolist()))
        return np.array([one[:3]]), np.array([one[3:]])
    rows = max(link.shape[0], acc_t.shape[0], acc_q.shape[0])
    out = np.empty((7, rows))
    columns = _link(list(link.T))
    if acc_q.shape[0] == 1 and link.shape[0] == rows:
        # link * q for one fixed q is linear in the link's quaternion: one matrix product.
        out[0], out[1], out[2] = _compose_translation(columns, _link(list(acc_t.T) + [0.0] * 4))
        np.matmul(_times_fixed(acc_q[0].tolist()), link[:, 3:7].T, out=out[3:])
    else:
        for row, value in zip(
            out, _compose(columns, _link(list(acc_t.T) + list(acc_q.T))), strict=True
        ):
            row[:] = value
    return out[:3].T, out[3:].T


def _link(values: Sequence[Value]) -> Link:
    """Return seven values (tx, ty, tz, qx, qy, qz, qw) as a :data:`Link`."""
    tx, ty, tz, qx, qy, qz, qw = values
    return (tx, ty, tz, qx, qy, qz, qw)


def _times_fixed(q: Sequence[Value]) -> FloatArray:
    """
    Return the 4x4 matrix ``M`` with ``M @ p == p * q`` for every quaternion ``p`` (column).

    ``p * q`` is :func:`~tf_demo.core.math3d.quat_multiply`: for one fixed ``q`` it is linear
    in ``p``, so many links times one accumulated rotation are one matrix product.
    """
    qx, qy, qz, qw = q
    return np.array(
        [
            [qw, qz, -qy, qx],
            [-qz, qw, qx, qy],
            [qy, -qx, qw, qz],
            [-qx, -qy, -qz, qw],
        ]
    )


def _interpolate(arrays: CacheArrays, older: IntArray, ratio: FloatArray) -> FloatArray:
    """
    Interpolate samples ``older`` and ``older + 1`` at ``ratio``, as TimeCache.get_data.

    :returns: ``(M, 7)`` (a column-major view: each component is contiguous).
    """
    result: FloatArray = _interpolate_rows(arrays, older, ratio).T
    return result


def _interpolate_rows(arrays: CacheArrays, older: IntArray, ratio: FloatArray) -> FloatArray:
    """Return :func:`_interpolate`'s result as ``(7, M)``: one contiguous row per component."""
    rows = arrays.intervals
    out = np.empty((7, older.shape[0]))
    for i in range(3):  # t0 + ratio (t1 - t0)
        row = out[i]
        np.multiply(rows[3 + i].take(older), ratio, out=row)
        row += rows[i].take(older)
    theta = rows[14].take(older)
    if arrays.max_theta <= _SQRT_COSINE_MAX_THETA:
        # One sine per lane.  tf2's slerp q0 sin(keep t) / sin t + q1 sin(ratio t) / sin t is
        # q0 cos(ratio t) + b sin(ratio t) with b = q1 / sin t - q0 cot t per interval, and
        # cos = sqrt(1 - sin^2) is accurate (~1e-16) while ratio t <= max_theta stays well
        # below pi / 2.  A zero angle has b = 0: the older rotation exactly, as tf2.
        sine = np.multiply(ratio, theta)
        np.sin(sine, out=sine)
        cosine = sine * sine
        np.subtract(1.0, cosine, out=cosine)
        np.sqrt(cosine, out=cosine)
        for i in range(4):
            row = out[3 + i]
            np.multiply(rows[6 + i].take(older), cosine, out=row)
            row += rows[18 + i].take(older) * sine
        return out
    keep = 1.0 - ratio
    scales = np.empty((2, older.shape[0]))
    np.multiply(keep, theta, out=scales[0])
    np.multiply(ratio, theta, out=scales[1])
    np.sin(scales, out=scales)
    scales *= rows[15].take(older)
    s0 = scales[0]
    s1 = scales[1]
    for i in range(4):
        row = out[3 + i]
        np.multiply(rows[6 + i].take(older), s0, out=row)
        row += rows[10 + i].take(older) * s1
    if arrays.any_still:
        still = theta == 0.0
        if still.any():  # a zero angle returns the older rotation unchanged, as tf2's slerp
            out[3:, still] = rows[6:10, older[still]]
    return out


def _older_indices(stamps: IntArray, times: IntArray) -> IntArray:
    """
    Return, per interior time, the last index whose stamp is <= the time.

    A linear guess (exact for evenly spaced streams) is checked and only the misses go through
    ``searchsorted``.
    """
    last = stamps.shape[0] - 1
    span = float(stamps[-1] - stamps[0])
    guess: IntArray = ((times - stamps[0]).astype(np.float64) * (last / span)).astype(np.int64)
    np.minimum(guess, last - 1, out=guess)  # times are inside: the guess is >= 0
    hit = stamps.take(guess) <= times
    hit &= stamps.take(guess + 1) > times
    if not hit.all():
        miss = ~hit
        guess[miss] = np.searchsorted(stamps, times[miss], side='right') - 1
    return guess


def sample_batch(
    cache: TimeCache | StaticCache, times: IntArray
) -> tuple[FloatArray, IntArray, BoolArray | None]:
    """
    Read ``cache`` at every time: ``(values, parent ids, ok)``.

    ``values`` is ``(M, 7)`` or ``(1, 7)`` (broadcasts), parent ids ``(M,)`` or ``(1,)``, and
    ``ok`` is None when every lane succeeded.
    """
    count = times.shape[0]
    if isinstance(cache, StaticCache):
        sample = cache.get_data(0)
        return (
            np.asarray(sample[:7], dtype=np.float64).reshape(1, 7),
            np.array([sample[7]], dtype=np.int64),
            None,
        )
    arrays = cache_arrays(cache)
    stamps = arrays.stamps
    columns = arrays.values
    parent_ids = arrays.parents
    size = stamps.shape[0]
    if size == 0:
        return np.zeros((1, 7)), np.zeros(1, dtype=np.int64), np.zeros(count, dtype=bool)
    latest = stamps[-1]
    earliest = stamps[0]
    if size > 1 and count and times.min() > earliest and times.max() < latest:
        # Fast path: every lane is strictly inside the history.
        older = _older_indices(stamps, times)
        ratio = (times - stamps.take(older)).astype(np.float64)
        ratio /= arrays.intervals[16].take(older)
        values = _interpolate(arrays, older, ratio)
        if not arrays.any_parent_change:
            return values, parent_ids[:1], None
        one_parent = np.take(parent_ids, older)
        switched = one_parent != np.take(parent_ids, older + 1)
        if switched.any():
            values[switched] = columns[:, older[switched]].T
        return values, one_parent, None

    values = np.zeros((count, 7))
    parents = np.zeros(count, dtype=np.int64)
    single = np.full(count, -1, dtype=np.int64)
    zero = times == 0
    single[zero] = size - 1
    if size == 1:
        single[~zero & (times == stamps[0])] = 0
    else:
        at_latest = ~zero & (times == latest)
        single[at_latest] = size - 1
        at_earliest = ~zero & ~at_latest & (times == earliest)
        single[at_earliest] = 0
        inside = ~zero & (times < latest) & (times > earliest)
        lanes = np.flatnonzero(inside)
        if lanes.size:
            lane_times = times[lanes]
            older = _older_indices(stamps, lane_times)
            same_parent = parent_ids[older] == parent_ids[older + 1]
            single[lanes[~same_parent]] = older[~same_parent]
            lanes = lanes[same_parent]
            older = older[same_parent]
            if lanes.size:
                ratio = (lane_times[same_parent] - stamps[older]).astype(np.float64)
                ratio /= arrays.intervals[16, older]
                values[lanes] = _interpolate(arrays, older, ratio)
                parents[lanes] = parent_ids[older]
                single[lanes] = -2
    chosen = single >= 0
    values[chosen] = columns[:, single[chosen]].T
    parents[chosen] = parent_ids[single[chosen]]
    ok = single != -1
    return values, parents, None if ok.all() else ok


def _compose_translation(link: Link, acc: Link) -> tuple[Value, Value, Value]:
    """Return the translation of ``link * acc`` (the first half of :func:`_compose`)."""
    lx, ly, lz, px, py, pz, pw = link
    sx, sy, sz = acc[0], acc[1], acc[2]
    ux = 2.0 * (py * sz - pz * sy)
    uy = 2.0 * (pz * sx - px * sz)
    uz = 2.0 * (px * sy - py * sx)
    return (
        sx + pw * ux + (py * uz - pz * uy) + lx,
        sy + pw * uy + (pz * ux - px * uz) + ly,
        sz + pw * uz + (px * uy - py * ux) + lz,
    )


def _compose(link: Link, acc: Link) -> Link:
    """Return ``link * acc`` on floats or lane arrays, with the scalar walk's formula."""
    x, y, z = _compose_translation(link, acc)
    _, _, _, px, py, pz, pw = link
    _, _, _, qx, qy, qz, qw = acc
    rx, ry, rz, rw = quat_multiply_lanes((px, py, pz, pw), (qx, qy, qz, qw))
    return (x, y, z, rx, ry, rz, rw)


def _uniform_parent(cache: TimeCache | StaticCache, earliest: int, latest: int) -> int | None:
    """
    Return the link's parent if it is the same for every lane and has data strictly inside.

    ``earliest`` / ``latest`` bound the lanes' times.  None when the link needs the general
    walk (parent changes, or some lane at or beyond an end of the history).
    """
    if isinstance(cache, StaticCache):
        return cache.get_parent(0)
    arrays = cache_arrays(cache)
    stamps = arrays.stamps
    if (
        arrays.any_parent_change
        or stamps.shape[0] < 2
        or not stamps[0] < earliest
        or not latest < stamps[-1]
    ):
        return None
    return int(arrays.parents[0])


def _chain_product(links: list[TimeCache | StaticCache], times: IntArray) -> Link:
    """Return ``top_T_bottom`` of ``links`` (bottom first) at every lane's time."""
    acc: Link = (0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0)
    first = True
    for cache in links:
        if isinstance(cache, StaticCache):
            lx, ly, lz, px, py, pz, pw, _ = cache.get_data(0)
            link: Link = (lx, ly, lz, px, py, pz, pw)
            acc = link if first else _compose(link, acc)
            first = False
            continue
        arrays = cache_arrays(cache)
        stamps = arrays.stamps
        older = _older_indices(stamps, times)
        ratio = (times - stamps.take(older)).astype(np.float64)
        ratio /= arrays.intervals[16].take(older)
        rows = _interpolate_rows(arrays, older, ratio)
        link = (rows[0], rows[1], rows[2], rows[3], rows[4], rows[5], rows[6])
        if first:
            acc = link
        elif isinstance(acc[3], float):
            # The same rotation for every lane (static links below): link * q is linear in
            # the link's quaternion, one matrix product instead of 28 array operations.
            x, y, z = _compose_translation(link, acc)
            product = _times_fixed(acc[3:]) @ rows[3:]
            acc = (x, y, z, product[0], product[1], product[2], product[3])
        else:
            acc = _compose(link, acc)
        first = False
    return acc


def _inverse(t: Link) -> Link:
    """Return ``t^-1`` as the scalar walk computes it: :func:`math3d.invert <invert>`'s steps."""
    tx, ty, tz, qx, qy, qz, qw = t
    x, y, z = rotate_vector_lanes((-qx, -qy, -qz, qw), (-tx, -ty, -tz))
    return (x, y, z, -qx, -qy, -qz, qw)


def _inverse_times(inverse: Link, source: Link) -> Link:
    """Return ``inverse * source`` as the scalar walk's full-path step (math3d's ``compose``)."""
    ox, oy, oz, ix, iy, iz, iw = inverse
    sx, sy, sz, sqx, sqy, sqz, sqw = source
    rx, ry, rz = rotate_vector_lanes((ix, iy, iz, iw), (sx, sy, sz))
    qx, qy, qz, qw = quat_multiply_lanes((ix, iy, iz, iw), (sqx, sqy, sqz, sqw))
    return (rx + ox, ry + oy, rz + oz, qx, qy, qz, qw)


def _uniform_side(
    caches: Sequence[TimeCache | StaticCache | None],
    frame: int,
    stop: int,
    other: int,
    window: tuple[int, int],
) -> tuple[list[TimeCache | StaticCache], int, int, bool] | None:
    """
    Collect the links from ``frame`` towards ``stop`` that every lane takes (one side).

    The side stops at ``stop``, at a frame without a cache, or at ``other`` (before taking its
    link).  ``window`` bounds the lanes' times.  :returns: None when some lane needs the general
    walk (see :func:`_uniform_parent`, or deeper than tf2's limit); else ``(links bottom first,
    the frame where the side stopped, the last frame whose link was taken or the start frame,
    whether it stopped at other)``.
    """
    links: list[TimeCache | StaticCache] = []
    last = frame
    while frame != stop:
        cache = caches[frame]
        if cache is None:
            break
        parent = _uniform_parent(cache, *window)
        if parent is None:
            return None
        if frame == other:
            return links, frame, last, True
        links.append(cache)
        last = frame
        frame = parent
        if len(links) > _MAX_GRAPH_DEPTH:
            return None
    return links, frame, last, False


def batch_walk_uniform(
    caches: Sequence[TimeCache | StaticCache | None],
    target_id: int,
    source_id: int,
    times: IntArray,
) -> tuple[FloatArray, FloatArray] | None:
    """
    Walk tf2's path once for all lanes when every lane takes the same links; else None.

    Applies when, along the path, no link changes parent and every lane's time is strictly
    inside every dynamic link's history (so no lane can fail): the links are found once and
    each is read for all lanes at once.  Returns ``target_T_source`` ``(N, 3)`` and ``(N, 4)``
    with the rotation canonical as :meth:`BufferCore.lookup_transform` gives it (made per pass,
    on contiguous components); None means "use :func:`batch_walk`".
    """
    count = times.shape[0]
    if not count:
        return None
    earliest = int(times.min())
    latest = int(times.max())
    if earliest <= 0:
        return None  # time 0 means "latest" to a cache: leave it to the general walk
    window = (earliest, latest)
    source = _uniform_side(caches, source_id, 0, target_id, window)
    if source is None:
        return None
    source_links, frame, last, met = source
    target_links: list[TimeCache | StaticCache] = []
    ending = _ENDING_TARGET_PARENT if met else _ENDING_NONE
    if not met:
        top = last if frame == 0 else frame
        target = _uniform_side(caches, target_id, top, source_id, window)
        if target is None:
            return None
        target_links, frame, _, met = target
        if met:
            ending = _ENDING_SOURCE_PARENT
        elif frame != top:
            return None  # a frame without a cache below the top: the general walk fails it
    translations = np.empty((count, 3))
    rotations = np.empty((count, 4))
    # Chunks keep the temporaries small: in cache, and reused by the allocator instead of
    # being handed back to the system and faulted in again.
    chunks = -(-count // UNIFORM_CHUNK)
    size = -(-count // chunks)  # balanced: no small remainder chunk
    for begin in range(0, count, size):
        end = min(begin + size, count)
        chunk = times[begin:end]
        if ending == _ENDING_SOURCE_PARENT:
            result = _inverse(_chain_product(target_links, chunk))
        elif target_links:
            result = _inverse_times(
                _inverse(_chain_product(target_links, chunk)),
                _chain_product(source_links, chunk),
            )
        else:
            result = _chain_product(source_links, chunk)
        for column in range(3):
            translations[begin:end, column] = result[column]
        canonical = canonical_quat_rows(*_full_rows(result[3:], end - begin))
        for column, values in enumerate(canonical):
            rotations[begin:end, column] = values
    return translations, rotations


def _full_rows(values: Sequence[Value], count: int) -> list[FloatArray]:
    """Return the values as arrays of ``count`` lanes (a float stands for every lane)."""
    return [np.full(count, value) if isinstance(value, float) else value for value in values]


def batch_walk(
    caches: Sequence[TimeCache | StaticCache | None],
    target_id: int,
    source_id: int,
    times: IntArray,
) -> tuple[FloatArray, FloatArray, BoolArray]:
    """
    Walk tf2's path for every lane; return raw ``target_T_source`` and a failure mask.

    Times must already be resolved (0 only where the latest common time is 0).
    """
    count = times.shape[0]
    failed = np.zeros(count, dtype=bool)
    ending = np.zeros(count, dtype=np.int8)
    top = np.full(count, source_id, dtype=np.int64)
    state = (top, failed, ending)
    src_t, src_q = _side_walk(caches, times, source_id, target_id, state, source_side=True)
    tgt_t, tgt_q = _side_walk(caches, times, target_id, source_id, state, source_side=False)
    full = (ending == _ENDING_NONE) & ~failed
    ending[full] = _ENDING_FULL

    if (
        full.all()
        and tgt_t.shape[0] == 1
        and not tgt_t.any()
        and tgt_q.tolist() == [[0.0, 0.0, 0.0, 1.0]]
    ):
        # Every lane met the target as the top: the inverse of an identity changes nothing.
        return _full(src_t, count), _full(src_q, count), failed
    inverse_q = tgt_q * np.array([-1.0, -1.0, -1.0, 1.0])
    inverse_t = rotate_vector_batch(inverse_q, -tgt_t)
    if full.all():
        return (
            _full(rotate_vector_batch(inverse_q, src_t) + inverse_t, count),
            _full(quat_multiply_batch(inverse_q, src_q), count),
            failed,
        )
    src_t = _full(src_t, count)
    src_q = _full(src_q, count)
    inverse_t = _full(inverse_t, count)
    inverse_q = _full(inverse_q, count)
    translations = src_t.copy()
    rotations = src_q.copy()
    lanes = ending == _ENDING_SOURCE_PARENT
    translations[lanes] = inverse_t[lanes]
    rotations[lanes] = inverse_q[lanes]
    translations[full] = rotate_vector_batch(inverse_q[full], src_t[full]) + inverse_t[full]
    rotations[full] = quat_multiply_batch(inverse_q[full], src_q[full])
    failed |= ending == _ENDING_NONE
    return translations, rotations, failed


def _full(array: FloatArray, count: int) -> FloatArray:
    """Return ``array`` with ``count`` rows (broadcasting a single row)."""
    if array.shape[0] == count:
        return array
    out: FloatArray = np.repeat(array, count, axis=0)
    return out


def _side_walk(
    caches: Sequence[TimeCache | StaticCache | None],
    times: IntArray,
    start_id: int,
    other_id: int,
    state: tuple[IntArray, BoolArray, npt.NDArray[np.int8]],
    *,
    source_side: bool,
) -> tuple[FloatArray, FloatArray]:
    """
    Walk one side for every lane, accumulating ``top_T_start``; updates the shared state.

    Source side: stops at a frame without cache or data (recording it as the lane's top), or
    at ``other_id`` (target is an ancestor).  Target side: stops at the lane's top, at
    ``other_id`` (source is an ancestor), or fails.
    """
    top, failed, ending = state
    count = times.shape[0]
    # The accumulators stay (1, n) while every lane has seen the same links (static links at
    # the bottom of the chain); they broadcast to (count, n) at the first per-lane value.
    acc_t = np.zeros((1, 3))
    acc_q = np.array([[0.0, 0.0, 0.0, 1.0]])
    frame = np.full(count, start_id, dtype=np.int64)
    active = np.ones(count, dtype=bool) if source_side else (ending == _ENDING_NONE) & ~failed
    for _ in range(_MAX_GRAPH_DEPTH + 1):
        if not source_side:
            active &= frame != top
        active_lanes = np.flatnonzero(active)
        if not active_lanes.size:
            return acc_t, acc_q
        everyone = active_lanes.size == count
        frames_here = frame if everyone else frame[active_lanes]
        first_frame = int(frames_here[0])
        if (frames_here == first_frame).all():
            groups: list[tuple[int, IntArray | None]] = [
                (first_frame, None if everyone else active_lanes)
            ]
        else:
            groups = [
                (frame_id, active_lanes[frames_here == frame_id])
                for frame_id in np.unique(frames_here).tolist()
            ]
        for frame_id, group_lanes in groups:
            lanes = group_lanes
            cache = caches[frame_id] if frame_id < len(caches) else None
            if cache is None:
                if source_side:
                    top[_all(lanes)] = frame_id
                else:
                    failed[_all(lanes)] = True  # below the top: extrapolation/connectivity
                active[_all(lanes)] = False
                continue
            values, parents, ok = sample_batch(cache, times if lanes is None else times[lanes])
            if ok is not None:
                lanes_index = np.arange(count) if lanes is None else lanes
                bad = lanes_index[~ok]
                if source_side:
                    top[bad] = frame_id
                else:
                    failed[bad] = True
                active[bad] = False
                lanes = lanes_index[ok]
                if not lanes.size:
                    continue
                if values.shape[0] > 1:
                    values = values[ok]
                    parents = parents[ok]
            if frame_id == other_id:
                ending[_all(lanes)] = (
                    _ENDING_TARGET_PARENT if source_side else _ENDING_SOURCE_PARENT
                )
                active[_all(lanes)] = False
                continue
            if lanes is None:
                acc_t, acc_q = _accumulate(values, acc_t, acc_q)
                frame[:] = parents
                if source_side:
                    top[:] = frame_id
            else:
                if acc_t.shape[0] != count:
                    acc_t = np.repeat(acc_t, count, axis=0)
                if acc_q.shape[0] != count:
                    acc_q = np.repeat(acc_q, count, axis=0)
                acc_t[lanes], acc_q[lanes] = _accumulate(values, acc_t[lanes], acc_q[lanes])
                frame[lanes] = parents
                if source_side:
                    top[lanes] = frame_id
    failed |= active  # deeper than tf2's MAX_GRAPH_DEPTH: the scalar walk reports the loop
    return acc_t, acc_q


def _all(lanes: IntArray | None) -> IntArray | slice:
    return slice(None) if lanes is None else lanes
