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
``odom_tf_broadcaster``: turn ``nav_msgs/Odometry`` into the odom -> base_link transform.

Each message on ``odom_topic`` (``/odom``) is re-published on ``/tf`` with the message's own
stamp, ``header.frame_id`` as parent and ``child_frame_id`` as child. Empty frame ids in the
message fall back to the ``odom_frame`` (``odom``) and ``base_frame`` (``base_link``) parameters.
"""

from __future__ import annotations

import sys
from typing import TYPE_CHECKING

from tf_demo.nodes.helpers import as_frame
from tf_demo.nodes.helpers import declare_checked
from tf_demo.nodes.helpers import declare_flexible
from tf_demo.nodes.helpers import NodeConfigError
from tf_demo.ros.transform_broadcaster import TransformBroadcaster
from tf_demo.transport import run_node
from tf_demo.transport.node import Node

if TYPE_CHECKING:
    from tf_demo.msgs.geometry_msgs import TransformStamped
    from tf_demo.msgs.nav_msgs import Odometry

NODE_NAME = 'odom_tf_broadcaster'
ODOM_QOS_DEPTH = 10


def transform_from_odometry(
    odometry: Odometry,
    transform_type: type[TransformStamped],
    default_parent: str,
    default_child: str,
) -> TransformStamped:
    """
    Build a ``TransformStamped`` equal to the odometry pose (the message is not modified).

    :param transform_type: the ``TransformStamped`` class to build.
    """
    out = transform_type()
    out.header.stamp.sec = odometry.header.stamp.sec
    out.header.stamp.nanosec = odometry.header.stamp.nanosec
    out.header.frame_id = odometry.header.frame_id or default_parent
    out.child_frame_id = odometry.child_frame_id or default_child
    position = odometry.pose.pose.position
    orientation = odometry.pose.pose.orientation
    out.transform.translation.x = position.x
    out.transform.translation.y = position.y
    out.transform.translation.z = position.z
    out.transform.rotation.x = orientation.x
    out.transform.rotation.y = orientation.y
    out.transform.rotation.z = orientation.z
    out.transform.rotation.w = orientation.w
    return out


class OdomTfBroadcaster(Node):
    """Re-publishes odometry poses as transforms."""

    def __init__(self) -> None:
        """Read the parameters and subscribe to odometry."""
        super().__init__(NODE_NAME)
        from tf_demo.transport.messages import geometry_msgs
        from tf_demo.transport.messages import nav_msgs

        self.odom_frame = declare_checked(self, 'odom_frame', 'odom', as_frame)
        self.base_frame = declare_checked(self, 'base_frame', 'base_link', as_frame)
        topic = declare_flexible(self, 'odom_topic', '/odom')
        if not isinstance(topic, str) or not topic:
            msg = f"parameter 'odom_topic' must be a topic name, got {topic!r}"
            raise NodeConfigError(msg)
        self._transform_type = geometry_msgs.TransformStamped
        self.broadcaster = TransformBroadcaster(self)
        self.subscription = self.create_subscription(
            nav_msgs.Odometry, topic, self.on_odometry, ODOM_QOS_DEPTH
        )

    def on_odometry(self, odometry: Odometry) -> None:
        """Publish the transform of one odometry message."""
        self.broadcaster.send_transform(
            transform_from_odometry(
                odometry, self._transform_type, self.odom_frame, self.base_frame
            )
        )


def main(args: list[str] | None = None) -> int:
    """Run the node until Ctrl-C; exit 1 with a one-line error on bad parameters."""
    return run_node(OdomTfBroadcaster, args)


if __name__ == '__main__':
    sys.exit(main())
