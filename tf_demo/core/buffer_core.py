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
tf2's ``BufferCore`` in pure Python: insertion, lookups and introspection, thread-safe.

Semantics and message texts are tf2 Jazzy's (``spec/tf2.md`` §1-3).  The frames, their caches
and tf2's walks over them are :class:`~tf_demo.core.frame_tree.FrameTree`'s, which this class
extends.  Every public method takes one lock, so several threads may insert and look up at once;
insert callbacks run after the lock is released.

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

from collections.abc import Callable
from collections.abc import Iterable
from collections.abc import Sequence
import logging
import math
import struct
import threading
from typing import NamedTuple
from typing import SupportsInt
from typing import TYPE_CHECKING

from mypy_extensions import mypyc_attr
from tf_demo.core import math3d
from tf_demo.core._batch import batch_walk
from tf_demo.core._batch import batch_walk_uniform
from tf_demo.core.exceptions import TransformException
from tf_demo.core.frame_tree import FrameTree
from tf_demo.core.frame_tree import MAX_GRAPH_DEPTH
from tf_demo.core.frame_tree import prune_shared_end
from tf_demo.core.frames_format import all_frames_as_dot
from tf_demo.core.frames_format import all_frames_as_string
from tf_demo.core.frames_format import all_frames_as_yaml
from tf_demo.core.frames_format import FrameInfo
from tf_demo.core.links import IDENTITY
from tf_demo.core.links import Transform7
from tf_demo.core.path_plan import common_time
from tf_demo.core.path_plan import compose_plan
from tf_demo.core.time_cache import DEFAULT_CACHE_TIME_NS
from tf_demo.core.time_cache import display_time_point
from tf_demo.core.time_cache import pack_values
from tf_demo.core.time_cache import StaticCache
from tf_demo.core.time_cache import TimeCache
from tf_demo.core.time_cache import unpack_values
from tf_demo.core.velocity import twist
from tf_demo.core.velocity import velocity_window

if TYPE_CHECKING:
    import numpy as np
    import numpy.typing as npt
    from tf_demo.core.math3d import Quat
    from tf_demo.core.math3d import Vec3

__all__ = [
    'MAX_GRAPH_DEPTH',
    'BufferCore',
    'FrameInfo',
    'TransformResult',
]

QUATERNION_NORMALIZATION_TOLERANCE = 10e-3

_LOGGER = logging.getLogger('tf_demo.core')
#: One transform for :meth:`BufferCore.set_transforms`: parent, child, stamp_ns, translation,
#: rotation.
InsertTuple = tuple[str, str, SupportsInt, Sequence[float], Sequence[float]]
#: :meth:`BufferCore.set_transform`'s arguments, in order.
SetTransformArguments = tuple[str, str, SupportsInt, Sequence[float], Sequence[float], str, bool]
#: Lanes per pass of :meth:`BufferCore.lookup_transforms`.
_BATCH_CHUNK = 4096
#: The identity, shared: ``lookup_transform`` tests ``q is _IDENTITY_Q`` to skip canonicalising.
_IDENTITY_T = math3d.ZERO_VEC
_IDENTITY_Q = math3d.IDENTITY_QUAT

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


@mypyc_attr(allow_interpreted_subclasses=True)  # tf2_ros' Buffer subclasses tf2's BufferCore
class BufferCore(FrameTree):
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
        super().__init__()
        self._lock = threading.Lock()
        self._callbacks: dict[int, Callable[[], None]] = {}
        self._callbacks_snapshot: tuple[Callable[[], None], ...] = ()
        self._next_handle = 1
        #: Frame ids by the names a valid insert gave (a leading ``/`` included).
        self._insert_ids: dict[str, int] = {}

    # ------------------------------------------------------------------ insertion

    def set_transform(  # noqa: PLR0917 (design.md §3.1 fixes this positional signature)
        self,
        parent: str,
        child: str,
        stamp_ns: SupportsInt,
        translation: Sequence[float],
        rotation: Sequence[float],
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
        # The fast path: both names met before in a valid insert, a finite translation, and a
        # rotation whose squared norm is far from 0 and overflow (valid whatever its exact
        # canonical form, which is made when the sample is first read).
        known = self._insert_ids
        try:
            child_id = known.get(child)
            parent_id = known.get(parent)
            tx, ty, tz = translation
            x, y, z, w = rotation
            values = pack_values(tx, ty, tz, x, y, z, w)
            stamp = stamp_ns if type(stamp_ns) is int else int(stamp_ns)
            norm2 = x * x + y * y + z * z + w * w
        except (TypeError, ValueError, struct.error):
            child_id = None  # the checked path says what is wrong
        if (
            is_static
            or child_id is None
            or parent_id is None
            or child_id == parent_id
            or not 1e-100 < norm2 < 1e100
            or (total := tx + ty + tz) != total  # NaN, or inf - inf
        ):
            return self._set_transform_checked(
                (parent, child, stamp_ns, translation, rotation, authority, is_static)
            )
        lock = self._lock
        lock.acquire()
        try:
            cache = self._caches[child_id]
            if cache is None or cache.is_static:
                cache = self._caches[child_id] = TimeCache(self.cache_time_ns, child_id)
            reshaped = cache.latest[1] != parent_id
            stored = cache.insert_raw(stamp, values, parent_id)
            if stored:
                self._authority[child_id] = authority
                if reshaped:
                    self._shape_version += 1
            callbacks = self._callbacks_snapshot
        finally:
            lock.release()
        if not stored:
            self._log_old_data(self._names[child_id], stamp, authority)
            return False
        for callback in callbacks:
            callback()
        return True

    def set_transforms(
        self, transforms: Iterable[InsertTuple], authority: str = '', is_static: bool = False
    ) -> list[tuple[str, str, Exception]]:
        """
        Insert many transforms, each exactly as :meth:`set_transform` would, in order.

        ``transforms`` yields ``(parent, child, stamp_ns, translation, rotation)``.  The lock is
        taken once for the run and the insert callbacks run once at the end (when something was
        stored) instead of after each transform; the rest, logs included, is the same.  The
        fast path is :meth:`set_transform`'s, inlined (``test_buffer_core.py`` pins the two to
        the same results).

        :returns: ``(parent, child, error)`` for each transform whose insert raised (a
            ``TypeError`` for bad input), the others are inserted all the same.
        :raises ValueError: for an item that is not five values (before or after it, the
            others are inserted).
        """
        failures: list[tuple[str, str, Exception]] = []
        known = self._insert_ids
        caches = self._caches
        lock = self._lock
        stored_any = False
        lock.acquire()
        try:
            for parent, child, stamp, translation, rotation in transforms:
                try:
                    child_id = known.get(child)
                    parent_id = known.get(parent)
                    tx, ty, tz = translation
                    x, y, z, w = rotation
                    values = pack_values(tx, ty, tz, x, y, z, w)
                    stamp_ns = stamp if type(stamp) is int else int(stamp)
                    norm2 = x * x + y * y + z * z + w * w
                except (TypeError, ValueError, struct.error):
                    child_id = None
                if (
                    is_static
                    or child_id is None
                    or parent_id is None
                    or child_id == parent_id
                    or not 1e-100 < norm2 < 1e100
                    or (total := tx + ty + tz) != total  # NaN, or inf - inf
                ):
                    lock.release()
                    try:
                        self._set_transform_checked(
                            (parent, child, stamp, translation, rotation, authority, is_static)
                        )
                    except TypeError as error:
                        failures.append((parent, child, error))
                    finally:
                        lock.acquire()
                    continue
                cache = caches[child_id]
                if cache is None or cache.is_static:
                    cache = caches[child_id] = TimeCache(self.cache_time_ns, child_id)
                reshaped = cache.latest[1] != parent_id
                if cache.insert_raw(stamp_ns, values, parent_id):
                    stored_any = True
                    self._authority[child_id] = authority
                    if reshaped:
                        self._shape_version += 1
                else:
                    lock.release()  # logs are written outside the lock, in order
                    try:
                        self._log_old_data(self._names[child_id], stamp_ns, authority)
                    finally:
                        lock.acquire()
            callbacks = self._callbacks_snapshot
        finally:
            lock.release()
        if stored_any:
            for callback in callbacks:
                callback()
        return failures

    def _set_transform_checked(self, arguments: SetTransformArguments) -> bool:
        """:meth:`set_transform` with every check, for what its fast path does not take."""
        parent, child, stamp_ns, translation, rotation, authority, is_static = arguments
        if not isinstance(parent, str) or not isinstance(child, str):
            raise TypeError(
                f'parent and child must be str, got {type(parent).__name__} and '
                f'{type(child).__name__}'
            )
        try:
            tx, ty, tz = translation
            x, y, z, w = rotation
            tx, ty, tz, x, y, z, w = unpack_values(pack_values(tx, ty, tz, x, y, z, w))
            stamp = int(stamp_ns)
        except (TypeError, ValueError, struct.error) as error:
            raise TypeError(
                'set_transform needs translation (x, y, z), rotation (x, y, z, w) as numbers '
                f'and an integer stamp_ns: {error}'
            ) from error
        given_parent, given_child = parent, child
        if parent and parent[0] == '/':
            parent = parent[1:]
        if child and child[0] == '/':
            child = child[1:]
        rx, ry, rz, rw = math3d.canonical_quat((x, y, z, w))
        total = tx + ty + tz + rx + ry + rz + rw  # NaN if any value is NaN (or inf - inf)
        if (
            child == parent or not child or not parent or total != total  # noqa: PLR0124
        ) and self._log_invalid(parent, child, authority, (tx, ty, tz), (rx, ry, rz, rw)):
            return False
        with self._lock:
            child_id = self._intern(child)
            cache = self._caches[child_id]
            if cache is None or cache.is_static != is_static:
                cache = (
                    StaticCache(child_id) if is_static else TimeCache(self.cache_time_ns, child_id)
                )
                self._caches[child_id] = cache
            parent_id = self._intern(parent)
            if child_id != parent_id:  # the fast path may take these names from now on
                self._insert_ids[given_child] = child_id
                self._insert_ids[given_parent] = parent_id
            sample = (tx, ty, tz, rx, ry, rz, rw, parent_id)
            # A new parent (or a new static value) changes the shape the path plans rely on.
            reshaped = cache.latest[1] != parent_id or (is_static and cache.get_data(0) != sample)
            stored = cache.insert(stamp, sample)
            if stored:
                self._authority[child_id] = authority
                if reshaped:
                    self._shape_version += 1
            callbacks = self._callbacks_snapshot
        if not stored:
            self._log_old_data(child, stamp, authority)
            return False
        for callback in callbacks:
            callback()
        return True

    def _log_old_data(self, child: str, stamp_ns: int, authority: str) -> None:
        """Log tf2's TF_OLD_DATA warning for a sample older than the cache keeps."""
        self._log(
            logging.WARNING,
            f'TF_OLD_DATA ignoring data from the past for frame {child} at time '
            f'{display_time_point(stamp_ns)} according to authority {authority}\n'
            'Possible reasons are listed at http://wiki.ros.org/tf/Errors%20explained',
        )

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
            self._shape_version += 1

    # ------------------------------------------------------------------ latest common time

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

    # ------------------------------------------------------------------ lookups

    def _lookup_locked(self, target: str, source: str, time_ns: int) -> tuple[Transform7, int]:
        """
        tf2's ``lookupTransformImpl``: string short-cut, validation, walk (lock held).

        :returns: as :meth:`~tf_demo.core.frame_tree.FrameTree._walk`.
        """
        if target == source:
            if time_ns == 0:
                cache = self._caches[self._ids.get(target, 0)]
                if cache is not None:
                    time_ns = cache.latest_stamp_ns
            return IDENTITY, time_ns
        # The remembered plan, also filed under the names once they were validated.
        if self._plans_version == self._shape_version:
            plan = self._plans.get((target, source))
            if plan is not None:
                time_ns = time_ns or common_time(plan)
                composed = compose_plan(plan, time_ns)
                if composed is not None:
                    return composed, time_ns
        ids = self._ids
        # Names never start with '/' once interned (inserts strip one), except '//x' -> '/x',
        # which tf2 also refuses here: check the slash before trusting the id.
        target_id = ids.get(target, 0)
        if not target_id or target[0] == '/':
            target_id = self._validate('lookupTransform argument target_frame', target)
        source_id = ids.get(source, 0)
        if not source_id or source[0] == '/':
            source_id = self._validate('lookupTransform argument source_frame', source)
        if target_id != source_id:
            plan = self._plan(target_id, source_id)
            if plan is not None:
                self._plans[(target, source)] = plan
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
        lock = self._lock
        lock.acquire()
        try:
            values, stamp = self._lookup_locked(target, source, time_ns)
        finally:
            lock.release()
        if values is IDENTITY:
            # tuple.__new__: the NamedTuple without its Python-level __new__ (a Python call).
            return tuple.__new__(TransformResult, (_IDENTITY_T, _IDENTITY_Q, stamp))
        # ROS 2 stores the result in a tf2::Transform (a matrix) and reads the quaternion back.
        tx, ty, tz, qx, qy, qz, qw = values
        q = math3d.canonical_quat((qx, qy, qz, qw))
        return tuple.__new__(TransformResult, ((tx, ty, tz), q, stamp))

    def lookup_transform_full(
        self, target: str, target_time_ns: int, source: str, source_time_ns: int, fixed: str
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
            first, _ = self._lookup_locked(fixed, source, source_time_ns)
            second, stamp = self._lookup_locked(target, fixed, target_time_ns)
        t1, q1 = first[:3], first[3:]
        t2, q2 = second[:3], second[3:]
        basis2 = math3d.matrix_from_quat(q2)
        basis = math3d.matrix_times(basis2, math3d.matrix_from_quat(q1))
        ox, oy, oz = math3d.matrix_apply(basis2, t1)
        return TransformResult(
            (ox + t2[0], oy + t2[1], oz + t2[2]), math3d.quat_from_matrix(basis), stamp
        )

    def can_transform(self, target: str, source: str, time_ns: int) -> bool:
        """Return whether ``lookup_transform`` would succeed (never raises tf2 errors)."""
        return not self.transform_error(target, source, time_ns)

    def transform_error(self, target: str, source: str, time_ns: int) -> str:
        """
        Return why ``lookup_transform`` would fail, in tf2's words; ``''`` when it would succeed.

        tf2_ros's ``can_transform(..., return_debug_tuple=True)`` gives ``(not text, text)``.
        """
        if target == source:
            return ''
        ids = self._ids
        lock = self._lock
        lock.acquire()  # as lookup_transform: fewer calls than ``with`` (a hot path)
        try:
            # Interned names never start with '/' except '//x' -> '/x', which tf2 refuses here.
            target_id = ids.get(target, 0)
            source_id = ids.get(source, 0)
            if target_id and source_id and target[0] != '/' and source[0] != '/':
                return self._can_walk(target_id, source_id, time_ns) or ''
            target_id, text = self._validate_quietly('canTransform argument target_frame', target)
            if target_id:
                source_id, text = self._validate_quietly(
                    'canTransform argument source_frame', source
                )
                if source_id:
                    text = self._can_walk(target_id, source_id, time_ns) or ''
        finally:
            lock.release()
        return text

    def can_transform_full(
        self, target: str, target_time_ns: int, source: str, source_time_ns: int, fixed: str
    ) -> bool:
        """Return whether ``lookup_transform_full`` would succeed (never raises tf2 errors)."""
        return not self.transform_error_full(target, target_time_ns, source, source_time_ns, fixed)

    def transform_error_full(
        self, target: str, target_time_ns: int, source: str, source_time_ns: int, fixed: str
    ) -> str:
        """Return why ``lookup_transform_full`` would fail (tf2's text); ``''`` if it would not."""
        with self._lock:
            ids = []
            for label, frame in (
                ('canTransform argument target_frame', target),
                ('canTransform argument source_frame', source),
                ('canTransform argument fixed_frame', fixed),
            ):
                frame_id, text = self._validate_quietly(label, frame)
                if not frame_id:
                    return text
                ids.append(frame_id)
            target_id, source_id, fixed_id = ids
            return (
                self._can_walk(target_id, fixed_id, target_time_ns)
                or self._can_walk(fixed_id, source_id, source_time_ns)
                or ''
            )

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
            window = velocity_window(time_ns, averaging_ns, latest)
            start, _ = self._lookup_locked(observation, tracking, window.start_ns)
            end, _ = self._lookup_locked(observation, tracking, window.end_ns)
            reference, _ = self._lookup_locked(observation, tracking, window.reference_ns)
        return twist(start, end, reference, window.seconds)

    # ------------------------------------------------------------------ chain

    def chain(
        self, target: str, target_time_ns: int, source: str, source_time_ns: int, fixed: str
    ) -> list[str]:
        """
        Return the frames between ``source`` and ``target`` as tf2's ``_chainAsVector``.

        The list reproduces tf2's quirks (see ``spec/tf2.md`` §3.8), as Jazzy's own core
        answers them (the differential test drives it in the ROS world).

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
                # As Jazzy: an empty source chain keeps nothing of the target's, and chains
                # equal to their ends keep the target's first frame twice.
                stop = prune_shared_end(source_chain, target_chain)
                if stop < len(target_chain):
                    source_chain.extend(target_chain[: stop + 1])
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
        import numpy as np

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
                return uniform
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
                    values, _ = self._walk(target_id, source_id, int(times[begin + index]))
                    chunk_t[index] = values[:3]
                    chunk_q[index] = values[3:]
                translations[begin:end] = chunk_t
                rotations[begin:end] = math3d.canonical_quat_batch(chunk_q)
        return translations, rotations

    # ------------------------------------------------------------------ introspection

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
