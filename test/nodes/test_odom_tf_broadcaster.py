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

"""Pure logic of odom_tf_broadcaster: odometry to a transform."""

from __future__ import annotations

import math

from tf_demo.msgs import geometry_msgs
from tf_demo.msgs import nav_msgs
from tf_demo.nodes.odom_tf_broadcaster import transform_from_odometry


def test_odometry_becomes_a_transform_with_its_own_stamp_and_frames() -> None:
    """Stamp, frames, position and orientation are copied; empty frames use the defaults."""
    odom = nav_msgs.Odometry()
    odom.header.stamp.sec, odom.header.stamp.nanosec = 12, 345
    odom.header.frame_id = 'odom'
    odom.child_frame_id = 'base_footprint'
    odom.pose.pose.position.x, odom.pose.pose.position.y = 1.0, 2.0
    q = odom.pose.pose.orientation
    q.z, q.w = math.sqrt(0.5), math.sqrt(0.5)
    t = transform_from_odometry(odom, geometry_msgs.TransformStamped, 'o', 'b')
    assert (t.header.stamp.sec, t.header.stamp.nanosec) == (12, 345)
    assert (t.header.frame_id, t.child_frame_id) == ('odom', 'base_footprint')
    assert (t.transform.translation.x, t.transform.translation.y) == (1.0, 2.0)
    assert t.transform.rotation.z == math.sqrt(0.5)
    odom.header.frame_id = odom.child_frame_id = ''
    t = transform_from_odometry(odom, geometry_msgs.TransformStamped, 'o', 'b')
    assert (t.header.frame_id, t.child_frame_id) == ('o', 'b')
