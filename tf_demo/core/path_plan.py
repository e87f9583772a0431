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
The path between two frames, remembered until the tree changes shape.

While every dynamic link on the way has had one parent all along, the frames tf2's walk visits
between two frames are the same at every time: only whether each dynamic link has data at the
asked time varies.  :func:`plan_path` works out, once per shape of the tree, which dynamic
caches the walk reads (:attr:`PathPlan.reads`) and which ones ``getLatestCommonTime`` takes the
newest stamps of (:attr:`PathPlan.common`), so that ``can_transform`` and a lookup at time 0
need no walk.  Where the walk would fail, or a link has changed parent, there is no plan and the
full walk (with tf2's error texts) answers, as before.
"""

from __future__ import annotations

from typing import NamedTuple
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from collections.abc import Sequence

    from tf_demo.core.time_cache import StaticCache
    from tf_demo.core.time_cache import TimeCache

__all__ = ['PathPlan', 'common_time', 'has_data', 'plan_path']


class PathPlan(NamedTuple):
    """What the walk between two frames reads, for one shape of the tree."""

    #: The dynamic caches the walk reads: each must have data at the asked time.
    reads: tuple[TimeCache, ...]
    #: The dynamic caches between the two frames and their lowest common ancestor.
    common: tuple[TimeCache, ...]


def _ancestors(
    caches: Sequence[TimeCache | StaticCache | None], frame: int, max_depth: int
) -> list[int] | None:
    """
    Return ``frame`` and its ancestors up to the first frame without a cache.

    None when a dynamic link on the way is empty or has had more than one parent (the path then
    depends on the time), or on a loop.
    """
    frames = [frame]
    cache = caches[frame]
    while cache is not None:
        if not cache.is_static and cache.mixed:
            return None
        frame = cache.latest[1]  # 0 for an empty cache
        if not frame or len(frames) > max_depth:
            return None
        frames.append(frame)
        cache = caches[frame]
    return frames


def _dynamic(
    caches: Sequence[TimeCache | StaticCache | None], frames: Sequence[int]
) -> list[TimeCache]:
    """Return the dynamic caches of ``frames`` (frames without a cache skipped)."""
    found = []
    for frame in frames:
        cache = caches[frame]
        if cache is not None and not cache.is_static:
            found.append(cache)
    return found


def plan_path(
    caches: Sequence[TimeCache | StaticCache | None], target: int, source: int, max_depth: int
) -> PathPlan | None:
    """
    Return what tf2's walk from ``source`` to ``target`` (two different frames) reads.

    The walk (``walkToTopParent``) climbs from the source to the top, or to the target when
    the target is above it (whose cache it reads too); then from the target up to that top, or
    to the source when the source is above it.  None when there is no plan to make: see
    :func:`_ancestors`, or the frames are not connected.
    """
    source_up = _ancestors(caches, source, max_depth)
    target_up = _ancestors(caches, target, max_depth)
    if source_up is None or target_up is None:
        return None
    # The walk: the source side reads every cache up to the target or the top.
    if target in source_up:
        reads = _dynamic(caches, source_up[: source_up.index(target) + 1])
    else:
        top = source_up[-1]
        reads = _dynamic(caches, source_up)
        if target != top:
            if top not in target_up:
                return None  # two trees
            side = target_up[: target_up.index(top)]
            if source in side:
                side = side[: side.index(source) + 1]
            reads += _dynamic(caches, side)
    # getLatestCommonTime: the links below the lowest common ancestor, on both sides.
    if target in source_up:
        common = _dynamic(caches, source_up[: source_up.index(target)])
    else:
        above_source = set(source_up)
        meet = next(index for index, frame in enumerate(target_up) if frame in above_source)
        ancestor = target_up[meet]
        common = _dynamic(caches, target_up[:meet])
        if ancestor != source:
            common += _dynamic(caches, source_up[: source_up.index(ancestor)])
    return PathPlan(tuple(reads), tuple(common))


def common_time(plan: PathPlan) -> int:
    """Return tf2's latest common time of the planned frames (0: no link constrains it)."""
    newest = [stamp for stamp in (cache.latest[0] for cache in plan.common) if stamp]
    return min(newest) if newest else 0


def has_data(plan: PathPlan, time_ns: int) -> bool:
    """Return whether every dynamic link the walk reads has data at ``time_ns`` (0: newest)."""
    if time_ns:
        for cache in plan.reads:
            stamps = cache._stamps
            if not stamps[cache._start] <= time_ns <= stamps[-1]:
                return False
    return True
