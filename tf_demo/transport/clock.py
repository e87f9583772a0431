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
Time, durations and clocks: rclpy's own objects in the rclpy world, else the standalone ones.

The world is chosen once, here, when the module is first imported
(:func:`tf_demo.transport.backend.rclpy_world`). The type checker always sees the standalone
classes (:mod:`tf_demo.transport.dds.time`, ``dds.clock``, ``dds.time_source``), which follow
``rclpy.time``, ``rclpy.duration``, ``rclpy.clock`` and ``rclpy.time_source`` name for name.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from tf_demo.transport.backend import rclpy_world

if TYPE_CHECKING or not rclpy_world():
    from tf_demo.transport.dds.clock import *  # noqa: F403 - the standalone names
    from tf_demo.transport.dds.time import *  # noqa: F403 - the standalone names
    from tf_demo.transport.dds.time_source import *  # noqa: F403 - the standalone names
else:  # pragma: no cover - needs a ROS 2 installation
    from rclpy.clock import *  # noqa: F403 - rclpy's own
    from rclpy.duration import *  # noqa: F403 - rclpy's own
    from rclpy.time import *  # noqa: F403 - rclpy's own
    from rclpy.time_source import *  # noqa: F403 - rclpy's own
    from tf_demo.transport.dds.time_source import CLOCK_TOPIC  # tf_demo's in both worlds
    from tf_demo.transport.dds.time_source import USE_SIM_TIME_NAME
