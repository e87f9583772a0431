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
The standalone world's ``geometry_msgs/msg`` types (rclpy-compatible fields and defaults).

The fields come from :data:`tf_demo.msgs._schema.DEFINITIONS`; see
:class:`tf_demo.msgs._message.Message`.
"""

from __future__ import annotations

from tf_demo.msgs._message import Message
import tf_demo.msgs.std_msgs  # noqa: F401 - defines the nested types first

__all__ = [
    'Point',
    'Point32',
    'PointStamped',
    'Polygon',
    'PolygonStamped',
    'Pose',
    'PoseStamped',
    'PoseWithCovariance',
    'PoseWithCovarianceStamped',
    'Quaternion',
    'Transform',
    'TransformStamped',
    'Twist',
    'TwistWithCovariance',
    'Vector3',
    'Vector3Stamped',
]


class Vector3(Message):
    """geometry_msgs/msg/Vector3."""


class Quaternion(Message):
    """geometry_msgs/msg/Quaternion."""


class Point(Message):
    """geometry_msgs/msg/Point."""


class Point32(Message):
    """geometry_msgs/msg/Point32."""


class Pose(Message):
    """geometry_msgs/msg/Pose."""


class Transform(Message):
    """geometry_msgs/msg/Transform."""


class TransformStamped(Message):
    """geometry_msgs/msg/TransformStamped."""


class PointStamped(Message):
    """geometry_msgs/msg/PointStamped."""


class Vector3Stamped(Message):
    """geometry_msgs/msg/Vector3Stamped."""


class PoseStamped(Message):
    """geometry_msgs/msg/PoseStamped."""


class PoseWithCovariance(Message):
    """geometry_msgs/msg/PoseWithCovariance."""


class PoseWithCovarianceStamped(Message):
    """geometry_msgs/msg/PoseWithCovarianceStamped."""


class Twist(Message):
    """geometry_msgs/msg/Twist."""


class TwistWithCovariance(Message):
    """geometry_msgs/msg/TwistWithCovariance."""


class Polygon(Message):
    """geometry_msgs/msg/Polygon."""


class PolygonStamped(Message):
    """geometry_msgs/msg/PolygonStamped."""
