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
Parameters: rclpy's own classes in the rclpy world, else the standalone ones.

The world is chosen once, when the module is first imported; the type checker sees the
standalone classes (:mod:`tf_demo.transport.dds.parameters`). The standalone node's own
parameter machinery lives in :mod:`tf_demo.transport.dds.parameter_store`.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from tf_demo.transport.backend import rclpy_world

if TYPE_CHECKING or not rclpy_world():
    from tf_demo.transport.dds.parameters import *  # noqa: F403 - the standalone names
else:  # pragma: no cover - needs a ROS 2 installation
    from rcl_interfaces.msg import *  # noqa: F403 - rclpy's own
    from rclpy.exceptions import *  # noqa: F403 - rclpy's own
    from rclpy.parameter import *  # noqa: F403 - rclpy's own

    ParameterType = Parameter.Type  # rclpy nests the type enum in Parameter
