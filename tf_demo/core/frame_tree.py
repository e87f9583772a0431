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

from bisect import bisect_right
from collections.abc import Container
import math
from typing import NoReturn
from typing import TYPE_CHECKING

from tf_demo.core import math3d
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
from tf_demo.core.path_plan import common_time
from tf_demo.core.path_plan import has_data
from tf_demo.core.path_plan import PathPlan
from tf_demo.core.path_plan import plan_path
from tf_demo.core.time_cache import ERROR_BACKWARD_EXTRAPOLATION
from tf_demo.core.time_cache import ERROR_FORWARD_EXTRAPOLATION
from tf_demo.core.time_cache import ERROR_NO_DATA_FOR_EXTRAPOLATION
from tf_demo.core.time_cache import StaticCache
from tf_demo.core.time_cache import TimeCache

if TYPE_CHECKING:
    from tf_demo.core.math3d import Quat
    from tf_demo.core.math3d import Vec3

__all__ = [
    'MAX_GRAPH_DEPTH',
    'NO_PARENT',
    'Cache',
    'FrameTree',
    'accumulate_side',
]

MAX_GRAPH_DEPTH = 1000
#: Plans remembered at most (all are dropped beyond: a client asking ever new pairs).
_MAX_PLANS = 4096
NO_PARENT = 'NO_PARENT'

Cache = TimeCache | StaticCache

_bisect_right = bisect_right
_acos = math.acos
_sin = math.sin
#: The identity, shared: ``lookup_transform`` tests ``q is _IDENTITY_Q`` to skip canonicalising.
_IDENTITY_T = math3d.ZERO_VEC
_IDENTITY_Q = math3d.IDENTITY_QUAT

# How one side of a walk ended (:func:`accumulate_side`, :meth:`FrameTree._climb`).
SIDE_REACHED_STOP = 0
SIDE_NO_CACHE = 1
SIDE_NO_DATA = 2
SIDE_REACHED_OTHER = 3
SIDE_LOOP = 4

SideResult = tuple[int, int, int, int, float, float, float, float, float, float, float]


def accumulate_side(
    caches: list[Cache | None], frame: int, stop: int, other: int, time_ns: int
) -> SideResult:
    """
    Walk from ``frame`` towards the root, accumulating ``top_T_frame`` (one side of the walk).

    This is one side of tf2's ``walkToTopParent`` with :meth:`TimeCache.get_data` (tf2's
    ``findClosest`` and ``interpolate``) inlined: per link only locals, no tuple per link.  The
    inlined lerp, slerp and composition are copies of :mod:`~tf_demo.core.math3d`'s, kept for
    speed and pinned to it (within 1e-12) by ``test/core/test_math3d_inlined.py``.
    The walk stops at ``stop``, at a frame without cache or data, at ``other`` (once its data
    was read) or after ``MAX_GRAPH_DEPTH`` steps.

    :returns: ``(outcome, frame, last_frame, depth, x, y, z, qx, qy, qz, qw)``: the outcome
        (``SIDE_*``), the frame where the walk stopped, the last frame whose link was
        accumulated (the start frame when none), the number of links accumulated and the
        accumulated transform (identity when none).
    """
    depth = 0
    last_frame = frame
    x = y = z = qx = qy = qz = 0.0
    qw = 1.0
    acos = _acos
    sin = _sin
    while frame != stop:
        cache = caches[frame]
        if cache is None:
            return SIDE_NO_CACHE, frame, last_frame, depth, x, y, z, qx, qy, qz, qw
        if cache.is_static:
            lx, ly, lz, px, py, pz, pw, parent = cache._sample
        else:
            view = cache._view
            if view is None:
                view = cache.view()
            earliest, latest, scale, start, last, stamps, samples = view
            if not (earliest < time_ns < latest and time_ns):
                # At an end of the history, time 0 (the newest sample), or no data.
                if start > last:
                    return SIDE_NO_DATA, frame, last_frame, depth, x, y, z, qx, qy, qz, qw
                if time_ns in (0, latest):
                    lx, ly, lz, px, py, pz, pw, parent = samples[last]
                elif time_ns == earliest:
                    lx, ly, lz, px, py, pz, pw, parent = samples[start]
                else:
                    return SIDE_NO_DATA, frame, last_frame, depth, x, y, z, qx, qy, qz, qw
            else:
                # Interior: a linear guess (exact for evenly spaced streams), else bisect.
                index = start + int((time_ns - earliest) * scale)
                if index >= last:
                    index = last - 1
                one_stamp = stamps[index]
                if one_stamp <= time_ns:
                    two_stamp = stamps[index + 1]
                    if two_stamp <= time_ns:
                        index = _bisect_right(stamps, time_ns, index + 2, last + 1) - 1
                        one_stamp = stamps[index]
                        two_stamp = stamps[index + 1]
                else:
                    index = _bisect_right(stamps, time_ns, start, index) - 1
                    one_stamp = stamps[index]
                    two_stamp = stamps[index + 1]
                lx, ly, lz, px, py, pz, pw, parent = samples[index]
                tx1, ty1, tz1, x1, y1, z1, w1, parent1 = samples[index + 1]
                if parent1 == parent:
                    # tf2's interpolate: lerp the translation, slerp the rotation.
                    ratio = (time_ns - one_stamp) / (two_stamp - one_stamp)
                    keep = 1.0 - ratio
                    lx = keep * lx + ratio * tx1
                    ly = keep * ly + ratio * ty1
                    lz = keep * lz + ratio * tz1
                    dot = px * x1 + py * y1 + pz * z1 + pw * w1
                    if dot < 0:
                        theta = acos(-dot if -dot < 1.0 else 1.0)
                        if theta != 0.0:
                            d = 1.0 / sin(theta)
                            s0 = sin(keep * theta) * d
                            s1 = -sin(ratio * theta) * d
                            px = px * s0 + x1 * s1
                            py = py * s0 + y1 * s1
                            pz = pz * s0 + z1 * s1
                            pw = pw * s0 + w1 * s1
                    else:
                        theta = acos(dot if dot < 1.0 else 1.0)
                        if theta != 0.0:
                            d = 1.0 / sin(theta)
                            s0 = sin(keep * theta) * d
                            s1 = sin(ratio * theta) * d
                            px = px * s0 + x1 * s1
                            py = py * s0 + y1 * s1
                            pz = pz * s0 + z1 * s1
                            pw = pw * s0 + w1 * s1
        if frame == other:
            return SIDE_REACHED_OTHER, frame, last_frame, depth, x, y, z, qx, qy, qz, qw
        if depth:
            # link * acc.  p' = R(q) p + t with v + 2w(u x v) + 2u x (u x v): fewer operations
            # than tf2's q * v * conj(q), equal to about 1e-16.
            ux = 2.0 * (py * z - pz * y)
            uy = 2.0 * (pz * x - px * z)
            uz = 2.0 * (px * y - py * x)
            x, y, z = (
                x + pw * ux + (py * uz - pz * uy) + lx,
                y + pw * uy + (pz * ux - px * uz) + ly,
                z + pw * uz + (px * uy - py * ux) + lz,
            )
            qx, qy, qz, qw = (
                pw * qx + px * qw + py * qz - pz * qy,
                pw * qy + py * qw + pz * qx - px * qz,
                pw * qz + pz * qw + px * qy - py * qx,
                pw * qw - px * qx - py * qy - pz * qz,
            )
        else:
            x, y, z, qx, qy, qz, qw = lx, ly, lz, px, py, pz, pw
        last_frame = frame
        frame = parent
        depth += 1
        if depth > MAX_GRAPH_DEPTH:
            return SIDE_LOOP, frame, last_frame, depth, x, y, z, qx, qy, qz, qw
    return SIDE_REACHED_STOP, frame, last_frame, depth, x, y, z, qx, qy, qz, qw


def _extrapolation_error(code: int, text: str) -> ExtrapolationException:
    if code == ERROR_BACKWARD_EXTRAPOLATION:
        return BackwardExtrapolationException(text)
    if code == ERROR_FORWARD_EXTRAPOLATION:
        return ForwardExtrapolationException(text)
    if code == ERROR_NO_DATA_FOR_EXTRAPOLATION:
        return NoDataForExtrapolationException(text)
    return ExtrapolationException(text)


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
        self._plans: dict[tuple[int, int], PathPlan | None] = {}
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

    def _walk(self, target_id: int, source_id: int, time_ns: int) -> tuple[Vec3, Quat, int]:
        """
        Accumulate ``target_T_source`` at ``time_ns`` (tf2's ``walkToTopParent``).

        :returns: translation, raw (not re-canonicalised) rotation and the resolved time.
        """
        if source_id == target_id:
            return _IDENTITY_T, _IDENTITY_Q, time_ns
        if time_ns == 0:
            plan = self._plan(target_id, source_id)
            if plan is not None:
                time_ns = common_time(plan)
            else:
                time_ns = self._latest_common_time(target_id, source_id)
        caches = self._caches

        # Source side: accumulate top_T_source.
        outcome, frame, last, _, sx, sy, sz, sqx, sqy, sqz, sqw = accumulate_side(
            caches, source_id, 0, target_id, time_ns
        )
        if outcome == SIDE_REACHED_OTHER:
            return (sx, sy, sz), (sqx, sqy, sqz, sqw), time_ns
        if outcome == SIDE_LOOP:
            raise LookupException(self._loop_text())
        top = last if outcome == SIDE_REACHED_STOP else frame
        failed_cache = caches[frame] if outcome == SIDE_NO_DATA else None

        if target_id == top:
            # The target is the top itself: the inverse of an identity changes nothing.
            return (sx, sy, sz), (sqx, sqy, sqz, sqw), time_ns
        # Target side: accumulate top_T_target.
        outcome, frame, _, depth, tx, ty, tz, tqx, tqy, tqz, tqw = accumulate_side(
            caches, target_id, top, source_id, time_ns
        )
        if outcome == SIDE_NO_DATA:
            self._walk_error(caches[frame], time_ns, source_id, target_id)
        if outcome == SIDE_REACHED_OTHER:
            iq = (-tqx, -tqy, -tqz, tqw)
            return math3d.rotate_vector(iq, (-tx, -ty, -tz)), iq, time_ns
        if outcome == SIDE_LOOP:
            raise LookupException(self._loop_text())
        if outcome == SIDE_NO_CACHE:
            if failed_cache is not None:
                self._walk_error(failed_cache, time_ns, source_id, target_id)
            raise ConnectivityException(self._connectivity_text(source_id, target_id))

        if not depth:
            # The target is the top itself: the inverse of an identity changes nothing.
            return (sx, sy, sz), (sqx, sqy, sqz, sqw), time_ns
        # Full path: (top_T_target)^-1 * top_T_source.
        iq = (-tqx, -tqy, -tqz, tqw)
        ix, iy, iz = math3d.rotate_vector(iq, (-tx, -ty, -tz))
        rx, ry, rz = math3d.rotate_vector(iq, (sx, sy, sz))
        return (
            (rx + ix, ry + iy, rz + iz),
            math3d.quat_multiply(iq, (sqx, sqy, sqz, sqw)),
            time_ns,
        )

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
        """Run the walk on parents only; return None when possible, else tf2's error text."""
        if source_id == target_id:
            return None
        plan = self._plan(target_id, source_id)
        if plan is not None and has_data(plan, time_ns or common_time(plan)):
            return None
        if time_ns == 0:
            try:
                time_ns = self._latest_common_time(target_id, source_id)
            except TransformException as error:
                return str(error)
        outcome, top, failed_cache = self._climb(source_id, 0, target_id, time_ns)
        if outcome == SIDE_REACHED_OTHER or top == target_id:
            return None
        if outcome == SIDE_LOOP:
            return self._loop_text()
        outcome, _, no_data = self._climb(target_id, top, source_id, time_ns)
        if outcome == SIDE_NO_DATA and no_data is not None:
            return no_data.explain_failure(time_ns)[1] + self._walk_suffix(source_id, target_id)
        if outcome == SIDE_LOOP:
            return self._loop_text()
        if outcome == SIDE_NO_CACHE:
            if failed_cache is not None:
                text = failed_cache.explain_failure(time_ns)[1]
                return text + self._walk_suffix(source_id, target_id)
            return self._connectivity_text(source_id, target_id)
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
        m = len(reverse)
        n = len(chain)
        while m > 0 and n > 0:
            m -= 1
            n -= 1
            if chain[n] != reverse[m]:
                break
        if n > 0:
            del chain[n - 1 :]
        if m < len(reverse):
            chain.extend(reversed(reverse[: m + 1]))
        return chain
