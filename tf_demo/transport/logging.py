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
from tf_demo.transport.dds.log_format import DEFAULT_OUTPUT_FORMAT
from tf_demo.transport.dds.log_format import format_log_line
from tf_demo.transport.dds.logging import Logger
from tf_demo.transport.dds.logging import set_default_logger_level

if TYPE_CHECKING or not rclpy_world():
    from tf_demo.transport.dds.log_format import get_logging_severity_from_string
    from tf_demo.transport.dds.log_format import LoggingSeverity
    from tf_demo.transport.dds.logging import get_logger
    from tf_demo.transport.dds.logging import get_logger_effective_level
    from tf_demo.transport.dds.logging import get_logger_level
    from tf_demo.transport.dds.logging import set_logger_level
else:  # pragma: no cover - needs a ROS 2 installation
    from tf_demo.transport.rclpy_backend import get_logger
    from tf_demo.transport.rclpy_backend import get_logger_effective_level
    from tf_demo.transport.rclpy_backend import get_logger_level
    from tf_demo.transport.rclpy_backend import get_logging_severity_from_string
    from tf_demo.transport.rclpy_backend import LoggingSeverity
    from tf_demo.transport.rclpy_backend import set_logger_level

__all__ = [
    'DEFAULT_OUTPUT_FORMAT',
    'Logger',
    'LoggingSeverity',
    'format_log_line',
    'get_logger',
    'get_logger_effective_level',
    'get_logger_level',
    'get_logging_severity_from_string',
    'set_default_logger_level',
    'set_logger_level',
]
