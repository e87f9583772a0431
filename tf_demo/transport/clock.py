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
Time, durations and clocks with the API and rules of ``rclpy.time``/``duration``/``clock``.

* :class:`Time` and :class:`Duration` hold integer nanoseconds; a ``Time`` carries the
  :class:`ClockType` that produced it and refuses to be compared with or subtracted from a time
  of another clock type (``TypeError``), exactly as rclpy.
* :class:`ROSClock` reports system time until ROS time is activated (``use_sim_time``); then it
  reports the last value given to :meth:`ROSClock.set_ros_time_override` (from ``/clock``).
  Jump callbacks fire as rcl fires them (``rcl/time.c``): on activation/deactivation when
  ``on_clock_change``, and on an override whose delta crosses a threshold.
* :meth:`Clock.sleep_until` waits on the clock itself, so it works in sim time.
* :class:`TimeSource` is what a standalone node uses to follow ``use_sim_time`` and ``/clock``.

In the rclpy world every public name here is rclpy's own object.
"""

from __future__ import annotations

from collections.abc import Callable
from enum import IntEnum
import sys
import threading
import time as _time
from typing import Any
from typing import Protocol
from typing import TYPE_CHECKING
import weakref

from tf_demo.transport.backend import rclpy_world

if TYPE_CHECKING:
    from tf_demo.transport.parameters import Parameter
    from tf_demo.transport.parameters import SetParametersResult

__all__ = [
    'CLOCK_TOPIC',
    'USE_SIM_TIME_NAME',
    'Clock',
    'ClockChange',
    'ClockType',
    'Duration',
    'Infinite',
    'JumpHandle',
    'JumpThreshold',
    'ROSClock',
    'Time',
    'TimeJump',
    'TimeSource',
]

S_TO_NS = 1_000_000_000
_INT64_MIN = -(2**63)
_INT64_LIMIT = 2**63
CLOCK_TOPIC = '/clock'
USE_SIM_TIME_NAME = 'use_sim_time'


class ClockType(IntEnum):
    """The kind of clock a time comes from (values as ``rcl_clock_type_t``)."""

    UNINITIALIZED = 0
    ROS_TIME = 1
    SYSTEM_TIME = 2
    STEADY_TIME = 3


class ClockChange(IntEnum):
    """What happened to a ROS clock in a time jump (values as ``rcl_clock_change_t``)."""

    ROS_TIME_NO_CHANGE = 1
    ROS_TIME_ACTIVATED = 2
    ROS_TIME_DEACTIVATED = 3
    SYSTEM_TIME_NO_CHANGE = 4


class Duration:
    """A signed span of time with nanosecond precision (``rclpy.duration.Duration``)."""

    __slots__ = ('_nanoseconds',)

    def __init__(self, *, seconds: float = 0, nanoseconds: float = 0) -> None:
        total = int(seconds * S_TO_NS) + int(nanoseconds)
        if not _INT64_MIN <= total < _INT64_LIMIT:
            msg = 'Total nanoseconds value is too large to store in C duration.'
            raise OverflowError(msg)
        self._nanoseconds = total

    @property
    def nanoseconds(self) -> int:
        """The span in integer nanoseconds."""
        return self._nanoseconds

    def __repr__(self) -> str:
        return f'Duration(nanoseconds={self._nanoseconds})'

    def __str__(self) -> str:
        if self._nanoseconds == _INT64_LIMIT - 1:
            return 'Infinite'
        return f'{self._nanoseconds} nanoseconds'

    def __eq__(self, other: object) -> bool:
        if isinstance(other, Duration):
            return self._nanoseconds == other._nanoseconds
        return NotImplemented

    def __ne__(self, other: object) -> bool:
        if isinstance(other, Duration):
            return self._nanoseconds != other._nanoseconds
        return NotImplemented

    def __lt__(self, other: object) -> bool:
        if isinstance(other, Duration):
            return self._nanoseconds < other._nanoseconds
        return NotImplemented

    def __le__(self, other: object) -> bool:
        if isinstance(other, Duration):
            return self._nanoseconds <= other._nanoseconds
        return NotImplemented

    def __gt__(self, other: object) -> bool:
        if isinstance(other, Duration):
            return self._nanoseconds > other._nanoseconds
        return NotImplemented

    def __ge__(self, other: object) -> bool:
        if isinstance(other, Duration):
            return self._nanoseconds >= other._nanoseconds
        return NotImplemented

    __hash__ = None  # type: ignore[assignment]  # rclpy's Duration is unhashable too

    def to_msg(self) -> Any:
        """Return a ``builtin_interfaces/msg/Duration`` message (``sec`` from divmod)."""
        from tf_demo.msgs import builtin_interfaces

        sec, nanosec = divmod(self._nanoseconds, S_TO_NS)
        return builtin_interfaces.Duration(sec=sec, nanosec=nanosec)

    @classmethod
    def from_msg(cls, msg: Any) -> Duration:
        """Build a Duration from a ``builtin_interfaces/msg/Duration`` (either world's class)."""
        if not _looks_like_stamp(msg):
            msg_text = 'Must pass a builtin_interfaces.msg.Duration object'
            raise TypeError(msg_text)
        return cls(seconds=msg.sec, nanoseconds=msg.nanosec)


Infinite = Duration(nanoseconds=_INT64_LIMIT - 1)


def _looks_like_stamp(msg: object) -> bool:
    """Whether ``msg`` has integer ``sec`` and ``nanosec`` fields (a Time or Duration message)."""
    return isinstance(getattr(msg, 'sec', None), int) and isinstance(
        getattr(msg, 'nanosec', None), int
    )


def _check_clock_type(clock_type: object) -> ClockType:
    if not isinstance(clock_type, ClockType):
        msg = 'Clock type must be a ClockType enum'
        raise TypeError(msg)
    return clock_type


class Time:
    """A point in time of one clock type, in non-negative nanoseconds (``rclpy.time.Time``)."""

    __slots__ = ('_clock_type', '_nanoseconds')

    def __init__(
        self,
        *,
        seconds: float = 0,
        nanoseconds: float = 0,
        clock_type: ClockType = ClockType.SYSTEM_TIME,
    ) -> None:
        self._clock_type = _check_clock_type(clock_type)
        if seconds < 0:
            msg = 'Seconds value must not be negative'
            raise ValueError(msg)
        if nanoseconds < 0:
            msg = 'Nanoseconds value must not be negative'
            raise ValueError(msg)
        total = int(seconds * S_TO_NS) + int(nanoseconds)
        if total >= _INT64_LIMIT:
            msg = 'Total nanoseconds value is too large to store in C time point.'
            raise OverflowError(msg)
        self._nanoseconds = total

    @property
    def nanoseconds(self) -> int:
        """Nanoseconds since the clock's epoch."""
        return self._nanoseconds

    @property
    def clock_type(self) -> ClockType:
        """The type of clock that produced this time."""
        return self._clock_type

    def seconds_nanoseconds(self) -> tuple[int, int]:
        """Return ``(seconds, nanoseconds)`` with ``0 <= nanoseconds < 10**9``."""
        return divmod(self._nanoseconds, S_TO_NS)

    def __repr__(self) -> str:
        return f'Time(nanoseconds={self._nanoseconds}, clock_type={self._clock_type.name})'

    def __add__(self, other: object) -> Time:
        if isinstance(other, Duration):
            try:
                return Time(
                    nanoseconds=self._nanoseconds + other.nanoseconds,
                    clock_type=self._clock_type,
                )
            except OverflowError as error:
                msg = 'Addition leads to overflow in C storage.'
                raise OverflowError(msg) from error
        return NotImplemented

    def __radd__(self, other: object) -> Time:
        return self.__add__(other)

    def __sub__(self, other: object) -> Any:
        if isinstance(other, Time):
            if self._clock_type != other._clock_type:
                msg = "Can't subtract times with different clock types"
                raise TypeError(msg)
            return Duration(nanoseconds=self._nanoseconds - other._nanoseconds)
        if isinstance(other, Duration):
            try:
                return Time(
                    nanoseconds=self._nanoseconds - other.nanoseconds,
                    clock_type=self._clock_type,
                )
            except ValueError as error:
                msg = 'Subtraction leads to negative time.'
                raise ValueError(msg) from error
        return NotImplemented

    def _comparable(self, other: Time) -> None:
        if self._clock_type != other._clock_type:
            msg = "Can't compare times with different clock types"
            raise TypeError(msg)

    def __eq__(self, other: object) -> bool:
        if isinstance(other, Time):
            self._comparable(other)
            return self._nanoseconds == other._nanoseconds
        return NotImplemented

    def __ne__(self, other: object) -> bool:
        if isinstance(other, Time):
            return not self.__eq__(other)
        return NotImplemented

    def __lt__(self, other: object) -> bool:
        if isinstance(other, Time):
            self._comparable(other)
            return self._nanoseconds < other._nanoseconds
        return NotImplemented

    def __le__(self, other: object) -> bool:
        if isinstance(other, Time):
            self._comparable(other)
            return self._nanoseconds <= other._nanoseconds
        return NotImplemented

    def __gt__(self, other: object) -> bool:
        if isinstance(other, Time):
            self._comparable(other)
            return self._nanoseconds > other._nanoseconds
        return NotImplemented

    def __ge__(self, other: object) -> bool:
        if isinstance(other, Time):
            self._comparable(other)
            return self._nanoseconds >= other._nanoseconds
        return NotImplemented

    __hash__ = None  # type: ignore[assignment]  # rclpy's Time is unhashable too

    def to_msg(self) -> Any:
        """Return a ``builtin_interfaces/msg/Time`` message."""
        from tf_demo.msgs import builtin_interfaces

        sec, nanosec = self.seconds_nanoseconds()
        return builtin_interfaces.Time(sec=sec, nanosec=nanosec)

    @classmethod
    def from_msg(cls, msg: Any, clock_type: ClockType = ClockType.ROS_TIME) -> Time:
        """Build a Time from a ``builtin_interfaces/msg/Time`` (either world's class)."""
        if not _looks_like_stamp(msg):
            text = 'Must pass a builtin_interfaces.msg.Time object'
            raise TypeError(text)
        return cls(seconds=msg.sec, nanoseconds=msg.nanosec, clock_type=clock_type)


class JumpThreshold:
    """When a clock jump is reported to a callback (``rclpy.clock.JumpThreshold``)."""

    def __init__(
        self,
        *,
        min_forward: Duration | None,
        min_backward: Duration | None,
        on_clock_change: bool = True,
    ) -> None:
        if min_forward is not None and min_forward.nanoseconds <= 0:
            msg = 'min_forward must be a positive non-zero duration'
            raise ValueError(msg)
        if min_backward is not None and min_backward.nanoseconds >= 0:
            msg = 'min_backward must be a negative non-zero duration'
            raise ValueError(msg)
        if min_forward is None and min_backward is None and not on_clock_change:
            msg = 'At least one jump threshold must be enabled'
            raise ValueError(msg)
        self.min_forward = min_forward
        self.min_backward = min_backward
        self.on_clock_change = on_clock_change

    def is_exceeded(self, clock_change: ClockChange, delta_ns: int) -> bool:
        """Whether a jump of ``delta_ns`` with ``clock_change`` crosses this threshold (rcl)."""
        is_clock_change = clock_change in (
            ClockChange.ROS_TIME_ACTIVATED,
            ClockChange.ROS_TIME_DEACTIVATED,
        )
        if is_clock_change and self.on_clock_change:
            return True
        if self.min_backward is not None and delta_ns <= self.min_backward.nanoseconds:
            return True
        return self.min_forward is not None and delta_ns >= self.min_forward.nanoseconds


class TimeJump:
    """A clock jump as passed to a post-jump callback."""

    def __init__(self, clock_change: ClockChange, delta: Duration) -> None:
        if not isinstance(clock_change, ClockChange):
            msg = 'clock_change must be an instance of rclpy.clock.ClockChange'
            raise TypeError(msg)
        self._clock_change = clock_change
        self._delta = delta

    @property
    def clock_change(self) -> ClockChange:
        """Whether ROS time was activated, deactivated or unchanged."""
        return self._clock_change

    @property
    def delta(self) -> Duration:
        """The size of the jump (new time minus old time)."""
        return self._delta

    def __repr__(self) -> str:
        return f'TimeJump(clock_change={self._clock_change.name}, delta={self._delta!r})'


class JumpHandle:
    """A registered jump callback; :meth:`unregister` removes it."""

    def __init__(
        self,
        *,
        clock: Clock,
        threshold: JumpThreshold,
        pre_callback: Callable[[], None] | None,
        post_callback: Callable[[TimeJump], None] | None,
    ) -> None:
        if pre_callback is None and post_callback is None:
            msg = 'One of pre_callback or post_callback must be callable'
            raise ValueError(msg)
        if pre_callback is not None and not callable(pre_callback):
            msg = 'pre_callback must be callable if given'
            raise ValueError(msg)
        if post_callback is not None and not callable(post_callback):
            msg = 'post_callback must be callable if given'
            raise ValueError(msg)
        self._clock: Clock | None = clock
        self.threshold = threshold
        self.pre_callback = pre_callback
        self.post_callback = post_callback
        clock._add_jump_handle(self)

    def unregister(self) -> None:
        """Remove the callback from its clock (idempotent)."""
        if self._clock is not None:
            self._clock._remove_jump_handle(self)
            self._clock = None

    def __enter__(self) -> JumpHandle:
        return self

    def __exit__(self, *exc_info: object) -> None:
        self.unregister()


class _Context(Protocol):
    def ok(self) -> bool: ...


def _default_context() -> _Context | None:
    """Return the standalone backend's context when it is loaded and initialised, else None."""
    backend = sys.modules.get('tf_demo.transport.dds_backend')
    if backend is not None and backend.ok():
        return backend
    return None


class Clock:
    """
    A clock of one :class:`ClockType`; ``Clock(clock_type=ClockType.ROS_TIME)`` is a ROSClock.

    ``now()`` reads the system clock (``time.time_ns``), the steady clock
    (``time.monotonic_ns``) or, for an active ROS clock, the last override.
    """

    _clock_type: ClockType
    _condition: threading.Condition
    _jump_handles: list[JumpHandle]
    _ros_time_active: bool
    _ros_time_ns: int

    def __new__(cls, *, clock_type: ClockType = ClockType.SYSTEM_TIME) -> Clock:
        _check_clock_type(clock_type)
        if clock_type is ClockType.UNINITIALIZED:
            msg = 'Clock type must not be UNINITIALIZED'
            raise ValueError(msg)
        target = ROSClock if clock_type is ClockType.ROS_TIME else cls
        self = object.__new__(target)
        self._clock_type = clock_type
        self._condition = threading.Condition(threading.RLock())
        self._jump_handles = []
        self._ros_time_active = False
        self._ros_time_ns = 0
        return self

    def __init__(self, *, clock_type: ClockType = ClockType.SYSTEM_TIME) -> None:
        """Nothing to do: ``__new__`` has built the clock."""

    @property
    def clock_type(self) -> ClockType:
        """The type of this clock."""
        return self._clock_type

    def __repr__(self) -> str:
        return f'Clock(clock_type={self._clock_type.name})'

    def _now_ns(self) -> int:
        if self._clock_type is ClockType.STEADY_TIME:
            return _time.monotonic_ns()
        if self._ros_time_active:
            return self._ros_time_ns
        return _time.time_ns()

    def now(self) -> Time:
        """Return the current time of this clock."""
        return Time(nanoseconds=self._now_ns(), clock_type=self._clock_type)

    def create_jump_callback(
        self,
        threshold: JumpThreshold,
        *,
        pre_callback: Callable[[], None] | None = None,
        post_callback: Callable[[TimeJump], None] | None = None,
    ) -> JumpHandle:
        """
        Register callbacks run before and after a time jump that crosses ``threshold``.

        :return: a handle whose ``unregister()`` removes the callbacks.
        """
        return JumpHandle(
            clock=self,
            threshold=threshold,
            pre_callback=pre_callback,
            post_callback=post_callback,
        )

    def _add_jump_handle(self, handle: JumpHandle) -> None:
        with self._condition:
            self._jump_handles.append(handle)

    def _remove_jump_handle(self, handle: JumpHandle) -> None:
        with self._condition:
            if handle in self._jump_handles:
                self._jump_handles.remove(handle)

    def _call_jump_callbacks(
        self, clock_change: ClockChange, delta_ns: int, *, before_jump: bool
    ) -> None:
        with self._condition:
            handles = list(self._jump_handles)
        for handle in handles:
            if not handle.threshold.is_exceeded(clock_change, delta_ns):
                continue
            if before_jump and handle.pre_callback is not None:
                handle.pre_callback()
            elif not before_jump and handle.post_callback is not None:
                handle.post_callback(TimeJump(clock_change, Duration(nanoseconds=delta_ns)))

    def _wake_sleepers(self) -> None:
        with self._condition:
            self._condition.notify_all()

    def sleep_until(self, until: Time, context: _Context | None = None) -> bool:
        """
        Sleep until this clock reaches ``until``; in sim time, until ``/clock`` gets there.

        :param context: anything with ``ok()``; the sleep ends early when it turns false.
            ``None``: the standalone backend's process context, when it has been initialised.
        :raises ValueError: when ``until`` is of another clock type (rclpy's text).
        :return: True when ``until`` was reached, False when woken by shutdown or by ROS time
            being activated or deactivated.
        """
        if not isinstance(until, Time):
            msg = f'until must be a Time, not {type(until).__name__}'
            raise TypeError(msg)
        if until.clock_type != self._clock_type:
            msg = "until's clock type does not match this clock's type"
            raise ValueError(msg)
        if context is None:
            context = _default_context()
        with self._condition:
            active_at_start = self._ros_time_active
            while True:
                if context is not None and not context.ok():
                    return False
                if self._ros_time_active != active_at_start:
                    return False
                remaining_ns = until.nanoseconds - self._now_ns()
                if remaining_ns <= 0:
                    return True
                # Sim time advances only through overrides, which notify; wall clocks are
                # waited on directly. The cap keeps a shutdown of `context` noticed.
                wait_s = 0.1 if self._ros_time_active else min(remaining_ns / S_TO_NS, 0.1)
                self._condition.wait(wait_s)

    def sleep_for(self, rel_time: Duration, context: _Context | None = None) -> bool:
        """Sleep for ``rel_time`` of this clock (see :meth:`sleep_until`)."""
        return self.sleep_until(self.now() + rel_time, context)


class ROSClock(Clock):
    """The ROS time clock: system time, or the ``/clock`` time while ROS time is active."""

    def __new__(cls) -> ROSClock:
        clock = Clock.__new__(Clock, clock_type=ClockType.ROS_TIME)
        assert isinstance(clock, ROSClock)
        return clock

    def __init__(self, *, clock_type: ClockType = ClockType.ROS_TIME) -> None:
        """Nothing to do: ``__new__`` has built the clock (``clock_type`` comes from Clock)."""

    @property
    def ros_time_is_active(self) -> bool:
        """Whether the clock reports the overridden (simulated) time."""
        return self._ros_time_active

    def _set_ros_time_is_active(self, enabled: bool) -> None:
        """Activate or deactivate ROS time; called by the TimeSource that manages the clock."""
        with self._condition:
            if enabled == self._ros_time_active:
                return
            change = (
                ClockChange.ROS_TIME_ACTIVATED if enabled else ClockChange.ROS_TIME_DEACTIVATED
            )
        self._call_jump_callbacks(change, 0, before_jump=True)
        with self._condition:
            self._ros_time_active = bool(enabled)
        self._call_jump_callbacks(change, 0, before_jump=False)
        self._wake_sleepers()

    def set_ros_time_override(self, time: Time) -> None:
        """Set the time reported while ROS time is active (the latest ``/clock`` value)."""
        if not isinstance(time, Time):
            msg = f'Time must be specified as rclpy.time.Time. Received type: {type(time)}'
            raise TypeError(msg)
        with self._condition:
            active = self._ros_time_active
            delta_ns = time.nanoseconds - self._ros_time_ns
        if active:
            self._call_jump_callbacks(ClockChange.ROS_TIME_NO_CHANGE, delta_ns, before_jump=True)
        with self._condition:
            self._ros_time_ns = time.nanoseconds
        if active:
            self._call_jump_callbacks(ClockChange.ROS_TIME_NO_CHANGE, delta_ns, before_jump=False)
        self._wake_sleepers()


class _TimeSourceNode(Protocol):
    """What :class:`TimeSource` needs from a node (a subset of ``rclpy.node.Node``)."""

    def has_parameter(self, name: str) -> bool: ...

    def declare_parameter(self, name: str, value: Any = None) -> Any: ...

    def get_parameter(self, name: str) -> Any: ...

    def add_on_set_parameters_callback(
        self, callback: Callable[[list[Parameter]], SetParametersResult]
    ) -> None: ...

    def create_subscription(self, msg_type: Any, topic: str, callback: Any, qos: Any) -> Any: ...

    def destroy_subscription(self, subscription: Any) -> Any: ...

    def get_logger(self) -> Any: ...


class TimeSource:
    """
    Follows ``use_sim_time`` and ``/clock`` for the ROS clocks of a node (``rclpy.time_source``).

    When ``use_sim_time`` is true it subscribes to ``/clock`` (KEEP_LAST 1, BEST_EFFORT) and
    feeds every attached :class:`ROSClock`; when it turns false it unsubscribes and the clocks
    return to system time.
    """

    def __init__(self, *, node: _TimeSourceNode | None = None) -> None:
        self._node_ref: weakref.ReferenceType[Any] | None = None
        self._clock_subscription: Any = None
        self._clocks: weakref.WeakSet[ROSClock] = weakref.WeakSet()
        self._last_time_set: Time | None = None
        self._ros_time_is_active = False
        if node is not None:
            self.attach_node(node)

    @property
    def ros_time_is_active(self) -> bool:
        """Whether the attached clocks report ``/clock`` time."""
        return self._ros_time_is_active

    @ros_time_is_active.setter
    def ros_time_is_active(self, enabled: bool) -> None:
        if self._ros_time_is_active == enabled:
            return
        self._ros_time_is_active = enabled
        for clock in list(self._clocks):
            clock._set_ros_time_is_active(enabled)
        if enabled:
            self._subscribe_to_clock_topic()
        else:
            node = self._node()
            if self._clock_subscription is not None and node is not None:
                node.destroy_subscription(self._clock_subscription)
            self._clock_subscription = None

    def _node(self) -> Any:
        return self._node_ref() if self._node_ref is not None else None

    def _subscribe_to_clock_topic(self) -> None:
        node = self._node()
        if self._clock_subscription is not None or node is None:
            return
        from tf_demo.msgs import rosgraph_msgs
        from tf_demo.transport.qos import QoSProfile
        from tf_demo.transport.qos import ReliabilityPolicy

        self._clock_subscription = node.create_subscription(
            rosgraph_msgs.Clock,
            CLOCK_TOPIC,
            self.clock_callback,
            QoSProfile(depth=1, reliability=ReliabilityPolicy.BEST_EFFORT),
        )

    def attach_node(self, node: _TimeSourceNode) -> None:
        """Declare ``use_sim_time`` on ``node`` (if needed) and follow its value."""
        from tf_demo.transport.parameters import Parameter

        self._node_ref = weakref.ref(node)
        if not node.has_parameter(USE_SIM_TIME_NAME):
            node.declare_parameter(USE_SIM_TIME_NAME, False)
        parameter = node.get_parameter(USE_SIM_TIME_NAME)
        if parameter.type_ == Parameter.Type.BOOL:
            self.ros_time_is_active = parameter.value
        elif parameter.type_ != Parameter.Type.NOT_SET:
            node.get_logger().error(
                f"Invalid type for parameter '{USE_SIM_TIME_NAME}' {parameter.type_!r} "
                'should be bool'
            )
        node.add_on_set_parameters_callback(self._on_parameter_event)

    def detach_node(self) -> None:
        """Stop following the node (unsubscribes from ``/clock``)."""
        node = self._node()
        if self._clock_subscription is not None and node is not None:
            node.destroy_subscription(self._clock_subscription)
        self._clock_subscription = None
        self._node_ref = None

    def attach_clock(self, clock: ROSClock) -> None:
        """Drive ``clock`` from this source."""
        if not isinstance(clock, ROSClock):
            msg = 'Only clocks with type ROS_TIME can be attached.'
            raise ValueError(msg)
        if self._last_time_set is not None:
            clock.set_ros_time_override(self._last_time_set)
        clock._set_ros_time_is_active(self._ros_time_is_active)
        self._clocks.add(clock)

    def clock_callback(self, msg: Any) -> None:
        """Take the time of one ``rosgraph_msgs/msg/Clock`` message."""
        now = Time.from_msg(msg.clock)
        self._last_time_set = now
        for clock in list(self._clocks):
            clock.set_ros_time_override(now)

    def _on_parameter_event(self, parameters: list[Parameter]) -> SetParametersResult:
        from tf_demo.transport.parameters import Parameter
        from tf_demo.transport.parameters import SetParametersResult

        for parameter in parameters:
            if parameter.name != USE_SIM_TIME_NAME:
                continue
            if parameter.type_ != Parameter.Type.BOOL:
                reason = f'{USE_SIM_TIME_NAME} parameter set to something besides a bool'
                node = self._node()
                if node is not None:
                    node.get_logger().error(reason)
                return SetParametersResult(successful=False, reason=reason)
            self.ros_time_is_active = parameter.value
            break
        return SetParametersResult(successful=True)


if rclpy_world():  # pragma: no cover - needs a ROS 2 installation
    from tf_demo.transport import rclpy_backend as _rclpy_backend

    globals().update(_rclpy_backend.clock_exports())
