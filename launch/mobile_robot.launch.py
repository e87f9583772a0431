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
The REP-105 mobile robot of ``urdf/mobile_robot.urdf.xacro``, driven around a circle.

robot_state_publisher publishes the robot's frames (base_footprint -> base_link -> wheels, lidar
and camera) from the xacro, joint_state_publisher feeds it the wheel joints (it reads the model
from ``robot_description``), and dynamic_tf_pub moves odom -> base_footprint on a circle (a
stand-in for odometry).

    ros2 launch tf_demo mobile_robot.launch.py [rviz:=false] [radius:=1.0]
"""

import os

from ament_index_python.packages import get_package_share_directory
from ament_index_python.packages import PackageNotFoundError
from launch.actions import DeclareLaunchArgument
from launch.conditions import IfCondition
from launch.substitutions import Command
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node
from launch_ros.parameter_descriptions import ParameterValue

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
    xacro_file = os.path.join(share, 'urdf', 'mobile_robot.urdf.xacro')
    rviz_config = os.path.join(share, 'config', 'tf_demo.rviz')
    robot_description = ParameterValue(Command(['xacro ', xacro_file]), value_type=str)
    return LaunchDescription(
        [
            DeclareLaunchArgument(
                'rviz',
                default_value=str(rviz_installed()).lower(),
                description='Start rviz2 (default: true where rviz2 is installed)',
            ),
            DeclareLaunchArgument(
                'radius', default_value='1.0', description='Radius of the circle (m)'
            ),
            Node(
                package='tf_demo',
                executable='robot_state_publisher',
                name='robot_state_publisher',
                output='screen',
                parameters=[{'robot_description': robot_description}],
            ),
            Node(
                package='tf_demo',
                executable='joint_state_publisher',
                name='joint_state_publisher',
                output='screen',
            ),
            Node(
                package='tf_demo',
                executable='dynamic_tf_pub',
                name='odometry',
                output='screen',
                parameters=[
                    {
                        'parent_frame': 'odom',
                        'child_frame': 'base_footprint',
                        'radius': LaunchConfiguration('radius'),
                    }
                ],
            ),
            Node(
                package='rviz2',
                executable='rviz2',
                name='rviz2',
                arguments=['-d', rviz_config, '-f', 'odom'],
                condition=IfCondition(LaunchConfiguration('rviz')),
                output='screen',
            ),
        ]
    )
