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

"""The course's listener, written for rclpy and tf2_ros: odom <- camera_link every 0.1 s."""

from geometry_msgs.msg import PointStamped
import rclpy
from rclpy.duration import Duration
from rclpy.executors import ExternalShutdownException
from rclpy.node import Node
from rclpy.qos import DurabilityPolicy
from rclpy.qos import QoSProfile
import tf2_geometry_msgs  # noqa: F401 - registers geometry_msgs types for Buffer.transform
from tf2_msgs.msg import TFMessage
from tf2_ros import TransformException
from tf2_ros.buffer import Buffer
from tf2_ros.transform_listener import TransformListener


class FrameListener(Node):
    """Look camera_link up in odom, transform a point, count static frames."""

    def __init__(self):
        super().__init__('frame_listener')
        self.target_frame = self.declare_parameter('target_frame', 'odom').value
        self.tf_buffer = Buffer(cache_time=Duration(seconds=10.0))
        self.tf_listener = TransformListener(self.tf_buffer, self)
        latched = QoSProfile(depth=1, durability=DurabilityPolicy.TRANSIENT_LOCAL)
        self.static_count = 0
        self.create_subscription(TFMessage, '/tf_static', self.on_static, latched)
        self.timer = self.create_timer(0.1, self.on_timer)

    def on_static(self, msg):
        self.static_count = len(msg.transforms)

    def on_timer(self):
        try:
            t = self.tf_buffer.lookup_transform(
                self.target_frame,
                'camera_link',
                rclpy.time.Time(),  # as the course writes it: rclpy's submodules by attribute
                timeout=rclpy.duration.Duration(seconds=0.05),
            )
        except TransformException as ex:
            self.get_logger().info(f'Could not transform {self.target_frame} to camera_link: {ex}')
            return
        point = PointStamped()
        point.header.frame_id = 'camera_link'
        point.header.stamp = t.header.stamp
        point.point.x = 1.0
        moved = self.tf_buffer.transform(point, self.target_frame)
        print(
            f'RESULT {t.header.frame_id} {t.child_frame_id} z={t.transform.translation.z:.3f} '
            f'point_frame={moved.header.frame_id} static_count={self.static_count}',
            flush=True,
        )


def main(args=None):
    rclpy.init(args=args)
    node = FrameListener()
    try:
        rclpy.spin(node)
    except (KeyboardInterrupt, ExternalShutdownException):
        pass
    node.destroy_node()
    rclpy.try_shutdown()


if __name__ == '__main__':
    main()
