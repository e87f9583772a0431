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
Clocks with the API and rules of ``rclpy.clock``.

:class:`ROSClock` reports system time until ROS time is activated (``use_sim_time``); then it
reports the last value given to :meth:`ROSClock.set_ros_time_override` (from ``/clock``). Jump
callbacks fire as rcl fires them (``rcl/time.c``): on activation/deactivation when
``on_clock_change``, and on an override whose delta crosses a threshold.
:meth:`Clock.sleep_until` waits on the clock itself, so it works in sim time. The standalone
world's classes; the rclpy world uses rclpy's own.
"""

from __future__ import annotations

from collections.abc import Callable
import sys
import threading
import time as _time
from typing import Protocol

from tf_demo.transport.dds.time import _check_clock_type
from tf_demo.transport.dds.time import ClockChange
from tf_demo.transport.dds.time import ClockType
from tf_demo.transport.dds.time import Duration
from tf_demo.transport.dds.time import S_TO_NS
from tf_demo.transport.dds.time import Time

__all__ = ['Clock', 'JumpHandle', 'JumpThreshold', 'ROSClock', 'TimeJump']


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
