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
    from tf_demo.transport.dds.qos import DurabilityPolicy
    from tf_demo.transport.dds.qos import HistoryPolicy
    from tf_demo.transport.dds.qos import InvalidQoSProfileException
    from tf_demo.transport.dds.qos import LivelinessPolicy
    from tf_demo.transport.dds.qos import qos_profile_action_status_default
    from tf_demo.transport.dds.qos import qos_profile_best_available
    from tf_demo.transport.dds.qos import qos_profile_default
    from tf_demo.transport.dds.qos import qos_profile_parameter_events
    from tf_demo.transport.dds.qos import qos_profile_parameters
    from tf_demo.transport.dds.qos import qos_profile_sensor_data
    from tf_demo.transport.dds.qos import qos_profile_services_default
    from tf_demo.transport.dds.qos import qos_profile_system_default
    from tf_demo.transport.dds.qos import qos_profile_unknown
    from tf_demo.transport.dds.qos import QoSDurabilityPolicy
    from tf_demo.transport.dds.qos import QoSHistoryPolicy
    from tf_demo.transport.dds.qos import QoSLivelinessPolicy
    from tf_demo.transport.dds.qos import QoSPresetProfiles
    from tf_demo.transport.dds.qos import QoSProfile
    from tf_demo.transport.dds.qos import QoSReliabilityPolicy
    from tf_demo.transport.dds.qos import ReliabilityPolicy
else:  # pragma: no cover - needs a ROS 2 installation
    from tf_demo.transport.rclpy_backend import DurabilityPolicy
    from tf_demo.transport.rclpy_backend import HistoryPolicy
    from tf_demo.transport.rclpy_backend import InvalidQoSProfileException
    from tf_demo.transport.rclpy_backend import LivelinessPolicy
    from tf_demo.transport.rclpy_backend import qos_profile_action_status_default
    from tf_demo.transport.rclpy_backend import qos_profile_best_available
    from tf_demo.transport.rclpy_backend import qos_profile_default
    from tf_demo.transport.rclpy_backend import qos_profile_parameter_events
    from tf_demo.transport.rclpy_backend import qos_profile_parameters
    from tf_demo.transport.rclpy_backend import qos_profile_sensor_data
    from tf_demo.transport.rclpy_backend import qos_profile_services_default
    from tf_demo.transport.rclpy_backend import qos_profile_system_default
    from tf_demo.transport.rclpy_backend import qos_profile_unknown
    from tf_demo.transport.rclpy_backend import QoSDurabilityPolicy
    from tf_demo.transport.rclpy_backend import QoSHistoryPolicy
    from tf_demo.transport.rclpy_backend import QoSLivelinessPolicy
    from tf_demo.transport.rclpy_backend import QoSPresetProfiles
    from tf_demo.transport.rclpy_backend import QoSProfile
    from tf_demo.transport.rclpy_backend import QoSReliabilityPolicy
    from tf_demo.transport.rclpy_backend import ReliabilityPolicy

__all__ = [
    'DurabilityPolicy',
    'DynamicBroadcasterQoS',
    'DynamicListenerQoS',
    'HistoryPolicy',
    'InvalidQoSProfileException',
    'LivelinessPolicy',
    'QoSDurabilityPolicy',
    'QoSHistoryPolicy',
    'QoSLivelinessPolicy',
    'QoSPresetProfiles',
    'QoSProfile',
    'QoSReliabilityPolicy',
    'ReliabilityPolicy',
    'StaticBroadcasterQoS',
    'StaticListenerQoS',
    'qos_profile_action_status_default',
    'qos_profile_best_available',
    'qos_profile_default',
    'qos_profile_parameter_events',
    'qos_profile_parameters',
    'qos_profile_sensor_data',
    'qos_profile_services_default',
    'qos_profile_system_default',
    'qos_profile_unknown',
]


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
