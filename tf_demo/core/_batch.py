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
from tf_demo.core.math3d import slerp_batch
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


def sample_batch(
    cache: TimeCache | StaticCache, times: IntArray
) -> tuple[FloatArray, IntArray, BoolArray]:
    """Read ``cache`` at every time: ``(values (M, 7), parent ids (M,), ok (M,))``."""
    count = times.shape[0]
    if isinstance(cache, StaticCache):
        sample = cache.get_data(0)
        values = np.broadcast_to(np.asarray(sample[:7], dtype=np.float64), (count, 7)).copy()
        return values, np.full(count, sample[7], dtype=np.int64), np.ones(count, dtype=bool)
    stamps, table = cache.arrays()
    size = stamps.shape[0]
    values = np.zeros((count, 7))
    parents = np.zeros(count, dtype=np.int64)
    ok = np.zeros(count, dtype=bool)
    if size == 0:
        return values, parents, ok
    data = table[:, :7]
    parent_ids = table[:, 7].astype(np.int64)

    single = np.full(count, -1, dtype=np.int64)
    zero = times == 0
    single[zero] = size - 1
    if size == 1:
        match = ~zero & (times == stamps[0])
        single[match] = 0
        chosen = single >= 0
        values[chosen] = data[single[chosen]]
        parents[chosen] = parent_ids[single[chosen]]
        ok[chosen] = True
        return values, parents, ok

    latest = stamps[-1]
    earliest = stamps[0]
    at_latest = ~zero & (times == latest)
    single[at_latest] = size - 1
    at_earliest = ~zero & ~at_latest & (times == earliest)
    single[at_earliest] = 0
    inside = ~zero & ~at_latest & ~at_earliest & (times < latest) & (times > earliest)
    lanes = np.flatnonzero(inside)
    if lanes.size:
        older = np.searchsorted(stamps, times[lanes], side='right') - 1
        newer = older + 1
        same_parent = parent_ids[older] == parent_ids[newer]
        single[lanes[~same_parent]] = older[~same_parent]
        lanes = lanes[same_parent]
        older = older[same_parent]
        newer = newer[same_parent]
        if lanes.size:
            one_stamp = stamps[older]
            two_stamp = stamps[newer]
            equal = two_stamp == one_stamp
            span = np.where(equal, 1, two_stamp - one_stamp).astype(np.float64)
            ratio = (times[lanes] - one_stamp).astype(np.float64) / span
            keep = 1.0 - ratio
            one = data[older]
            two = data[newer]
            interpolated = np.empty((lanes.size, 7))
            interpolated[:, :3] = keep[:, None] * one[:, :3] + ratio[:, None] * two[:, :3]
            interpolated[:, 3:] = slerp_batch(one[:, 3:], two[:, 3:], ratio)
            interpolated[equal] = two[equal]
            values[lanes] = interpolated
            parents[lanes] = parent_ids[older]
            ok[lanes] = True
    chosen = single >= 0
    values[chosen] = data[single[chosen]]
    parents[chosen] = parent_ids[single[chosen]]
    ok[chosen] = True
    return values, parents, ok


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
    src_t = np.zeros((count, 3))
    src_q = np.zeros((count, 4))
    src_q[:, 3] = 1.0
    tgt_t = np.zeros((count, 3))
    tgt_q = np.zeros((count, 4))
    tgt_q[:, 3] = 1.0
    top = np.full(count, source_id, dtype=np.int64)
    flagged = np.zeros(count, dtype=bool)

    # Source side.
    frame = np.full(count, source_id, dtype=np.int64)
    active = np.ones(count, dtype=bool)
    depth = 0
    while active.any():
        active_lanes = np.flatnonzero(active)
        for frame_id in np.unique(frame[active_lanes]).tolist():
            lanes = active_lanes[frame[active_lanes] == frame_id]
            cache = caches[frame_id] if frame_id < len(caches) else None
            if cache is None:
                top[lanes] = frame_id
                active[lanes] = False
                continue
            values, parents, ok = sample_batch(cache, times[lanes])
            bad = lanes[~ok]
            top[bad] = frame_id
            flagged[bad] = True
            active[bad] = False
            lanes = lanes[ok]
            if not lanes.size:
                continue
            values = values[ok]
            if frame_id == target_id:
                ending[lanes] = _ENDING_TARGET_PARENT
                active[lanes] = False
                continue
            quats = values[:, 3:]
            src_t[lanes] = rotate_vector_batch(quats, src_t[lanes]) + values[:, :3]
            src_q[lanes] = quat_multiply_batch(quats, src_q[lanes])
            top[lanes] = frame_id
            frame[lanes] = parents[ok]
        depth += 1
        if depth > _MAX_GRAPH_DEPTH:
            failed |= active
            break

    # Target side.
    frame = np.full(count, target_id, dtype=np.int64)
    active = (ending == _ENDING_NONE) & ~failed
    depth = 0
    while True:
        active &= frame != top
        if not active.any():
            break
        active_lanes = np.flatnonzero(active)
        for frame_id in np.unique(frame[active_lanes]).tolist():
            lanes = active_lanes[frame[active_lanes] == frame_id]
            cache = caches[frame_id] if frame_id < len(caches) else None
            if cache is None:
                failed[lanes] = True  # stopped below the top: extrapolation or connectivity
                active[lanes] = False
                continue
            values, parents, ok = sample_batch(cache, times[lanes])
            failed[lanes[~ok]] = True
            active[lanes[~ok]] = False
            lanes = lanes[ok]
            if not lanes.size:
                continue
            values = values[ok]
            if frame_id == source_id:
                ending[lanes] = _ENDING_SOURCE_PARENT
                active[lanes] = False
                continue
            quats = values[:, 3:]
            tgt_t[lanes] = rotate_vector_batch(quats, tgt_t[lanes]) + values[:, :3]
            tgt_q[lanes] = quat_multiply_batch(quats, tgt_q[lanes])
            frame[lanes] = parents[ok]
        depth += 1
        if depth > _MAX_GRAPH_DEPTH:
            failed |= active
            break
    full = (ending == _ENDING_NONE) & ~failed
    ending[full] = _ENDING_FULL

    translations = src_t.copy()
    rotations = src_q.copy()
    inverse_q = tgt_q * np.array([-1.0, -1.0, -1.0, 1.0])
    inverse_t = rotate_vector_batch(inverse_q, -tgt_t)
    lanes = ending == _ENDING_SOURCE_PARENT
    translations[lanes] = inverse_t[lanes]
    rotations[lanes] = inverse_q[lanes]
    lanes = ending == _ENDING_FULL
    translations[lanes] = rotate_vector_batch(inverse_q[lanes], src_t[lanes]) + inverse_t[lanes]
    rotations[lanes] = quat_multiply_batch(inverse_q[lanes], src_q[lanes])
    failed |= ending == _ENDING_NONE
    return translations, rotations, failed
