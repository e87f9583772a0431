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
What tf_demo's launch files share: the viewer switch, the circle's radius, this package's nodes.

The launch files import it from their own directory (it is installed beside them, in
``share/tf_demo/launch``).
"""

import os

from ament_index_python.packages import get_package_share_directory
from ament_index_python.packages import PackageNotFoundError
from launch.actions import DeclareLaunchArgument
from launch.conditions import IfCondition
from launch.substitutions import EqualsSubstitution
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def share_path(*parts: str) -> str:
    """A path inside tf_demo's installed share directory."""
    return os.path.join(get_package_share_directory('tf_demo'), *parts)


def rviz_installed() -> bool:
    """Whether rviz2 is installed (it is not part of every ROS 2 installation)."""
    try:
        get_package_share_directory('rviz2')
    except PackageNotFoundError:
        return False
    return True


VIEWERS = ('rviz', 'web', 'none')


def viewer_argument() -> DeclareLaunchArgument:
    """``viewer:=rviz|web|none``: rviz2 where it is installed, else tf_view in the browser."""
    return DeclareLaunchArgument(
        'viewer',
        default_value='rviz' if rviz_installed() else 'web',
        choices=list(VIEWERS),
        description='rviz: rviz2; web: tf_view, a 3D view in the browser; none: no viewer '
        '(default: rviz where rviz2 is installed, else web)',
    )


def radius_argument() -> DeclareLaunchArgument:
    """``radius:=<m>``, the radius of the circle the moving frame drives (1 m by default)."""
    return DeclareLaunchArgument(
        'radius', default_value='1.0', description='Radius of the circle (m)'
    )


def tf_demo_node(*, executable: str, name: str, **parameters: object) -> Node:
    """One of tf_demo's nodes, printing to the screen, given ``parameters`` (if any)."""
    return Node(
        package='tf_demo',
        executable=executable,
        name=name,
        output='screen',
        parameters=[parameters] if parameters else None,
    )


def viewer(fixed_frame: str, *rviz_arguments: str) -> list[Node]:
    """
    The chosen viewer on ``fixed_frame``: rviz2 on tf_demo's configuration (``rviz_arguments``
    added) when ``viewer:=rviz``, tf_view (which prints its URL) when ``viewer:=web``.
    """
    chosen = LaunchConfiguration('viewer')
    return [
        Node(
            package='rviz2',
            executable='rviz2',
            name='rviz2',
            arguments=[
                '-d',
                share_path('config', 'tf_demo.rviz'),
                '-f',
                fixed_frame,
                *rviz_arguments,
            ],
            condition=IfCondition(EqualsSubstitution(chosen, 'rviz')),
            output='screen',
        ),
        Node(
            package='tf_demo',
            executable='tf_view',
            name='tf_view',
            arguments=['--fixed-frame', fixed_frame],
            condition=IfCondition(EqualsSubstitution(chosen, 'web')),
            output='screen',
        ),
    ]
