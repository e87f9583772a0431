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

"""The setup the robot_state_publisher tests share: the node in process, as a process, its feed."""

from __future__ import annotations

from collections.abc import Callable
from collections.abc import Mapping
from pathlib import Path
from typing import Any
from typing import NamedTuple

from conftest import eventually
from conftest import Processes
from conftest import ProcessOutput
from conftest import Spinning
import pytest

SAMPLES = Path(__file__).resolve().parents[2] / 'urdf'
SECOND = 1_000_000_000


def wait_until(condition: Callable[[], bool], timeout: float = 10.0, what: str = '') -> None:
    """Wait (polling) until ``condition`` holds; fail naming ``what`` after ``timeout`` s."""
    if not eventually(condition, timeout, 0.01):
        pytest.fail(f'timed out waiting for {what}')


def reliable_joint_states(depth: int) -> dict[str, Any]:
    """Upstream's qos_overrides that make the joint_states subscription reliable (``depth``).

    With them a busy machine cannot drop the input a test feeds.
    """
    return {
        'qos_overrides./joint_states.subscription.reliability': 'reliable',
        'qos_overrides./joint_states.subscription.depth': depth,
    }


def parameter_args(parameters: dict[str, Any]) -> tuple[str, ...]:
    """``parameters`` as ``-p name:=value`` command-line arguments."""
    return tuple(arg for name, value in parameters.items() for arg in ('-p', f'{name}:={value}'))


def joint_state(names: list[str], positions: list[float], stamp_ns: int) -> Any:
    """A sensor_msgs/JointState of this run's world."""
    from tf_demo.transport.messages import sensor_msgs

    message = sensor_msgs.JointState()
    message.header.stamp.sec, message.header.stamp.nanosec = divmod(stamp_ns, SECOND)
    message.name = names
    message.position = positions
    return message


def add_rsp(
    nodes: Spinning,
    xml: str,
    *,
    reliable_input: bool = True,
    parameters: Mapping[str, object] | None = None,
) -> Any:
    """A robot_state_publisher node in this process on ``xml`` and ``parameters``, spun."""
    from tf_demo.nodes.robot_state_publisher import RobotStatePublisher
    from tf_demo.transport.parameters import Parameter

    overrides = [Parameter('robot_description', value=xml)]
    values = {**(reliable_joint_states(100) if reliable_input else {}), **(parameters or {})}
    overrides += [Parameter(name, value=value) for name, value in values.items()]
    return nodes.add(RobotStatePublisher((), parameter_overrides=overrides))


class Feed(NamedTuple):
    """A node that feeds robot_state_publisher joint states and collects what it puts on /tf."""

    node: Any
    joint_states: Any
    tf: list[Any]


def feed(nodes: Spinning, name: str, *, joint_states_qos: Any = 10, tf_depth: int = 100) -> Feed:
    """A :class:`Feed` node called ``name`` (spun with ``nodes``; start them when it is ready)."""
    from tf_demo.transport.messages import sensor_msgs
    from tf_demo.transport.messages import tf2_msgs

    node = nodes.node(name)
    tf: list[Any] = []
    node.create_subscription(tf2_msgs.TFMessage, '/tf', tf.append, tf_depth)
    joint_states = node.create_publisher(sensor_msgs.JointState, 'joint_states', joint_states_qos)
    return Feed(node, joint_states, tf)


def start_connected(nodes: Spinning, rsp_feed: Feed) -> None:
    """Start spinning; wait until the robot_state_publisher takes the feed and publishes /tf."""
    nodes.start()
    wait_until(
        lambda: rsp_feed.joint_states.get_subscription_count() >= 1, what='rsp subscription'
    )
    wait_until(lambda: rsp_feed.node.count_publishers('/tf') >= 1, what='rsp /tf publisher')


def urdf_file(sample: str) -> tuple[str, str]:
    """``-p urdf_file:=<a sample of urdf/>``."""
    return ('-p', f'urdf_file:={SAMPLES / sample}')


def rsp_process(spawn: Processes, *ros_args: str) -> ProcessOutput:
    """The robot_state_publisher executable started with ``--ros-args`` ``ros_args``."""
    return ProcessOutput(spawn.start('robot_state_publisher', '--ros-args', *ros_args))


def refused_in_one_line(spawn: Processes, *command: str, timeout: float = 120.0) -> str:
    """Run an executable that must refuse its input: exit code 1, one stderr line (returned)."""
    process = spawn.start(*command)
    _, stderr = process.communicate(timeout=timeout)
    lines = [line for line in stderr.splitlines() if line.strip()]
    assert process.returncode == 1, stderr
    assert len(lines) == 1, stderr
    return lines[0]
