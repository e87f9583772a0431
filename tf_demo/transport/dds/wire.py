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
ROS 2's wire conventions on top of Cyclone DDS (cyclonedds-python 11.0.1), in one import.

How a ROS entity looks on DDS (``spec/ros2_dds_wire.md``) is written in two modules, whose
names this one re-exports: :mod:`tf_demo.transport.dds.wire_config`, the pure part (domain and
discovery configuration, ``rt/`` topic and ``pkg::msg::dds_::Name_`` type names, the QoS
mapping as ``rmw_cyclonedds`` builds it), and :mod:`tf_demo.transport.dds.participant`, the
imperative shell (the process' one participant, raw-bytes writers and readers, waitsets).
"""

from __future__ import annotations

from tf_demo.transport.dds.participant import close_participant
from tf_demo.transport.dds.participant import DdsParticipant
from tf_demo.transport.dds.participant import get_participant
from tf_demo.transport.dds.raw_endpoints import RawReader
from tf_demo.transport.dds.raw_endpoints import RawWriter
from tf_demo.transport.dds.raw_endpoints import WaitSet
from tf_demo.transport.dds.wire_config import cyclone_config
from tf_demo.transport.dds.wire_config import dds_topic_name
from tf_demo.transport.dds.wire_config import dds_type_name
from tf_demo.transport.dds.wire_config import DdsConfigError
from tf_demo.transport.dds.wire_config import DdsWireError
from tf_demo.transport.dds.wire_config import discovery_config_from_env
from tf_demo.transport.dds.wire_config import DISCOVERY_INFO_TOPIC
from tf_demo.transport.dds.wire_config import DISCOVERY_INFO_TYPE
from tf_demo.transport.dds.wire_config import DiscoveryConfig
from tf_demo.transport.dds.wire_config import DiscoveryRange
from tf_demo.transport.dds.wire_config import domain_id_from_env
from tf_demo.transport.dds.wire_config import LOOPBACK_DISCOVERY_XML
from tf_demo.transport.dds.wire_config import ros_topic_name
from tf_demo.transport.dds.wire_config import ros_type_name
from tf_demo.transport.dds.wire_qos import cyclone_qos
from tf_demo.transport.dds.wire_qos import DDS_INFINITY
from tf_demo.transport.dds.wire_qos import endpoint_qos_from_profile
from tf_demo.transport.dds.wire_qos import EndpointQos
from tf_demo.transport.dds.wire_qos import incompatible_policy_name
from tf_demo.transport.dds.wire_qos import profile_from_cyclone

__all__ = [
    'DDS_INFINITY',
    'DISCOVERY_INFO_TOPIC',
    'DISCOVERY_INFO_TYPE',
    'LOOPBACK_DISCOVERY_XML',
    'DdsConfigError',
    'DdsParticipant',
    'DdsWireError',
    'DiscoveryConfig',
    'DiscoveryRange',
    'EndpointQos',
    'RawReader',
    'RawWriter',
    'WaitSet',
    'close_participant',
    'cyclone_config',
    'cyclone_qos',
    'dds_topic_name',
    'dds_type_name',
    'discovery_config_from_env',
    'domain_id_from_env',
    'endpoint_qos_from_profile',
    'get_participant',
    'incompatible_policy_name',
    'profile_from_cyclone',
    'ros_topic_name',
    'ros_type_name',
]
