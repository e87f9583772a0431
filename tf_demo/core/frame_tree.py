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
The frame tree under :class:`~tf_demo.core.buffer_core.BufferCore`: frame ids, caches, walks.

Frame names are interned to integer ids in order of first appearance (child before parent); id 0
is ``NO_PARENT``.  Each child frame has one cache (:class:`~tf_demo.core.time_cache.TimeCache`
or :class:`~tf_demo.core.time_cache.StaticCache`) whose samples name the parent.  This module
holds tf2's algorithms over that tree: ``getLatestCommonTime``, ``walkToTopParent`` (the lookup
walk, the can-transform walk and the frame chain) and tf2's texts for their failures.  It takes
no lock: :class:`~tf_demo.core.buffer_core.BufferCore` calls it with its lock held.
"""

from __future__ import annotations

from collections.abc import Container
from typing import NoReturn

from mypy_extensions import mypyc_attr
from tf_demo.core.exceptions import BackwardExtrapolationException
from tf_demo.core.exceptions import ConnectivityException
from tf_demo.core.exceptions import ExtrapolationException
from tf_demo.core.exceptions import ForwardExtrapolationException
from tf_demo.core.exceptions import InvalidArgumentException
from tf_demo.core.exceptions import LookupException
from tf_demo.core.exceptions import NoDataForExtrapolationException
from tf_demo.core.exceptions import TransformException
from tf_demo.core.frames_format import all_frames_as_string
from tf_demo.core.frames_format import FrameInfo
from tf_demo.core.frames_format import NO_AUTHORITY
from tf_demo.core.links import compose_route
from tf_demo.core.links import IDENTITY
from tf_demo.core.links import Route
from tf_demo.core.links import ROUTE_ACROSS
from tf_demo.core.links import ROUTE_DOWN
from tf_demo.core.links import ROUTE_UP
from tf_demo.core.links import Transform7
from tf_demo.core.path_plan import common_time
from tf_demo.core.path_plan import compose_plan
from tf_demo.core.path_plan import has_data
from tf_demo.core.path_plan import PathPlan
from tf_demo.core.path_plan import plan_path
from tf_demo.core.time_cache import ERROR_BACKWARD_EXTRAPOLATION
from tf_demo.core.time_cache import ERROR_FORWARD_EXTRAPOLATION
from tf_demo.core.time_cache import ERROR_NO_DATA_FOR_EXTRAPOLATION
from tf_demo.core.time_cache import StaticCache
from tf_demo.core.time_cache import TimeCache

__all__ = [
    'MAX_GRAPH_DEPTH',
    'NO_PARENT',
    'Cache',
    'FrameTree',
    'prune_shared_end',
]

MAX_GRAPH_DEPTH = 1000
#: ``_plans.get``'s answer for a pair not planned yet (None means: no plan to make).
_UNPLANNED: PathPlan | None = PathPlan((), (), (0, (), ()), ())
#: Plans remembered at most (all are dropped beyond: a client asking ever new pairs).
_MAX_PLANS = 4096
NO_PARENT = 'NO_PARENT'

Cache = TimeCache | StaticCache

# How one side of a walk ended (:meth:`FrameTree._climb`).
SIDE_REACHED_STOP = 0
SIDE_NO_CACHE = 1
SIDE_NO_DATA = 2
SIDE_REACHED_OTHER = 3
SIDE_LOOP = 4


def prune_shared_end(chain: list[int], other: list[int]) -> int:
    """
    tf2's chain pruning: cut ``chain`` where its end stops matching ``other``'s end.

    ``chain`` loses its frames from one before the first difference (compared from the ends);
    the return value is where the comparison stopped in ``other``.  To the letter of
    ``walkToTopParent`` and ``_chainAsVector`` (quirks included): the caller then appends
    ``other[: stop + 1]`` (reversed in the walk) when ``stop < len(other)``.
    """
    m = len(other)
    n = len(chain)
    while m > 0 and n > 0:
        m -= 1
        n -= 1
        if chain[n] != other[m]:
            break
    if n > 0:
        del chain[n - 1 :]
    return m


def _links(caches: list[Cache | None], frames: list[int]) -> list[Cache]:
    """Return the caches of ``frames`` (frames a walk accumulated: each has one)."""
    return [cache for frame in frames if (cache := caches[frame]) is not None]


def _extrapolation_error(code: int, text: str) -> ExtrapolationException:
    if code == ERROR_BACKWARD_EXTRAPOLATION:
        return BackwardExtrapolationException(text)
    if code == ERROR_FORWARD_EXTRAPOLATION:
        return ForwardExtrapolationException(text)
    if code == ERROR_NO_DATA_FOR_EXTRAPOLATION:
        return NoDataForExtrapolationException(text)
    return ExtrapolationException(text)


@mypyc_attr(allow_interpreted_subclasses=True)
class FrameTree:
    """
    Frame ids, one cache per child frame, and tf2's walks over them (no lock: see module).

    :class:`~tf_demo.core.buffer_core.BufferCore` derives from it and adds the lock, insertion
    and the public API.
    """

    def __init__(self) -> None:
        self._ids: dict[str, int] = {NO_PARENT: 0}
        self._names: list[str] = [NO_PARENT]
        self._caches: list[Cache | None] = [None]
        self._authority: dict[int, str] = {}
        #: Bumped whenever a link appears, changes parent or static value, or caches are cleared.
        self._shape_version = 0
        #: Path plans by frame ids, and by frame names once a lookup validated them.
        self._plans: dict[tuple[int, int] | tuple[str, str], PathPlan | None] = {}
        self._plans_version = 0

    # ------------------------------------------------------------------ frame ids

    def _intern(self, name: str) -> int:
        frame_id = self._ids.get(name)
        if frame_id is None:
            frame_id = len(self._names)
            self._ids[name] = frame_id
            self._names.append(name)
            self._caches.append(None)
        return frame_id

    def _validate(self, label: str, frame: str) -> int:
        """Return the id of ``frame`` or raise tf2's error for argument ``label``."""
        if not frame:
            raise InvalidArgumentException(
                f'Invalid argument "{frame}" passed to {label} - in tf2 frame_ids cannot be empty'
            )
        if frame[0] == '/':
            raise InvalidArgumentException(
                f'Invalid argument "{frame}" passed to {label} - '
                "in tf2 frame_ids cannot start with a '/'"
            )
        frame_id = self._ids.get(frame, 0)
        if frame_id == 0:
            raise LookupException(f'"{frame}" passed to {label} does not exist. ')
        return frame_id

    def _validate_quietly(self, label: str, frame: str) -> tuple[int, str]:
        """Return ``(id, '')`` or ``(0, tf2's "Invalid frame ID" text)``."""
        if not frame:
            rationale = 'in tf2 frame_ids cannot be empty'
        elif frame[0] == '/':
            rationale = "in tf2 frame_ids cannot start with a '/'"
        else:
            frame_id = self._ids.get(frame, 0)
            if frame_id:
                return frame_id, ''
            rationale = 'frame does not exist'
        return 0, f'Invalid frame ID "{frame}" passed to {label} - {rationale}'

    def _frame_infos(self) -> list[FrameInfo]:
        infos = []
        names = self._names
        authority = self._authority
        for frame_id, cache in enumerate(self._caches):
            if cache is None:
                continue
            _, parent = cache.latest_time_and_parent()
            infos.append(
                FrameInfo(
                    names[frame_id],
                    names[parent] if parent else None,
                    authority.get(frame_id, NO_AUTHORITY),
                    cache.is_static,
                    cache.oldest_stamp_ns,
                    cache.latest_stamp_ns,
                    len(cache),
                )
            )
        return infos

    # ------------------------------------------------------------------ tf2's failure texts

    def _loop_text(self) -> str:
        frames = self._frame_infos()
        return (
            f'The tf tree is invalid because it contains a loop.\n{all_frames_as_string(frames)}\n'
        )

    def _connectivity_text(self, source_id: int, target_id: int) -> str:
        return (
            f"Could not find a connection between '{self._names[target_id]}' and "
            f"'{self._names[source_id]}' because they are not part of the same tree."
            'Tf has two or more unconnected trees.'
        )

    def _walk_suffix(self, source_id: int, target_id: int) -> str:
        return (
            f', when looking up transform from frame [{self._names[source_id]}] to frame '
            f'[{self._names[target_id]}]'
        )

    def _walk_error(
        self, cache: Cache | None, time_ns: int, source_id: int, target_id: int
    ) -> NoReturn:
        """Raise tf2's extrapolation error for ``cache`` (no data at ``time_ns``)."""
        code, text = (
            cache.explain_failure(time_ns)
            if cache is not None
            else (ERROR_NO_DATA_FOR_EXTRAPOLATION, '')
        )
        raise _extrapolation_error(code, text + self._walk_suffix(source_id, target_id))

    # ------------------------------------------------------------------ path plans

    def _plan(self, target_id: int, source_id: int) -> PathPlan | None:
        """Return the remembered plan between two different frames (made on first use)."""
        plans = self._plans
        if self._plans_version != self._shape_version or len(plans) > _MAX_PLANS:
            plans.clear()
            self._plans_version = self._shape_version
        key = (target_id, source_id)
        try:
            return plans[key]
        except KeyError:
            plan = plans[key] = plan_path(self._caches, target_id, source_id, MAX_GRAPH_DEPTH)
            return plan

    # ------------------------------------------------------------------ latest common time

    def _latest_links(self, frame: int, stop: Container[int]) -> tuple[list[tuple[int, int]], int]:
        """
        Return the ``(newest stamp, parent)`` links from ``frame`` up, and their common time.

        The list ends at the top, or early with the first link whose parent is in ``stop``.
        The common time is the oldest non-zero stamp of the list (static links do not
        constrain), -1 when there is none.

        :raises LookupException: on a loop (more than ``MAX_GRAPH_DEPTH`` links).
        """
        caches = self._caches
        links: list[tuple[int, int]] = []
        common = -1
        depth = 0
        while True:
            cache = caches[frame]
            if cache is None:
                return links, common
            link = cache.latest
            stamp, frame = link
            if frame == 0:
                return links, common
            if stamp != 0 and (common < 0 or stamp < common):
                common = stamp
            links.append(link)
            if frame in stop:
                return links, common
            depth += 1
            if depth > MAX_GRAPH_DEPTH:
                raise LookupException(self._loop_text())

    def _latest_common_time(self, target_id: int, source_id: int) -> int:
        """tf2's ``getLatestCommonTime`` on ids; raises tf2's errors."""
        if source_id == 0 or target_id == 0:
            raise LookupException('')
        if source_id == target_id:
            cache = self._caches[source_id]
            return cache.latest_stamp_ns if cache is not None else 0
        source_links, common = self._latest_links(source_id, (target_id,))
        if source_links and source_links[-1][1] == target_id:
            return max(common, 0)  # the target is above the source
        # The source side has no loop (else it raised), so the source is none of its parents.
        stop = {parent for _, parent in source_links}
        stop.add(source_id)
        target_links, common = self._latest_links(target_id, stop)
        if target_links:
            parent = target_links[-1][1]
            if parent == source_id:
                return max(common, 0)  # the source is above the target
            if parent in stop:  # the first common parent: add the source side's links
                for stamp, link_parent in source_links:
                    if stamp != 0 and (common < 0 or stamp < common):
                        common = stamp
                    if link_parent == parent:
                        break
                return max(common, 0)
        raise ConnectivityException(self._connectivity_text(source_id, target_id))

    # ------------------------------------------------------------------ the walks

    def _walk(self, target_id: int, source_id: int, time_ns: int) -> tuple[Transform7, int]:
        """
        Accumulate ``target_T_source`` at ``time_ns`` (tf2's ``walkToTopParent``).

        The route comes from the remembered plan when every link on it has data at that time,
        else from the full walk (:meth:`_route`), which raises tf2's errors.

        :returns: the translation and raw (not re-canonicalised) rotation as seven floats
            (:data:`IDENTITY` itself between a frame and itself), and the resolved time.
        """
        if source_id == target_id:
            return IDENTITY, time_ns
        plan = (
            self._plans.get((target_id, source_id), _UNPLANNED)
            if self._plans_version == self._shape_version
            else _UNPLANNED
        )
        if plan is _UNPLANNED:
            plan = self._plan(target_id, source_id)
        if time_ns == 0:
            if plan is not None:
                time_ns = common_time(plan)
            else:
                time_ns = self._latest_common_time(target_id, source_id)
        composed = None if plan is None else compose_plan(plan, time_ns)
        if composed is None:
            composed = compose_route(self._route(target_id, source_id, time_ns), time_ns)
            if composed is None:  # pragma: no cover - the walk found data on every link
                raise AssertionError(self._walk_suffix(source_id, target_id))
        return composed, time_ns

    def _route(self, target_id: int, source_id: int, time_ns: int) -> Route:
        """
        Walk the parents at ``time_ns`` as tf2's ``walkToTopParent`` does; return the route.

        :raises LookupException: on a loop.
        :raises ConnectivityException: if the frames are in two trees.
        :raises ExtrapolationException: (a subclass) if a link has no data at ``time_ns``.
        """
        caches = self._caches
        source_path: list[int] = []
        outcome, top, failed_cache = self._climb(source_id, 0, target_id, time_ns, source_path)
        source_links = _links(caches, source_path[:-1])
        if outcome == SIDE_REACHED_OTHER or top == target_id:
            return ROUTE_UP, source_links, ()
        if outcome == SIDE_LOOP:
            raise LookupException(self._loop_text())
        target_path: list[int] = []
        outcome, _, no_data = self._climb(target_id, top, source_id, time_ns, target_path)
        if outcome == SIDE_NO_DATA:
            self._walk_error(no_data, time_ns, source_id, target_id)
        if outcome == SIDE_REACHED_OTHER:
            return ROUTE_DOWN, (), _links(caches, target_path[:-1])
        if outcome == SIDE_LOOP:
            raise LookupException(self._loop_text())
        if outcome == SIDE_NO_CACHE:
            if failed_cache is not None:
                self._walk_error(failed_cache, time_ns, source_id, target_id)
            raise ConnectivityException(self._connectivity_text(source_id, target_id))
        if not target_path:
            return ROUTE_UP, source_links, ()
        return ROUTE_ACROSS, source_links, _links(caches, target_path)

    def _climb(
        self, frame: int, stop: int, other: int, time_ns: int, path: list[int] | None = None
    ) -> tuple[int, int, Cache | None]:
        """
        Follow the parents at ``time_ns`` from ``frame`` towards ``stop`` (one side, no math).

        The same stops as :func:`accumulate_side`; the frames visited (the one it stopped at
        included, ``stop`` excluded) are appended to ``path`` when given.

        :returns: the outcome (``SIDE_*``), the frame where it stopped and, for
            ``SIDE_NO_DATA``, the cache without data at ``time_ns``.
        """
        caches = self._caches
        depth = 0
        while frame != stop:
            cache = caches[frame]
            if path is not None:
                path.append(frame)
            if cache is None:
                return SIDE_NO_CACHE, frame, None
            parent = cache.get_parent(time_ns)
            if parent == 0:
                return SIDE_NO_DATA, frame, cache
            if frame == other:
                return SIDE_REACHED_OTHER, frame, None
            frame = parent
            depth += 1
            if depth > MAX_GRAPH_DEPTH:
                return SIDE_LOOP, frame, None
        return SIDE_REACHED_STOP, frame, None

    def _can_walk(self, target_id: int, source_id: int, time_ns: int) -> str | None:
        """Return None when the walk would succeed, else tf2's error text."""
        if source_id == target_id:
            return None
        plan = self._plan(target_id, source_id)
        if plan is not None and has_data(plan.reads, time_ns or common_time(plan)):
            return None
        try:
            if time_ns == 0:
                time_ns = self._latest_common_time(target_id, source_id)
            self._route(target_id, source_id, time_ns)
        except TransformException as error:
            return str(error)
        return None

    def _walk_chain(self, target_id: int, source_id: int, time_ns: int) -> list[int]:
        """Run the walk recording frames, with tf2's chain pruning (``frame_chain`` output)."""
        if source_id == target_id:
            return []
        self._walk(target_id, source_id, time_ns)  # raises exactly what the walk raises
        if time_ns == 0:
            time_ns = self._latest_common_time(target_id, source_id)
        chain: list[int] = []
        outcome, top, _ = self._climb(source_id, 0, target_id, time_ns, chain)
        if outcome == SIDE_REACHED_OTHER:
            return chain
        reverse: list[int] = []
        outcome, _, _ = self._climb(target_id, top, source_id, time_ns, reverse)
        if outcome == SIDE_REACHED_OTHER:
            return reverse
        stop = prune_shared_end(chain, reverse)
        if stop < len(reverse):
            chain.extend(reversed(reverse[: stop + 1]))
        return chain
