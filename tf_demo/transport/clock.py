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
from tf_demo.transport.dds.time_source import CLOCK_TOPIC
from tf_demo.transport.dds.time_source import USE_SIM_TIME_NAME

if TYPE_CHECKING or not rclpy_world():
    from tf_demo.transport.dds.clock import Clock
    from tf_demo.transport.dds.clock import JumpHandle
    from tf_demo.transport.dds.clock import JumpThreshold
    from tf_demo.transport.dds.clock import ROSClock
    from tf_demo.transport.dds.clock import TimeJump
    from tf_demo.transport.dds.time import ClockChange
    from tf_demo.transport.dds.time import ClockType
    from tf_demo.transport.dds.time import Duration
    from tf_demo.transport.dds.time import Infinite
    from tf_demo.transport.dds.time import Time
    from tf_demo.transport.dds.time_source import TimeSource
else:  # pragma: no cover - needs a ROS 2 installation
    from tf_demo.transport.rclpy_backend import Clock
    from tf_demo.transport.rclpy_backend import ClockChange
    from tf_demo.transport.rclpy_backend import ClockType
    from tf_demo.transport.rclpy_backend import Duration
    from tf_demo.transport.rclpy_backend import Infinite
    from tf_demo.transport.rclpy_backend import JumpHandle
    from tf_demo.transport.rclpy_backend import JumpThreshold
    from tf_demo.transport.rclpy_backend import ROSClock
    from tf_demo.transport.rclpy_backend import Time
    from tf_demo.transport.rclpy_backend import TimeJump
    from tf_demo.transport.rclpy_backend import TimeSource

__all__ = [
    'CLOCK_TOPIC',
    'USE_SIM_TIME_NAME',
    'Clock',
    'ClockChange',
    'ClockType',
    'Duration',
    'Infinite',
    'JumpHandle',
    'JumpThreshold',
    'ROSClock',
    'Time',
    'TimeJump',
    'TimeSource',
]
