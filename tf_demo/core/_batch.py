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
exception.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING

import numpy as np
from tf_demo.core.math3d import quat_multiply_batch
from tf_demo.core.math3d import rotate_vector_batch
from tf_demo.core.time_cache import StaticCache
from tf_demo.core.time_cache import TimeCache

if TYPE_CHECKING:
    import numpy.typing as npt

    FloatArray = npt.NDArray[np.float64]
    IntArray = npt.NDArray[np.int64]
    BoolArray = npt.NDArray[np.bool_]

__all__ = ['batch_walk', 'sample_batch']

_MAX_GRAPH_DEPTH = 1000
_ENDING_NONE = 0
_ENDING_TARGET_PARENT = 1
_ENDING_SOURCE_PARENT = 2
_ENDING_FULL = 3
_IDENTITY_ROW = np.array([[0.0, 0.0, 0.0, 1.0]])


def _accumulate(
    quats: FloatArray, translations: FloatArray, acc_t: FloatArray, acc_q: FloatArray
) -> tuple[FloatArray, FloatArray]:
    """Return ``link * acc`` row-wise, with the same formula as the scalar walk."""
    px, py, pz, pw = quats[:, 0], quats[:, 1], quats[:, 2], quats[:, 3]
    sx, sy, sz = acc_t[:, 0], acc_t[:, 1], acc_t[:, 2]
    ux = 2.0 * (py * sz - pz * sy)
    uy = 2.0 * (pz * sx - px * sz)
    uz = 2.0 * (px * sy - py * sx)
    new_t = np.stack(
        (
            sx + pw * ux + (py * uz - pz * uy),
            sy + pw * uy + (pz * ux - px * uz),
            sz + pw * uz + (px * uy - py * ux),
        ),
        axis=-1,
    )
    new_t += translations
    return new_t, quat_multiply_batch(quats, acc_q)


def _interpolate(
    columns: FloatArray, slerp: FloatArray, older: IntArray, ratio: FloatArray
) -> FloatArray:
    """
    Interpolate samples ``older`` and ``older + 1`` at ``ratio``, as TimeCache.get_data.

    ``columns`` is ``(7, K)``; ``slerp`` holds the per-interval slerp constants.
    """
    keep = 1.0 - ratio
    newer = older + 1
    out = np.empty((7, older.shape[0]))
    for i in range(3):
        np.add(keep * np.take(columns[i], older), ratio * np.take(columns[i], newer), out=out[i])
    theta = np.take(slerp[0], older)
    inverse_sin = np.take(slerp[1], older)
    s0 = np.sin(keep * theta) * inverse_sin
    s1 = np.sin(ratio * theta) * (inverse_sin * np.take(slerp[2], older))
    for i in range(3, 7):
        one = np.take(columns[i], older)
        np.add(one * s0, np.take(columns[i], newer) * s1, out=out[i])
    still = theta == 0.0
    if still.any():  # a zero angle returns the older rotation unchanged, as tf2's slerp
        out[3:, still] = columns[3:, older[still]]
    result: FloatArray = out.T
    return result


def _older_indices(stamps: IntArray, times: IntArray) -> IntArray:
    """
    Return, per interior time, the last index whose stamp is <= the time.

    A linear guess (exact for evenly spaced streams) is checked and only the misses go through
    ``searchsorted``.
    """
    last = stamps.shape[0] - 1
    span = float(stamps[-1] - stamps[0])
    guess: IntArray = ((times - stamps[0]).astype(np.float64) * (last / span)).astype(np.int64)
    np.clip(guess, 0, last - 1, out=guess)
    hit = (np.take(stamps, guess) <= times) & (np.take(stamps, guess + 1) > times)
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
    stamps, columns, parent_ids, slerp = cache.arrays()
    size = stamps.shape[0]
    if size == 0:
        return np.zeros((1, 7)), np.zeros(1, dtype=np.int64), np.zeros(count, dtype=bool)
    latest = stamps[-1]
    earliest = stamps[0]
    if size > 1 and count and times.min() > earliest and times.max() < latest:
        # Fast path: every lane is strictly inside the history.
        older = _older_indices(stamps, times)
        one_parent = parent_ids[older]
        one_stamp = stamps[older]
        ratio = (times - one_stamp).astype(np.float64) / (stamps[older + 1] - one_stamp).astype(
            np.float64
        )
        values = _interpolate(columns, slerp, older, ratio)
        switched = one_parent != parent_ids[older + 1]
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
                one_stamp = stamps[older]
                ratio = (lane_times[same_parent] - one_stamp).astype(np.float64) / (
                    stamps[older + 1] - one_stamp
                ).astype(np.float64)
                values[lanes] = _interpolate(columns, slerp, older, ratio)
                parents[lanes] = parent_ids[older]
                single[lanes] = -2
    chosen = single >= 0
    values[chosen] = columns[:, single[chosen]].T
    parents[chosen] = parent_ids[single[chosen]]
    ok = single != -1
    return values, parents, None if ok.all() else ok


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
        and np.array_equal(tgt_q, _IDENTITY_ROW)
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
            quats = values[:, 3:]
            if lanes is None:
                acc_t, acc_q = _accumulate(quats, values[:, :3], acc_t, acc_q)
                frame[:] = parents
                if source_side:
                    top[:] = frame_id
            else:
                if acc_t.shape[0] != count:
                    acc_t = np.repeat(acc_t, count, axis=0)
                if acc_q.shape[0] != count:
                    acc_q = np.repeat(acc_q, count, axis=0)
                acc_t[lanes], acc_q[lanes] = _accumulate(
                    quats, values[:, :3], acc_t[lanes], acc_q[lanes]
                )
                frame[lanes] = parents
                if source_side:
                    top[lanes] = frame_id
    failed |= active  # deeper than tf2's MAX_GRAPH_DEPTH: the scalar walk reports the loop
    return acc_t, acc_q


def _all(lanes: IntArray | None) -> IntArray | slice:
    return slice(None) if lanes is None else lanes
