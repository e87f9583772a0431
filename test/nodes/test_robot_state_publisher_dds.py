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

"""robot_state_publisher and joint_state_publisher over real DDS: FK via tf, throttle, params."""

from __future__ import annotations

from collections.abc import Callable
from collections.abc import Iterator
import math
from pathlib import Path
import queue
import random
import threading
import time
from typing import Any

from conftest import ProcessOutput
from hypothesis import given
from hypothesis import HealthCheck
from hypothesis import settings
import pytest
from tf_demo.core.math3d import matrix_from_quat
from tf_demo.testing.urdf_strategies import GeneratedRobot
from tf_demo.testing.urdf_strategies import pinocchio_link_poses
from tf_demo.testing.urdf_strategies import robots
from tf_demo.urdf import RobotModel

pytestmark = [pytest.mark.dds, pytest.mark.timeout(180)]

SAMPLES = Path(__file__).resolve().parents[2] / 'urdf'
SECOND = 1_000_000_000


def wait_until(condition: Callable[[], bool], timeout: float = 10.0, what: str = '') -> None:
    deadline = time.monotonic() + timeout
    while not condition():
        if time.monotonic() > deadline:
            pytest.fail(f'timed out waiting for {what}')
        time.sleep(0.01)


class World:
    """In-process nodes on the test's DDS domain, spun by one executor thread."""

    def __init__(self) -> None:
        from tf_demo import transport

        self.transport = transport
        transport.init(['test_rsp_dds'])
        self.nodes: list[Any] = []
        self.executor = transport.SingleThreadedExecutor()
        self._stop = threading.Event()
        self._thread: threading.Thread | None = None

    def add(self, node: Any) -> Any:
        self.nodes.append(node)
        self.executor.add_node(node)
        return node

    def node(self, name: str) -> Any:
        return self.add(self.transport.create_node(name))

    def rsp(self, xml: str, *, reliable_input: bool = True, **parameters: Any) -> Any:
        from tf_demo.nodes.robot_state_publisher import RobotStatePublisher
        from tf_demo.transport.parameters import Parameter

        # reliable joint_states (upstream's qos_overrides) so a busy machine cannot drop input
        reliable = {
            'qos_overrides./joint_states.subscription.reliability': 'reliable',
            'qos_overrides./joint_states.subscription.depth': 100,
        }
        if not reliable_input:
            reliable = {}
        overrides = [Parameter('robot_description', value=xml)]
        overrides += [Parameter(k, value=v) for k, v in {**reliable, **parameters}.items()]
        return self.add(RobotStatePublisher((), parameter_overrides=overrides))

    def start(self) -> None:
        def spin() -> None:
            while not self._stop.is_set():
                self.executor.spin_once(timeout_sec=0.05)

        self._thread = threading.Thread(target=spin, daemon=True)
        self._thread.start()

    def close(self) -> None:
        self._stop.set()
        if self._thread is not None:
            self._thread.join(timeout=10)
        for node in self.nodes:
            node.destroy_node()
        self.transport.shutdown()


@pytest.fixture
def world(world_env: dict[str, str]) -> Iterator[World]:
    created = World()
    try:
        yield created
    finally:
        created.close()


def joint_state(names: list[str], positions: list[float], stamp_ns: int) -> Any:
    from tf_demo.transport.messages import sensor_msgs

    message = sensor_msgs.JointState()
    message.header.stamp.sec, message.header.stamp.nanosec = divmod(stamp_ns, SECOND)
    message.name = names
    message.position = positions
    return message


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
            lambda link=link: buffer.can_transform(root, prefix + link, stamp_ns),
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
def test_published_tf_of_sample_and_generated_robots_matches_pinocchio(world: World) -> None:
    """/tf + /tf_static from the node, read through tf_demo's Buffer, equal pinocchio's FK."""
    from tf_demo.ros import Buffer
    from tf_demo.ros import TransformListener
    from tf_demo.transport.messages import sensor_msgs
    from tf_demo.transport.parameters import Parameter

    first = RobotModel.from_file(SAMPLES / 'example_revolute.urdf')
    rsp = world.rsp(first.xml)
    client = world.node('fk_client')
    buffer = Buffer()
    TransformListener(buffer, client)
    publisher = client.create_publisher(sensor_msgs.JointState, 'joint_states', 10)
    world.start()
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


def test_throttle_rate_table_over_dds(world: World) -> None:
    """Counts of /tf messages for rows of the spec's rate table (synthetic stamps, paced input)."""
    from tf_demo.transport.messages import sensor_msgs
    from tf_demo.transport.messages import tf2_msgs
    from tf_demo.transport.parameters import Parameter

    model = RobotModel.from_file(SAMPLES / 'example_revolute.urdf')
    rsp = world.rsp(model.xml)
    client = world.node('throttle_client')
    received: queue.Queue[Any] = queue.Queue()
    client.create_subscription(tf2_msgs.TFMessage, '/tf', received.put, 1000)
    publisher = client.create_publisher(sensor_msgs.JointState, 'joint_states', 10)
    world.start()
    wait_until(lambda: publisher.get_subscription_count() >= 1, what='rsp subscription')
    wait_until(lambda: client.count_publishers('/tf') >= 1, what='rsp /tf publisher')
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
            publisher.publish(joint_state(['frame_1_to_frame_2'], [0.1 * k], stamp_ns))
            time.sleep(0.003)
        time.sleep(0.5)
        count = 0
        while not received.empty():
            message = received.get()
            assert len(message.transforms) == 1
            count += 1
        assert count == expected, (hz, frequency, ignore, zero)


def test_runtime_parameter_changes_are_validated_and_reload_the_model(world: World) -> None:
    """Bad values are refused with upstream's reasons; a good description reloads and latches."""
    from tf_demo.transport.messages import std_msgs
    from tf_demo.transport.messages import tf2_msgs
    from tf_demo.transport.parameters import Parameter
    from tf_demo.transport.qos import DurabilityPolicy
    from tf_demo.transport.qos import QoSProfile
    from tf_demo.transport.qos import ReliabilityPolicy

    old = RobotModel.from_file(SAMPLES / 'example_fixed.urdf')
    rsp = world.rsp(old.xml)
    world.start()

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

    late = world.node('late_subscriber')
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


class Running(ProcessOutput):
    """A spawned executable whose output lines are collected in the background."""

    def wait_for(self, text: str, timeout: float = 20.0) -> None:
        wait_until(
            lambda: any(text in line for line in self.lines), timeout, f'{text!r} in {self.lines}'
        )


def test_jsp_and_rsp_processes_feed_a_late_listener(spawn: Any, world: World) -> None:
    """joint_state_publisher + robot_state_publisher processes; a listener started later gets
    the latched fixed joints and the moving ones at the published joint positions."""
    from tf_demo.ros import Buffer
    from tf_demo.ros import TransformListener
    from tf_demo.transport.messages import sensor_msgs
    from tf_demo.transport.messages import tf2_msgs

    xacro = SAMPLES / 'mobile_robot.urdf.xacro'
    rsp = Running(
        spawn.start(
            'robot_state_publisher',
            '--ros-args',
            '-p',
            f'urdf_file:={xacro}',
            '-p',
            'xacro_args:=prefix:=r1_',
        )
    )
    jsp = Running(
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
    rsp.wait_for('Robot initialized')
    time.sleep(1.0)  # the listener joins late
    model = RobotModel.from_file(xacro, {'prefix': 'r1_'})
    client = world.node('late_listener')
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
    world.start()
    # the throttle drops some joint states (20 Hz in, publish_frequency 20): compare at a stamp
    # that made it to /tf, so the buffer answers with that sample and not an interpolation
    wait_until(lambda: len(tf_stamps & set(states)) >= 3, what='joint states and their /tf')
    assert all(set(s) == {'r1_left_wheel_joint', 'r1_right_wheel_joint'} for s in states.values())
    stamp_ns = max(tf_stamps & set(states))
    checked = assert_buffer_matches_pinocchio(buffer, model, states[stamp_ns], stamp_ns, '')
    assert checked == len(model.links) == 6
    for process in (rsp.process, jsp.process):
        assert process.poll() is None


def test_broken_description_exits_with_one_line_and_code_1(spawn: Any, tmp_path: Path) -> None:
    """A broken description at start: one-line error naming the problem, exit code 1."""
    bad = tmp_path / 'bad.urdf'
    bad.write_text('<robot name="r"><link name="a"/><joint name="j" type="ball"/></robot>')
    process = spawn.start('robot_state_publisher', '--ros-args', '-p', f'urdf_file:={bad}')
    _, stderr = process.communicate(timeout=60)
    assert process.returncode == 1
    lines = [line for line in stderr.splitlines() if line.strip()]
    assert len(lines) == 1, stderr
    assert 'Traceback' not in stderr
    assert f"{bad}:1: joint 'j': Joint [j] has no known type [ball]" in lines[0]
    empty = spawn.start('robot_state_publisher')
    _, stderr = empty.communicate(timeout=60)
    assert empty.returncode == 1
    assert 'robot_description parameter must not be empty' in stderr
    frequency = spawn.start(
        'robot_state_publisher',
        '--ros-args',
        '-p',
        f'urdf_file:={SAMPLES / "example_fixed.urdf"}',
        '-p',
        'publish_frequency:=0.0',
    )
    _, stderr = frequency.communicate(timeout=60)
    assert frequency.returncode == 1
    assert 'publish_frequency must be between 0 (exclusive) and 1000' in stderr


def test_invalid_joint_states_are_warned_about_and_dropped(spawn: Any, world: World) -> None:
    """Length mismatches produce upstream's texts and no /tf; the node keeps running."""
    from tf_demo.transport.messages import sensor_msgs
    from tf_demo.transport.messages import tf2_msgs

    rsp = Running(
        spawn.start(
            'robot_state_publisher',
            '--ros-args',
            '-p',
            f'urdf_file:={SAMPLES / "example_revolute.urdf"}',
        )
    )
    client = world.node('bad_states')
    received: list[Any] = []
    client.create_subscription(tf2_msgs.TFMessage, '/tf', received.append, 100)
    publisher = client.create_publisher(sensor_msgs.JointState, 'joint_states', 10)
    world.start()
    wait_until(lambda: publisher.get_subscription_count() >= 1, what='rsp subscription')
    wait_until(lambda: client.count_publishers('/tf') >= 1, what='rsp /tf publisher')
    publisher.publish(joint_state(['frame_1_to_frame_2'], [], 2000 * SECOND))
    publisher.publish(joint_state(['frame_1_to_frame_2'], [0.1, 0.2], 2001 * SECOND))
    rsp.wait_for(
        'Robot state publisher ignored a JointState message about joint(s) "frame_1_to_frame_2"'
        '(,...) whose position member was empty.'
    )
    rsp.wait_for('Robot state publisher ignored an invalid JointState message')
    publisher.publish(joint_state(['frame_1_to_frame_2'], [0.3], 2002 * SECOND))
    wait_until(lambda: len(received) == 1, what='the valid message on /tf')
    [transform] = received[0].transforms
    assert (transform.header.stamp.sec, transform.child_frame_id) == (2002, 'frame_2')
    # names that are no moving joint are ignored silently, but the message is still answered
    publisher.publish(joint_state(['nobody', 'world_to_frame_1'], [1.0, 2.0], 2003 * SECOND))
    wait_until(lambda: len(received) == 2, what='the empty /tf message')
    assert list(received[1].transforms) == []
    assert rsp.process.poll() is None


def test_jsp_takes_the_description_from_the_topic_and_merges_sources(
    spawn: Any, world: World
) -> None:
    """Without a file, joint_state_publisher waits for the latched robot_description (published
    by robot_state_publisher), publishes defaults, and republishes values from source_list."""
    from tf_demo.transport.messages import sensor_msgs

    jsp = Running(
        spawn.start(
            'joint_state_publisher',
            '--ros-args',
            '-p',
            'rate:=20',
            '-p',
            'source_list:=[ext_states]',
        )
    )
    jsp.wait_for('Waiting for robot_description to be published on the robot_description topic')
    rsp = Running(
        spawn.start(
            'robot_state_publisher',
            '--ros-args',
            '-p',
            f'urdf_file:={SAMPLES / "example_revolute.urdf"}',
        )
    )
    client = world.node('jsp_client')
    states: list[Any] = []
    client.create_subscription(sensor_msgs.JointState, 'joint_states', states.append, 10)
    source = client.create_publisher(sensor_msgs.JointState, 'ext_states', 10)
    world.start()
    wait_until(lambda: bool(states), what='joint states after the description arrived')
    assert list(states[-1].name) == ['frame_1_to_frame_2']
    assert list(states[-1].position) == [0.0]
    wait_until(lambda: source.get_subscription_count() >= 1, what='source_list subscription')
    source.publish(joint_state(['frame_1_to_frame_2', 'unknown'], [1.25, 9.0], 0))
    wait_until(lambda: list(states[-1].position) == [1.25], what='the source value republished')
    assert list(states[-1].name) == ['frame_1_to_frame_2']
    assert rsp.process.poll() is None


def test_positional_urdf_file_fallback_of_upstream(spawn: Any) -> None:
    """A non-ROS argument is taken as the URDF file (with upstream's warning); a missing one
    is a one-line error naming it."""
    ok = Running(spawn.start('robot_state_publisher', str(SAMPLES / 'example_fixed.urdf')))
    ok.wait_for('Assuming argument is name of URDF file.')
    ok.wait_for('Robot initialized')
    missing = spawn.start('robot_state_publisher', 'no_such.urdf')
    _, stderr = missing.communicate(timeout=60)
    assert missing.returncode == 1
    assert 'Failed to load URDF file no_such.urdf: no_such.urdf: file: no such file' in stderr
    assert 'Traceback' not in stderr


def test_backward_sim_time_jump_resets_the_throttle(world: World, capfd: Any) -> None:
    """With use_sim_time, /clock going backwards warns and lets a throttled stamp through."""
    from tf_demo.transport.messages import rosgraph_msgs
    from tf_demo.transport.messages import sensor_msgs
    from tf_demo.transport.messages import tf2_msgs
    from tf_demo.transport.qos import QoSProfile

    model = RobotModel.from_file(SAMPLES / 'example_revolute.urdf')
    rsp = world.rsp(model.xml, use_sim_time=True)
    client = world.node('sim_clock')
    clock = client.create_publisher(rosgraph_msgs.Clock, '/clock', QoSProfile(depth=10))
    received: list[Any] = []
    client.create_subscription(tf2_msgs.TFMessage, '/tf', received.append, 100)
    publisher = client.create_publisher(sensor_msgs.JointState, 'joint_states', 10)
    world.start()
    wait_until(lambda: publisher.get_subscription_count() >= 1, what='rsp subscription')
    wait_until(lambda: clock.get_subscription_count() >= 1, what='rsp /clock subscription')
    wait_until(lambda: client.count_publishers('/tf') >= 1, what='rsp /tf publisher')

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


def test_jsp_ignores_an_invalid_description_from_the_topic(world: World) -> None:
    """A broken description on robot_description is reported; the node keeps running and takes
    the next valid one."""
    from tf_demo.nodes.joint_state_publisher import JointStatePublisher
    from tf_demo.transport.messages import message_module
    from tf_demo.transport.messages import sensor_msgs
    from tf_demo.transport.messages import std_msgs
    from tf_demo.transport.qos import DurabilityPolicy
    from tf_demo.transport.qos import QoSProfile

    world.add(JointStatePublisher(None))
    client = world.node('description_source')
    description = client.create_publisher(
        std_msgs.String,
        'robot_description',
        QoSProfile(depth=1, durability=DurabilityPolicy.TRANSIENT_LOCAL),
    )
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
    world.start()
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


def test_topics_and_qos_are_upstreams(world: World) -> None:
    """joint_states: sensor data QoS; /tf: reliable volatile 100; /tf_static and
    robot_description: reliable transient local 1."""
    from tf_demo.transport.qos import DurabilityPolicy
    from tf_demo.transport.qos import ReliabilityPolicy

    rsp = world.rsp(RobotModel.from_file(SAMPLES / 'example_fixed.urdf').xml, reliable_input=False)
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


def test_qos_overrides_parameters_change_the_profiles(world: World) -> None:
    """qos_overrides.<topic>.<entity>.<policy> parameters are declared and applied at start."""
    from tf_demo.transport.qos import DurabilityPolicy
    from tf_demo.transport.qos import HistoryPolicy

    rsp = world.rsp(
        RobotModel.from_file(SAMPLES / 'example_fixed.urdf').xml,
        **{
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
        world.rsp(
            RobotModel.from_file(SAMPLES / 'example_fixed.urdf').xml,
            **{'qos_overrides./tf.publisher.reliability': 'sometimes'},
        )
