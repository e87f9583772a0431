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
The course demo: static base_link -> camera_link, moving odom -> base_link, and a viewer
(rviz2, or tf_view in the browser).

    ros2 launch tf_demo tf_demo.launch.py [viewer:=rviz|web|none] [rviz:=true|false] [radius:=2.0]
"""

import os
import sys

from launch.substitutions import LaunchConfiguration

from launch import LaunchDescription

sys.path.insert(0, os.path.dirname(__file__))  # tf_demo_launch is installed beside this file
from tf_demo_launch import radius_argument
from tf_demo_launch import tf_demo_node
from tf_demo_launch import viewer
from tf_demo_launch import viewer_argument


def generate_launch_description() -> LaunchDescription:
    return LaunchDescription(
        [
            *viewer_argument(),
            radius_argument(),
            tf_demo_node(executable='static_tf_pub', name='static_tf_pub'),
            tf_demo_node(
                executable='dynamic_tf_pub',
                name='dynamic_tf_pub',
                radius=LaunchConfiguration('radius'),
            ),
            *viewer('odom'),
        ]
    )
