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

"""Clocks, jump callbacks and sleeps follow rclpy's rules (rclpy test_clock.py), in both worlds."""

import threading

import pytest
from tf_demo.transport.clock import Clock
from tf_demo.transport.clock import ClockChange
from tf_demo.transport.clock import ClockType
from tf_demo.transport.clock import Duration
from tf_demo.transport.clock import JumpThreshold
from tf_demo.transport.clock import ROSClock
from tf_demo.transport.clock import Time
from tf_demo.transport.clock import TimeJump
from tf_demo.transport.clock import TimeSource

ROS = ClockType.ROS_TIME


def sim_time_source(clock: ROSClock) -> TimeSource:
    """A node-less TimeSource driving ``clock``: rclpy's public way to switch ROS time on/off."""
    source = TimeSource()
    source.attach_clock(clock)
    return source


def test_clock_with_ros_time_type_is_a_ros_clock() -> None:
    """Clock(clock_type=ROS_TIME) builds a ROSClock, as in rclpy."""
    assert isinstance(Clock(clock_type=ROS), ROSClock)
    assert isinstance(ROSClock(), ROSClock)
    assert not isinstance(Clock(), ROSClock)
    assert Clock(clock_type=ClockType.STEADY_TIME).now().clock_type == ClockType.STEADY_TIME


def test_ros_clock_reports_the_override_only_while_ros_time_is_active() -> None:
    """An inactive ROS clock reads system time; active, it reads the last override."""
    clock = ROSClock()
    source = sim_time_source(clock)
    clock.set_ros_time_override(Time(seconds=5, clock_type=ROS))
    system_now = Clock().now().nanoseconds
    assert clock.now().nanoseconds >= system_now
    source.ros_time_is_active = True
    assert clock.ros_time_is_active
    assert clock.now() == Time(seconds=5, clock_type=ROS)
    clock.set_ros_time_override(Time(seconds=7, clock_type=ROS))
    assert clock.now() == Time(seconds=7, clock_type=ROS)
    source.ros_time_is_active = False
    assert clock.now().nanoseconds >= system_now


def test_jump_callbacks_fire_as_rcl_fires_them() -> None:
    """Activation fires on_clock_change callbacks; overrides fire past the thresholds only."""
    clock = ROSClock()
    source = sim_time_source(clock)
    changes: list[TimeJump] = []
    backward: list[TimeJump] = []
    pre_calls: list[int] = []
    # Keep every handle: under rclpy a dropped JumpHandle leaves rcl a dangling callback.
    changes_handle = clock.create_jump_callback(
        JumpThreshold(min_forward=None, min_backward=None, on_clock_change=True),
        post_callback=changes.append,
    )
    handle = clock.create_jump_callback(
        JumpThreshold(min_forward=None, min_backward=Duration(seconds=-1), on_clock_change=False),
        pre_callback=lambda: pre_calls.append(clock.now().nanoseconds),
        post_callback=backward.append,
    )
    source.ros_time_is_active = True
    clock.set_ros_time_override(Time(seconds=10, clock_type=ROS))
    clock.set_ros_time_override(Time(seconds=9.5, clock_type=ROS))
    clock.set_ros_time_override(Time(seconds=8, clock_type=ROS))
    assert [jump.clock_change for jump in changes] == [ClockChange.ROS_TIME_ACTIVATED]
    assert [jump.delta for jump in backward] == [Duration(seconds=-1.5)]
    assert pre_calls == [9_500_000_000]  # the pre-callback sees the time before the jump
    handle.unregister()
    clock.set_ros_time_override(Time(seconds=1, clock_type=ROS))
    assert len(backward) == 1
    source.ros_time_is_active = False
    assert changes[-1].clock_change == ClockChange.ROS_TIME_DEACTIVATED
    changes_handle.unregister()


def test_jump_threshold_validates_its_limits() -> None:
    """Thresholds must have the right sign and at least one must be enabled."""
    with pytest.raises(ValueError, match='min_forward must be a positive'):
        JumpThreshold(min_forward=Duration(), min_backward=None)
    with pytest.raises(ValueError, match='min_backward must be a negative'):
        JumpThreshold(min_forward=None, min_backward=Duration(seconds=1))
    with pytest.raises(ValueError, match='At least one jump threshold'):
        JumpThreshold(min_forward=None, min_backward=None, on_clock_change=False)


def test_sleep_until_waits_for_sim_time_to_arrive(ros: None) -> None:
    """sleep_until on an active ROS clock returns once an override reaches the target."""
    clock = ROSClock()
    source = sim_time_source(clock)
    source.ros_time_is_active = True
    clock.set_ros_time_override(Time(seconds=1, clock_type=ROS))
    reached = threading.Event()
    result: list[bool] = []

    def sleeper() -> None:
        result.append(clock.sleep_until(Time(seconds=3, clock_type=ROS)))
        reached.set()

    thread = threading.Thread(target=sleeper)
    thread.start()
    clock.set_ros_time_override(Time(seconds=2, clock_type=ROS))
    assert not reached.wait(0.2)  # two simulated seconds are not enough
    clock.set_ros_time_override(Time(seconds=3, clock_type=ROS))
    thread.join(timeout=10)
    assert result == [True]


def test_sleep_until_returns_false_when_ros_time_is_deactivated(ros: None) -> None:
    """Deactivating ROS time ends a sim-time sleep with False, as rclpy documents."""
    clock = ROSClock()
    source = sim_time_source(clock)
    source.ros_time_is_active = True
    result: list[bool] = []
    thread = threading.Thread(
        target=lambda: result.append(clock.sleep_until(Time(seconds=100, clock_type=ROS)))
    )
    thread.start()
    source.ros_time_is_active = False
    thread.join(timeout=10)
    assert result == [False]


def test_sleep_until_rejects_another_clock_type(ros: None) -> None:
    """A target time of another clock type raises ValueError, as in rclpy."""
    with pytest.raises(ValueError, match="until's clock type does not match"):
        ROSClock().sleep_until(Time(seconds=1))


def test_sleep_for_on_the_system_clock_reaches_its_target(ros: None) -> None:
    """sleep_for returns True after the clock has advanced by at least the duration."""
    clock = Clock()
    start = clock.now()
    assert clock.sleep_for(Duration(seconds=0.05))
    assert clock.now() - start >= Duration(seconds=0.05)
