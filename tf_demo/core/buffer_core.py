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
tf2's ``BufferCore`` in pure Python: insertion, the tree walk, lookups and introspection.

Semantics and message texts are tf2 Jazzy's (``spec/tf2.md`` §1-3).  Frame names are interned
to integer ids in order of first appearance (child before parent); id 0 is ``NO_PARENT``.  Every
public method takes one lock, so several threads may insert and look up at once; insert
callbacks run after the lock is released.

``lookup_transform(target, source, t)`` returns ``target_T_source``: the pose of ``source`` in
``target``, mapping coordinates given in ``source`` into ``target``.

Numerics.  Results agree with tf2's C++ core to about 1e-15: the walk rotates vectors with
``v + 2w(u x v) + 2u x (u x v)`` instead of tf2's ``q v q*``, slerp skips tf2's division by the
(unit) norms, and exact zeros are stored as one shared ``0.0`` (the sign of a zero is not kept).
As in ROS 2, where ``lookupTransform`` goes through a ``tf2::Transform`` that stores a rotation
matrix, looked-up rotations are re-extracted from that matrix: normalised, with tf2's canonical
sign (``spec/tf2.md`` §9 says they are not; the upstream source wins).
"""

from __future__ import annotations

from bisect import bisect_right
from collections.abc import Callable
import logging
import math
import threading
from typing import Literal
from typing import NamedTuple
from typing import overload
from typing import TYPE_CHECKING

import numpy as np
from tf_demo.core import math3d
from tf_demo.core._batch import batch_walk
from tf_demo.core._batch import batch_walk_uniform
from tf_demo.core.exceptions import BackwardExtrapolationException
from tf_demo.core.exceptions import ConnectivityException
from tf_demo.core.exceptions import ExtrapolationException
from tf_demo.core.exceptions import ForwardExtrapolationException
from tf_demo.core.exceptions import InvalidArgumentException
from tf_demo.core.exceptions import LookupException
from tf_demo.core.exceptions import NoDataForExtrapolationException
from tf_demo.core.exceptions import TransformException
from tf_demo.core.frames_format import all_frames_as_dot
from tf_demo.core.frames_format import all_frames_as_string
from tf_demo.core.frames_format import all_frames_as_yaml
from tf_demo.core.frames_format import FrameInfo
from tf_demo.core.frames_format import NO_AUTHORITY
from tf_demo.core.time_cache import DEFAULT_CACHE_TIME_NS
from tf_demo.core.time_cache import display_time_point
from tf_demo.core.time_cache import duration_to_sec
from tf_demo.core.time_cache import ERROR_BACKWARD_EXTRAPOLATION
from tf_demo.core.time_cache import ERROR_FORWARD_EXTRAPOLATION
from tf_demo.core.time_cache import ERROR_NO_DATA_FOR_EXTRAPOLATION
from tf_demo.core.time_cache import StaticCache
from tf_demo.core.time_cache import TimeCache

if TYPE_CHECKING:
    import numpy.typing as npt
    from tf_demo.core.math3d import Quat
    from tf_demo.core.math3d import Vec3

__all__ = [
    'MAX_GRAPH_DEPTH',
    'BufferCore',
    'FrameInfo',
    'TransformResult',
]

MAX_GRAPH_DEPTH = 1000
QUATERNION_NORMALIZATION_TOLERANCE = 10e-3
NO_PARENT = 'NO_PARENT'

_LOGGER = logging.getLogger('tf_demo.core')
_canonical_quat = math3d.canonical_quat
_bisect_right = bisect_right
_new_tuple = tuple.__new__  # builds a NamedTuple without its Python-level __new__
#: Lanes per pass of :meth:`BufferCore.lookup_transforms`.
_BATCH_CHUNK = 4096
_acos = math.acos
_sin = math.sin
_IDENTITY_T: Vec3 = (0.0, 0.0, 0.0)
_IDENTITY_Q: Quat = (0.0, 0.0, 0.0, 1.0)

Cache = TimeCache | StaticCache
LogFunction = Callable[[int, str], None]


class TransformResult(NamedTuple):
    """A looked-up transform ``target_T_source`` and the time it was resolved for."""

    translation: tuple[float, float, float]
    rotation: tuple[float, float, float, float]
    stamp_ns: int


def _default_log(level: int, text: str) -> None:
    _LOGGER.log(level, '%s', text)


def _c_float(value: float) -> str:
    """Format like C's ``%f`` (``nan``/``-nan``/``inf``)."""
    if math.isnan(value):
        return '-nan' if math.copysign(1.0, value) < 0 else 'nan'
    return f'{value:f}'


def _extrapolation_error(code: int, text: str) -> ExtrapolationException:
    if code == ERROR_BACKWARD_EXTRAPOLATION:
        return BackwardExtrapolationException(text)
    if code == ERROR_FORWARD_EXTRAPOLATION:
        return ForwardExtrapolationException(text)
    if code == ERROR_NO_DATA_FOR_EXTRAPOLATION:
        return NoDataForExtrapolationException(text)
    return ExtrapolationException(text)


# Outcomes of :func:`_accumulate_side`.
_SIDE_REACHED_STOP = 0
_SIDE_NO_CACHE = 1
_SIDE_NO_DATA = 2
_SIDE_REACHED_OTHER = 3
_SIDE_LOOP = 4

SideResult = tuple[int, int, int, int, float, float, float, float, float, float, float]


def _accumulate_side(
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
        (``_SIDE_*``), the frame where the walk stopped, the last frame whose link was
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
            return _SIDE_NO_CACHE, frame, last_frame, depth, x, y, z, qx, qy, qz, qw
        if cache.is_static:
            lx, ly, lz, px, py, pz, pw, parent = cache._sample  # type: ignore[union-attr]
        else:
            view = cache._view  # type: ignore[union-attr]
            if view is None:
                view = cache.view()  # type: ignore[union-attr]
            earliest, latest, scale, start, last, stamps, samples = view
            if not (earliest < time_ns < latest and time_ns):
                # At an end of the history, time 0 (the newest sample), or no data.
                if start > last:
                    return _SIDE_NO_DATA, frame, last_frame, depth, x, y, z, qx, qy, qz, qw
                if time_ns in (0, latest):
                    lx, ly, lz, px, py, pz, pw, parent = samples[last]
                elif time_ns == earliest:
                    lx, ly, lz, px, py, pz, pw, parent = samples[start]
                else:
                    return _SIDE_NO_DATA, frame, last_frame, depth, x, y, z, qx, qy, qz, qw
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
            return _SIDE_REACHED_OTHER, frame, last_frame, depth, x, y, z, qx, qy, qz, qw
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
            return _SIDE_LOOP, frame, last_frame, depth, x, y, z, qx, qy, qz, qw
    return _SIDE_REACHED_STOP, frame, last_frame, depth, x, y, z, qx, qy, qz, qw


def _time_from_sec(seconds: float) -> int:
    """Convert seconds to nanoseconds as tf2's ``timeFromSec`` (floor, then rounded ns)."""
    sec = math.floor(seconds)
    nsec = round((seconds - sec) * 1e9)
    return int(sec) * 1_000_000_000 + int(nsec)


class BufferCore:
    """
    tf2's transform buffer: per-link time caches plus tree walking (thread-safe).

    :param cache_time_ns: how much history each dynamic link keeps (tf2's default is 10 s).
    :param log: receives ``(level, text)`` for tf2's error and warning lines (TF_OLD_DATA,
        TF_NAN_INPUT, ...); defaults to the stdlib logger ``tf_demo.core``.
    """

    def __init__(
        self, cache_time_ns: int = DEFAULT_CACHE_TIME_NS, *, log: LogFunction | None = None
    ) -> None:
        if int(cache_time_ns) < 0:
            raise ValueError(f'cache_time_ns must not be negative, got {cache_time_ns}')
        self.cache_time_ns = int(cache_time_ns)
        self._log: LogFunction = log if log is not None else _default_log
        self._lock = threading.Lock()
        self._ids: dict[str, int] = {NO_PARENT: 0}
        self._names: list[str] = [NO_PARENT]
        self._caches: list[Cache | None] = [None]
        self._authority: dict[int, str] = {}
        self._callbacks: dict[int, Callable[[], None]] = {}
        self._callbacks_snapshot: tuple[Callable[[], None], ...] = ()
        self._next_handle = 1

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

    # ------------------------------------------------------------------ insertion

    def set_transform(  # noqa: PLR0917 (design.md §3.1 fixes this positional signature)
        self,
        parent: str,
        child: str,
        stamp_ns: int,
        translation: Vec3 | tuple[float, ...],
        rotation: Quat | tuple[float, ...],
        authority: str = '',
        is_static: bool = False,
    ) -> bool:
        """
        Insert ``parent_T_child`` at ``stamp_ns`` as tf2's ``setTransform``.

        The rotation is normalised and sign-canonicalised (through a rotation matrix, as tf2
        does); one leading ``/`` is stripped from both names.  Invalid transforms are logged
        with tf2's texts and rejected.

        :returns: True when stored (an exact duplicate counts as stored), False when rejected.
        :raises TypeError: if the arguments are not strings / numbers of the right shape.
        """
        if not isinstance(parent, str) or not isinstance(child, str):
            raise TypeError(
                f'parent and child must be str, got {type(parent).__name__} and '
                f'{type(child).__name__}'
            )
        try:
            tx, ty, tz = translation
            tx = float(tx)
            ty = float(ty)
            tz = float(tz)
            rx, ry, rz, rw = _canonical_quat(rotation)  # type: ignore[arg-type]
            stamp_ns = int(stamp_ns)
        except (TypeError, ValueError) as error:
            raise TypeError(
                'set_transform needs translation (x, y, z), rotation (x, y, z, w) as numbers '
                f'and an integer stamp_ns: {error}'
            ) from error
        # Share one object for exact zeros (planar robots store many): saves memory per sample.
        if tx == 0.0:
            tx = 0.0
        if ty == 0.0:
            ty = 0.0
        if tz == 0.0:
            tz = 0.0
        if rx == 0.0:
            rx = 0.0
        if ry == 0.0:
            ry = 0.0
        if rz == 0.0:
            rz = 0.0
        if parent and parent[0] == '/':
            parent = parent[1:]
        if child and child[0] == '/':
            child = child[1:]
        total = tx + ty + tz + rx + ry + rz + rw  # NaN if any value is NaN (or inf - inf)
        if (
            child == parent or not child or not parent or total != total  # noqa: PLR0124
        ) and self._log_invalid(parent, child, authority, (tx, ty, tz), (rx, ry, rz, rw)):
            return False

        with self._lock:
            child_id = self._ids.get(child)
            if child_id is None:
                child_id = self._intern(child)
            cache = self._caches[child_id]
            if cache is None or cache.is_static != is_static:
                cache = (
                    StaticCache(child_id) if is_static else TimeCache(self.cache_time_ns, child_id)
                )
                self._caches[child_id] = cache
            parent_id = self._ids.get(parent)
            if parent_id is None:
                parent_id = self._intern(parent)
            stored = cache.insert(stamp_ns, (tx, ty, tz, rx, ry, rz, rw, parent_id))
            if stored:
                self._authority[child_id] = authority
            callbacks = self._callbacks_snapshot
        if not stored:
            self._log(
                logging.WARNING,
                f'TF_OLD_DATA ignoring data from the past for frame {child} at time '
                f'{display_time_point(stamp_ns)} according to authority {authority}\n'
                'Possible reasons are listed at http://wiki.ros.org/tf/Errors%20explained',
            )
            return False
        for callback in callbacks:
            callback()
        return True

    def _log_invalid(
        self, parent: str, child: str, authority: str, translation: Vec3, rotation: Quat
    ) -> bool:
        """Log tf2's error line for every failed insert check; return whether any failed."""
        tx, ty, tz = translation
        rx, ry, rz, rw = rotation
        log = self._log
        failed = False
        if child == parent:
            log(
                logging.ERROR,
                f'TF_SELF_TRANSFORM: Ignoring transform from authority "{authority}" with '
                f'frame_id and  child_frame_id "{child}" because they are the same',
            )
            failed = True
        if not child:
            log(
                logging.ERROR,
                f'TF_NO_CHILD_FRAME_ID: Ignoring transform from authority "{authority}" '
                'because child_frame_id not set ',
            )
            failed = True
        if not parent:
            log(
                logging.ERROR,
                f'TF_NO_FRAME_ID: Ignoring transform with child_frame_id "{child}"  from '
                f'authority "{authority}" because frame_id not set',
            )
            failed = True
        isnan = math.isnan
        if isnan(tx) or isnan(ty) or isnan(tz) or isnan(rx) or isnan(ry) or isnan(rz) or isnan(rw):
            numbers = ' '.join(_c_float(v) for v in (tx, ty, tz))
            quat = ' '.join(_c_float(v) for v in (rx, ry, rz, rw))
            log(
                logging.ERROR,
                f'TF_NAN_INPUT: Ignoring transform for child_frame_id "{child}" from authority '
                f'"{authority}" because of a nan value in the transform ({numbers}) ({quat})',
            )
            failed = True
        if (
            not abs((rw * rw + rx * rx + ry * ry + rz * rz) - 1.0)
            < QUATERNION_NORMALIZATION_TOLERANCE
        ):
            quat = ' '.join(_c_float(v) for v in (rx, ry, rz, rw))
            log(
                logging.ERROR,
                f'TF_DENORMALIZED_QUATERNION: Ignoring transform for child_frame_id "{child}" '
                f'from authority "{authority}" because of an invalid quaternion in the '
                f'transform ({quat})',
            )
            failed = True
        return failed

    def add_insert_callback(self, callback: Callable[[], None]) -> int:
        """Call ``callback()`` after each successful insert (outside the lock); return a handle."""
        with self._lock:
            handle = self._next_handle
            self._next_handle += 1
            self._callbacks[handle] = callback
            self._callbacks_snapshot = tuple(self._callbacks.values())
        return handle

    def remove_insert_callback(self, handle: int) -> None:
        """Forget the callback registered under ``handle`` (unknown handles are ignored)."""
        with self._lock:
            self._callbacks.pop(handle, None)
            self._callbacks_snapshot = tuple(self._callbacks.values())

    def clear(self) -> None:
        """Empty every dynamic cache; static transforms, frame ids and authorities survive."""
        with self._lock:
            for cache in self._caches:
                if cache is not None:
                    cache.clear()

    # ------------------------------------------------------------------ latest common time

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

    def _latest_common_time(self, target_id: int, source_id: int) -> int:
        """tf2's ``getLatestCommonTime`` on ids; raises tf2's errors."""
        if source_id == 0 or target_id == 0:
            raise LookupException('')
        caches = self._caches
        if source_id == target_id:
            cache = caches[source_id]
            return cache.latest_stamp_ns if cache is not None else 0

        source_links: list[tuple[int, int]] = []
        frame = source_id
        depth = 0
        common = -1
        while frame != 0:
            cache = caches[frame]
            if cache is None:
                break
            stamp, parent = cache.latest
            if parent == 0:
                break
            if stamp != 0 and (common < 0 or stamp < common):
                common = stamp
            source_links.append((stamp, parent))
            frame = parent
            if frame == target_id:
                return max(common, 0)
            depth += 1
            if depth > MAX_GRAPH_DEPTH:
                raise LookupException(self._loop_text())

        frame = target_id
        depth = 0
        common = -1
        common_parent = 0
        source_parents = {parent for _, parent in source_links}
        while True:
            cache = caches[frame]
            if cache is None:
                break
            stamp, parent = cache.latest
            if parent == 0:
                break
            if stamp != 0 and (common < 0 or stamp < common):
                common = stamp
            if parent in source_parents:
                common_parent = parent
                break
            frame = parent
            if frame == source_id:
                return max(common, 0)
            depth += 1
            if depth > MAX_GRAPH_DEPTH:
                raise LookupException(self._loop_text())

        if common_parent == 0:
            raise ConnectivityException(self._connectivity_text(source_id, target_id))
        for stamp, parent in source_links:
            if stamp != 0 and (common < 0 or stamp < common):
                common = stamp
            if parent == common_parent:
                break
        return max(common, 0)

    def get_latest_common_time(self, target: str, source: str) -> int:
        """
        Return the newest time at which ``target`` and ``source`` can be related (ns).

        Zero stamps (static links) impose no constraint; 0 means "no constraint at all".

        :raises InvalidArgumentException, LookupException: for bad or unknown frame names.
        :raises ConnectivityException: if the frames are not connected.
        """
        with self._lock:
            target_id = self._validate('get_latest_common_time', target)
            source_id = self._validate('get_latest_common_time', source)
            return self._latest_common_time(target_id, source_id)

    # ------------------------------------------------------------------ the walk

    def _walk_error(self, cache: Cache, time_ns: int, source_id: int, target_id: int) -> None:
        code, text = cache.explain_failure(time_ns)
        raise _extrapolation_error(
            code,
            f'{text}, when looking up transform from frame [{self._names[source_id]}] to frame '
            f'[{self._names[target_id]}]',
        )

    def _walk(self, target_id: int, source_id: int, time_ns: int) -> tuple[Vec3, Quat, int]:
        """
        Accumulate ``target_T_source`` at ``time_ns`` (tf2's ``walkToTopParent``).

        :returns: translation, raw (not re-canonicalised) rotation and the resolved time.
        """
        if source_id == target_id:
            return _IDENTITY_T, _IDENTITY_Q, time_ns
        if time_ns == 0:
            time_ns = self._latest_common_time(target_id, source_id)
        caches = self._caches

        # Source side: accumulate top_T_source.
        outcome, frame, last, _, sx, sy, sz, sqx, sqy, sqz, sqw = _accumulate_side(
            caches, source_id, 0, target_id, time_ns
        )
        if outcome == _SIDE_REACHED_OTHER:
            return (sx, sy, sz), (sqx, sqy, sqz, sqw), time_ns
        if outcome == _SIDE_LOOP:
            raise LookupException(self._loop_text())
        top = last if outcome == _SIDE_REACHED_STOP else frame
        failed_cache = caches[frame] if outcome == _SIDE_NO_DATA else None

        if target_id == top:
            # The target is the top itself: the inverse of an identity changes nothing.
            return (sx, sy, sz), (sqx, sqy, sqz, sqw), time_ns
        # Target side: accumulate top_T_target.
        outcome, frame, _, depth, tx, ty, tz, tqx, tqy, tqz, tqw = _accumulate_side(
            caches, target_id, top, source_id, time_ns
        )
        if outcome == _SIDE_NO_DATA:
            self._walk_error(caches[frame], time_ns, source_id, target_id)  # type: ignore[arg-type]
        if outcome == _SIDE_REACHED_OTHER:
            iq = (-tqx, -tqy, -tqz, tqw)
            return math3d.rotate_vector(iq, (-tx, -ty, -tz)), iq, time_ns
        if outcome == _SIDE_LOOP:
            raise LookupException(self._loop_text())
        if outcome == _SIDE_NO_CACHE:
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

    def _can_walk(self, target_id: int, source_id: int, time_ns: int) -> str | None:
        """Run the walk on parents only; return None when possible, else tf2's error text."""
        if source_id == target_id:
            return None
        if time_ns == 0:
            try:
                time_ns = self._latest_common_time(target_id, source_id)
            except TransformException as error:
                return str(error)
        caches = self._caches
        frame = source_id
        top = frame
        depth = 0
        failed_cache: Cache | None = None
        while frame != 0:
            cache = caches[frame]
            if cache is None:
                top = frame
                break
            parent = cache.get_parent(time_ns)
            if parent == 0:
                top = frame
                failed_cache = cache
                break
            if frame == target_id:
                return None
            top = frame
            frame = parent
            depth += 1
            if depth > MAX_GRAPH_DEPTH:
                return self._loop_text()
        frame = target_id
        depth = 0
        suffix = (
            f', when looking up transform from frame [{self._names[source_id]}] to frame '
            f'[{self._names[target_id]}]'
        )
        while frame != top:
            cache = caches[frame]
            if cache is None:
                break
            parent = cache.get_parent(time_ns)
            if parent == 0:
                return cache.explain_failure(time_ns)[1] + suffix
            if frame == source_id:
                return None
            frame = parent
            depth += 1
            if depth > MAX_GRAPH_DEPTH:
                return self._loop_text()
        if frame != top:
            if failed_cache is not None:
                return failed_cache.explain_failure(time_ns)[1] + suffix
            return self._connectivity_text(source_id, target_id)
        return None

    # ------------------------------------------------------------------ lookups

    def _lookup_locked(self, target: str, source: str, time_ns: int) -> tuple[Vec3, Quat, int]:
        """tf2's ``lookupTransformImpl``: string short-cut, validation, walk (lock held)."""
        if target == source:
            if time_ns == 0:
                cache = self._caches[self._ids.get(target, 0)]
                if cache is not None:
                    time_ns = cache.latest_stamp_ns
            return _IDENTITY_T, _IDENTITY_Q, time_ns
        ids = self._ids
        # Names never start with '/' once interned (inserts strip one), except '//x' -> '/x',
        # which tf2 also refuses here: check the slash before trusting the id.
        target_id = ids.get(target, 0)
        if not target_id or target[0] == '/':
            target_id = self._validate('lookupTransform argument target_frame', target)
        source_id = ids.get(source, 0)
        if not source_id or source[0] == '/':
            source_id = self._validate('lookupTransform argument source_frame', source)
        return self._walk(target_id, source_id, time_ns)

    def lookup_transform(self, target: str, source: str, time_ns: int) -> TransformResult:
        """
        Return ``target_T_source`` at ``time_ns`` (0 = latest common time).

        The stamp of the result is the resolved time.  As in ROS 2's tf2 the rotation goes
        through a rotation matrix, so it comes back normalised with the canonical sign.

        :raises InvalidArgumentException: for an empty name or one starting with ``/``.
        :raises LookupException: for an unknown frame or a loop in the tree.
        :raises ConnectivityException: if the frames are not connected.
        :raises ExtrapolationException: (a subclass of it) if a link has no data at that time.
        """
        with self._lock:
            translation, q, stamp = self._lookup_locked(target, source, time_ns)
        # ROS 2 stores the result in a tf2::Transform (a matrix) and reads the quaternion back.
        if q is not _IDENTITY_Q:
            q = _canonical_quat(q)
        return _new_tuple(TransformResult, (translation, q, stamp))  # TransformResult(...)

    def lookup_transform_full(
        self,
        target: str,
        target_time_ns: int,
        source: str,
        source_time_ns: int,
        fixed: str,
    ) -> TransformResult:
        """
        Return ``target_T_source`` with ``source`` at one time and ``target`` at another.

        ``fixed`` is a frame that does not move between the two times.  The result's stamp is
        the resolved target time.

        :raises TransformException: as :meth:`lookup_transform`.
        """
        with self._lock:
            self._validate('lookupTransform argument target_frame', target)
            self._validate('lookupTransform argument source_frame', source)
            self._validate('lookupTransform argument fixed_frame', fixed)
            t1, q1, _ = self._lookup_locked(fixed, source, source_time_ns)
            t2, q2, stamp = self._lookup_locked(target, fixed, target_time_ns)
        basis2 = math3d.matrix_from_quat(q2)
        basis = math3d.matrix_times(basis2, math3d.matrix_from_quat(q1))
        ox, oy, oz = math3d.matrix_apply(basis2, t1)
        return TransformResult(
            (ox + t2[0], oy + t2[1], oz + t2[2]), math3d.quat_from_matrix(basis), stamp
        )

    @overload
    def can_transform(
        self,
        target: str,
        source: str,
        time_ns: int,
        return_debug_tuple: Literal[False] = False,
    ) -> bool: ...

    @overload
    def can_transform(
        self, target: str, source: str, time_ns: int, return_debug_tuple: Literal[True]
    ) -> tuple[bool, str]: ...

    @overload
    def can_transform(
        self, target: str, source: str, time_ns: int, return_debug_tuple: bool
    ) -> bool | tuple[bool, str]: ...

    def can_transform(
        self, target: str, source: str, time_ns: int, return_debug_tuple: bool = False
    ) -> bool | tuple[bool, str]:
        """
        Return whether ``lookup_transform`` would succeed (never raises tf2 errors).

        With ``return_debug_tuple`` the result is ``(ok, error text)`` as in tf2_ros.
        """
        if target == source:
            return (True, '') if return_debug_tuple else True
        with self._lock:
            target_id, text = self._validate_quietly('canTransform argument target_frame', target)
            if target_id:
                source_id, text = self._validate_quietly(
                    'canTransform argument source_frame', source
                )
                if source_id:
                    error = self._can_walk(target_id, source_id, time_ns)
                    text = error or ''
        ok = not text
        return (ok, text) if return_debug_tuple else ok

    @overload
    def can_transform_full(
        self,
        target: str,
        target_time_ns: int,
        source: str,
        source_time_ns: int,
        fixed: str,
        return_debug_tuple: Literal[False] = False,
    ) -> bool: ...

    @overload
    def can_transform_full(
        self,
        target: str,
        target_time_ns: int,
        source: str,
        source_time_ns: int,
        fixed: str,
        return_debug_tuple: Literal[True],
    ) -> tuple[bool, str]: ...

    @overload
    def can_transform_full(
        self,
        target: str,
        target_time_ns: int,
        source: str,
        source_time_ns: int,
        fixed: str,
        return_debug_tuple: bool,
    ) -> bool | tuple[bool, str]: ...

    def can_transform_full(  # noqa: PLR0917 (tf2's argument order)
        self,
        target: str,
        target_time_ns: int,
        source: str,
        source_time_ns: int,
        fixed: str,
        return_debug_tuple: bool = False,
    ) -> bool | tuple[bool, str]:
        """Return whether ``lookup_transform_full`` would succeed (never raises tf2 errors)."""
        with self._lock:
            text = ''
            ids = []
            for label, frame in (
                ('canTransform argument target_frame', target),
                ('canTransform argument source_frame', source),
                ('canTransform argument fixed_frame', fixed),
            ):
                frame_id, text = self._validate_quietly(label, frame)
                if not frame_id:
                    break
                ids.append(frame_id)
            if not text:
                target_id, source_id, fixed_id = ids
                text = self._can_walk(target_id, fixed_id, target_time_ns) or ''
                if not text:
                    text = self._can_walk(fixed_id, source_id, source_time_ns) or ''
        ok = not text
        return (ok, text) if return_debug_tuple else ok

    def lookup_velocity(
        self, tracking: str, observation: str, time_ns: int, averaging_ns: int
    ) -> tuple[Vec3, Vec3]:
        """
        Return the twist ``((vx, vy, vz), (wx, wy, wz))`` of ``tracking`` in ``observation``.

        Finite differences of two lookups around ``time_ns +- averaging_ns / 2``, clamped to the
        latest common time, with tf2's arithmetic (``lookupVelocity``).

        :raises TransformException: as :meth:`lookup_transform`.
        """
        with self._lock:
            try:
                latest = self._latest_common_time(
                    self._ids.get(observation, 0), self._ids.get(tracking, 0)
                )
            except TransformException:
                latest = 0
            time_s = duration_to_sec(time_ns)
            interval_s = duration_to_sec(averaging_ns)
            end_s = min(time_s + interval_s * 0.5, duration_to_sec(latest))
            start_s = max(0.00001 + interval_s, end_s) - interval_s
            corrected = end_s - start_s
            start_t, start_q, _ = self._lookup_locked(
                observation, tracking, _time_from_sec(start_s)
            )
            end_t, end_q, _ = self._lookup_locked(observation, tracking, _time_from_sec(end_s))
            ref_t, ref_q, _ = self._lookup_locked(observation, tracking, _time_from_sec(time_s))
        start_basis = math3d.matrix_from_quat(start_q)
        delta = math3d.quat_from_matrix(
            math3d.matrix_times(
                math3d.matrix_transpose(start_basis), math3d.matrix_from_quat(end_q)
            )
        )
        w = delta[3]
        s_squared = 1.0 - w * w
        if s_squared < 10.0 * 2.220446049250313e-16:
            axis: Vec3 = (1.0, 0.0, 0.0)
        else:
            s = math.sqrt(s_squared)
            axis = (delta[0] / s, delta[1] / s, delta[2] / s)
        angle = 2.0 * math.acos(max(-1.0, min(1.0, w)))
        ox, oy, oz = math3d.matrix_apply(start_basis, axis)
        scale = angle / corrected
        twist_rot = (ox * scale, oy * scale, oz * scale)
        twist_vel = (
            (end_t[0] - start_t[0]) / corrected,
            (end_t[1] - start_t[1]) / corrected,
            (end_t[2] - start_t[2]) / corrected,
        )
        ref_basis = math3d.matrix_from_quat(ref_q)
        out_rot = math3d.matrix_apply(ref_basis, twist_rot)
        vx, vy, vz = math3d.matrix_apply(ref_basis, twist_vel)
        px, py, pz = ref_t
        cross = (
            py * out_rot[2] - pz * out_rot[1],
            pz * out_rot[0] - px * out_rot[2],
            px * out_rot[1] - py * out_rot[0],
        )
        return (vx + cross[0], vy + cross[1], vz + cross[2]), out_rot

    # ------------------------------------------------------------------ chain

    def _walk_chain(self, target_id: int, source_id: int, time_ns: int) -> list[int]:
        """Run the walk recording frames, with tf2's chain pruning (``frame_chain`` output)."""
        if source_id == target_id:
            return []
        self._walk(target_id, source_id, time_ns)  # raises exactly what the walk raises
        if time_ns == 0:
            time_ns = self._latest_common_time(target_id, source_id)
        caches = self._caches
        chain: list[int] = []
        frame = source_id
        top = frame
        while frame != 0:
            cache = caches[frame]
            chain.append(frame)
            if cache is None:
                top = frame
                break
            parent = cache.get_parent(time_ns)
            if parent == 0:
                top = frame
                break
            if frame == target_id:
                return chain
            top = frame
            frame = parent
        reverse: list[int] = []
        frame = target_id
        while frame != top:
            cache = caches[frame]
            reverse.append(frame)
            if cache is None:
                break
            parent = cache.get_parent(time_ns)
            if frame == source_id:
                return reverse
            frame = parent
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

    def chain(
        self,
        target: str,
        target_time_ns: int,
        source: str,
        source_time_ns: int,
        fixed: str,
    ) -> list[str]:
        """
        Return the frames between ``source`` and ``target`` as tf2's ``_chainAsVector``.

        The list reproduces tf2's quirks (see ``spec/tf2.md`` §3.8).

        :raises TransformException: as the underlying walks do.
        """
        with self._lock:
            ids = self._ids
            source_id = ids.get(source, 0)
            fixed_id = ids.get(fixed, 0)
            target_id = ids.get(target, 0)
            source_chain = self._walk_chain(fixed_id, source_id, source_time_ns)
            if source_time_ns != target_time_ns:
                target_chain = self._walk_chain(target_id, fixed_id, target_time_ns)
                m = len(target_chain) - 1
                n = len(source_chain) - 1
                while m >= 0 and n >= 0:
                    if source_chain[n] != target_chain[m]:
                        break
                    m -= 1
                    n -= 1
                if n > 0:
                    del source_chain[n - 1 :]
                if m < len(target_chain):
                    source_chain.extend(target_chain[: m + 1])
            names = self._names
            return [names[frame_id] for frame_id in source_chain]

    # ------------------------------------------------------------------ batch lookups

    def lookup_transforms(
        self, target: str, source: str, times_ns: npt.ArrayLike
    ) -> tuple[npt.NDArray[np.float64], npt.NDArray[np.float64]]:
        """
        Return ``target_T_source`` at each of N stamps in one vectorised call.

        Equal (within 1e-9) to N calls of :meth:`lookup_transform`; if any of them would fail,
        raises what the first failing one (in input order) raises.

        :returns: translations ``(N, 3)`` and rotations ``(N, 4)`` (x, y, z, w).
        """
        times = np.asarray(times_ns, dtype=np.int64).reshape(-1)
        count = times.shape[0]
        with self._lock:
            if target == source:
                translations = np.zeros((count, 3))
                rotations = np.zeros((count, 4))
                rotations[:, 3] = 1.0
                return translations, rotations
            target_id = self._validate('lookupTransform argument target_frame', target)
            source_id = self._validate('lookupTransform argument source_frame', source)
            resolved = times.copy()
            latest_wanted = times == 0
            common_time_failed = False
            if latest_wanted.any():
                try:
                    resolved[latest_wanted] = self._latest_common_time(target_id, source_id)
                except TransformException:
                    common_time_failed = True
            uniform = batch_walk_uniform(self._caches, target_id, source_id, resolved)
            if uniform is not None:
                return uniform[0], math3d.canonical_quat_batch(uniform[1], out=uniform[1])
            translations = np.empty((count, 3))
            rotations = np.empty((count, 4))
            # Chunks keep every temporary small (in cache, and reused by the allocator
            # instead of being returned to the system and faulted in again on every call).
            for begin in range(0, count, _BATCH_CHUNK):
                end = min(begin + _BATCH_CHUNK, count)
                chunk_t, chunk_q, failed = batch_walk(
                    self._caches, target_id, source_id, resolved[begin:end]
                )
                if common_time_failed:
                    failed |= latest_wanted[begin:end]
                for index in np.flatnonzero(failed).tolist():
                    t, q, _ = self._walk(target_id, source_id, int(times[begin + index]))
                    chunk_t[index] = t
                    chunk_q[index] = q
                translations[begin:end] = chunk_t
                rotations[begin:end] = math3d.canonical_quat_batch(chunk_q)
        return translations, rotations

    # ------------------------------------------------------------------ introspection

    def _frame_infos(self) -> list[FrameInfo]:
        infos = []
        names = self._names
        authority = self._authority
        for frame_id, cache in enumerate(self._caches):
            if cache is None:
                continue
            stamp, parent = cache.latest_time_and_parent()
            del stamp
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

    def frames_info(self) -> list[FrameInfo]:
        """Return one :class:`FrameInfo` per child frame (frames with a cache), in id order."""
        with self._lock:
            return self._frame_infos()

    def all_frames_as_string(self) -> str:
        """Return tf2's ``allFramesAsString`` text."""
        with self._lock:
            return all_frames_as_string(self._frame_infos())

    def all_frames_as_yaml(self, current_time_ns: int = 0) -> str:
        """Return tf2's ``allFramesAsYAML`` text (what the ``tf2_frames`` service answers)."""
        with self._lock:
            return all_frames_as_yaml(
                self._frame_infos(),
                any_frame_known=len(self._names) > 1,
                current_time_ns=current_time_ns,
            )

    def all_frames_as_dot(self, current_time_ns: int = 0) -> str:
        """Return tf2's ``_allFramesAsDot`` graph (what view_frames renders)."""
        with self._lock:
            infos = {info.child: info for info in self._frame_infos()}
            rows = [(name, infos.get(name)) for name in self._names[1:]]
        return all_frames_as_dot(rows, current_time_ns=current_time_ns)

    def frame_exists(self, frame: str) -> bool:
        """Return whether ``frame`` was ever interned (true for ``NO_PARENT`` too, as tf2)."""
        with self._lock:
            return frame in self._ids

    def frame_ids(self) -> list[str]:
        """Return every known frame name except ``NO_PARENT``, in id order."""
        with self._lock:
            return self._names[1:]

    def parent_of(self, frame: str, time_ns: int = 0) -> str | None:
        """Return the parent of ``frame`` at ``time_ns``, or None (unknown, root or no data)."""
        with self._lock:
            cache = self._caches[self._ids.get(frame, 0)]
            if cache is None:
                return None
            parent = cache.get_parent(time_ns)
            return self._names[parent] if parent else None
