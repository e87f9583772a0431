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

"""Timers on a node's clock: periods, cancel and reset, autostart, and sim time."""

from __future__ import annotations

import time

from conftest import STANDALONE_ONLY
import pytest

pytest.importorskip('cyclonedds', reason=STANDALONE_ONLY)

from dds_helpers import spin_until
from tf_demo.msgs import builtin_interfaces
from tf_demo.msgs import rosgraph_msgs
from tf_demo.transport import dds_backend
from tf_demo.transport.parameters import Parameter
from tf_demo.transport.qos import QoSProfile
from tf_demo.transport.qos import ReliabilityPolicy


@pytest.mark.dds
def test_timers_fire_periodically_and_stop_when_canceled(dds_world):
    """A 10 ms timer fires repeatedly under spin_once; after cancel() it no longer fires."""
    node = dds_backend.DdsNode('ticker')
    ticks: list[int] = []
    timer = node.create_timer(0.01, lambda: ticks.append(1))
    executor = dds_backend.SingleThreadedExecutor()
    executor.add_node(node)
    assert spin_until(executor, lambda: len(ticks) >= 5)
    timer.cancel()
    count = len(ticks)
    for _ in range(5):
        executor.spin_once(timeout_sec=0.02)
    assert len(ticks) == count
    with pytest.raises(ValueError, match='timer period must be non-negative'):
        node.create_timer(-0.01, lambda: None)


@pytest.mark.dds
def test_timer_period_and_autostart_follow_rclpy(dds_world):
    """Periods truncate to whole ns, 0 s fires on every spin, autostart=False waits for reset()."""
    node = dds_backend.DdsNode('rclpy_timers')
    assert node.create_timer(1.9e-9, lambda: None).timer_period_ns == 1
    busy: list[int] = []
    node.create_timer(0, lambda: busy.append(1))
    waiting: list[int] = []
    idle = node.create_timer(0.001, lambda: waiting.append(1), autostart=False)
    assert idle.is_canceled()
    executor = dds_backend.SingleThreadedExecutor()
    executor.add_node(node)
    assert spin_until(executor, lambda: len(busy) >= 3)
    assert waiting == []
    idle.reset()
    assert spin_until(executor, lambda: len(waiting) >= 2)


@pytest.mark.dds
def test_sim_time_timer_follows_clock_and_survives_a_backward_jump(dds_world):
    """A 1 s timer on /clock time fires as sim time advances, also after /clock jumps back."""
    node = dds_backend.DdsNode(
        'sim_timer', parameter_overrides=[Parameter('use_sim_time', value=True)]
    )
    clock_node = dds_backend.DdsNode('sim_clock')
    clock_publisher = clock_node.create_publisher(
        rosgraph_msgs.Clock,
        '/clock',
        QoSProfile(depth=1, reliability=ReliabilityPolicy.BEST_EFFORT),
    )
    fired_at: list[int] = []
    node.create_timer(1.0, lambda: fired_at.append(node.get_clock().now().nanoseconds))
    executor = dds_backend.SingleThreadedExecutor()
    executor.add_node(node)

    def advance_to(seconds: float) -> None:
        target = round(seconds * 1e9)
        sec, nanosec = divmod(target, 1_000_000_000)
        deadline = time.monotonic() + 5
        while node.get_clock().now().nanoseconds != target and time.monotonic() < deadline:
            clock_publisher.publish(
                rosgraph_msgs.Clock(clock=builtin_interfaces.Time(sec=sec, nanosec=nanosec))
            )
            executor.spin_once(timeout_sec=0.02)
        for _ in range(3):
            executor.spin_once(timeout_sec=0.02)

    for seconds in (100.0, 100.5, 101.2):
        advance_to(seconds)
    # Created at sim time 0, the timer is overdue when /clock jumps to 100 s (as in rcl).
    assert fired_at == [100_000_000_000, 101_200_000_000]
    for seconds in (10.0, 10.6, 11.3):
        advance_to(seconds)
    assert fired_at == [100_000_000_000, 101_200_000_000, 11_300_000_000]
