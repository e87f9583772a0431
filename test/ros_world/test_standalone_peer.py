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
A standalone node is a full peer for ROS 2's tools: the real ros2cli against standalone processes.

``ros2 param list/get/set/describe`` through the parameter services (rmw_cyclonedds' request/reply
mapping), ``ros2 service list``, ``/parameter_events`` and ``/rosout`` seen by real rclpy, and a
standalone Buffer's ``tf2_frames`` service called by a real rclpy client and by ``view_frames``.
The standalone processes run from ``TF_DEMO_STANDALONE_PYTHON`` (no ROS in their environment).
"""

from __future__ import annotations

from collections.abc import Callable
from collections.abc import Iterator
import math
from pathlib import Path
import subprocess
from typing import Any

from conftest import eventually
from conftest import PARAMETER_SERVICES
from conftest import run_captured
import pytest
from ros_world.jazzy import graph_lists
from ros_world.jazzy import RclpyNode
from ros_world.jazzy import require_package
from ros_world.jazzy import require_ros2_cli
from ros_world.jazzy import ros2
from ros_world.jazzy import standalone_command
from ros_world.jazzy import standalone_env
from ros_world.jazzy import started

pytestmark = [pytest.mark.rclpy_world, pytest.mark.timeout(300)]


@pytest.fixture
def ros2_env(world_env: dict[str, str]) -> dict[str, str]:
    """The test's private domain, with the real ros2cli on PATH."""
    require_ros2_cli()
    return world_env


@pytest.fixture
def real_node(ros2_env: dict[str, str]) -> Iterator[RclpyNode]:
    del ros2_env
    node = RclpyNode('standalone_peer_checker')
    try:
        yield node
    finally:
        node.close()


def param(env: dict[str, str], *args: str) -> subprocess.CompletedProcess[str]:
    """Run ``ros2 param ...`` without the daemon."""
    return ros2(env, 'param', *args, '--no-daemon', timeout=90)


def until(check: Callable[[], Any], timeout: float = 60.0) -> Any:
    return eventually(check, timeout, 0.2)


def test_ros2_param_works_on_a_standalone_node(
    ros2_env: dict[str, str], real_node: RclpyNode
) -> None:
    """list/get/set/describe on a standalone dynamic_tf_pub; the set radius moves the frame."""
    from rcl_interfaces.msg import ParameterEvent
    from rclpy.qos import qos_profile_parameter_events
    from tf2_msgs.msg import TFMessage

    events = real_node.collect(ParameterEvent, '/parameter_events', qos_profile_parameter_events)
    tf = real_node.collect(TFMessage, '/tf', 100)
    command = standalone_command('nodes.dynamic_tf_pub', '--ros-args', '-p', 'radius:=1.5')
    with started(command, standalone_env(ros2_env)) as process:
        assert graph_lists(ros2_env, 'node', timeout=60)('/dynamic_tf_pub')
        listed = until(
            lambda: (r := param(ros2_env, 'list', '/dynamic_tf_pub')).returncode == 0 and r
        )
        assert listed, 'ros2 param list failed'
        names = listed.stdout.split()
        for name in ('radius', 'rate', 'parent_frame', 'child_frame', 'use_sim_time'):
            assert name in names, listed.stdout
        got = param(ros2_env, 'get', '/dynamic_tf_pub', 'radius')
        assert got.stdout.strip() == 'Double value is: 1.5', (got.stdout, got.stderr)
        frame = param(ros2_env, 'get', '/dynamic_tf_pub', 'parent_frame')
        assert frame.stdout.strip() == 'String value is: odom', (frame.stdout, frame.stderr)
        described = param(ros2_env, 'describe', '/dynamic_tf_pub', 'radius')
        assert 'Parameter name: radius' in described.stdout, (described.stdout, described.stderr)
        assert 'Type: double' in described.stdout

        set_ = param(ros2_env, 'set', '/dynamic_tf_pub', 'radius', '2.5')
        assert 'Set parameter successful' in set_.stdout, (set_.stdout, set_.stderr)
        assert param(ros2_env, 'get', '/dynamic_tf_pub', 'radius').stdout.strip() == (
            'Double value is: 2.5'
        )
        refused = param(ros2_env, 'set', '/dynamic_tf_pub', 'radius', 'not_a_number')
        assert 'Setting parameter failed: parameter' in refused.stderr, (
            refused.stdout,
            refused.stderr,
        )
        count = len(tf)

        def radius_now() -> bool:
            return any(
                abs(math.hypot(t.transform.translation.x, t.transform.translation.y) - 2.5) < 1e-9
                for message in tf[count:]
                for t in message.transforms
            )

        assert until(radius_now), 'the new radius did not reach /tf'

        def changed_event() -> bool:
            return any(
                event.node == '/dynamic_tf_pub'
                and [(p.name, p.value.double_value) for p in event.changed_parameters]
                == [('radius', 2.5)]
                for event in events
            )

        assert until(changed_event), events
        assert process.poll() is None


def test_ros2_service_list_shows_standalone_parameter_services(ros2_env: dict[str, str]) -> None:
    """The six parameter services appear in ros2 service list and ros2 node info."""
    command = standalone_command('nodes.static_tf_pub')
    with started(command, standalone_env(ros2_env)):
        shows = graph_lists(ros2_env, 'service', timeout=60)
        for suffix in PARAMETER_SERVICES:
            assert shows(f'/static_tf_pub/{suffix}'), suffix
        typed = ros2(ros2_env, 'service', 'type', '/static_tf_pub/get_parameters')
        assert typed.stdout.strip() == 'rcl_interfaces/srv/GetParameters', typed
        info = until(
            lambda: (
                'Service Servers:'
                in (r := ros2(ros2_env, 'node', 'info', '/static_tf_pub', '--no-daemon')).stdout
                and '/static_tf_pub/set_parameters' in r.stdout
                and r
            )
        )
        assert info, 'ros2 node info does not list the parameter services'
        assert '/rosout: rcl_interfaces/msg/Log' in info.stdout
        assert '/parameter_events: rcl_interfaces/msg/ParameterEvent' in info.stdout


def test_rosout_carries_standalone_log_lines(
    ros2_env: dict[str, str], real_node: RclpyNode
) -> None:
    """A real rclpy /rosout subscription and ros2 topic echo see a standalone node's log line."""
    from rcl_interfaces.msg import Log
    from rclpy.qos import DurabilityPolicy
    from rclpy.qos import QoSProfile
    from rclpy.qos import ReliabilityPolicy

    rosout_qos = QoSProfile(
        depth=1000,
        reliability=ReliabilityPolicy.RELIABLE,
        durability=DurabilityPolicy.TRANSIENT_LOCAL,
    )  # rcl's rcl_qos_profile_rosout_default, but for the lifespan
    logs = real_node.collect(Log, '/rosout', rosout_qos)
    echo = ['ros2', 'topic', 'echo', '--once', '/rosout', 'rcl_interfaces/msg/Log']
    with started(echo, ros2_env) as echo_process:

        def subscribed() -> bool:
            info = ros2(ros2_env, 'topic', 'info', '/rosout', '--no-daemon').stdout
            return 'Subscription count: 2' in info  # this test's node and ros2 topic echo

        assert until(subscribed), 'ros2 topic echo did not subscribe to /rosout'
        command = standalone_command('nodes.dynamic_tf_pub')
        with started(command, standalone_env(ros2_env)):

            def published() -> list[Any]:
                return [m for m in logs if m.name == 'dynamic_tf_pub' and 'circle' in m.msg]

            assert until(published), [m.msg for m in logs]
            echoed, _ = echo_process.communicate(timeout=90)
        [line] = published()[:1]
        assert line.level == Log.INFO
        assert line.msg.startswith('Publishing odom -> base_link on a circle of radius 1 m')
        assert line.file.endswith('dynamic_tf_pub.py')
        assert line.function == '__init__'
        assert line.line > 0
        assert line.stamp.sec > 0
    assert 'name: dynamic_tf_pub' in echoed, echoed
    assert 'msg: Publishing odom -> base_link on a circle of radius 1 m' in echoed


def test_tf2_frames_of_a_standalone_buffer(ros2_env: dict[str, str], real_node: RclpyNode) -> None:
    """A real rclpy client gets the standalone tf_listener Buffer's frames as YAML."""
    from tf2_msgs.srv import FrameGraph
    import yaml

    standalone = standalone_env(ros2_env)
    with (
        started(standalone_command('nodes.static_tf_pub'), standalone),
        started(standalone_command('nodes.tf_listener'), standalone),
    ):

        def frames() -> Any:
            response = real_node.call(FrameGraph, '/tf2_frames', FrameGraph.Request())
            data = yaml.safe_load(response.frame_yaml) if response is not None else None
            return data if data and 'camera_link' in data else None

        data = until(frames, timeout=90)
        assert data, 'no tf2_frames answer with camera_link'
        assert data['camera_link']['parent'] == 'base_link'
        assert data['camera_link']['broadcaster']


def test_real_view_frames_draws_a_standalone_tree(
    ros2_env: dict[str, str], tmp_path: Path
) -> None:
    """ros2 run tf2_tools view_frames renders the tree standalone publishers broadcast."""
    require_package(ros2_env, 'tf2_tools')
    standalone = standalone_env(ros2_env)
    with (
        started(standalone_command('nodes.static_tf_pub'), standalone),
        started(standalone_command('nodes.tf_listener'), standalone),
    ):
        assert graph_lists(ros2_env, 'service', timeout=60)('/tf2_frames')
        view_frames = ['ros2', 'run', 'tf2_tools', 'view_frames', '-t', '3', '-o', 'frames']
        completed = run_captured(view_frames, ros2_env, cwd=tmp_path, timeout=120)
    assert completed.returncode == 0, (completed.stdout, completed.stderr)
    drawing = (tmp_path / 'frames.gv').read_text()
    assert '"base_link" -> "camera_link"' in drawing, drawing
