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

"""use_sim_time and /clock drive a standalone node's ROS clock."""

from __future__ import annotations

import time

from conftest import STANDALONE_ONLY
import pytest

pytest.importorskip('cyclonedds', reason=STANDALONE_ONLY)

from tf_demo.msgs import builtin_interfaces
from tf_demo.msgs import rosgraph_msgs
from tf_demo.transport import dds_backend
from tf_demo.transport.parameters import Parameter
from tf_demo.transport.qos import QoSProfile
from tf_demo.transport.qos import ReliabilityPolicy


@pytest.mark.dds
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
