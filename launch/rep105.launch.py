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
A REP-105 frame tree: map -> odom -> base_footprint -> base_link -> {lidar_link, camera_link}.

map -> odom is a static identity (stand-in for localisation), odom -> base_footprint moves on a
circle (stand-in for odometry) and the robot's static frames come from
``config/rep105_static_transforms.yaml``.

    ros2 launch tf_demo rep105.launch.py [viewer:=rviz|web|none] [rviz:=true|false]
"""

import os
import sys

from launch import LaunchDescription

sys.path.insert(0, os.path.dirname(__file__))  # tf_demo_launch is installed beside this file
from tf_demo_launch import share_path
from tf_demo_launch import tf_demo_node
from tf_demo_launch import viewer
from tf_demo_launch import viewer_argument


def generate_launch_description() -> LaunchDescription:
    return LaunchDescription(
        [
            *viewer_argument(),
            tf_demo_node(
                executable='static_tf_pub',
                name='robot_static_frames',
                transforms_file=share_path('config', 'rep105_static_transforms.yaml'),
            ),
            tf_demo_node(
                executable='static_tf_pub',
                name='map_to_odom',
                parent_frame='map',
                child_frame='odom',
                translation=[0.0, 0.0, 0.0],
                rotation=[0.0, 0.0, 0.0],
            ),
            tf_demo_node(
                executable='dynamic_tf_pub',
                name='odometry',
                parent_frame='odom',
                child_frame='base_footprint',
            ),
            *viewer('map'),
        ]
    )
