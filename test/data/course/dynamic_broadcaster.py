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

"""The course's dynamic broadcaster, written for rclpy and tf2_ros (odom -> base_link)."""

import math

from geometry_msgs.msg import TransformStamped
import rclpy
from rclpy.node import Node
from rclpy.qos import QoSProfile
from rclpy.qos import ReliabilityPolicy
from std_msgs.msg import String
from tf2_ros import TransformBroadcaster


class DynamicFramePublisher(Node):
    """Drive base_link on a circle of radius 2 around odom at 20 Hz."""

    def __init__(self):
        super().__init__('dynamic_frame_publisher')
        self.tf_broadcaster = TransformBroadcaster(self)
        self.status = self.create_publisher(
            String, 'robot_status', QoSProfile(depth=10, reliability=ReliabilityPolicy.RELIABLE)
        )
        self.start = self.get_clock().now()
        self.timer = self.create_timer(0.05, self.on_timer)

    def on_timer(self):
        now = self.get_clock().now()
        elapsed = (now - self.start).nanoseconds / 1e9
        t = TransformStamped()
        t.header.stamp = now.to_msg()
        t.header.frame_id = 'odom'
        t.child_frame_id = 'base_link'
        t.transform.translation.x = 2.0 * math.cos(elapsed)
        t.transform.translation.y = 2.0 * math.sin(elapsed)
        t.transform.rotation.z = math.sin(elapsed / 2)
        t.transform.rotation.w = math.cos(elapsed / 2)
        self.tf_broadcaster.sendTransform(t)
        self.status.publish(String(data='moving'))


def main(args=None):
    rclpy.init(args=args)
    node = DynamicFramePublisher()
    try:
        rclpy.spin(node)
    except KeyboardInterrupt:
        pass
    node.destroy_node()
    rclpy.try_shutdown()


if __name__ == '__main__':
    main()
