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

    ros2 launch tf_demo mobile_robot.launch.py [viewer:=rviz|web|none] [rviz:=true|false]
        [radius:=1.0]
"""

import os
import sys

from launch.substitutions import Command
from launch.substitutions import LaunchConfiguration
from launch_ros.parameter_descriptions import ParameterValue

from launch import LaunchDescription

sys.path.insert(0, os.path.dirname(__file__))  # tf_demo_launch is installed beside this file
from tf_demo_launch import radius_argument
from tf_demo_launch import share_path
from tf_demo_launch import tf_demo_node
from tf_demo_launch import viewer
from tf_demo_launch import viewer_argument


def generate_launch_description() -> LaunchDescription:
    xacro_file = share_path('urdf', 'mobile_robot.urdf.xacro')
    robot_description = ParameterValue(Command(['xacro ', xacro_file]), value_type=str)
    return LaunchDescription(
        [
            *viewer_argument(),
            radius_argument(),
            tf_demo_node(
                executable='robot_state_publisher',
                name='robot_state_publisher',
                robot_description=robot_description,
            ),
            tf_demo_node(executable='joint_state_publisher', name='joint_state_publisher'),
            tf_demo_node(
                executable='dynamic_tf_pub',
                name='odometry',
                parent_frame='odom',
                child_frame='base_footprint',
                radius=LaunchConfiguration('radius'),
            ),
            *viewer('odom'),
        ]
    )
