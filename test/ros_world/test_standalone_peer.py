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
import threading
from typing import Any

from jazzy import eventually
from jazzy import graph_lists
from jazzy import require_package
from jazzy import require_ros2_cli
from jazzy import ros2
from jazzy import standalone_command
from jazzy import standalone_env
from jazzy import started
import pytest

pytestmark = [pytest.mark.rclpy_world, pytest.mark.timeout(300)]

PARAMETER_SERVICES = (
    'describe_parameters',
    'get_parameter_types',
    'get_parameters',
    'list_parameters',
    'set_parameters',
    'set_parameters_atomically',
)


@pytest.fixture
def jazzy_env(world_env: dict[str, str]) -> dict[str, str]:
    """The test's private domain, with the real ros2cli on PATH."""
    require_ros2_cli()
    return world_env


class RealNode:
    """A real rclpy node in this process, spun by a thread (its own context)."""

    def __init__(self, name: str) -> None:
        import rclpy
        from rclpy.executors import SingleThreadedExecutor

        self._rclpy = rclpy
        self.context = rclpy.Context()
        rclpy.init(context=self.context)
        self.node = rclpy.create_node(name, context=self.context)
        self.executor = SingleThreadedExecutor(context=self.context)
        self.executor.add_node(self.node)
        self._thread = threading.Thread(target=self._spin, daemon=True)
        self._thread.start()

    def _spin(self) -> None:
        while self.context.ok():
            try:
                self.executor.spin_once(timeout_sec=0.1)
            except Exception:
                return

    def collect(self, msg_type: Any, topic: str, qos: Any) -> list[Any]:
        """Subscribe to ``topic``; return the list the messages are appended to."""
        received: list[Any] = []
        self.node.create_subscription(msg_type, topic, received.append, qos)
        return received

    def call(self, srv_type: Any, name: str, request: Any, timeout: float = 60.0) -> Any:
        """Call a service (waiting for it); the response, or None."""
        client = self.node.create_client(srv_type, name)
        if not client.wait_for_service(timeout_sec=timeout):
            return None
        future = client.call_async(request)
        if not eventually(future.done, timeout, 0.05):
            return None
        return future.result()

    def close(self) -> None:
        self.executor.shutdown()
        self.node.destroy_node()
        self._rclpy.shutdown(context=self.context)
        self._thread.join(10)


@pytest.fixture
def real_node(jazzy_env: dict[str, str]) -> Iterator[RealNode]:
    del jazzy_env
    node = RealNode('standalone_peer_checker')
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
    jazzy_env: dict[str, str], real_node: RealNode
) -> None:
    """list/get/set/describe on a standalone dynamic_tf_pub; the set radius moves the frame."""
    from rcl_interfaces.msg import ParameterEvent
    from rclpy.qos import qos_profile_parameter_events
    from tf2_msgs.msg import TFMessage

    events = real_node.collect(ParameterEvent, '/parameter_events', qos_profile_parameter_events)
    tf = real_node.collect(TFMessage, '/tf', 100)
    command = standalone_command('nodes.dynamic_tf_pub', '--ros-args', '-p', 'radius:=1.5')
    with started(command, standalone_env(jazzy_env)) as process:
        assert graph_lists(jazzy_env, 'node', timeout=60)('/dynamic_tf_pub')
        listed = until(
            lambda: (r := param(jazzy_env, 'list', '/dynamic_tf_pub')).returncode == 0 and r
        )
        assert listed, 'ros2 param list failed'
        names = listed.stdout.split()
        for name in ('radius', 'rate', 'parent_frame', 'child_frame', 'use_sim_time'):
            assert name in names, listed.stdout
        got = param(jazzy_env, 'get', '/dynamic_tf_pub', 'radius')
        assert got.stdout.strip() == 'Double value is: 1.5', (got.stdout, got.stderr)
        frame = param(jazzy_env, 'get', '/dynamic_tf_pub', 'parent_frame')
        assert frame.stdout.strip() == 'String value is: odom', (frame.stdout, frame.stderr)
        described = param(jazzy_env, 'describe', '/dynamic_tf_pub', 'radius')
        assert 'Parameter name: radius' in described.stdout, (described.stdout, described.stderr)
        assert 'Type: double' in described.stdout

        set_ = param(jazzy_env, 'set', '/dynamic_tf_pub', 'radius', '2.5')
        assert 'Set parameter successful' in set_.stdout, (set_.stdout, set_.stderr)
        assert param(jazzy_env, 'get', '/dynamic_tf_pub', 'radius').stdout.strip() == (
            'Double value is: 2.5'
        )
        refused = param(jazzy_env, 'set', '/dynamic_tf_pub', 'radius', 'not_a_number')
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


def test_ros2_service_list_shows_standalone_parameter_services(jazzy_env: dict[str, str]) -> None:
    """The six parameter services appear in ros2 service list and ros2 node info."""
    command = standalone_command('nodes.static_tf_pub')
    with started(command, standalone_env(jazzy_env)):
        shows = graph_lists(jazzy_env, 'service', timeout=60)
        for suffix in PARAMETER_SERVICES:
            assert shows(f'/static_tf_pub/{suffix}'), suffix
        typed = ros2(jazzy_env, 'service', 'type', '/static_tf_pub/get_parameters')
        assert typed.stdout.strip() == 'rcl_interfaces/srv/GetParameters', typed
        info = until(
            lambda: (
                'Service Servers:'
                in (r := ros2(jazzy_env, 'node', 'info', '/static_tf_pub', '--no-daemon')).stdout
                and '/static_tf_pub/set_parameters' in r.stdout
                and r
            )
        )
        assert info, 'ros2 node info does not list the parameter services'
        assert '/rosout: rcl_interfaces/msg/Log' in info.stdout
        assert '/parameter_events: rcl_interfaces/msg/ParameterEvent' in info.stdout


def test_rosout_carries_standalone_log_lines(
    jazzy_env: dict[str, str], real_node: RealNode
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
    with started(echo, jazzy_env) as echo_process:

        def subscribed() -> bool:
            info = ros2(jazzy_env, 'topic', 'info', '/rosout', '--no-daemon').stdout
            return 'Subscription count: 2' in info  # this test's node and ros2 topic echo

        assert until(subscribed), 'ros2 topic echo did not subscribe to /rosout'
        command = standalone_command('nodes.dynamic_tf_pub')
        with started(command, standalone_env(jazzy_env)):

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


def test_tf2_frames_of_a_standalone_buffer(jazzy_env: dict[str, str], real_node: RealNode) -> None:
    """A real rclpy client gets the standalone tf_listener Buffer's frames as YAML."""
    from tf2_msgs.srv import FrameGraph
    import yaml

    standalone = standalone_env(jazzy_env)
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
    jazzy_env: dict[str, str], tmp_path: Path
) -> None:
    """ros2 run tf2_tools view_frames renders the tree standalone publishers broadcast."""
    require_package(jazzy_env, 'tf2_tools')
    standalone = standalone_env(jazzy_env)
    with (
        started(standalone_command('nodes.static_tf_pub'), standalone),
        started(standalone_command('nodes.tf_listener'), standalone),
    ):
        assert graph_lists(jazzy_env, 'service', timeout=60)('/tf2_frames')
        completed = subprocess.run(
            ['ros2', 'run', 'tf2_tools', 'view_frames', '-t', '3', '-o', 'frames'],
            env=jazzy_env, cwd=tmp_path, capture_output=True, text=True, timeout=120,
            check=False,
        )  # fmt: skip
    assert completed.returncode == 0, (completed.stdout, completed.stderr)
    drawing = (tmp_path / 'frames.gv').read_text()
    assert '"base_link" -> "camera_link"' in drawing, drawing
