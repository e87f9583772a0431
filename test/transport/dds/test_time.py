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

"""Time and Duration follow rclpy's rules (rclpy/test/test_time.py), in both worlds."""

from hypothesis import given
from hypothesis import strategies as st
import pytest
from tf_demo.transport.clock import ClockType
from tf_demo.transport.clock import Duration
from tf_demo.transport.clock import Infinite
from tf_demo.transport.clock import Time
from tf_demo.transport.messages import builtin_interfaces

ROS = ClockType.ROS_TIME


def test_time_holds_integer_nanoseconds_from_seconds_and_nanoseconds() -> None:
    """Seconds (with fraction) and nanoseconds add up to integer nanoseconds."""
    t = Time(seconds=1.5, nanoseconds=7, clock_type=ROS)
    assert t.nanoseconds == 1_500_000_007
    assert t.seconds_nanoseconds() == (1, 500_000_007)
    assert t.clock_type == ROS
    assert repr(t) == 'Time(nanoseconds=1500000007, clock_type=ROS_TIME)'


def test_time_rejects_negative_values_and_int64_overflow() -> None:
    """Negative seconds/nanoseconds raise ValueError; 2**63 ns raises OverflowError."""
    with pytest.raises(ValueError, match='Seconds value must not be negative'):
        Time(seconds=-1)
    with pytest.raises(ValueError, match='Nanoseconds value must not be negative'):
        Time(nanoseconds=-1)
    with pytest.raises(OverflowError):
        Time(nanoseconds=2**63)
    assert Time(nanoseconds=2**63 - 1).nanoseconds == 2**63 - 1


def test_time_requires_a_clock_type_enum() -> None:
    """A clock type that is not a ClockType raises TypeError with rclpy's text."""
    with pytest.raises(TypeError, match='Clock type must be a ClockType enum'):
        Time(clock_type=1)  # type: ignore[arg-type]


def test_time_arithmetic_with_durations() -> None:
    """Time ± Duration is a Time of the same clock; Time - Time is a (signed) Duration."""
    t = Time(seconds=10, clock_type=ROS)
    assert (t + Duration(seconds=2)).nanoseconds == 12 * 10**9
    assert (Duration(seconds=2) + t).clock_type == ROS
    assert (t - Duration(seconds=3)).nanoseconds == 7 * 10**9
    assert (Time(seconds=1, clock_type=ROS) - t) == Duration(seconds=-9)
    with pytest.raises(ValueError, match='Subtraction leads to negative time'):
        t - Duration(seconds=11)
    with pytest.raises(OverflowError, match='Addition leads to overflow'):
        Time(nanoseconds=2**63 - 1) + Duration(nanoseconds=1)


def test_times_of_different_clock_types_do_not_mix() -> None:
    """Comparing or subtracting times of different clock types raises TypeError."""
    ros = Time(seconds=1, clock_type=ROS)
    system = Time(seconds=1, clock_type=ClockType.SYSTEM_TIME)
    with pytest.raises(TypeError, match="Can't compare times with different clock types"):
        _ = ros == system
    with pytest.raises(TypeError, match="Can't compare times with different clock types"):
        _ = ros < system
    with pytest.raises(TypeError, match="Can't subtract times with different clock types"):
        _ = ros - system


def test_time_and_duration_refuse_foreign_operands() -> None:
    """Arithmetic with ints raises TypeError and equality with other types is False."""
    with pytest.raises(TypeError):
        _ = Time(seconds=1) + 1
    with pytest.raises(TypeError):
        _ = Duration(seconds=1) < 1
    assert Duration(seconds=1) != 1_000_000_000
    assert Time(seconds=1) != 1_000_000_000


def test_duration_is_signed_and_bounded_to_int64() -> None:
    """Durations may be negative; outside int64 they raise OverflowError."""
    assert Duration(seconds=-1.5).nanoseconds == -1_500_000_000
    with pytest.raises(OverflowError):
        Duration(nanoseconds=2**63)
    with pytest.raises(OverflowError):
        Duration(nanoseconds=-(2**63) - 1)
    assert Duration(nanoseconds=-(2**63)).nanoseconds == -(2**63)
    assert str(Infinite) == 'Infinite'
    # rclpy Jazzy's Duration has no arithmetic of its own (Time +/- Duration does the work)
    with pytest.raises(TypeError):
        _ = Duration(seconds=2) * 3  # type: ignore[operator]
    with pytest.raises(TypeError):
        _ = Duration(seconds=2) + Duration(seconds=1)  # type: ignore[operator]


def test_messages_round_trip_with_divmod_semantics() -> None:
    """to_msg uses divmod (negative durations keep 0 <= nanosec < 1e9); from_msg inverts it."""
    msg = Duration(seconds=-1.5).to_msg()
    assert (msg.sec, msg.nanosec) == (-2, 500_000_000)
    assert Duration.from_msg(msg) == Duration(seconds=-1.5)
    stamp = Time(seconds=3, nanoseconds=4, clock_type=ROS).to_msg()
    assert isinstance(stamp, builtin_interfaces.Time)
    assert (stamp.sec, stamp.nanosec) == (3, 4)
    back = Time.from_msg(stamp)
    assert back.clock_type == ROS
    assert back == Time(seconds=3, nanoseconds=4, clock_type=ROS)
    with pytest.raises(TypeError, match=r'Must pass a builtin_interfaces\.msg\.Time object'):
        Time.from_msg(object())  # type: ignore[arg-type]  # the refusal is tested


INT64 = st.integers(min_value=-(2**63), max_value=2**63 - 1)
TIME_NS = st.integers(min_value=0, max_value=2**63 - 1)


@pytest.mark.property
@given(INT64)
def test_duration_message_round_trip_for_every_int64(nanoseconds: int) -> None:
    """Duration -> message -> Duration is the identity, with 0 <= nanosec < 1e9."""
    msg = Duration(nanoseconds=nanoseconds).to_msg()
    assert 0 <= msg.nanosec < 10**9
    assert msg.sec * 10**9 + msg.nanosec == nanoseconds
    assert Duration.from_msg(msg).nanoseconds == nanoseconds


@pytest.mark.property
@given(TIME_NS, st.integers(min_value=0, max_value=2**62))
def test_adding_then_subtracting_a_duration_is_the_identity(start: int, step: int) -> None:
    """(t + d) - d == t and (t + d) - t == d whenever t + d fits in int64."""
    t = Time(nanoseconds=start, clock_type=ROS)
    d = Duration(nanoseconds=step)
    if start + step >= 2**63:
        with pytest.raises(OverflowError):
            _ = t + d
        return
    assert (t + d) - d == t
    assert (t + d) - t == d
    assert t <= t + d
