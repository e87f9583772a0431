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

"""robot_state_publisher and friends as processes, fed hostile input: they keep running."""

from __future__ import annotations

import contextlib
import itertools
import math
from pathlib import Path
import shutil
import subprocess
from typing import Any

from conftest import Processes
from conftest import ProcessOutput
from conftest import Spinning
import pytest
from ros_world.jazzy import require_package
from ros_world.jazzy import running
from rsp_world import feed
from rsp_world import joint_state
from rsp_world import parameter_args
from rsp_world import refused_in_one_line
from rsp_world import reliable_joint_states
from rsp_world import rsp_process
from rsp_world import SAMPLES
from rsp_world import SECOND
from rsp_world import start_connected
from rsp_world import urdf_file
from rsp_world import wait_until
from tf_demo.urdf import expand_xacro

pytestmark = [pytest.mark.dds, pytest.mark.timeout(240)]

RELIABLE_INPUT = parameter_args(reliable_joint_states(200))
NOT_FINITE = 'position inf is not a finite number'


def upstream_rsp(
    env: dict[str, str], *args: str
) -> contextlib.AbstractContextManager[ProcessOutput]:
    """The real robot_state_publisher (``ros2 run``), stopped with Ctrl-C at the end."""
    command = ['ros2', 'run', 'robot_state_publisher', 'robot_state_publisher', '--ros-args']
    return running([*command, *args], env)


def reliable_qos() -> Any:
    """The QoS of a joint_states publisher matching :data:`RELIABLE_INPUT`."""
    from tf_demo.transport.qos import QoSProfile
    from tf_demo.transport.qos import ReliabilityPolicy

    return QoSProfile(depth=200, reliability=ReliabilityPolicy.RELIABLE)


def test_non_finite_and_mismatched_joint_states_are_dropped_and_publishing_goes_on(
    spawn: Processes, nodes: Spinning
) -> None:
    """inf/nan positions and a velocity of the wrong length: warned (throttled), dropped."""
    rsp = rsp_process(spawn, *urdf_file('example_revolute.urdf'), *RELIABLE_INPUT)
    client = feed(nodes, 'hostile_states', joint_states_qos=reliable_qos())
    start_connected(nodes, client)
    publisher = client.joint_states
    received = client.tf
    joint = 'frame_1_to_frame_2'
    publisher.publish(joint_state([joint], [math.inf], 2000 * SECOND))
    rsp.wait_for_line(
        f"Robot state publisher ignored a JointState message: joint '{joint}': {NOT_FINITE}",
        anywhere=True,
    )
    wrong_velocity = joint_state([joint], [0.1], 2001 * SECOND)
    wrong_velocity.velocity = [0.0, 1.0]
    publisher.publish(wrong_velocity)
    rsp.wait_for_line(
        'ignored a JointState message with 1 names but 2 velocity values', anywhere=True
    )
    for index in range(100):
        bad = math.nan if index % 2 else -math.inf
        publisher.publish(joint_state([joint], [bad], (2002 + index) * SECOND))
    publisher.publish(joint_state([joint], [0.25], 3000 * SECOND))
    wait_until(lambda: bool(received), timeout=30, what='the valid message on /tf')
    [message] = received
    [transform] = message.transforms
    assert (transform.header.stamp.sec, transform.child_frame_id) == (3000, 'frame_2')
    assert transform.transform.rotation.z == pytest.approx(math.sin(0.125))
    assert rsp.process.poll() is None
    warnings = [line for line in rsp.lines if 'is not a finite number' in line]
    assert 1 <= len(warnings) < 10, warnings  # 101 bad messages, throttled per 5 s
    assert not [line for line in rsp.lines if 'Traceback' in line or 'ValueError' in line]


@pytest.mark.parametrize(
    'command',
    [
        ('robot_state_publisher', '--ros-args', '-p', 'urdf_file:=/dev/zero'),
        ('joint_state_publisher', '/dev/zero'),
        ('static_tf_pub', '--ros-args', '-p', 'transforms_file:=/dev/zero'),
    ],
    ids=['robot_state_publisher', 'joint_state_publisher', 'static_tf_pub'],
)
def test_a_device_as_input_file_is_refused_with_one_line(
    spawn: Processes, command: tuple[str, ...]
) -> None:
    """/dev/zero is not read until memory runs out: exit code 1 and one line naming it."""
    line = refused_in_one_line(spawn, *command)
    assert '/dev/zero' in line
    assert 'not a regular file' in line


def test_a_recursive_xacro_as_urdf_file_is_refused_with_one_line(
    spawn: Processes, tmp_path: Path
) -> None:
    """A macro that calls itself: one line naming the file and the macro, no RecursionError."""
    path = tmp_path / 'again.urdf.xacro'
    path.write_text(
        '<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro"><link name="a"/>'
        '<xacro:macro name="again"><xacro:again/></xacro:macro><xacro:again/></robot>',
        encoding='utf-8',
    )
    line = refused_in_one_line(
        spawn, 'robot_state_publisher', '--ros-args', '-p', f'urdf_file:={path}'
    )
    assert f'{path}: xacro: xacro failed: macros nested deeper than' in line
    assert '(again -> again' in line


def test_the_course_command_runs_on_the_sample_robot(
    spawn: Processes, world_env: dict[str, str]
) -> None:
    """-p robot_description:="$(xacro urdf/mobile_robot.urdf.xacro)" starts the node (and, in
    the ROS world, the real robot_state_publisher on the real xacro's output)."""
    sample = SAMPLES / 'mobile_robot.urdf.xacro'
    description = f'robot_description:={expand_xacro(sample)}'
    ours = rsp_process(spawn, '-p', description)
    ours.wait_for_line('Robot initialized', timeout=60, anywhere=True)
    assert ours.process.poll() is None
    xacro = shutil.which('xacro')
    if shutil.which('ros2') is None or xacro is None:
        return  # the standalone world has no upstream robot_state_publisher
    require_package(world_env, 'robot_state_publisher')
    text = subprocess.run(
        [xacro, str(sample)], capture_output=True, text=True, timeout=60, check=True
    ).stdout
    arguments = ('-r', '__ns:=/upstream', '-p', f'robot_description:={text}')
    with upstream_rsp(world_env, *arguments) as theirs:
        theirs.wait_for_line('Robot initialized', timeout=60, anywhere=True)
        assert theirs.process.poll() is None


GHOST_MIMIC = (
    '<robot name="r"><link name="a"/><link name="b"/>'
    '<joint name="j" type="continuous"><parent link="a"/><child link="b"/><axis xyz="0 0 1"/>'
    '<mimic joint="ghost" multiplier="2"/></joint></robot>'
)


def test_a_mimic_of_a_missing_joint_loads_and_publishes_as_upstream(
    spawn: Processes, nodes: Spinning, world_env: dict[str, str]
) -> None:
    """The robot loads with one warning naming the joint; j is published as an ordinary joint
    (in the ROS world, the real robot_state_publisher publishes the same transform)."""
    from tf_demo.transport.messages import sensor_msgs

    ours = rsp_process(spawn, '-p', f'robot_description:={GHOST_MIMIC}', *RELIABLE_INPUT)
    upstream_wanted = shutil.which('ros2') is not None
    if upstream_wanted:
        require_package(world_env, 'robot_state_publisher')
    client = feed(nodes, 'ghost_mimic', joint_states_qos=reliable_qos())
    received = client.tf
    publishers = [client.joint_states]
    arguments = (
        '-r', '__ns:=/upstream', '-p', 'frame_prefix:=upstream/',
        '-p', f'robot_description:={GHOST_MIMIC}', *RELIABLE_INPUT,
    )  # fmt: skip
    if upstream_wanted:
        upstream_topic = '/upstream/joint_states'
        publishers.append(
            client.node.create_publisher(sensor_msgs.JointState, upstream_topic, reliable_qos())
        )
    nodes.start()
    context = upstream_rsp(world_env, *arguments) if upstream_wanted else contextlib.nullcontext()
    with context as theirs:
        ours.wait_for_line(
            "joint 'j' mimics joint 'ghost', which does not exist", timeout=60, anywhere=True
        )
        for publisher in publishers:

            def subscribed(publisher: Any = publisher) -> bool:
                count: int = publisher.get_subscription_count()
                return count >= 1

            wait_until(subscribed, timeout=60, what='a robot_state_publisher subscription')
        children = {'b'} | ({'upstream/b'} if upstream_wanted else set())
        sent = itertools.count()

        def published() -> dict[str, Any]:
            found = {}
            for message in received.copy():
                for transform in message.transforms:
                    found[transform.child_frame_id] = transform.transform.rotation
            return found

        def fed_until_published() -> bool:
            # Sent again (a newer stamp each time, as joint_state_publisher would) every half
            # second: a sample written while a reader on either side is still matching is lost.
            count = next(sent)
            if count % 50 == 0:
                stamp = (2000 + count // 50) * SECOND
                for publisher in publishers:
                    publisher.publish(joint_state(['j', 'ghost'], [math.pi / 2, 1.0], stamp))
            return children <= set(published())

        wait_until(fed_until_published, timeout=30, what=f'{children} on /tf')
        half = math.sqrt(0.5)
        for child, rotation in published().items():
            assert (rotation.x, rotation.y, rotation.z, rotation.w) == pytest.approx(
                (0.0, 0.0, half, half)
            ), child
        if theirs is not None:
            assert theirs.process.poll() is None
    warnings = [line for line in ours.lines if "mimics joint 'ghost'" in line]
    assert len(warnings) == 1, ours.lines
    assert ours.process.poll() is None
