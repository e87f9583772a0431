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
The message modules of the selected world, so node code is written once.

``geometry_msgs.TransformStamped()`` is ``geometry_msgs.msg.TransformStamped`` under rclpy and
``tf_demo.msgs.geometry_msgs.TransformStamped`` in the standalone world.
:func:`new_transform_stamped` makes a filled one the fastest way each world allows (the
buffer's lookups answer with it), :func:`transform_stamped_args` reads one so (its inserts).
"""

from __future__ import annotations

import importlib
from types import ModuleType
from typing import TYPE_CHECKING

from tf_demo.core.buffer_core import TransformResult
from tf_demo.transport.backend import rclpy_world

__all__ = [
    'builtin_interfaces',
    'geometry_msgs',
    'message_module',
    'nav_msgs',
    'new_transform_stamped',
    'rosgraph_msgs',
    'sensor_msgs',
    'service_module',
    'std_msgs',
    'tf2_msgs',
    'transform_stamped_args',
]


def message_module(package: str) -> ModuleType:
    """Return the message module of ROS package ``package`` in the selected world."""
    if rclpy_world():
        return importlib.import_module(f'{package}.msg')
    return importlib.import_module(f'tf_demo.msgs.{package}')


def service_module(package: str) -> ModuleType:
    """Return the service module of ROS package ``package`` in the selected world."""
    if rclpy_world():
        return importlib.import_module(f'{package}.srv')
    return importlib.import_module(f'tf_demo.msgs.{package}')


# The type checker sees the standalone modules, whose classes follow rclpy's name for name.
if TYPE_CHECKING or not rclpy_world():
    from tf_demo.msgs import builtin_interfaces
    from tf_demo.msgs import geometry_msgs
    from tf_demo.msgs import nav_msgs
    from tf_demo.msgs import rosgraph_msgs
    from tf_demo.msgs import sensor_msgs
    from tf_demo.msgs import std_msgs
    from tf_demo.msgs import tf2_msgs
    from tf_demo.msgs.convert import fill_transform_stamped
    from tf_demo.msgs.convert import transform_stamped_args

    def new_transform_stamped(
        target: str, source: str, result: TransformResult
    ) -> geometry_msgs.TransformStamped:
        """Return the core's ``result`` as a TransformStamped of ``target`` <- ``source``."""
        return fill_transform_stamped(
            geometry_msgs.TransformStamped(),
            target,
            source,
            result.stamp_ns,
            result.translation,
            result.rotation,
        )

else:  # pragma: no cover - needs a ROS 2 installation
    builtin_interfaces = message_module('builtin_interfaces')
    geometry_msgs = message_module('geometry_msgs')
    nav_msgs = message_module('nav_msgs')
    rosgraph_msgs = message_module('rosgraph_msgs')
    sensor_msgs = message_module('sensor_msgs')
    std_msgs = message_module('std_msgs')
    tf2_msgs = message_module('tf2_msgs')
    from tf_demo.transport.rclpy_builders import new_transform_stamped
    from tf_demo.transport.rclpy_builders import transform_stamped_args
