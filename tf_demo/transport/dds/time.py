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
Times and durations with the API and rules of ``rclpy.time`` and ``rclpy.duration``.

:class:`Time` and :class:`Duration` hold integer nanoseconds; a ``Time`` carries the
:class:`ClockType` that produced it and refuses to be compared with or subtracted from a time of
another clock type (``TypeError``), exactly as rclpy. The standalone world's classes; the rclpy
world uses rclpy's own (:mod:`tf_demo.transport.clock` chooses).
"""

from __future__ import annotations

from enum import IntEnum
from typing import overload

from tf_demo.msgs import builtin_interfaces
from tf_demo.msgs.convert import StampLike

__all__ = ['S_TO_NS', 'ClockChange', 'ClockType', 'Duration', 'Infinite', 'Time']

S_TO_NS = 1_000_000_000
_INT64_MIN = -(2**63)
_INT64_LIMIT = 2**63


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

    def to_msg(self) -> builtin_interfaces.Duration:
        """Return a ``builtin_interfaces/msg/Duration`` message (``sec`` from divmod)."""
        sec, nanosec = divmod(self._nanoseconds, S_TO_NS)
        return builtin_interfaces.Duration(sec=sec, nanosec=nanosec)

    @classmethod
    def from_msg(cls, msg: StampLike) -> Duration:
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

    @overload
    def __sub__(self, other: Time) -> Duration: ...

    @overload
    def __sub__(self, other: Duration) -> Time: ...

    def __sub__(self, other: object) -> Duration | Time:
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

    def to_msg(self) -> builtin_interfaces.Time:
        """Return a ``builtin_interfaces/msg/Time`` message."""
        sec, nanosec = self.seconds_nanoseconds()
        return builtin_interfaces.Time(sec=sec, nanosec=nanosec)

    @classmethod
    def from_msg(cls, msg: StampLike, clock_type: ClockType = ClockType.ROS_TIME) -> Time:
        """Build a Time from a ``builtin_interfaces/msg/Time`` (either world's class)."""
        if not _looks_like_stamp(msg):
            text = 'Must pass a builtin_interfaces.msg.Time object'
            raise TypeError(text)
        return cls(seconds=msg.sec, nanoseconds=msg.nanosec, clock_type=clock_type)
