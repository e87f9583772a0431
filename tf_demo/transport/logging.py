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
Logging: rclpy's loggers in the rclpy world, else the standalone ones (rcutils' output).

The world is chosen once, when the module is first imported; the type checker sees the
standalone functions (:mod:`tf_demo.transport.dds.logging`). :func:`format_log_line` (rcutils'
line format, used by the tools in both worlds), :class:`Logger` and
:func:`set_default_logger_level` (``--log-level`` in the standalone world) are the standalone
world's in both.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from tf_demo.transport.backend import rclpy_world

if TYPE_CHECKING or not rclpy_world():
    from tf_demo.transport.dds.log_format import *  # noqa: F403 - the standalone names
    from tf_demo.transport.dds.logging import *  # noqa: F403 - the standalone names
else:  # pragma: no cover - needs a ROS 2 installation
    from rclpy.logging import *  # noqa: F403 - rclpy's own
    from tf_demo.transport.dds.log_format import DEFAULT_OUTPUT_FORMAT  # tf_demo's in both worlds
    from tf_demo.transport.dds.log_format import format_log_line
    from tf_demo.transport.dds.logging import Logger
    from tf_demo.transport.dds.logging import set_default_logger_level
