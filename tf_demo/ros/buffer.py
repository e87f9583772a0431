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
``Buffer``: tf2_ros's Python buffer around a :class:`tf_demo.core.BufferCore`.

Same methods, signatures and results as ``tf2_ros.Buffer`` (Jazzy), including the ``tf2_py``
core names it inherits upstream (``lookup_transform_core``, ``can_transform_core``...).
Upstream's ``Buffer`` *is* a ``BufferCore`` whose methods it redefines with other signatures;
this one *holds* its core (:attr:`Buffer.core`, where tf_demo's extensions such as
``lookup_transforms`` or ``frames_info`` live), so both keep their own signatures. The waits
live in :class:`~tf_demo.ros.buffer_waits.BufferWaits`. With these improvements:

**Event-driven waits.** ``can_transform``/``lookup_transform`` with a timeout block on a
:class:`threading.Condition` that the core's insert callback and the clock's jump callback
notify; there is no 20 ms polling. Deadlines are measured on the buffer's clock (the node's
clock when ``node`` is given), so ``use_sim_time`` works: a wait of 2 s ends when ``/clock`` has
advanced 2 s, whatever the wall clock does (so, as in C++ tf2, a paused simulation never times
out).

**No deadlock in a single-threaded executor.** A blocking wait can only succeed if some other
thread fills the buffer. The buffer knows which threads deliver data to it (the listener reports
the thread of every ``/tf`` message) and whether a dedicated thread does (``TransformListener(
..., spin_thread=True)`` or :meth:`Buffer.set_using_dedicated_thread`). When the waiting thread is
the only thread that has delivered data, is not a worker of a thread pool (rclpy's
``MultiThreadedExecutor``), and there is no dedicated thread, data cannot arrive
while it waits (it would be delivered by this very thread after the callback returns), so the
wait does not block: it returns at once with the current answer (``False``, or the core's
exception for ``lookup_transform``) and logs C++ tf2's "dedicated thread" warning once. Use
``spin_thread=True``, a ``MultiThreadedExecutor``, or the awaitable API
(``await buffer.lookup_transform_async(..., timeout=...)`` from an ``async`` callback) instead.
Limitation: before the first ``/tf`` message has been delivered the buffer cannot know who will
deliver it, so such a wait still runs to its timeout, as upstream's does.

**Awaitable waits with a timeout.** ``wait_for_transform_async``,
``wait_for_transform_full_async``, ``lookup_transform_async`` and ``lookup_transform_full_async``
accept ``timeout`` (a Duration, ``builtin_interfaces`` Duration or int ns; ``None`` waits forever
as upstream) and then fail with
:class:`~tf_demo.core.exceptions.TimeoutException`. The async lookup does the lookup once.

**Time jumps.** A backward jump of the buffer's ROS clock by 1 s or more, or ROS time being
(de)activated, clears the buffer (static transforms survive) with upstream's warning
``Detected jump back in time. Clearing tf buffer.``.

**transform() without registration.** :meth:`Buffer.transform` knows every type of
:mod:`tf_demo.ros.geometry` (no ``import tf2_geometry_msgs`` side effect needed) and never
modifies its input. Extra types can be added per buffer with :meth:`Buffer.register_transform`.

Times may be ``rclpy``/tf_demo ``Time`` (``nanoseconds``), a ``builtin_interfaces`` Time message
(``sec``/``nanosec``) or an ``int`` of nanoseconds; durations likewise. Lookups return the
world's own ``geometry_msgs/TransformStamped``.
"""

from __future__ import annotations

from collections.abc import Iterable
import logging
import threading
from typing import NamedTuple
from typing import Protocol
from typing import TYPE_CHECKING
from typing import TypeVar

from tf_demo.core.buffer_core import BufferCore
from tf_demo.core.exceptions import TimeoutException
from tf_demo.core.exceptions import TransformException
from tf_demo.core.time_cache import DEFAULT_CACHE_TIME_NS
from tf_demo.msgs.log_throttle import PerWriterThrottle
from tf_demo.msgs.log_throttle import Writer
from tf_demo.ros.buffer_waits import BufferWaits
from tf_demo.ros.geometry import ros_type_name
from tf_demo.ros.geometry import TRANSFORM_FUNCTIONS
from tf_demo.ros.geometry import TransformFunction
from tf_demo.transport.clock import Clock
from tf_demo.transport.clock import Duration
from tf_demo.transport.clock import JumpThreshold
from tf_demo.transport.clock import Time
from tf_demo.transport.future import Future
from tf_demo.transport.logging import get_logger
from tf_demo.transport.messages import new_transform_stamped
from tf_demo.transport.messages import service_module
from tf_demo.transport.messages import transform_stamped_args

if TYPE_CHECKING:
    from tf_demo.core.math3d import Vec3
    from tf_demo.msgs.cdr import TransformTuple
    from tf_demo.msgs.convert import HeaderLike
    from tf_demo.msgs.convert import StampLike
    from tf_demo.msgs.convert import TransformStampedLike
    from tf_demo.msgs.geometry_msgs import TransformStamped
    from tf_demo.msgs.tf2_msgs import FrameGraph
    from tf_demo.msgs.tf2_msgs import FrameGraph_Response
    from tf_demo.transport.clock import JumpHandle
    from tf_demo.transport.clock import TimeJump
    from tf_demo.transport.logging import Logger
    from tf_demo.transport.node import Node

    #: A time: rclpy-style ``Time``, a ``builtin_interfaces/Time`` message (either world's:
    #: ``sec`` and ``nanosec``) or int nanoseconds.
    TimeLike = Time | StampLike | int
    #: A duration: ``Duration``, a ``builtin_interfaces/Duration`` message or int nanoseconds.
    DurationLike = Duration | StampLike | int

JUMP_BACK_CLEAR_THRESHOLD_NS = 1_000_000_000
"""A backward jump of at least this much clears the buffer (tf2_ros Python's threshold)."""

DIRECT_WRITER = 'direct set_transform calls'
"""Who :meth:`Buffer.set_log_source` names when no listener said who sent a transform."""


class Stamped(Protocol):
    """A stamped geometry message (``header.frame_id``, ``header.stamp``) of either world."""

    @property
    def header(self) -> HeaderLike: ...


StampedT = TypeVar('StampedT', bound=Stamped)


class TypeException(Exception):  # noqa: N818 - tf2_ros's name
    """``Buffer.transform`` got a message type it cannot transform (tf2_ros's name)."""


def ns_from_time(time: TimeLike) -> int:
    """
    Integer nanoseconds of a time given as ``Time``, a Time message or ``int`` ns.

    :raises TypeError: with tf2_py's text for anything else.
    """
    return _ns_from(time, 'time')


def ns_from_duration(duration: DurationLike | None) -> int:
    """
    Integer nanoseconds of a duration given as ``Duration``, a Duration message or ``int`` ns.

    ``None`` means zero (no waiting).

    :raises TypeError: with tf2_py's text for anything else.
    """
    if duration is None:
        return 0
    return _ns_from(duration, 'duration')


def _ns_from(value: object, what: str) -> int:
    """Nanoseconds of ``value`` (checked at run time: callers of an untyped API pass anything)."""
    if isinstance(value, int) and not isinstance(value, bool):
        return value
    nanoseconds = getattr(value, 'nanoseconds', None)
    if isinstance(nanoseconds, int):
        return nanoseconds
    sec = getattr(value, 'sec', None)
    nanosec = getattr(value, 'nanosec', None)
    if sec is not None and nanosec is not None:
        return int(sec) * 1_000_000_000 + int(nanosec)
    msg = f'{what} must have sec and nanosec, or nanoseconds.'
    raise TypeError(msg)


class _Query(NamedTuple):
    """
    A question of tf2's basic API to a core: target_T_source at one time (integer ns).

    What the blocking, awaitable and ``*_core`` variants of a tf2_ros method share.
    """

    core: BufferCore
    target_frame: str
    source_frame: str
    time_ns: int

    def answer(self) -> tuple[bool, str]:
        """Return ``(possible, error text)`` now."""
        text = self.core.transform_error(self.target_frame, self.source_frame, self.time_ns)
        return not text, text

    def ready(self) -> bool:
        """Whether the lookup would succeed now."""
        return self.core.can_transform(self.target_frame, self.source_frame, self.time_ns)

    def lookup(self) -> TransformStamped:
        """Look the transform up now; raises tf2's exceptions."""
        result = self.core.lookup_transform(self.target_frame, self.source_frame, self.time_ns)
        return new_transform_stamped(self.target_frame, self.source_frame, result)

    def timeout_text(self) -> str:
        """Return the text of the ``TimeoutException`` of an awaitable wait that timed out."""
        return (
            f'Timed out waiting for transform from [{self.source_frame}] to [{self.target_frame}]'
        )


class _FullQuery(NamedTuple):
    """A question of tf2's advanced API: target and source at two times, via a fixed frame."""

    core: BufferCore
    args: tuple[str, int, str, int, str]
    """The core's arguments: target frame, target time (ns), source frame, source time, fixed."""

    def answer(self) -> tuple[bool, str]:
        """Return ``(possible, error text)`` now."""
        text = self.core.transform_error_full(*self.args)
        return not text, text

    def ready(self) -> bool:
        """Whether the lookup would succeed now."""
        return self.core.can_transform_full(*self.args)

    def lookup(self) -> TransformStamped:
        """Look the transform up now; raises tf2's exceptions."""
        target_frame, _, source_frame, _, _ = self.args
        return new_transform_stamped(
            target_frame, source_frame, self.core.lookup_transform_full(*self.args)
        )

    def timeout_text(self) -> str:
        """Return the text of the ``TimeoutException`` of an awaitable wait that timed out."""
        target_frame, _, source_frame, _, fixed_frame = self.args
        return (
            f'Timed out waiting for transform from [{source_frame}] to [{target_frame}] '
            f'via [{fixed_frame}]'
        )


def _query(core: BufferCore, target_frame: str, source_frame: str, time: TimeLike) -> _Query:
    """Return the basic-API question of tf2_ros's arguments, its time in integer nanoseconds."""
    return _Query(core, target_frame, source_frame, ns_from_time(time))


def _full_query(  # noqa: PLR0917 - tf2_ros argument order
    core: BufferCore,
    target_frame: str,
    target_time: TimeLike,
    source_frame: str,
    source_time: TimeLike,
    fixed_frame: str,
) -> _FullQuery:
    """Return the advanced-API question of tf2_ros's arguments, times in integer nanoseconds."""
    return _FullQuery(
        core,
        (
            target_frame,
            ns_from_time(target_time),
            source_frame,
            ns_from_time(source_time),
            fixed_frame,
        ),
    )


class Buffer:
    """
    tf2_ros-compatible transform buffer: a core plus waits, async API and ``transform()``.

    See the module docstring for how waiting works and how it avoids executor deadlocks.
    """

    def __init__(
        self,
        cache_time: DurationLike | None = None,
        node: Node | None = None,
        *,
        clock: Clock | None = None,
    ) -> None:
        """
        Create a buffer.

        :param cache_time: how long to keep past transforms (Duration, Duration message or int
            ns); default 10 s.
        :param node: optional node: its clock measures timeouts and drives time-jump clearing,
            and its logger receives tf2's warnings. Without it a system clock is used, as
            upstream does.
        :param clock: a clock to use instead of the node's (tf_demo extension, e.g. a ``ROSClock``
            driven by ``/clock`` or by a test).
        """
        cache_time_ns = (
            DEFAULT_CACHE_TIME_NS if cache_time is None else ns_from_duration(cache_time)
        )
        self._rejections = PerWriterThrottle('rejected transforms')
        self._log_source = threading.local()
        self.core = BufferCore(cache_time_ns, log=self._log_core)
        """The tf2 core this buffer wraps (tf_demo's extensions of tf2's core API live there)."""
        self._node = node
        self._extra_transforms: dict[str, TransformFunction] = {}
        if clock is None:
            clock = node.get_clock() if node is not None else Clock()
        self.clock: Clock = clock
        self._waits: BufferWaits[TransformStamped] = BufferWaits(
            self._now_ns, lambda text: self._logger().warning(text)
        )
        self.core.add_insert_callback(self._waits.on_new_data)
        self.jump_handle = self._register_jump_callback()
        self.srv = _create_frames_service(node, self) if node is not None else None

    # ----------------------------------------------------------------------------- plumbing

    def _logger(self) -> Logger:
        if self._node is not None:
            node_logger: Logger = self._node.get_logger()
            return node_logger
        return get_logger('tf2_buffer')

    def set_log_source(self, writer: Writer | None) -> None:
        """
        Name who sent the transforms this thread inserts next (the listener calls it).

        tf2's lines about rejected transforms (``TF_NAN_INPUT``, ``TF_OLD_DATA``...) are
        throttled per writer and kind: the first is logged, then a count every few seconds.
        ``None`` means direct calls of :meth:`set_transform`.
        """
        self._log_source.writer = writer

    def log_pending_rejections(self) -> None:
        """Log the counts of rejected transforms not reported yet."""
        for line in self._rejections.pending():
            self._emit(logging.WARNING, line)

    def _log_core(self, level: int, text: str) -> None:
        writer = getattr(self._log_source, 'writer', None) or DIRECT_WRITER
        kind = text.split(None, 1)[0].rstrip(':') if text.startswith('TF_') else ''
        line = self._rejections.line(writer, text, kind)
        if line is not None:
            self._emit(level, line)

    def _emit(self, level: int, text: str) -> None:
        try:
            logger = self._logger()
            if level >= logging.ERROR:
                logger.error(text)
            elif level >= logging.WARNING:
                logger.warning(text)
            else:
                logger.info(text)
        except Exception:
            logging.getLogger('tf_demo.ros').log(level, text)

    def _register_jump_callback(self) -> JumpHandle | None:
        """Watch the clock: clear on backward jumps, and wake deadline checks on every tick."""
        create = getattr(self.clock, 'create_jump_callback', None)
        if create is None:
            return None
        threshold = JumpThreshold(
            min_forward=Duration(nanoseconds=1),
            min_backward=Duration(nanoseconds=-1),
            on_clock_change=True,
        )
        try:
            handle: JumpHandle = create(threshold, post_callback=self.time_jump_callback)
        except Exception as error:
            logging.getLogger('tf_demo.ros').debug('no clock jump callbacks: %s', error)
            return None
        return handle

    def time_jump_callback(self, time_jump: TimeJump) -> None:
        """
        React to a jump of the buffer's clock (tf2_ros's name).

        A backward jump of 1 s or more, or ROS time being (de)activated, clears the buffer with
        upstream's warning; every jump wakes the waits, whose deadlines are on this clock.
        """
        change = time_jump.clock_change.name
        if change in ('ROS_TIME_ACTIVATED', 'ROS_TIME_DEACTIVATED') or (
            time_jump.delta.nanoseconds <= -JUMP_BACK_CLEAR_THRESHOLD_NS
        ):
            # Always on tf2_buffer, node or not, as tf2_ros's time_jump_callback logs it.
            get_logger('tf2_buffer').warning('Detected jump back in time. Clearing tf buffer.')
            self.clear()
        self._waits.wake()

    def _now_ns(self) -> int:
        return int(self.clock.now().nanoseconds)

    def note_feeder_thread(self) -> None:
        """Record that the calling thread delivers transforms (called by the listener)."""
        self._waits.note_feeder_thread()

    def set_using_dedicated_thread(self, value: bool) -> None:
        """Declare that a thread other than the callers' fills this buffer (C++'s name)."""
        self._waits.set_using_dedicated_thread(value)

    setUsingDedicatedThread = set_using_dedicated_thread  # noqa: N815 - tf2 C++ spelling

    # ---------------------------------------------------------------------- message in/out

    def set_transform(self, transform: TransformStampedLike, authority: str) -> None:
        """Insert a dynamic ``TransformStamped``; a rejected one is logged, as tf2_ros does."""
        self.core.set_transform(*transform_stamped_args(transform), authority, False)

    def set_transform_static(self, transform: TransformStampedLike, authority: str) -> None:
        """Insert a static ``TransformStamped`` (valid at all times); rejections are logged."""
        self.core.set_transform(*transform_stamped_args(transform), authority, True)

    def insert_decoded(
        self, transforms: Iterable[TransformTuple], authority: str, writer: Writer, is_static: bool
    ) -> list[tuple[str, str, Exception]]:
        """
        Insert transforms decoded straight from serialised ``/tf`` bytes: the listener's fast path.

        :class:`~tf_demo.ros.TransformListener` decodes each ``TFMessage`` with
        :func:`tf_demo.msgs.cdr.decode_tf_message_transforms` and hands the tuples
        ``(parent, child, stamp_ns, translation, rotation)`` here; they go into
        :meth:`BufferCore.set_transforms <tf_demo.core.BufferCore.set_transforms>` (one lock for
        the message) with no message object built. Rejected transforms are logged as tf2 logs
        them, throttled per ``writer``.

        :returns: ``(parent, child, error)`` for each transform whose insert raised (the others
            are inserted all the same).
        """
        self._log_source.writer = writer
        try:
            return self.core.set_transforms(transforms, authority, is_static)
        finally:
            self._log_source.writer = None

    # ---------------------------------------------------------------- tf2_py's core names

    def lookup_transform_core(
        self, target_frame: str, source_frame: str, time: TimeLike
    ) -> TransformStamped:
        """Look up target_T_source now, without waiting; raises tf2's exceptions."""
        result = self.core.lookup_transform(target_frame, source_frame, ns_from_time(time))
        return new_transform_stamped(target_frame, source_frame, result)

    def lookup_transform_full_core(
        self,
        target_frame: str,
        target_time: TimeLike,
        source_frame: str,
        source_time: TimeLike,
        fixed_frame: str,
    ) -> TransformStamped:
        """Look up with the advanced (time-travel) API now, without waiting."""
        return _full_query(
            self.core, target_frame, target_time, source_frame, source_time, fixed_frame
        ).lookup()

    def can_transform_core(
        self, target_frame: str, source_frame: str, time: TimeLike
    ) -> tuple[bool, str]:
        """Return ``(possible, error_text)`` now, without waiting."""
        return _query(self.core, target_frame, source_frame, time).answer()

    def can_transform_full_core(
        self,
        target_frame: str,
        target_time: TimeLike,
        source_frame: str,
        source_time: TimeLike,
        fixed_frame: str,
    ) -> tuple[bool, str]:
        """Return ``(possible, error_text)`` for the advanced API now, without waiting."""
        return _full_query(
            self.core, target_frame, target_time, source_frame, source_time, fixed_frame
        ).answer()

    def lookupVelocityCore(  # noqa: N802 - tf2_py name
        self,
        tracking_frame: str,
        observation_frame: str,
        time: TimeLike,
        averaging_interval: DurationLike,
    ) -> tuple[Vec3, Vec3]:
        """Return the twist ``((vx, vy, vz), (wx, wy, wz))`` of a frame (tf2's velocity)."""
        return self.core.lookup_velocity(
            tracking_frame,
            observation_frame,
            ns_from_time(time),
            ns_from_duration(averaging_interval),
        )

    # ------------------------------------------------------------------------ blocking API

    def lookup_transform(
        self,
        target_frame: str,
        source_frame: str,
        time: TimeLike,
        timeout: DurationLike | None = None,
    ) -> TransformStamped:
        """
        Get the transform from the source frame to the target frame.

        :param target_frame: name of the frame to transform into.
        :param source_frame: name of the input frame.
        :param time: the time of the transform (0 means the latest common time).
        :param timeout: how long to wait for it, on the buffer's clock (default: no wait).
        :return: target_T_source as a ``TransformStamped``.
        :raises TransformException: the core's specific error when it is (still) unavailable.
        """
        return self._lookup(_query(self.core, target_frame, source_frame, time), timeout)

    def lookup_transform_full(  # noqa: PLR0917 - tf2_ros signature
        self,
        target_frame: str,
        target_time: TimeLike,
        source_frame: str,
        source_time: TimeLike,
        fixed_frame: str,
        timeout: DurationLike | None = None,
    ) -> TransformStamped:
        """
        As :meth:`lookup_transform`, with target and source at two times (tf2's advanced API).

        ``source_frame`` at ``source_time`` is chained through ``fixed_frame`` (a frame that does
        not move between the two times) to ``target_frame`` at ``target_time``.
        """
        query = _full_query(
            self.core, target_frame, target_time, source_frame, source_time, fixed_frame
        )
        return self._lookup(query, timeout)

    def can_transform(
        self,
        target_frame: str,
        source_frame: str,
        time: TimeLike,
        timeout: DurationLike | None = None,
        return_debug_tuple: bool = False,
    ) -> bool | tuple[bool, str]:
        """
        Check whether :meth:`lookup_transform` would succeed, waiting up to ``timeout`` for it.

        :return: ``bool``, or ``(bool, error_text)`` when ``return_debug_tuple``.
        """
        query = _query(self.core, target_frame, source_frame, time)
        return self._check(query, timeout, return_debug_tuple)

    def can_transform_full(  # noqa: PLR0917 - tf2_ros signature
        self,
        target_frame: str,
        target_time: TimeLike,
        source_frame: str,
        source_time: TimeLike,
        fixed_frame: str,
        timeout: DurationLike | None = None,
        return_debug_tuple: bool = False,
    ) -> bool | tuple[bool, str]:
        """As :meth:`can_transform`, for :meth:`lookup_transform_full`'s question."""
        query = _full_query(
            self.core, target_frame, target_time, source_frame, source_time, fixed_frame
        )
        return self._check(query, timeout, return_debug_tuple)

    def _lookup(
        self, query: _Query | _FullQuery, timeout: DurationLike | None
    ) -> TransformStamped:
        """Wait up to ``timeout`` until ``query`` can be answered, then look it up."""
        self._waits.wait_until(query.ready, ns_from_duration(timeout))
        return query.lookup()

    def _check(
        self, query: _Query | _FullQuery, timeout: DurationLike | None, return_debug_tuple: bool
    ) -> bool | tuple[bool, str]:
        """Wait up to ``timeout`` until ``query`` can be answered; return whether it can."""
        self._waits.wait_until(query.ready, ns_from_duration(timeout))
        answer = query.answer()
        return answer if return_debug_tuple else answer[0]

    # --------------------------------------------------------------------------- async API

    def wait_for_transform_async(
        self,
        target_frame: str,
        source_frame: str,
        time: TimeLike,
        timeout: DurationLike | None = None,
    ) -> Future[TransformStamped]:
        """
        Wait for a transform without blocking; the future resolves to the ``TransformStamped``.

        :param timeout: optional limit on the buffer's clock; then the future fails with
            ``TimeoutException``. ``None`` waits forever (upstream behaviour).
        :return: a future (rclpy ``Future`` API) resolving to target_T_source.
        """
        return self._wait_async(_query(self.core, target_frame, source_frame, time), timeout)

    def wait_for_transform_full_async(  # noqa: PLR0917 - tf2_ros signature
        self,
        target_frame: str,
        target_time: TimeLike,
        source_frame: str,
        source_time: TimeLike,
        fixed_frame: str,
        timeout: DurationLike | None = None,
    ) -> Future[TransformStamped]:
        """As :meth:`wait_for_transform_async`, for :meth:`lookup_transform_full`'s question."""
        query = _full_query(
            self.core, target_frame, target_time, source_frame, source_time, fixed_frame
        )
        return self._wait_async(query, timeout)

    async def lookup_transform_async(
        self,
        target_frame: str,
        source_frame: str,
        time: TimeLike,
        timeout: DurationLike | None = None,
    ) -> TransformStamped:
        """
        Await the transform from the source frame to the target frame (looked up once).

        :raises TimeoutException: when ``timeout`` passes first.
        """
        return await self.wait_for_transform_async(target_frame, source_frame, time, timeout)

    async def lookup_transform_full_async(  # noqa: PLR0917 - tf2_ros signature
        self,
        target_frame: str,
        target_time: TimeLike,
        source_frame: str,
        source_time: TimeLike,
        fixed_frame: str,
        timeout: DurationLike | None = None,
    ) -> TransformStamped:
        """As :meth:`lookup_transform_async`, for :meth:`lookup_transform_full`'s question."""
        return await self.wait_for_transform_full_async(
            target_frame, target_time, source_frame, source_time, fixed_frame, timeout
        )

    def _wait_async(
        self, query: _Query | _FullQuery, timeout: DurationLike | None
    ) -> Future[TransformStamped]:
        timeout_ns = None if timeout is None else ns_from_duration(timeout)
        return self._waits.wait_async(query.ready, query.lookup, timeout_ns, query.timeout_text())

    # ---------------------------------------------------------------------------- transform

    def register_transform(self, msg_type: type, function: TransformFunction) -> None:
        """Teach this buffer (only) how to transform ``msg_type``: ``function(msg, tf)``."""
        self._extra_transforms[ros_type_name(msg_type)] = function

    def _transform_function(self, msg_type: type) -> TransformFunction:
        name = ros_type_name(msg_type)
        function = self._extra_transforms.get(name) or TRANSFORM_FUNCTIONS.get(name)
        if function is None:
            msg = f'Type {msg_type} is not loaded or supported'
            raise TypeException(msg)
        return function

    def transform(
        self,
        object_stamped: StampedT,
        target_frame: str,
        timeout: DurationLike | None = None,
        new_type: type[StampedT] | None = None,
    ) -> StampedT:
        """
        Transform a stamped geometry message into ``target_frame`` (input not modified).

        :param object_stamped: a message with a ``header``, of a type in
            :data:`tf_demo.ros.geometry.TRANSFORM_FUNCTIONS` or registered on this buffer.
        :param target_frame: the frame to express it in.
        :param timeout: how long to wait for the transform.
        :param new_type: optional output type; only the input's own type is supported.
        :return: a new message of the same type.
        """
        function = self._transform_function(type(object_stamped))
        header = object_stamped.header
        transform = self.lookup_transform(target_frame, header.frame_id, header.stamp, timeout)
        result: StampedT = function(object_stamped, transform)
        return _check_new_type(result, new_type)

    def transform_full(  # noqa: PLR0917 - tf2_ros signature
        self,
        object_stamped: StampedT,
        target_frame: str,
        target_time: TimeLike,
        fixed_frame: str,
        timeout: DurationLike | None = None,
        new_type: type[StampedT] | None = None,
    ) -> StampedT:
        """Transform a stamped message to ``target_frame`` at ``target_time`` via a fixed frame."""
        function = self._transform_function(type(object_stamped))
        header = object_stamped.header
        transform = self.lookup_transform_full(
            target_frame, target_time, header.frame_id, header.stamp, fixed_frame, timeout
        )
        result: StampedT = function(object_stamped, transform)
        return _check_new_type(result, new_type)

    # ------------------------------------------------------------------------ introspection

    def get_latest_common_time(self, target_frame: str, source_frame: str) -> Time:
        """Return the latest time at which both frames are connected, as a ``Time``."""
        return Time(nanoseconds=self.core.get_latest_common_time(target_frame, source_frame))

    def all_frames_as_yaml(self, current_time: TimeLike = 0) -> str:
        """Return tf2's YAML description of every frame."""
        return self.core.all_frames_as_yaml(ns_from_time(current_time))

    def all_frames_as_string(self) -> str:
        """Return tf2's text description of every frame."""
        return self.core.all_frames_as_string()

    def clear(self) -> None:
        """Forget all dynamic transforms (static ones stay), as tf2 does."""
        self.core.clear()
        self._waits.wake()

    def frame_ids(self) -> list[str]:
        """Return every known frame name (tf_demo's name for ``_getFrameStrings``)."""
        return self.core.frame_ids()

    def _frameExists(self, frame_id: str) -> bool:  # noqa: N802 - tf2_py name
        return self.core.frame_exists(frame_id)

    def _getFrameStrings(self) -> list[str]:  # noqa: N802 - tf2_py name
        return self.core.frame_ids()

    def _allFramesAsDot(self, time: TimeLike = 0) -> str:  # noqa: N802 - tf2_py name
        return self.core.all_frames_as_dot(ns_from_time(time))


def _create_frames_service(node: Node, buffer: Buffer) -> object:
    """
    Offer tf2_ros's ``tf2_frames`` service (``tf2_msgs/srv/FrameGraph``) as tf2_ros does.

    ``ros2 run tf2_tools view_frames`` calls it. The service type is the world's (rclpy's
    ``tf2_msgs.srv`` inside ROS 2, ``tf_demo.msgs`` standalone); nodes without
    ``create_service`` simply do not offer it.
    """
    create_service = getattr(node, 'create_service', None)
    if create_service is None:
        return None
    frame_graph: type[FrameGraph] = service_module('tf2_msgs').FrameGraph

    def answer(_request: object, _response: object) -> FrameGraph_Response:
        return frame_graph.Response(frame_yaml=buffer.all_frames_as_yaml())

    service: object = create_service(frame_graph, 'tf2_frames', answer)
    return service


def _check_new_type(result: StampedT, new_type: type[StampedT] | None) -> StampedT:
    if new_type is None or isinstance(result, new_type):
        return result
    msg = f'cannot convert {type(result).__name__} to {getattr(new_type, "__name__", new_type)}'
    raise TypeException(msg)


__all__ = [
    'Buffer',
    'TimeoutException',
    'TransformException',
    'TypeException',
    'ns_from_duration',
    'ns_from_time',
]
