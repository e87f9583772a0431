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

    ros2 launch tf_demo rep105.launch.py [rviz:=false]
"""

import os

from ament_index_python.packages import get_package_share_directory
from ament_index_python.packages import PackageNotFoundError
from launch.actions import DeclareLaunchArgument
from launch.conditions import IfCondition
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node

from launch import LaunchDescription


def rviz_installed() -> bool:
    """Whether rviz2 is installed (it is not part of every ROS 2 installation)."""
    try:
        get_package_share_directory('rviz2')
    except PackageNotFoundError:
        return False
    return True


def generate_launch_description() -> LaunchDescription:
    share = get_package_share_directory('tf_demo')
    transforms_file = os.path.join(share, 'config', 'rep105_static_transforms.yaml')
    rviz_config = os.path.join(share, 'config', 'tf_demo.rviz')
    return LaunchDescription(
        [
            DeclareLaunchArgument(
                'rviz',
                default_value=str(rviz_installed()).lower(),
                description='Start rviz2 (default: true where rviz2 is installed)',
            ),
            Node(
                package='tf_demo',
                executable='static_tf_pub',
                name='robot_static_frames',
                output='screen',
                parameters=[{'transforms_file': transforms_file}],
            ),
            Node(
                package='tf_demo',
                executable='static_tf_pub',
                name='map_to_odom',
                output='screen',
                parameters=[
                    {
                        'parent_frame': 'map',
                        'child_frame': 'odom',
                        'translation': [0.0, 0.0, 0.0],
                        'rotation': [0.0, 0.0, 0.0],
                    }
                ],
            ),
            Node(
                package='tf_demo',
                executable='dynamic_tf_pub',
                name='odometry',
                output='screen',
                parameters=[{'parent_frame': 'odom', 'child_frame': 'base_footprint'}],
            ),
            Node(
                package='rviz2',
                executable='rviz2',
                name='rviz2',
                arguments=['-d', rviz_config, '-f', 'map'],
                condition=IfCondition(LaunchConfiguration('rviz')),
                output='screen',
            ),
        ]
    )
