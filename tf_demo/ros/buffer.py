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
``Buffer``: tf2_ros's Python buffer on top of :class:`tf_demo.core.BufferCore`.

Same methods, signatures and results as ``tf2_ros.Buffer`` (Jazzy), with these improvements:

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

from collections.abc import Callable
import logging
import threading
from typing import Any
from typing import TypeVar

from tf_demo.core.buffer_core import BufferCore
from tf_demo.core.exceptions import TimeoutException
from tf_demo.core.exceptions import TransformException
from tf_demo.msgs.convert import fill_transform_stamped
from tf_demo.msgs.convert import transform_stamped_args
from tf_demo.msgs.log_throttle import PerWriterThrottle
from tf_demo.msgs.log_throttle import Writer
from tf_demo.ros.geometry import ros_type_name
from tf_demo.ros.geometry import TRANSFORM_FUNCTIONS
from tf_demo.ros.geometry import TransformFunction
from tf_demo.transport.future import Future

DEFAULT_CACHE_TIME_NS = 10_000_000_000
JUMP_BACK_CLEAR_THRESHOLD_NS = 1_000_000_000
"""A backward jump of at least this much clears the buffer (tf2_ros Python's threshold)."""
POOL_THREAD_PREFIX = 'ThreadPoolExecutor'
"""Name prefix of ``concurrent.futures`` worker threads (rclpy's MultiThreadedExecutor)."""
MAX_WAIT_SLICE_S = 1.0
"""Longest single condition wait; bounds how late a deadline on a silent clock is noticed."""

DIRECT_WRITER = 'direct set_transform calls'
"""Who :meth:`Buffer.set_log_source` names when no listener said who sent a transform."""

DEDICATED_THREAD_WARNING = (
    'Do not call canTransform or lookupTransform with a timeout unless you are using another '
    'thread for populating data. Without a dedicated thread it will always timeout.  If you '
    'have a separate thread servicing tf messages, call setUsingDedicatedThread(true) on your '
    'Buffer instance.'
)

T = TypeVar('T')


class TypeException(Exception):  # noqa: N818 - tf2_ros's name
    """``Buffer.transform`` got a message type it cannot transform (tf2_ros's name)."""


def ns_from_time(time: Any) -> int:
    """
    Integer nanoseconds of a time given as ``Time``, a Time message or ``int`` ns.

    :raises TypeError: with tf2_py's text for anything else.
    """
    return _ns_from(time, 'time')


def ns_from_duration(duration: Any) -> int:
    """
    Integer nanoseconds of a duration given as ``Duration``, a Duration message or ``int`` ns.

    ``None`` means zero (no waiting).

    :raises TypeError: with tf2_py's text for anything else.
    """
    if duration is None:
        return 0
    return _ns_from(duration, 'duration')


def _ns_from(value: Any, what: str) -> int:
    if isinstance(value, int) and not isinstance(value, bool):
        return value
    nanoseconds = getattr(value, 'nanoseconds', None)
    if isinstance(nanoseconds, int):
        return nanoseconds
    if hasattr(value, 'sec') and hasattr(value, 'nanosec'):
        return int(value.sec) * 1_000_000_000 + int(value.nanosec)
    msg = f'{what} must have sec and nanosec, or nanoseconds.'
    raise TypeError(msg)


def _default_clock() -> Any:
    from tf_demo.transport.clock import Clock

    return Clock()


def _buffer_logger() -> Any:
    from tf_demo.transport.logging import get_logger

    return get_logger('tf2_buffer')


class _AsyncWait:
    """One pending asynchronous wait: its readiness check, its lookup and its deadline."""

    __slots__ = ('deadline_ns', 'future', 'lookup', 'ready', 'timeout_text')

    def __init__(
        self,
        ready: Callable[[], bool],
        lookup: Callable[[], Any],
        deadline_ns: int | None,
        future: Future[Any],
        timeout_text: str,
    ) -> None:
        self.timeout_text = timeout_text
        self.ready = ready
        self.lookup = lookup
        self.deadline_ns = deadline_ns
        self.future = future


class Buffer(BufferCore):
    """
    tf2_ros-compatible transform buffer: the core plus waits, async API and ``transform()``.

    See the module docstring for how waiting works and how it avoids executor deadlocks.
    """

    def __init__(self, cache_time: Any = None, node: Any = None, *, clock: Any = None) -> None:
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
        super().__init__(cache_time_ns, log=self._log_core)
        self._node = node
        self._condition = threading.Condition()
        self._blocked_waits = 0
        """Threads inside :meth:`_wait_until`'s condition wait (changed under ``_condition``)."""
        self._async_waits: list[_AsyncWait] = []
        self._watcher: threading.Thread | None = None
        self._dedicated_thread = False
        self._feeder_threads: set[int] = set()
        self._warned_no_dedicated_thread = False
        self._extra_transforms: dict[str, TransformFunction] = {}
        if clock is None:
            clock = node.get_clock() if node is not None else _default_clock()
        self.clock: Any = clock
        self.add_insert_callback(self._on_new_data)
        self._jump_handle = self._register_jump_callback()
        self.srv = _create_frames_service(node, self) if node is not None else None

    # ----------------------------------------------------------------------------- plumbing

    def _logger(self) -> Any:
        if self._node is not None:
            return self._node.get_logger()
        return _buffer_logger()

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

    def _register_jump_callback(self) -> Any:
        """Watch the clock: clear on backward jumps, and wake deadline checks on every tick."""
        create = getattr(self.clock, 'create_jump_callback', None)
        if create is None:
            return None
        from tf_demo.transport.clock import Duration
        from tf_demo.transport.clock import JumpThreshold

        threshold = JumpThreshold(
            min_forward=Duration(nanoseconds=1),
            min_backward=Duration(nanoseconds=-1),
            on_clock_change=True,
        )
        try:
            return create(threshold, post_callback=self._on_time_jump)
        except Exception as error:
            logging.getLogger('tf_demo.ros').debug('no clock jump callbacks: %s', error)
            return None

    def _on_time_jump(self, time_jump: Any) -> None:
        change = getattr(getattr(time_jump, 'clock_change', None), 'name', '')
        delta_ns = getattr(getattr(time_jump, 'delta', None), 'nanoseconds', 0)
        if change in ('ROS_TIME_ACTIVATED', 'ROS_TIME_DEACTIVATED') or (
            delta_ns <= -JUMP_BACK_CLEAR_THRESHOLD_NS
        ):
            self._logger().warning('Detected jump back in time. Clearing tf buffer.')
            self.clear()
        self._wake()

    def _now_ns(self) -> int:
        return int(self.clock.now().nanoseconds)

    def _wake(self) -> None:
        with self._condition:
            self._condition.notify_all()

    def _on_new_data(self) -> None:
        """Core insert callback: wake blocking waits (if any) and resolve asynchronous ones."""
        # A waiter registers under the lock before it checks its condition, so one that
        # registers after this read sees the inserted data itself: no wake-up is lost.
        if self._blocked_waits:
            self._wake()
        if self._async_waits:
            self._service_async_waits(now_ns=None)

    def note_feeder_thread(self) -> None:
        """Record that the calling thread delivers transforms (called by the listener)."""
        ident = threading.get_ident()
        if ident not in self._feeder_threads:
            with self._condition:
                self._feeder_threads.add(ident)

    def set_using_dedicated_thread(self, value: bool) -> None:
        """Declare that a thread other than the callers' fills this buffer (C++'s name)."""
        self._dedicated_thread = value

    setUsingDedicatedThread = set_using_dedicated_thread  # noqa: N815 - tf2 C++ spelling

    def _data_can_arrive_while_waiting(self) -> bool:
        if self._dedicated_thread:
            return True
        current = threading.current_thread()
        if current.name.startswith(POOL_THREAD_PREFIX):
            return True  # a multi-threaded executor: another worker can deliver meanwhile
        with self._condition:
            feeders = set(self._feeder_threads)
        return feeders != {current.ident}

    def _wait_until(self, ready: Callable[[], bool], timeout_ns: int) -> None:
        """Block until ``ready()`` or until ``timeout_ns`` passed on the buffer's clock."""
        if timeout_ns <= 0 or ready():
            return
        if not self._data_can_arrive_while_waiting():
            if not self._warned_no_dedicated_thread:
                self._warned_no_dedicated_thread = True
                self._logger().warning(DEDICATED_THREAD_WARNING)
            return
        deadline_ns = self._now_ns() + timeout_ns
        with self._condition:
            self._blocked_waits += 1
            try:
                while not ready():
                    remaining_ns = deadline_ns - self._now_ns()
                    if remaining_ns <= 0:
                        return
                    self._condition.wait(min(remaining_ns / 1e9, MAX_WAIT_SLICE_S))
            finally:
                self._blocked_waits -= 1

    # ---------------------------------------------------------------------- message in/out

    def set_transform(self, transform: Any, authority: str) -> None:  # type: ignore[override]
        """Insert a dynamic ``TransformStamped``; a rejected one is logged, as tf2_ros does."""
        self._insert(transform, authority, is_static=False)

    def set_transform_static(self, transform: Any, authority: str) -> None:
        """Insert a static ``TransformStamped`` (valid at all times); rejections are logged."""
        self._insert(transform, authority, is_static=True)

    def _insert(self, transform: Any, authority: str, *, is_static: bool) -> None:
        parent, child, stamp_ns, translation, rotation = transform_stamped_args(transform)
        BufferCore.set_transform(
            self, parent, child, stamp_ns, translation, rotation, authority, is_static
        )

    @staticmethod
    def _message(target_frame: str, source_frame: str, result: Any) -> Any:
        from tf_demo.transport.messages import geometry_msgs

        msg = geometry_msgs.TransformStamped()
        fill_transform_stamped(
            msg, target_frame, source_frame, result.stamp_ns, result.translation, result.rotation
        )
        return msg

    # -------------------------------------------------------------------------- core names

    def lookup_transform_core(self, target_frame: str, source_frame: str, time: Any) -> Any:
        """Look up target_T_source now, without waiting; raises tf2's exceptions."""
        result = BufferCore.lookup_transform(self, target_frame, source_frame, ns_from_time(time))
        return self._message(target_frame, source_frame, result)

    def lookup_transform_full_core(
        self,
        target_frame: str,
        target_time: Any,
        source_frame: str,
        source_time: Any,
        fixed_frame: str,
    ) -> Any:
        """Look up with the advanced (time-travel) API now, without waiting."""
        result = BufferCore.lookup_transform_full(
            self, *_full_query(target_frame, target_time, source_frame, source_time, fixed_frame)
        )
        return self._message(target_frame, source_frame, result)

    def can_transform_core(
        self, target_frame: str, source_frame: str, time: Any
    ) -> tuple[bool, str]:
        """Return ``(possible, error_text)`` now, without waiting."""
        answer = BufferCore.can_transform(
            self, target_frame, source_frame, ns_from_time(time), return_debug_tuple=True
        )
        return _debug_tuple(answer)

    def can_transform_full_core(
        self,
        target_frame: str,
        target_time: Any,
        source_frame: str,
        source_time: Any,
        fixed_frame: str,
    ) -> tuple[bool, str]:
        """Return ``(possible, error_text)`` for the advanced API now, without waiting."""
        answer = BufferCore.can_transform_full(
            self,
            *_full_query(target_frame, target_time, source_frame, source_time, fixed_frame),
            return_debug_tuple=True,
        )
        return _debug_tuple(answer)

    # ------------------------------------------------------------------------ blocking API

    def lookup_transform(
        self, target_frame: str, source_frame: str, time: Any, timeout: Any = None
    ) -> Any:
        """
        Get the transform from the source frame to the target frame.

        :param target_frame: name of the frame to transform into.
        :param source_frame: name of the input frame.
        :param time: the time of the transform (0 means the latest common time).
        :param timeout: how long to wait for it, on the buffer's clock (default: no wait).
        :return: target_T_source as a ``TransformStamped``.
        :raises TransformException: the core's specific error when it is (still) unavailable.
        """
        time_ns = ns_from_time(time)
        self._wait_until(
            lambda: self.can_transform_core(target_frame, source_frame, time_ns)[0],
            ns_from_duration(timeout),
        )
        return self.lookup_transform_core(target_frame, source_frame, time_ns)

    def lookup_transform_full(  # noqa: PLR0917 - tf2_ros signature
        self,
        target_frame: str,
        target_time: Any,
        source_frame: str,
        source_time: Any,
        fixed_frame: str,
        timeout: Any = None,
    ) -> Any:
        """
        Get the transform between two frames at two times through a fixed frame.

        :return: the transform as a ``TransformStamped``.
        """
        query = _full_query(target_frame, target_time, source_frame, source_time, fixed_frame)
        self._wait_until(
            lambda: self.can_transform_full_core(*query)[0], ns_from_duration(timeout)
        )
        return self.lookup_transform_full_core(*query)

    def can_transform(  # type: ignore[override]
        self,
        target_frame: str,
        source_frame: str,
        time: Any,
        timeout: Any = None,
        return_debug_tuple: bool = False,
    ) -> bool | tuple[bool, str]:
        """
        Check whether the transform is possible, waiting up to ``timeout`` for it.

        :return: ``bool``, or ``(bool, error_text)`` when ``return_debug_tuple``.
        """
        time_ns = ns_from_time(time)
        self._wait_until(
            lambda: self.can_transform_core(target_frame, source_frame, time_ns)[0],
            ns_from_duration(timeout),
        )
        answer = self.can_transform_core(target_frame, source_frame, time_ns)
        return answer if return_debug_tuple else answer[0]

    def can_transform_full(  # type: ignore[override]  # noqa: PLR0917
        self,
        target_frame: str,
        target_time: Any,
        source_frame: str,
        source_time: Any,
        fixed_frame: str,
        timeout: Any = None,
        return_debug_tuple: bool = False,
    ) -> bool | tuple[bool, str]:
        """
        Check whether the advanced-API transform is possible, waiting up to ``timeout``.

        :return: ``bool``, or ``(bool, error_text)`` when ``return_debug_tuple``.
        """
        query = _full_query(target_frame, target_time, source_frame, source_time, fixed_frame)
        self._wait_until(
            lambda: self.can_transform_full_core(*query)[0], ns_from_duration(timeout)
        )
        answer = self.can_transform_full_core(*query)
        return answer if return_debug_tuple else answer[0]

    # --------------------------------------------------------------------------- async API

    def wait_for_transform_async(
        self, target_frame: str, source_frame: str, time: Any, timeout: Any = None
    ) -> Future[Any]:
        """
        Wait for a transform without blocking; the future resolves to the ``TransformStamped``.

        :param timeout: optional limit on the buffer's clock; then the future fails with
            ``TimeoutException``. ``None`` waits forever (upstream behaviour).
        :return: a future (rclpy ``Future`` API) resolving to target_T_source.
        """
        time_ns = ns_from_time(time)
        return self._wait_async(
            lambda: self.can_transform_core(target_frame, source_frame, time_ns)[0],
            lambda: self.lookup_transform_core(target_frame, source_frame, time_ns),
            timeout,
            f'Timed out waiting for transform from [{source_frame}] to [{target_frame}]',
        )

    def wait_for_transform_full_async(  # noqa: PLR0917 - tf2_ros signature
        self,
        target_frame: str,
        target_time: Any,
        source_frame: str,
        source_time: Any,
        fixed_frame: str,
        timeout: Any = None,
    ) -> Future[Any]:
        """
        Wait for an advanced-API transform without blocking; resolves to the transform.

        :return: a future resolving to the ``TransformStamped``.
        """
        query = _full_query(target_frame, target_time, source_frame, source_time, fixed_frame)
        return self._wait_async(
            lambda: self.can_transform_full_core(*query)[0],
            lambda: self.lookup_transform_full_core(*query),
            timeout,
            f'Timed out waiting for transform from [{source_frame}] to [{target_frame}] '
            f'via [{fixed_frame}]',
        )

    async def lookup_transform_async(
        self, target_frame: str, source_frame: str, time: Any, timeout: Any = None
    ) -> Any:
        """
        Await the transform from the source frame to the target frame (looked up once).

        :raises TimeoutException: when ``timeout`` passes first.
        """
        return await self.wait_for_transform_async(target_frame, source_frame, time, timeout)

    async def lookup_transform_full_async(  # noqa: PLR0917 - tf2_ros signature
        self,
        target_frame: str,
        target_time: Any,
        source_frame: str,
        source_time: Any,
        fixed_frame: str,
        timeout: Any = None,
    ) -> Any:
        """Await an advanced-API transform (looked up once)."""
        return await self.wait_for_transform_full_async(
            target_frame, target_time, source_frame, source_time, fixed_frame, timeout
        )

    def _wait_async(
        self,
        ready: Callable[[], bool],
        lookup: Callable[[], Any],
        timeout: Any,
        timeout_text: str,
    ) -> Future[Any]:
        future: Future[Any] = Future()
        if ready():
            _resolve(future, lookup)
            return future
        timeout_ns = ns_from_duration(timeout) if timeout is not None else None
        deadline_ns = None if timeout_ns is None else self._now_ns() + timeout_ns
        wait = _AsyncWait(ready, lookup, deadline_ns, future, timeout_text)
        wait.future.add_done_callback(lambda _: self._forget(wait))
        with self._condition:
            self._async_waits.append(wait)
            if deadline_ns is not None:
                self._ensure_watcher()
        # Data may have arrived between the first check and the registration.
        self._service_async_waits(now_ns=None)
        return future

    def _forget(self, wait: _AsyncWait) -> None:
        with self._condition:
            if wait in self._async_waits:
                self._async_waits.remove(wait)

    def _service_async_waits(self, now_ns: int | None) -> None:
        """Resolve ready waits; fail expired ones when ``now_ns`` is given."""
        with self._condition:
            pending = list(self._async_waits)
        for wait in pending:
            if wait.future.done():
                continue
            try:
                is_ready = wait.ready()
            except Exception as error:
                wait.future.set_exception(error)
                continue
            if is_ready:
                _resolve(wait.future, wait.lookup)
            elif _expired(wait, now_ns):
                wait.future.set_exception(TimeoutException(wait.timeout_text))

    def _ensure_watcher(self) -> None:
        """Start the deadline watcher thread if it is not running (caller holds the lock)."""
        if self._watcher is not None and self._watcher.is_alive():
            return
        self._watcher = threading.Thread(
            target=self._watch_deadlines, name='tf_demo_buffer_deadlines', daemon=True
        )
        self._watcher.start()

    def _watch_deadlines(self) -> None:
        """Fail asynchronous waits whose deadline passed on the buffer's clock."""
        while True:
            now_ns = self._now_ns()
            self._service_async_waits(now_ns)
            with self._condition:
                deadlines = [
                    w.deadline_ns
                    for w in self._async_waits
                    if w.deadline_ns is not None and not w.future.done()
                ]
                if not deadlines:
                    self._watcher = None
                    return
                remaining_ns = min(deadlines) - self._now_ns()
                if remaining_ns > 0:
                    self._condition.wait(min(remaining_ns / 1e9, MAX_WAIT_SLICE_S))

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
        self, object_stamped: Any, target_frame: str, timeout: Any = None, new_type: Any = None
    ) -> Any:
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
        transform = self.lookup_transform(
            target_frame, object_stamped.header.frame_id, object_stamped.header.stamp, timeout
        )
        return _check_new_type(function(object_stamped, transform), new_type)

    def transform_full(  # noqa: PLR0917 - tf2_ros signature
        self,
        object_stamped: Any,
        target_frame: str,
        target_time: Any,
        fixed_frame: str,
        timeout: Any = None,
        new_type: Any = None,
    ) -> Any:
        """Transform a stamped message to ``target_frame`` at ``target_time`` via a fixed frame."""
        function = self._transform_function(type(object_stamped))
        transform = self.lookup_transform_full(
            target_frame,
            target_time,
            object_stamped.header.frame_id,
            object_stamped.header.stamp,
            fixed_frame,
            timeout,
        )
        return _check_new_type(function(object_stamped, transform), new_type)

    # ------------------------------------------------------------------------ introspection

    def get_latest_common_time(self, target_frame: str, source_frame: str) -> Any:
        """Return the latest time at which both frames are connected, as a ``Time``."""
        from tf_demo.transport.clock import Time

        return Time(
            nanoseconds=BufferCore.get_latest_common_time(self, target_frame, source_frame)
        )

    def all_frames_as_yaml(self, current_time: Any = 0) -> str:
        """Return tf2's YAML description of every frame."""
        return BufferCore.all_frames_as_yaml(self, ns_from_time(current_time))

    def clear(self) -> None:
        """Forget all dynamic transforms (static ones stay), as tf2 does."""
        BufferCore.clear(self)
        self._wake()

    def _frameExists(self, frame_id: str) -> bool:  # noqa: N802 - tf2_py name
        return self.frame_exists(frame_id)

    def _getFrameStrings(self) -> list[str]:  # noqa: N802 - tf2_py name
        return self.frame_ids()

    def _allFramesAsDot(self, time: Any = 0) -> str:  # noqa: N802 - tf2_py name
        return self.all_frames_as_dot(ns_from_time(time))


def _create_frames_service(node: Any, buffer: Buffer) -> Any:
    """
    Offer tf2_ros's ``tf2_frames`` service (``tf2_msgs/srv/FrameGraph``) as tf2_ros does.

    ``ros2 run tf2_tools view_frames`` calls it. The service type is the world's (rclpy's
    ``tf2_msgs.srv`` inside ROS 2, ``tf_demo.msgs`` standalone); nodes without
    ``create_service`` simply do not offer it.
    """
    create_service = getattr(node, 'create_service', None)
    if create_service is None:
        return None
    from tf_demo.transport.messages import service_module

    frame_graph = service_module('tf2_msgs').FrameGraph

    def answer(_request: Any, _response: Any) -> Any:
        return frame_graph.Response(frame_yaml=buffer.all_frames_as_yaml())

    return create_service(frame_graph, 'tf2_frames', answer)


def _full_query(
    target_frame: str, target_time: Any, source_frame: str, source_time: Any, fixed_frame: str
) -> tuple[str, int, str, int, str]:
    """Return the core's advanced-API arguments, times in integer nanoseconds."""
    return (
        target_frame,
        ns_from_time(target_time),
        source_frame,
        ns_from_time(source_time),
        fixed_frame,
    )


def _debug_tuple(answer: bool | tuple[bool, str]) -> tuple[bool, str]:
    if isinstance(answer, tuple):
        return bool(answer[0]), str(answer[1])
    return bool(answer), ''


def _resolve(future: Future[Any], lookup: Callable[[], Any]) -> None:
    try:
        result = lookup()
    except Exception as error:
        future.set_exception(error)
    else:
        future.set_result(result)


def _expired(wait: _AsyncWait, now_ns: int | None) -> bool:
    return now_ns is not None and wait.deadline_ns is not None and now_ns >= wait.deadline_ns


def _check_new_type(result: Any, new_type: Any) -> Any:
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
