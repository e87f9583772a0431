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
Quality-of-service profiles: rclpy's own (``rclpy.qos``) in the rclpy world, else standalone ones.

A profile from here can be handed to the world's nodes: in the rclpy world to a real rclpy node.
The world is chosen once, when the module is first imported; the type checker sees the
standalone classes (:mod:`tf_demo.transport.dds.qos`).

tf2's profiles (``tf2_ros/qos.hpp``) are functions that build a fresh profile of the world's
class on each call: ``DynamicBroadcasterQoS()``, ``DynamicListenerQoS()`` (KEEP_LAST 100,
RELIABLE, VOLATILE), ``StaticBroadcasterQoS()`` (KEEP_LAST 1, RELIABLE, TRANSIENT_LOCAL) and
``StaticListenerQoS()`` (KEEP_LAST 100, RELIABLE, TRANSIENT_LOCAL).
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from tf_demo.transport.backend import rclpy_world

if TYPE_CHECKING or not rclpy_world():
    from tf_demo.transport.dds.qos import *  # noqa: F403 - the standalone names
else:  # pragma: no cover - needs a ROS 2 installation
    from rclpy.qos import *  # noqa: F403 - rclpy's own


def _tf2_profile(depth: int, durability: DurabilityPolicy) -> QoSProfile:
    """Return a KEEP_LAST ``depth``, RELIABLE profile with ``durability`` (tf2's four)."""
    return QoSProfile(depth=depth, reliability=ReliabilityPolicy.RELIABLE, durability=durability)


def DynamicBroadcasterQoS(depth: int = 100) -> QoSProfile:  # noqa: N802 - tf2_ros's name
    """Return tf2's ``/tf`` broadcaster profile: KEEP_LAST ``depth``, RELIABLE, VOLATILE."""
    return _tf2_profile(depth, DurabilityPolicy.VOLATILE)


def DynamicListenerQoS(depth: int = 100) -> QoSProfile:  # noqa: N802 - tf2_ros's name
    """Return tf2's ``/tf`` listener profile: KEEP_LAST ``depth``, RELIABLE, VOLATILE."""
    return _tf2_profile(depth, DurabilityPolicy.VOLATILE)


def StaticBroadcasterQoS(depth: int = 1) -> QoSProfile:  # noqa: N802 - tf2_ros's name
    """Return tf2's ``/tf_static`` broadcaster profile: KEEP_LAST 1, RELIABLE, TRANSIENT_LOCAL."""
    return _tf2_profile(depth, DurabilityPolicy.TRANSIENT_LOCAL)


def StaticListenerQoS(depth: int = 100) -> QoSProfile:  # noqa: N802 - tf2_ros's name
    """Return tf2's ``/tf_static`` listener profile: KEEP_LAST 100, RELIABLE, TRANSIENT_LOCAL."""
    return _tf2_profile(depth, DurabilityPolicy.TRANSIENT_LOCAL)
