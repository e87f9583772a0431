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
caches the walk reads (:attr:`PathPlan.reads`), which ones ``getLatestCommonTime`` takes the
newest stamps of (:attr:`PathPlan.common`) and the route itself (:attr:`PathPlan.route`), its
runs of static links folded into one transform each, so that ``can_transform`` and a lookup need
no walk.  Where the walk would fail, or a link has changed parent, there is no plan and the
full walk (with tf2's error texts) answers, as before.
"""

from __future__ import annotations

from typing import NamedTuple
from typing import TYPE_CHECKING

from tf_demo.core.links import accumulate_links
from tf_demo.core.links import compose_route
from tf_demo.core.links import Route
from tf_demo.core.links import ROUTE_ACROSS
from tf_demo.core.links import ROUTE_DOWN
from tf_demo.core.links import ROUTE_UP
from tf_demo.core.time_cache import StaticCache
from tf_demo.core.time_cache import TimeCache

if TYPE_CHECKING:
    from collections.abc import Sequence

    from tf_demo.core.links import Transform7

__all__ = ['PathPlan', 'common_time', 'compose_plan', 'has_data', 'plan_path']


class PathPlan(NamedTuple):
    """What the walk between two frames reads, for one shape of the tree."""

    #: The dynamic caches the walk reads: each must have data at the asked time.
    reads: tuple[TimeCache, ...]
    #: The dynamic caches between the two frames and their lowest common ancestor.
    common: tuple[TimeCache, ...]
    #: The walk's route, with each run of static links folded into one.
    route: Route
    #: The caches of :attr:`reads` that are not links of the route (whose data it checks).
    off_route: tuple[TimeCache, ...]


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
        if isinstance(cache, TimeCache) and cache.mixed:
            return None
        frame = cache.latest[1]  # 0 for an empty cache
        if not frame or len(frames) > max_depth:
            return None
        frames.append(frame)
        cache = caches[frame]
    return frames


def _folded(
    caches: Sequence[TimeCache | StaticCache | None], frames: Sequence[int]
) -> list[TimeCache | StaticCache]:
    """Return the links of ``frames`` (each has a cache), each run of static ones composed."""
    links: list[TimeCache | StaticCache] = []
    run: list[TimeCache | StaticCache] = []
    for frame in frames:
        cache = caches[frame]
        assert cache is not None  # frames a walk accumulates have caches
        if cache.is_static:
            run.append(cache)
            continue
        links += _fold(run)
        run = []
        links.append(cache)
    return links + _fold(run)


def _fold(run: list[TimeCache | StaticCache]) -> list[TimeCache | StaticCache]:
    """Return a run of static links as one link (the run itself when it is that short)."""
    if len(run) < 2:
        return run
    values = accumulate_links(run, 0)
    assert values is not None  # static links have data at every time
    folded = StaticCache()
    folded.insert(0, (*values, 0))
    return [folded]


def _dynamic(
    caches: Sequence[TimeCache | StaticCache | None], frames: Sequence[int]
) -> list[TimeCache]:
    """Return the dynamic caches of ``frames`` (frames without a cache skipped)."""
    found = []
    for frame in frames:
        cache = caches[frame]
        if isinstance(cache, TimeCache):
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
        up_to = source_up.index(target)
        reads = _dynamic(caches, source_up[: up_to + 1])
        route: Route = (ROUTE_UP, _folded(caches, source_up[:up_to]), ())
    else:
        top = source_up[-1]
        reads = _dynamic(caches, source_up)
        if top not in target_up:
            return None  # two trees
        side = target_up[: target_up.index(top)]
        if source in side:
            below = side.index(source)
            reads += _dynamic(caches, side[: below + 1])
            route = (ROUTE_DOWN, (), _folded(caches, side[:below]))
        else:
            reads += _dynamic(caches, side)
            route = (ROUTE_ACROSS, _folded(caches, source_up[:-1]), _folded(caches, side))
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
    on_route = {id(cache) for cache in (*route[1], *route[2])}
    off_route = tuple(cache for cache in reads if id(cache) not in on_route)
    return PathPlan(tuple(reads), tuple(common), route, off_route)


def common_time(plan: PathPlan) -> int:
    """Return tf2's latest common time of the planned frames (0: no link constrains it)."""
    oldest_newest = 0
    for cache in plan.common:
        stamp = cache.latest[0]
        if stamp and (stamp < oldest_newest or not oldest_newest):
            oldest_newest = stamp
    return oldest_newest


def has_data(caches: tuple[TimeCache, ...], time_ns: int) -> bool:
    """Return whether every one of ``caches`` has data at ``time_ns`` (0: the newest)."""
    return all(cache.covers(time_ns) for cache in caches)


def compose_plan(plan: PathPlan, time_ns: int) -> Transform7 | None:
    """
    Return ``target_T_source`` along the plan's route at ``time_ns`` (not 0), or None.

    None when a cache the walk reads has no data at that time: the full walk answers then,
    with tf2's error.
    """
    if plan.off_route and not has_data(plan.off_route, time_ns):
        return None
    return compose_route(plan.route, time_ns)
