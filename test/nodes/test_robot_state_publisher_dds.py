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

"""robot_state_publisher over real DDS (also fed by joint_state_publisher): FK, throttle, QoS."""

from __future__ import annotations

from functools import partial
import math
from pathlib import Path
import random
import time
from typing import Any

from conftest import Processes
from conftest import ProcessOutput
from conftest import Spinning
from hypothesis import given
from hypothesis import HealthCheck
from hypothesis import settings
import pytest
from rsp_world import add_rsp
from rsp_world import feed
from rsp_world import joint_state
from rsp_world import refused_in_one_line
from rsp_world import rsp_process
from rsp_world import SAMPLES
from rsp_world import SECOND
from rsp_world import start_connected
from rsp_world import urdf_file
from rsp_world import wait_until
from tf_demo.core.math3d import matrix_from_quat
from tf_demo.testing.urdf_strategies import GeneratedRobot
from tf_demo.testing.urdf_strategies import pinocchio_link_poses
from tf_demo.testing.urdf_strategies import robots
from tf_demo.urdf import RobotModel

pytestmark = [pytest.mark.dds, pytest.mark.timeout(180)]


def assert_buffer_matches_pinocchio(
    buffer: Any, model: RobotModel, positions: dict[str, float], stamp_ns: int, prefix: str
) -> int:
    """Look every reachable link up in the tf buffer at ``stamp_ns``; compare with pinocchio."""
    pytest.importorskip(
        'pinocchio', reason='pinocchio (PyPI pin), the kinematics oracle, is not installed'
    )
    expected = pinocchio_link_poses(model, positions)
    reachable = model.link_poses(positions)
    root = prefix + model.root
    for link in reachable:
        wait_until(
            partial(buffer.can_transform, root, prefix + link, stamp_ns),
            what=f'{root} -> {prefix + link}',
        )
        result = buffer.lookup_transform(root, prefix + link, stamp_ns).transform
        t = result.translation
        r = result.rotation
        pin_translation, pin_rotation = expected[link]
        assert (t.x, t.y, t.z) == pytest.approx(pin_translation, abs=1e-9), link
        for row, pin_row in zip(matrix_from_quat((r.x, r.y, r.z, r.w)), pin_rotation, strict=True):
            assert row == pytest.approx(pin_row, abs=1e-9), link
    for link in set(model.links) - set(reachable):
        assert not buffer.can_transform(root, prefix + link, stamp_ns), link
    return len(reachable)


@pytest.mark.differential
def test_published_tf_of_sample_and_generated_robots_matches_pinocchio(nodes: Spinning) -> None:
    """/tf + /tf_static from the node, read through tf_demo's Buffer, equal pinocchio's FK."""
    from tf_demo.ros import Buffer
    from tf_demo.ros import TransformListener
    from tf_demo.transport.messages import sensor_msgs
    from tf_demo.transport.parameters import Parameter

    first = RobotModel.from_file(SAMPLES / 'example_revolute.urdf')
    rsp = add_rsp(nodes, first.xml)
    client = nodes.node('fk_client')
    buffer = Buffer()
    TransformListener(buffer, client)
    publisher = client.create_publisher(sensor_msgs.JointState, 'joint_states', 10)
    nodes.start()
    wait_until(lambda: publisher.get_subscription_count() >= 1, what='rsp subscription')
    stamp_ns = 1000 * SECOND
    counter = iter(range(1_000_000))
    rng = random.Random(11)

    def check(model: RobotModel, positions: dict[str, float]) -> None:
        nonlocal stamp_ns
        prefix = f'r{next(counter)}/'
        results = rsp.set_parameters(
            [
                Parameter('frame_prefix', value=prefix),
                Parameter('robot_description', value=model.xml),
            ]
        )
        assert all(result.successful for result in results), results
        stamp_ns += SECOND
        publisher.publish(joint_state(list(positions), list(positions.values()), stamp_ns))
        assert_buffer_matches_pinocchio(buffer, model, positions, stamp_ns, prefix)

    samples = [
        RobotModel.from_file(SAMPLES / 'example_fixed.urdf'),
        first,
        RobotModel.from_file(SAMPLES / 'mobile_robot.urdf.xacro'),
    ]
    for model in samples:
        for _ in range(3):
            check(model, {n: rng.uniform(-math.pi, math.pi) for n in model.movable_joints})

    @settings(
        max_examples=8,
        deadline=None,
        database=None,
        suppress_health_check=[HealthCheck.too_slow],
    )
    @given(robots(max_links=6))
    def generated(robot: GeneratedRobot) -> None:
        check(RobotModel.from_string(robot.xml), robot.positions)

    generated()


def test_throttle_rate_table_over_dds(nodes: Spinning) -> None:
    """Counts of /tf messages for rows of the spec's rate table (synthetic stamps, paced input)."""
    from tf_demo.transport.parameters import Parameter

    model = RobotModel.from_file(SAMPLES / 'example_revolute.urdf')
    rsp = add_rsp(nodes, model.xml)
    client = feed(nodes, 'throttle_client', tf_depth=1000)
    start_connected(nodes, client)
    counted = 0
    rows = [
        # (input Hz, publish_frequency, ignore_timestamp, zero stamps, seconds, expected count)
        (100, 20.0, False, False, 2, 40),
        (50, 20.0, False, False, 3, 50),
        (40, 30.0, False, False, 2, 40),
        (100, 20.0, False, True, 1, 0),
        (100, 20.0, True, True, 1, 100),
    ]
    base_ns = 5000 * SECOND
    for hz, frequency, ignore, zero, seconds, expected in rows:
        results = rsp.set_parameters(
            [
                Parameter('publish_frequency', value=frequency),
                Parameter('ignore_timestamp', value=ignore),
            ]
        )
        assert all(result.successful for result in results)
        base_ns += 1000 * SECOND
        for k in range(hz * seconds):
            stamp_ns = 0 if zero else base_ns + k * SECOND // hz
            client.joint_states.publish(joint_state(['frame_1_to_frame_2'], [0.1 * k], stamp_ns))
            time.sleep(0.003)
        time.sleep(0.5)
        received = client.tf[counted:]
        counted += len(received)
        assert all(len(message.transforms) == 1 for message in received)
        assert len(received) == expected, (hz, frequency, ignore, zero)


def test_runtime_parameter_changes_are_validated_and_reload_the_model(nodes: Spinning) -> None:
    """Bad values are refused with upstream's reasons; a good description reloads and latches."""
    from tf_demo.transport.messages import std_msgs
    from tf_demo.transport.messages import tf2_msgs
    from tf_demo.transport.parameters import Parameter
    from tf_demo.transport.qos import DurabilityPolicy
    from tf_demo.transport.qos import QoSProfile
    from tf_demo.transport.qos import ReliabilityPolicy

    old = RobotModel.from_file(SAMPLES / 'example_fixed.urdf')
    rsp = add_rsp(nodes, old.xml)
    nodes.start()

    def refused(name: str, value: Any) -> str:
        [result] = rsp.set_parameters([Parameter(name, value=value)])
        assert not result.successful
        return str(result.reason)

    assert refused('robot_description', '') == 'Empty URDF is not allowed'
    reason = refused('robot_description', '<robot name="x"><link name="a"></robot>')
    assert reason.startswith('Unable to initialize urdf::model from robot description: ')
    assert 'malformed XML' in reason
    assert refused('publish_frequency', 0.0) == (
        'publish_frequency must be between 0.0 (exclusive) and 1000.0'
    )
    assert refused('publish_frequency', 1000.5).startswith('publish_frequency must be between')
    assert rsp.get_parameter('robot_description').value == old.xml

    new = RobotModel.from_file(SAMPLES / 'mobile_robot.urdf.xacro')
    [result] = rsp.set_parameters([Parameter('robot_description', value=new.xml)])
    assert result.successful

    late = nodes.node('late_subscriber')
    latched = QoSProfile(
        depth=1,
        durability=DurabilityPolicy.TRANSIENT_LOCAL,
        reliability=ReliabilityPolicy.RELIABLE,
    )
    descriptions: list[str] = []
    statics: list[Any] = []
    late.create_subscription(
        std_msgs.String, 'robot_description', lambda m: descriptions.append(m.data), latched
    )
    late.create_subscription(tf2_msgs.TFMessage, '/tf_static', statics.append, latched)
    wait_until(
        lambda: bool(descriptions) and bool(statics), what='latched description and statics'
    )
    assert descriptions[-1] == new.xml
    children = {t.child_frame_id for t in statics[-1].transforms}
    # the new fixed joints plus the old robot's frame, which stays latched as upstream
    assert children == {'frame_1', 'base_link', 'lidar_link', 'camera_link'}


def test_jsp_and_rsp_processes_feed_a_late_listener(spawn: Processes, nodes: Spinning) -> None:
    """joint_state_publisher + robot_state_publisher processes; a listener started later gets
    the latched fixed joints and the moving ones at the published joint positions."""
    from tf_demo.ros import Buffer
    from tf_demo.ros import TransformListener
    from tf_demo.transport.messages import sensor_msgs
    from tf_demo.transport.messages import tf2_msgs

    xacro = SAMPLES / 'mobile_robot.urdf.xacro'
    rsp = rsp_process(spawn, *urdf_file(xacro.name), '-p', 'xacro_args:=prefix:=r1_')
    jsp = ProcessOutput(
        spawn.start(
            'joint_state_publisher',
            str(xacro),
            '--ros-args',
            '-p',
            'xacro_args:=prefix:=r1_',
            '-p',
            'rate:=20',
            '-p',
            'delta:=0.05',
            '-p',
            'zeros.r1_left_wheel_joint:=0.5',
        )
    )
    rsp.wait_for_line('Robot initialized', anywhere=True)
    time.sleep(1.0)  # the listener joins late
    model = RobotModel.from_file(xacro, {'prefix': 'r1_'})
    client = nodes.node('late_listener')
    buffer = Buffer()
    TransformListener(buffer, client)
    states: dict[int, dict[str, float]] = {}

    def remember(message: Any) -> None:
        stamp_ns = message.header.stamp.sec * SECOND + message.header.stamp.nanosec
        states[stamp_ns] = dict(zip(message.name, message.position, strict=True))

    tf_stamps: set[int] = set()

    def remember_tf(message: Any) -> None:
        for transform in message.transforms:
            tf_stamps.add(transform.header.stamp.sec * SECOND + transform.header.stamp.nanosec)

    client.create_subscription(sensor_msgs.JointState, 'joint_states', remember, 10)
    client.create_subscription(tf2_msgs.TFMessage, '/tf', remember_tf, 100)
    nodes.start()
    # the throttle drops some joint states (20 Hz in, publish_frequency 20): compare at a stamp
    # that made it to /tf, so the buffer answers with that sample and not an interpolation
    wait_until(lambda: len(tf_stamps & set(states)) >= 3, what='joint states and their /tf')
    assert all(set(s) == {'r1_left_wheel_joint', 'r1_right_wheel_joint'} for s in states.values())
    stamp_ns = max(tf_stamps & set(states))
    checked = assert_buffer_matches_pinocchio(buffer, model, states[stamp_ns], stamp_ns, '')
    assert checked == len(model.links) == 6
    for process in (rsp.process, jsp.process):
        assert process.poll() is None


def test_broken_description_exits_with_one_line_and_code_1(
    spawn: Processes, tmp_path: Path
) -> None:
    """A broken description at start: one-line error naming the problem, exit code 1."""
    bad = tmp_path / 'bad.urdf'
    bad.write_text('<robot name="r"><link name="a"/><joint name="j" type="ball"/></robot>')
    line = refused_in_one_line(
        spawn, 'robot_state_publisher', '--ros-args', '-p', f'urdf_file:={bad}'
    )
    assert 'Traceback' not in line
    assert f"{bad}:1: joint 'j': Joint [j] has no known type [ball]" in line
    empty = spawn.start('robot_state_publisher')
    _, stderr = empty.communicate(timeout=60)
    assert empty.returncode == 1
    assert 'robot_description parameter must not be empty' in stderr
    frequency = spawn.start(
        'robot_state_publisher',
        '--ros-args',
        *urdf_file('example_fixed.urdf'),
        '-p',
        'publish_frequency:=0.0',
    )
    _, stderr = frequency.communicate(timeout=60)
    assert frequency.returncode == 1
    assert 'publish_frequency must be between 0 (exclusive) and 1000' in stderr


def test_invalid_joint_states_are_warned_about_and_dropped(
    spawn: Processes, nodes: Spinning
) -> None:
    """Length mismatches produce upstream's texts and no /tf; the node keeps running."""
    rsp = rsp_process(spawn, *urdf_file('example_revolute.urdf'))
    client = feed(nodes, 'bad_states')
    start_connected(nodes, client)
    publish = client.joint_states.publish
    received = client.tf
    publish(joint_state(['frame_1_to_frame_2'], [], 2000 * SECOND))
    publish(joint_state(['frame_1_to_frame_2'], [0.1, 0.2], 2001 * SECOND))
    rsp.wait_for_line(
        'Robot state publisher ignored a JointState message about joint(s) "frame_1_to_frame_2"'
        '(,...) whose position member was empty.',
        anywhere=True,
    )
    rsp.wait_for_line('Robot state publisher ignored an invalid JointState message', anywhere=True)
    publish(joint_state(['frame_1_to_frame_2'], [0.3], 2002 * SECOND))
    wait_until(lambda: len(received) == 1, what='the valid message on /tf')
    [transform] = received[0].transforms
    assert (transform.header.stamp.sec, transform.child_frame_id) == (2002, 'frame_2')
    # names that are no moving joint are ignored silently, but the message is still answered
    publish(joint_state(['nobody', 'world_to_frame_1'], [1.0, 2.0], 2003 * SECOND))
    wait_until(lambda: len(received) == 2, what='the empty /tf message')
    assert list(received[1].transforms) == []
    assert rsp.process.poll() is None


def test_positional_urdf_file_fallback_of_upstream(spawn: Processes) -> None:
    """A non-ROS argument is taken as the URDF file (with upstream's warning); a missing one
    is a one-line error naming it."""
    ok = ProcessOutput(spawn.start('robot_state_publisher', str(SAMPLES / 'example_fixed.urdf')))
    ok.wait_for_line('Assuming argument is name of URDF file.', anywhere=True)
    ok.wait_for_line('Robot initialized', anywhere=True)
    missing = spawn.start('robot_state_publisher', 'no_such.urdf')
    _, stderr = missing.communicate(timeout=60)
    assert missing.returncode == 1
    assert 'Failed to load URDF file no_such.urdf: no_such.urdf: file: no such file' in stderr
    assert 'Traceback' not in stderr


def test_backward_sim_time_jump_resets_the_throttle(nodes: Spinning, capfd: Any) -> None:
    """With use_sim_time, /clock going backwards warns and lets a throttled stamp through."""
    from tf_demo.transport.messages import rosgraph_msgs
    from tf_demo.transport.qos import QoSProfile

    model = RobotModel.from_file(SAMPLES / 'example_revolute.urdf')
    rsp = add_rsp(nodes, model.xml, parameters={'use_sim_time': True})
    client = feed(nodes, 'sim_clock')
    clock = client.node.create_publisher(rosgraph_msgs.Clock, '/clock', QoSProfile(depth=10))
    start_connected(nodes, client)
    wait_until(lambda: clock.get_subscription_count() >= 1, what='rsp /clock subscription')
    publisher = client.joint_states
    received = client.tf

    def set_clock(seconds: int) -> None:
        message = rosgraph_msgs.Clock()
        message.clock.sec = seconds
        clock.publish(message)
        wait_until(lambda: rsp.get_clock().now().nanoseconds == seconds * SECOND, what='sim time')

    set_clock(100)
    publisher.publish(joint_state(['frame_1_to_frame_2'], [0.1], 100 * SECOND))
    wait_until(lambda: len(received) == 1, what='first /tf')
    publisher.publish(joint_state(['frame_1_to_frame_2'], [0.2], 100 * SECOND))
    time.sleep(0.5)
    assert len(received) == 1  # same stamp again: throttled
    set_clock(50)
    publisher.publish(joint_state(['frame_1_to_frame_2'], [0.3], 100 * SECOND))
    wait_until(lambda: len(received) == 2, what='/tf after the clock jumped back')
    assert 'Moved backwards in time, re-publishing joint transforms!' in capfd.readouterr().err


def test_topics_and_qos_are_upstreams(nodes: Spinning) -> None:
    """joint_states: sensor data QoS; /tf: reliable volatile 100; /tf_static and
    robot_description: reliable transient local 1."""
    from tf_demo.transport.qos import DurabilityPolicy
    from tf_demo.transport.qos import ReliabilityPolicy

    rsp = add_rsp(
        nodes, RobotModel.from_file(SAMPLES / 'example_fixed.urdf').xml, reliable_input=False
    )
    [joint_states] = [s for s in rsp.subscriptions if s.topic_name == '/joint_states']
    qos = joint_states.qos_profile
    assert (qos.reliability, qos.durability, qos.depth) == (
        ReliabilityPolicy.BEST_EFFORT,
        DurabilityPolicy.VOLATILE,
        5,
    )
    publishers = {p.topic_name: p.qos_profile for p in rsp.publishers}
    expected = {
        '/tf': (ReliabilityPolicy.RELIABLE, DurabilityPolicy.VOLATILE, 100),
        '/tf_static': (ReliabilityPolicy.RELIABLE, DurabilityPolicy.TRANSIENT_LOCAL, 1),
        '/robot_description': (ReliabilityPolicy.RELIABLE, DurabilityPolicy.TRANSIENT_LOCAL, 1),
    }
    for topic, policies in expected.items():
        qos = publishers[topic]
        assert (qos.reliability, qos.durability, qos.depth) == policies, topic
    assert rsp.get_parameter('publish_frequency').value == 20.0
    assert rsp.get_parameter('ignore_timestamp').value is False
    assert rsp.get_parameter('frame_prefix').value == ''


def test_qos_overrides_parameters_change_the_profiles(nodes: Spinning) -> None:
    """qos_overrides.<topic>.<entity>.<policy> parameters are declared and applied at start."""
    from tf_demo.transport.qos import DurabilityPolicy
    from tf_demo.transport.qos import HistoryPolicy

    rsp = add_rsp(
        nodes,
        RobotModel.from_file(SAMPLES / 'example_fixed.urdf').xml,
        parameters={
            'qos_overrides./tf.publisher.depth': 7,
            'qos_overrides./tf.publisher.durability': 'transient_local',
            'qos_overrides./tf_static.publisher.history': 'keep_all',
        },
    )
    publishers = {p.topic_name: p.qos_profile for p in rsp.publishers}
    assert publishers['/tf'].depth == 7
    assert publishers['/tf'].durability == DurabilityPolicy.TRANSIENT_LOCAL
    assert publishers['/tf_static'].history == HistoryPolicy.KEEP_ALL
    assert rsp.get_parameter('qos_overrides./tf_static.publisher.depth').value == 1
    with pytest.raises(
        ValueError, match=r"invalid value 'sometimes' for parameter qos_overrides\./tf\.publisher"
    ):
        add_rsp(
            nodes,
            RobotModel.from_file(SAMPLES / 'example_fixed.urdf').xml,
            parameters={'qos_overrides./tf.publisher.reliability': 'sometimes'},
        )
