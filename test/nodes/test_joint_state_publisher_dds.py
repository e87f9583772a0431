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

"""joint_state_publisher over real DDS: the description from the topic, merged sources."""

from __future__ import annotations

import time
from typing import Any

from conftest import Processes
from conftest import ProcessOutput
from conftest import Spinning
import pytest
from rsp_world import joint_state
from rsp_world import rsp_process
from rsp_world import SAMPLES
from rsp_world import urdf_file
from rsp_world import wait_until
from tf_demo.urdf import RobotModel

pytestmark = [pytest.mark.dds, pytest.mark.timeout(180)]


def test_jsp_takes_the_description_from_the_topic_and_merges_sources(
    spawn: Processes, nodes: Spinning
) -> None:
    """Without a file, joint_state_publisher waits for the latched robot_description (published
    by robot_state_publisher), publishes defaults, and republishes values from source_list."""
    from tf_demo.transport.messages import sensor_msgs

    jsp = ProcessOutput(
        spawn.start(
            'joint_state_publisher',
            '--ros-args',
            '-p',
            'rate:=20',
            '-p',
            'source_list:=[ext_states]',
        )
    )
    jsp.wait_for_line(
        'Waiting for robot_description to be published on the robot_description topic',
        anywhere=True,
    )
    rsp = rsp_process(spawn, *urdf_file('example_revolute.urdf'))
    client = nodes.node('jsp_client')
    states: list[Any] = []
    client.create_subscription(sensor_msgs.JointState, 'joint_states', states.append, 10)
    source = client.create_publisher(sensor_msgs.JointState, 'ext_states', 10)
    nodes.start()
    wait_until(lambda: bool(states), what='joint states after the description arrived')
    assert list(states[-1].name) == ['frame_1_to_frame_2']
    assert list(states[-1].position) == [0.0]
    wait_until(lambda: source.get_subscription_count() >= 1, what='source_list subscription')
    source.publish(joint_state(['frame_1_to_frame_2', 'unknown'], [1.25, 9.0], 0))
    wait_until(lambda: list(states[-1].position) == [1.25], what='the source value republished')
    assert list(states[-1].name) == ['frame_1_to_frame_2']
    assert rsp.process.poll() is None


def test_jsp_ignores_an_invalid_description_from_the_topic(nodes: Spinning) -> None:
    """A broken description on robot_description is reported; the node keeps running and takes
    the next valid one."""
    from tf_demo.nodes.joint_state_publisher import JointStatePublisher
    from tf_demo.transport.messages import message_module
    from tf_demo.transport.messages import sensor_msgs
    from tf_demo.transport.messages import std_msgs
    from tf_demo.transport.qos import DurabilityPolicy
    from tf_demo.transport.qos import QoSProfile

    nodes.add(JointStatePublisher(None))
    client = nodes.node('description_source')
    latched = QoSProfile(depth=1, durability=DurabilityPolicy.TRANSIENT_LOCAL)
    description = client.create_publisher(std_msgs.String, 'robot_description', latched)
    states: list[Any] = []
    client.create_subscription(sensor_msgs.JointState, 'joint_states', states.append, 10)
    # The warning as every node reports it, on /rosout (reading captured stderr while the
    # node's thread writes to it could lose the line).
    logged: list[str] = []
    client.create_subscription(
        message_module('rcl_interfaces').Log,
        '/rosout',
        lambda record: logged.append(record.msg),
        QoSProfile(depth=1000, durability=DurabilityPolicy.TRANSIENT_LOCAL),
    )
    nodes.start()
    wait_until(lambda: description.get_subscription_count() >= 1, what='jsp subscription')
    description.publish(std_msgs.String(data='<robot name="r"><link name="a"></robot>'))

    def warned() -> bool:
        return any('Invalid robot_description given, ignoring' in text for text in logged)

    wait_until(warned, timeout=30.0, what='the warning')
    time.sleep(0.3)
    assert states == []
    xml = RobotModel.from_file(SAMPLES / 'mobile_robot.urdf.xacro').xml
    description.publish(std_msgs.String(data=xml))
    wait_until(lambda: bool(states), what='joint states of the valid description')
    assert list(states[-1].name) == ['left_wheel_joint', 'right_wheel_joint']
