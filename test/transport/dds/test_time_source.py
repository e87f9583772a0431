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
use_sim_time: a /clock publisher over real DDS drives node.get_clock().now().

The tests use the node API only and run in both worlds, except the one marked standalone, which
drives a DdsNode's clock directly.
"""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path
import signal
import subprocess
import sys
import time

from conftest import HAVE_CYCLONEDDS
import pytest
from tf_demo import transport
from tf_demo.transport.clock import ClockType
from tf_demo.transport.clock import Time
from tf_demo.transport.executors import Executor
from tf_demo.transport.executors import SingleThreadedExecutor
from tf_demo.transport.messages import builtin_interfaces
from tf_demo.transport.messages import rosgraph_msgs
from tf_demo.transport.messages import std_msgs
from tf_demo.transport.parameters import Parameter
from tf_demo.transport.qos import QoSProfile
from tf_demo.transport.qos import ReliabilityPolicy

if HAVE_CYCLONEDDS:  # for the standalone test only
    from tf_demo.transport import dds_backend

pytestmark = pytest.mark.dds


def spin_until(
    executor: Executor,
    condition: Callable[[], bool],
    publish: Callable[[], object] | None = None,
    limit_s: float = 20.0,
) -> bool:
    """Spin (publishing /clock each round) until condition() holds or the limit passes."""
    deadline = time.monotonic() + limit_s
    while time.monotonic() < deadline:
        if publish is not None:
            publish()
        executor.spin_once(timeout_sec=0.05)
        if condition():
            return True
    return condition()


def test_clock_topic_drives_now_when_use_sim_time_is_set(world_env: dict[str, str]) -> None:
    """With -p use_sim_time:=true, now() follows /clock; turning it off returns to system time."""
    transport.init(['test'])
    try:
        simulator = transport.create_node('simulator')
        clock_publisher = simulator.create_publisher(rosgraph_msgs.Clock, '/clock', 10)
        node = transport.create_node(
            'sim_node', cli_args=['--ros-args', '-p', 'use_sim_time:=true']
        )
        assert node.get_parameter('use_sim_time').value is True
        executor = SingleThreadedExecutor()
        executor.add_node(simulator)
        executor.add_node(node)
        clock = node.get_clock()
        assert clock.clock_type is ClockType.ROS_TIME
        assert clock.now().nanoseconds == 0  # ROS time is active but no /clock yet
        target = Time(seconds=42, nanoseconds=5, clock_type=ClockType.ROS_TIME)

        def publish() -> None:
            clock_publisher.publish(
                rosgraph_msgs.Clock(clock=builtin_interfaces.Time(sec=42, nanosec=5))
            )

        assert spin_until(executor, lambda: clock.now() == target, publish)
        later = Time(seconds=43, clock_type=ClockType.ROS_TIME)

        def publish_later() -> None:
            clock_publisher.publish(
                rosgraph_msgs.Clock(clock=builtin_interfaces.Time(sec=43, nanosec=0))
            )

        assert spin_until(executor, lambda: clock.now() == later, publish_later)
        [result] = node.set_parameters([Parameter('use_sim_time', value=False)])
        assert result.successful
        assert clock.now().nanoseconds > 1_600_000_000 * 10**9  # system time again (after 2020)
    finally:
        transport.shutdown()


def test_without_use_sim_time_clock_messages_are_ignored(world_env: dict[str, str]) -> None:
    """A node without use_sim_time keeps system time even while /clock is published."""
    transport.init(['test'])
    try:
        simulator = transport.create_node('simulator')
        clock_publisher = simulator.create_publisher(rosgraph_msgs.Clock, '/clock', 10)
        node = transport.create_node('wall_node')
        assert node.get_parameter('use_sim_time').value is False
        executor = SingleThreadedExecutor()
        executor.add_node(simulator)
        executor.add_node(node)
        for _ in range(10):
            clock_publisher.publish(rosgraph_msgs.Clock(clock=builtin_interfaces.Time(sec=7)))
            executor.spin_once(timeout_sec=0.02)
        assert node.get_clock().now().nanoseconds > 1_600_000_000 * 10**9
    finally:
        transport.shutdown()


STAMP_REPORTER = """
import sys
from tf_demo.transport import run_node
from tf_demo.transport.node import Node
from tf_demo.transport.messages import std_msgs


class StampReporter(Node):
    def __init__(self):
        super().__init__('stamp_reporter')
        self.publisher = self.create_publisher(std_msgs.String, 'stamps', 100)
        self.timer = self.create_timer(0.5, self.report)

    def report(self):
        self.publisher.publish(std_msgs.String(data=str(self.get_clock().now().nanoseconds)))


sys.exit(run_node(StampReporter))
"""


def test_node_process_with_use_sim_time_reports_clock_topic_time(
    world_env: dict[str, str], tmp_path: Path
) -> None:
    """A node process started with use_sim_time:=true stamps with /clock time, not wall time."""
    script = tmp_path / 'reporter.py'
    script.write_text(STAMP_REPORTER, encoding='utf-8')
    transport.init(['test'])
    process = subprocess.Popen(
        [sys.executable, str(script), '--ros-args', '-p', 'use_sim_time:=true'],
        env=world_env,
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
    )
    try:
        simulator = transport.create_node('simulator')
        clock_publisher = simulator.create_publisher(rosgraph_msgs.Clock, '/clock', 10)
        stamps: list[int] = []
        simulator.create_subscription(
            std_msgs.String, 'stamps', lambda msg: stamps.append(int(msg.data)), 100
        )
        executor = SingleThreadedExecutor()
        executor.add_node(simulator)
        sim_ns = 1000 * 10**9

        def advance() -> None:
            nonlocal sim_ns
            sim_ns += 50_000_000
            sec, nanosec = divmod(sim_ns, 10**9)
            clock_publisher.publish(
                rosgraph_msgs.Clock(clock=builtin_interfaces.Time(sec=sec, nanosec=nanosec))
            )

        assert spin_until(executor, lambda: len(stamps) >= 3, advance, limit_s=60.0)
        assert all(1000 * 10**9 < stamp <= sim_ns for stamp in stamps), stamps
        assert stamps == sorted(stamps)
    finally:
        process.send_signal(signal.SIGINT)
        try:
            _, stderr = process.communicate(timeout=20)
        finally:
            transport.shutdown()
    assert process.returncode == 0, stderr


@pytest.mark.standalone
def test_use_sim_time_drives_the_node_clock_from_clock_topic(dds_world):
    """With use_sim_time true, get_clock().now() follows the /clock messages."""
    node = dds_backend.DdsNode('sim', parameter_overrides=[Parameter('use_sim_time', value=True)])
    clock_node = dds_backend.DdsNode('clock_source')
    clock_publisher = clock_node.create_publisher(
        rosgraph_msgs.Clock,
        '/clock',
        QoSProfile(depth=1, reliability=ReliabilityPolicy.BEST_EFFORT),
    )
    executor = dds_backend.SingleThreadedExecutor()
    executor.add_node(node)
    deadline = time.monotonic() + 10
    while node.get_clock().now().nanoseconds != 42_000_000_007 and time.monotonic() < deadline:
        clock_publisher.publish(
            rosgraph_msgs.Clock(clock=builtin_interfaces.Time(sec=42, nanosec=7))
        )
        executor.spin_once(timeout_sec=0.05)
    assert node.get_clock().now().nanoseconds == 42_000_000_007
    assert node.get_parameter('use_sim_time').value is True
