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
from launch.actions import OpaqueFunction
from launch.launch_context import LaunchContext
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
#: The course launch's switch (``rviz:=true|false``); ``auto`` when not given.
RVIZ_SWITCH = ('true', 'false', 'auto')


def viewer_argument() -> list[DeclareLaunchArgument]:
    """
    ``viewer:=rviz|web|none`` and the course's ``rviz:=true|false`` (true: rviz, false: none).

    ``viewer:=`` wins when both are given; with neither, rviz2 where it is installed, else
    tf_view in the browser (:func:`chosen_viewer`).
    """
    return [
        DeclareLaunchArgument(
            'viewer',
            default_value='auto',
            choices=['auto', *VIEWERS],
            description='rviz: rviz2; web: tf_view, a 3D view in the browser; none: no viewer '
            '(auto: as rviz:= says, else rviz where rviz2 is installed, else web)',
        ),
        DeclareLaunchArgument(
            'rviz',
            default_value='auto',
            choices=list(RVIZ_SWITCH),
            description="the course launch's switch: true is viewer:=rviz, false viewer:=none",
        ),
    ]


def chosen_viewer(viewer: str, rviz: str, rviz_is_installed: bool) -> str:
    """The viewer to start from ``viewer:=`` and ``rviz:=`` (both ``auto`` when not given)."""
    if viewer != 'auto':
        return viewer
    if rviz != 'auto':
        return 'rviz' if rviz == 'true' else 'none'
    return 'rviz' if rviz_is_installed else 'web'


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


def viewer(fixed_frame: str, *rviz_arguments: str) -> list[OpaqueFunction]:
    """
    The chosen viewer on ``fixed_frame`` (:func:`chosen_viewer`): rviz2 on tf_demo's
    configuration (``rviz_arguments`` added), tf_view (which prints its URL; where the ``view``
    extra is missing it says so in one line and the launch goes on without it), or none.
    """

    def nodes(context: LaunchContext) -> list[Node]:
        chosen = chosen_viewer(
            LaunchConfiguration('viewer').perform(context),
            LaunchConfiguration('rviz').perform(context),
            rviz_installed(),
        )
        if chosen == 'rviz':
            arguments = ['-d', share_path('config', 'tf_demo.rviz'), '-f', fixed_frame]
            return [
                Node(
                    package='rviz2',
                    executable='rviz2',
                    name='rviz2',
                    arguments=[*arguments, *rviz_arguments],
                    output='screen',
                )
            ]
        if chosen == 'web':
            return [
                Node(
                    package='tf_demo',
                    executable='tf_view',
                    name='tf_view',
                    arguments=['--fixed-frame', fixed_frame, '--optional'],
                    output='screen',
                )
            ]
        return []

    return [OpaqueFunction(function=nodes)]
