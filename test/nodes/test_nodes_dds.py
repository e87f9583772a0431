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

"""The tutorial nodes as real processes over DDS, checked by an in-process tf listener."""

from __future__ import annotations

from collections.abc import Iterator
import itertools
import math
from pathlib import Path
import subprocess
import time
from typing import Any

from conftest import ProcessOutput
import pytest
from tf_demo import transport
from tf_demo.msgs.convert import ns_from_stamp
from tf_demo.ros import Buffer
from tf_demo.ros import TransformListener
from tf_demo.transport.clock import Duration
from tf_demo.transport.executors import SingleThreadedExecutor
from tf_demo.transport.messages import nav_msgs
from tf_demo.transport.messages import tf2_msgs
from tf_demo.transport.qos import DynamicListenerQoS

pytestmark = pytest.mark.dds

REPO = Path(__file__).resolve().parents[2]
STARTUP_TIMEOUT_S = 60.0
S = 1_000_000_000
CAMERA_OFFSET = (0.5, 0.0, 0.2)


@pytest.fixture
def tf_buffer(ros: None) -> Iterator[Buffer]:
    """A buffer filled by a listener with its own spin thread."""
    node = transport.create_node('test_listener')
    buffer = Buffer(node=node)
    listener = TransformListener(buffer, node, spin_thread=True)
    try:
        yield buffer
    finally:
        listener.unregister()


def assert_can_transform(
    buffer: Buffer, target: str, source: str, process: subprocess.Popen[str]
) -> None:
    """Wait for target <- source; on failure report what the publishing process said."""
    if buffer.can_transform(target, source, 0, Duration(seconds=STARTUP_TIMEOUT_S)):
        return
    details = f'process exit code {process.poll()}'
    if process.poll() is not None:
        details += f'; stderr: {process.stderr.read() if process.stderr else ""}'
    msg = f'{target} <- {source} never became available ({details})'
    raise AssertionError(msg)


def xyz(msg: Any) -> tuple[float, float, float]:
    t = msg.transform.translation
    return (t.x, t.y, t.z)


def xyzw(msg: Any) -> tuple[float, float, float, float]:
    q = msg.transform.rotation
    return (q.x, q.y, q.z, q.w)


def expected_camera_in_odom(yaw: float, position: tuple[float, float]) -> tuple[float, ...]:
    """odom_T_camera = circle pose (position, yaw) composed with the static offset."""
    ox, _, oz = CAMERA_OFFSET
    return (position[0] + ox * math.cos(yaw), position[1] + ox * math.sin(yaw), oz)


def assert_yaw_quaternion(actual: tuple[float, ...], yaw: float) -> None:
    expected = (0.0, 0.0, math.sin(yaw / 2.0), math.cos(yaw / 2.0))
    sign = 1.0 if sum(a * e for a, e in zip(actual, expected, strict=True)) >= 0 else -1.0
    assert [sign * a for a in actual] == pytest.approx(expected, abs=1e-6)


def test_late_listener_gets_static_and_interpolates_the_analytic_circle(
    spawn: Any, ros: None
) -> None:
    """Static + dynamic publishers; listeners started later see both; lookups match to 1e-6."""
    # Expected values are analytic: the course's circle at the published stamps, interpolated
    # as tf2 does (linear position, slerp of the yaw), composed with the static camera offset.
    static = spawn.start('static_tf_pub')
    dynamic = spawn.start('dynamic_tf_pub')
    observer = transport.create_node('tf_observer')
    samples: dict[int, tuple[float, float]] = {}

    def record(msg: Any) -> None:
        for t in msg.transforms:
            if (t.header.frame_id, t.child_frame_id) == ('odom', 'base_link'):
                samples[ns_from_stamp(t.header.stamp)] = (
                    t.transform.translation.x,
                    t.transform.translation.y,
                )

    observer.create_subscription(tf2_msgs.TFMessage, '/tf', record, DynamicListenerQoS())
    executor = SingleThreadedExecutor()
    executor.add_node(observer)
    deadline = time.monotonic() + STARTUP_TIMEOUT_S
    while len(samples) < 10 and time.monotonic() < deadline:
        executor.spin_once(timeout_sec=0.1)
    assert len(samples) >= 10, 'dynamic_tf_pub published nothing'
    assert static.poll() is None
    assert dynamic.poll() is None

    node = transport.create_node('late_listener')
    buffer = Buffer(node=node)
    listener = TransformListener(buffer, node, spin_thread=True)
    try:
        assert buffer.can_transform('base_link', 'camera_link', 0, Duration(seconds=30))
        assert xyz(buffer.lookup_transform('base_link', 'camera_link', 0)) == CAMERA_OFFSET
        assert buffer.can_transform('odom', 'camera_link', 0, Duration(seconds=30))
        while len(samples) < 40 and time.monotonic() < deadline:
            executor.spin_once(timeout_sec=0.1)
        stamps = sorted(s for s in samples if buffer.can_transform('odom', 'base_link', s))
        assert len(stamps) >= 5
        for before, after in itertools.pairwise(stamps):
            for ratio in (0.0, 0.25, 0.5):
                stamp = before + round((after - before) * ratio)
                out = buffer.lookup_transform('odom', 'camera_link', stamp)
                exact = (stamp - before) / (after - before)
                t0, t1 = before / 1e9, after / 1e9
                yaw = t0 + exact * (t1 - t0)
                position = (
                    math.cos(t0) + exact * (math.cos(t1) - math.cos(t0)),
                    math.sin(t0) + exact * (math.sin(t1) - math.sin(t0)),
                )
                assert xyz(out) == pytest.approx(expected_camera_in_odom(yaw, position), abs=1e-6)
                assert_yaw_quaternion(xyzw(out), yaw)
        late_process = spawn.start('tf_listener', '--ros-args', '-p', 'period:=0.2')
        line = ProcessOutput(late_process).wait_for_line(
            'Transform odom <- camera_link at ', STARTUP_TIMEOUT_S, anywhere=True
        )
        assert line.endswith('z=0.200')
    finally:
        listener.unregister()


def test_static_tf_pub_publishes_the_rep105_file(spawn: Any, tf_buffer: Buffer) -> None:
    """transforms_file=config/rep105_static_transforms.yaml publishes the whole set, latched."""
    path = REPO / 'config' / 'rep105_static_transforms.yaml'
    publisher = spawn.start('static_tf_pub', '--ros-args', '-p', f'transforms_file:={path}')
    assert_can_transform(tf_buffer, 'base_footprint', 'lidar_link', publisher)
    assert xyz(tf_buffer.lookup_transform('base_footprint', 'lidar_link', 0)) == pytest.approx(
        (0.2, 0.0, 0.35)
    )
    assert tf_buffer.can_transform('lidar_link', 'camera_link', 0, Duration(seconds=5))


def test_static_tf_pub_frame_translation_and_rpy_parameters(spawn: Any, tf_buffer: Buffer) -> None:
    """Frames, translation and an RPY rotation come from -p parameters (ints accepted)."""
    publisher = spawn.start(
        'static_tf_pub', '--ros-args',
        '-p', 'parent_frame:=world', '-p', 'child_frame:=sensor',
        '-p', 'translation:=[1, 2, 3]', '-p', 'rotation:=[0.0, 0.0, 1.5707963267948966]',
    )  # fmt: skip
    assert_can_transform(tf_buffer, 'world', 'sensor', publisher)
    out = tf_buffer.lookup_transform('world', 'sensor', 0)
    assert xyz(out) == (1.0, 2.0, 3.0)
    assert_yaw_quaternion(xyzw(out), math.pi / 2)


def test_static_tf_pub_bad_parameter_exits_1_with_one_line(spawn: Any, tmp_path: Path) -> None:
    """A bad rotation or transforms file: exit code 1 and a one-line error, no traceback."""
    bad = spawn.start('static_tf_pub', '--ros-args', '-p', 'rotation:=[1.0, 2.0]')
    _, err = bad.communicate(timeout=STARTUP_TIMEOUT_S)
    assert bad.returncode == 1
    assert err.strip().count('\n') == 0
    assert 'rotation must be 3 numbers [roll, pitch, yaw] or 4 [x, y, z, w]' in err
    broken = tmp_path / 'broken.yaml'
    broken.write_text('transforms: [{parent: a, translation: [0, 0, 0]}]\n', encoding='utf-8')
    bad_file = spawn.start('static_tf_pub', '--ros-args', '-p', f'transforms_file:={broken}')
    _, err = bad_file.communicate(timeout=STARTUP_TIMEOUT_S)
    assert bad_file.returncode == 1
    assert f"{broken}: transforms[0] is missing 'child'" in err
    assert 'Traceback' not in err


def test_tf_listener_warns_then_logs_the_translation(
    spawn: Any, world_env: dict[str, str]
) -> None:
    """Without data it warns 'Could not transform ...'; with the demo running it logs it."""
    listener = spawn.start('tf_listener', '--ros-args', '-p', 'period:=0.3')
    output = ProcessOutput(listener)
    warning = output.wait_for_line(
        'Could not transform odom to camera_link: ', STARTUP_TIMEOUT_S, anywhere=True
    )
    assert '[WARN]' in warning
    spawn.start('static_tf_pub')
    spawn.start('dynamic_tf_pub')
    line = output.wait_for_line(
        'Transform odom <- camera_link at ', STARTUP_TIMEOUT_S, anywhere=True
    )
    assert 'z=0.200' in line


def test_odom_tf_broadcaster_republishes_odometry_with_its_stamp(spawn: Any, ros: None) -> None:
    """An Odometry message comes back on /tf with the same stamp, frames and pose."""
    broadcaster = spawn.start('odom_tf_broadcaster')
    node = transport.create_node('odom_source')
    odom_pub = node.create_publisher(nav_msgs.Odometry, '/odom', 10)
    received: list[Any] = []
    node.create_subscription(
        tf2_msgs.TFMessage, '/tf', lambda m: received.extend(m.transforms), DynamicListenerQoS()
    )
    odom = nav_msgs.Odometry()
    odom.header.stamp.sec, odom.header.stamp.nanosec = 4321, 1234
    odom.header.frame_id, odom.child_frame_id = 'odom', 'base_link'
    odom.pose.pose.position.x, odom.pose.pose.position.y = 1.5, -2.5
    odom.pose.pose.orientation.z, odom.pose.pose.orientation.w = math.sqrt(0.5), math.sqrt(0.5)
    executor = SingleThreadedExecutor()
    executor.add_node(node)
    deadline = time.monotonic() + STARTUP_TIMEOUT_S
    while not received and time.monotonic() < deadline and broadcaster.poll() is None:
        odom_pub.publish(odom)
        executor.spin_once(timeout_sec=0.2)
    assert received, 'no transform came back'
    t = received[0]
    assert (t.header.stamp.sec, t.header.stamp.nanosec) == (4321, 1234)
    assert (t.header.frame_id, t.child_frame_id) == ('odom', 'base_link')
    assert xyz(t) == (1.5, -2.5, 0.0)
    assert xyzw(t) == (0.0, 0.0, math.sqrt(0.5), math.sqrt(0.5))


def test_point_transformer_logs_the_point_in_map(spawn: Any, world_env: dict[str, str]) -> None:
    """With map -> base_link = (1, 2, 0) yawed 90 degrees, (1, 0, 0) is (1, 3, 0) in map."""
    spawn.start(
        'static_tf_pub', '--ros-args',
        '-p', 'parent_frame:=map', '-p', 'child_frame:=base_link',
        '-p', 'translation:=[1.0, 2.0, 0.0]', '-p', 'rotation:=[0.0, 0.0, 1.5707963267948966]',
    )  # fmt: skip
    transformer = spawn.start('point_transformer', '--ros-args', '-p', 'period:=0.3')
    line = ProcessOutput(transformer).wait_for_line(
        'Point (1.000, 0.000, 0.000) in base_link is ', STARTUP_TIMEOUT_S, anywhere=True
    )
    assert line.endswith('is (1.000, 3.000, 0.000) in map')
