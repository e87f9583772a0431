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
The world's node class: ``rclpy.node.Node`` in the rclpy world, else the standalone one.

Every node of the package subclasses this :class:`Node`. The world is chosen once, when the
module is first imported (:func:`tf_demo.transport.backend.rclpy_world`); the type checker sees
the standalone class (:class:`tf_demo.transport.dds.node.DdsNode`), which has rclpy's method
names and signatures.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from tf_demo.transport.backend import rclpy_world

if TYPE_CHECKING or not rclpy_world():
    from tf_demo.transport.dds.node import *  # noqa: F403 - the standalone names
else:  # pragma: no cover - needs a ROS 2 installation
    from rclpy.node import *  # noqa: F403 - rclpy's own

# As ``rclpy.node`` imports rclpy.time, rclpy.qos, ...: with ``import tf_demo.transport as
# rclpy``, the course's ``rclpy.time.Time()`` works once its ``Node`` is imported.
from tf_demo.transport import import_rclpy_submodules

import_rclpy_submodules()
