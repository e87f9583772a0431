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
``static_transform_publisher``: publish one static transform, latched, until stopped.

Same arguments, texts and exit codes as tf2_ros' C++ tool in ROS 2 Jazzy::

    static_transform_publisher --x 1 --yaw 1.57 --frame-id base_link --child-frame-id laser
    static_transform_publisher 1 0 0 1.57 0 0 base_link laser      # deprecated: yaw pitch roll
    static_transform_publisher 1 0 0 0 0 0 1 base_link laser       # deprecated: quaternion

Errors print ``[ERROR] ... error parsing command line arguments: <why>`` and the usage, exit 1;
``--help`` prints the usage and exits 0. The transform is sent once on ``/tf_static``
(transient-local, so late listeners get it) by a node called
``static_transform_publisher_<16 random characters>``.
"""

from __future__ import annotations

import secrets
import string
import sys
from typing import TYPE_CHECKING

from tf_demo.cli._args import parse_static_transform_args
from tf_demo.cli._live import log_unnamed
from tf_demo.cli.formatting import format_static_info
from tf_demo.cli.formatting import STATIC_USAGE
from tf_demo.transport.ros_args import split_ros_args

if TYPE_CHECKING:
    from tf_demo.transport.node import Node
    from tf_demo.transport.qos import QoSProfile

TOOL = 'static_transform_publisher'


def random_node_name() -> str:
    """Return ``static_transform_publisher_`` plus 16 random letters and digits, as upstream."""
    alphabet = string.ascii_letters + string.digits
    return TOOL + '_' + ''.join(secrets.choice(alphabet) for _ in range(16))


STATIC_TOPIC = '/tf_static'
QOS_OVERRIDABLE = ('depth', 'history', 'reliability')


def static_broadcaster_qos(node: Node) -> QoSProfile:
    """
    tf2's static broadcaster QoS, after upstream's ``qos_overrides./tf_static.publisher.*``.

    tf2_ros' C++ StaticTransformBroadcaster publishes with ``QosOverridingOptions`` for depth,
    history and reliability.
    """
    from tf_demo.nodes.helpers import declare_qos_overrides
    from tf_demo.transport.qos import StaticBroadcasterQoS

    profile: QoSProfile = declare_qos_overrides(
        node, STATIC_TOPIC, 'publisher', StaticBroadcasterQoS(), QOS_OVERRIDABLE
    )
    return profile


def make_node(
    translation: tuple[float, float, float],
    rotation: tuple[float, float, float, float],
    frame_id: str,
    child_frame_id: str,
) -> Node:
    """Create the node, publish the transform once (latched) and log the start-up line."""
    from tf_demo import transport
    from tf_demo.msgs.convert import fill_transform_stamped
    from tf_demo.ros import StaticTransformBroadcaster
    from tf_demo.transport.messages import geometry_msgs
    from tf_demo.transport.parameters import ParameterDescriptor

    node = transport.create_node(random_node_name())
    values = {
        'translation.x': translation[0],
        'translation.y': translation[1],
        'translation.z': translation[2],
        'rotation.x': rotation[0],
        'rotation.y': rotation[1],
        'rotation.z': rotation[2],
        'rotation.w': rotation[3],
        'frame_id': frame_id,
        'child_frame_id': child_frame_id,
    }
    for name, value in values.items():
        node.declare_parameter(name, value, ParameterDescriptor(read_only=True))
    if frame_id == child_frame_id:
        node.get_logger().error(
            f"cannot publish static transform from '{frame_id}' to '{child_frame_id}', exiting"
        )
        node.destroy_node()
        msg = f"frame_id and child_frame_id are both '{frame_id}'"
        raise ValueError(msg)
    message = geometry_msgs.TransformStamped()
    fill_transform_stamped(
        message,
        frame_id,
        child_frame_id,
        node.get_clock().now().nanoseconds,
        translation,
        rotation,
    )
    # The node owns the broadcaster's latched publisher (rclpy's and the standalone node alike).
    StaticTransformBroadcaster(node, static_broadcaster_qos(node)).send_transform(message)
    node.get_logger().info(format_static_info(translation, rotation, frame_id, child_frame_id))
    return node


def main(args: list[str] | None = None) -> int:
    """Run static_transform_publisher with ``args`` (default: ``sys.argv[1:]``)."""
    tool_args, ros_args = split_ros_args(sys.argv[1:] if args is None else args)
    parsed = parse_static_transform_args(tool_args)
    for warning in parsed.warnings:
        log_unnamed('WARN', warning)
    if parsed.error:
        log_unnamed('ERROR', f'error parsing command line arguments: {parsed.error}')
        sys.stdout.write(STATIC_USAGE)
        sys.stdout.flush()
        return 1
    if parsed.help:
        sys.stdout.write(STATIC_USAGE)
        sys.stdout.flush()
        return 0
    from tf_demo import transport

    return transport.run_node(
        lambda: make_node(
            parsed.translation, parsed.rotation, parsed.frame_id, parsed.child_frame_id
        ),
        [TOOL, *ros_args],
    )


if __name__ == '__main__':
    sys.exit(main())
