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
ROS 2's wire conventions on DDS, the pure part: domain, discovery and names.

The domain and discovery configuration taken from ``ROS_DOMAIN_ID``,
``ROS_AUTOMATIC_DISCOVERY_RANGE``, ``ROS_LOCALHOST_ONLY`` and ``ROS_STATIC_PEERS``
(``spec/ros2_dds_wire.md``); ``rt/`` topic names and ``pkg::msg::dds_::Name_`` type names
(the QoS mapping is :mod:`tf_demo.transport.dds.wire_qos`'s). Plain functions:
:mod:`tf_demo.transport.dds.participant` is the shell that uses them.
"""

from __future__ import annotations

from collections.abc import Mapping
import enum
import re
from typing import NamedTuple

__all__ = [
    'DISCOVERY_INFO_TOPIC',
    'DISCOVERY_INFO_TYPE',
    'LOOPBACK_DISCOVERY_XML',
    'DdsConfigError',
    'DdsWireError',
    'DiscoveryConfig',
    'DiscoveryRange',
    'cyclone_config',
    'dds_topic_name',
    'dds_type_name',
    'discovery_config_from_env',
    'domain_id_from_env',
    'ros_topic_name',
]

DISCOVERY_INFO_TOPIC = 'ros_discovery_info'
DISCOVERY_INFO_TYPE = 'rmw_dds_common::msg::dds_::ParticipantEntitiesInfo_'

ROS_TOPIC_PREFIX = 'rt'

LOOPBACK_DISCOVERY_XML = (
    '<CycloneDDS><Domain id="any"><General><Interfaces><NetworkInterface name="lo"/></Interfaces>'
    '<AllowMulticast>false</AllowMulticast></General>'
    '<Discovery><ParticipantIndex>auto</ParticipantIndex>'
    '<MaxAutoParticipantIndex>32</MaxAutoParticipantIndex>'
    '<Peers><Peer address="127.0.0.1"/>{extra_peers}</Peers></Discovery></Domain></CycloneDDS>'
)
"""Loopback-only unicast discovery that meets both Cyclone 0.10 and 11 (spec §7.3)."""


class DdsWireError(RuntimeError):
    """A DDS entity could not be created or used; the message says which and why."""


class DdsConfigError(DdsWireError, ValueError):
    """The DDS environment (``ROS_DOMAIN_ID``, ``CYCLONEDDS_URI``, ...) is unusable."""


# --------------------------------------------------------------------------------------------
# Domain and discovery configuration (pure)
# --------------------------------------------------------------------------------------------


def domain_id_from_env(env: Mapping[str, str]) -> int:
    """
    Return the DDS domain id from ``ROS_DOMAIN_ID`` as rcl reads it (default 0).

    :raises DdsConfigError: when the value is not an integer that Cyclone accepts.
    """
    text = env.get('ROS_DOMAIN_ID', '').strip()
    if not text:
        return 0
    # strtoul(text, &end, 0) as rcl: 0x.. is hexadecimal, a leading 0 means octal.
    if text[:2].lower() == '0x':
        base = 16
    elif len(text) > 1 and text.startswith('0'):
        base = 8
    else:
        base = 10
    try:
        value = int(text, base)
    except ValueError:
        value = -1
    if not 0 <= value <= 232:
        msg = f'ROS_DOMAIN_ID={text!r} is not a valid domain id (expected an integer 0..232)'
        raise DdsConfigError(msg)
    return value


class DiscoveryRange(enum.Enum):
    """``ROS_AUTOMATIC_DISCOVERY_RANGE`` values (rmw ``rmw_automatic_discovery_range_t``)."""

    OFF = 'OFF'
    LOCALHOST = 'LOCALHOST'
    SUBNET = 'SUBNET'
    SYSTEM_DEFAULT = 'SYSTEM_DEFAULT'


class DiscoveryConfig(NamedTuple):
    """The resolved discovery settings and the warnings rcl would print while resolving them."""

    discovery_range: DiscoveryRange
    static_peers: tuple[str, ...]
    warnings: tuple[str, ...]


def discovery_config_from_env(env: Mapping[str, str]) -> DiscoveryConfig:
    """
    Resolve the discovery range and static peers as rcl 9 does.

    Unset or empty range means SUBNET; an unknown value means LOCALHOST with a warning; the
    deprecated ``ROS_LOCALHOST_ONLY=1`` forces LOCALHOST (with a warning) and drops static peers.
    """
    warnings: list[str] = []
    raw_range = env.get('ROS_AUTOMATIC_DISCOVERY_RANGE', '')
    if not raw_range:
        discovery_range = DiscoveryRange.SUBNET
    else:
        try:
            discovery_range = DiscoveryRange(raw_range)
        except ValueError:
            warnings.append(
                f'Invalid value {raw_range!r} for ROS_AUTOMATIC_DISCOVERY_RANGE, '
                'using LOCALHOST (expected OFF, LOCALHOST, SUBNET or SYSTEM_DEFAULT)'
            )
            discovery_range = DiscoveryRange.LOCALHOST
    peers = tuple(p.strip() for p in env.get('ROS_STATIC_PEERS', '').split(';') if p.strip())
    if env.get('ROS_LOCALHOST_ONLY', '') == '1':
        warnings.append(
            'ROS_LOCALHOST_ONLY is deprecated but still honored if it is enabled. '
            'Use ROS_AUTOMATIC_DISCOVERY_RANGE and ROS_STATIC_PEERS instead.'
        )
        discovery_range = DiscoveryRange.LOCALHOST
        peers = ()
    return DiscoveryConfig(discovery_range, peers, tuple(warnings))


def _xml_escape(text: str) -> str:
    return (
        text.replace('&', '&amp;').replace('<', '&lt;').replace('>', '&gt;').replace('"', '&quot;')
    )


def cyclone_config(config: DiscoveryConfig, user_uri: str | None, pid: int) -> str | None:
    """
    Return the Cyclone configuration string for ``config``, or None for plain Cyclone defaults.

    A user's ``CYCLONEDDS_URI`` is appended after our fragment, so it is respected and its
    settings win where both set the same element (Cyclone merges comma-separated sources in
    order), as rmw_cyclonedds does.
    """
    peers_xml = ''.join(f'<Peer address="{_xml_escape(p)}"/>' for p in config.static_peers)
    fragment: str | None
    if config.discovery_range is DiscoveryRange.LOCALHOST:
        fragment = LOOPBACK_DISCOVERY_XML.format(extra_peers=peers_xml)
    elif config.discovery_range is DiscoveryRange.OFF:
        fragment = (
            '<CycloneDDS><Domain id="any"><General><AllowMulticast>false</AllowMulticast>'
            '</General><Discovery><ParticipantIndex>none</ParticipantIndex>'
            f'<Tag>ros_discovery_off_{pid}</Tag></Discovery></Domain></CycloneDDS>'
        )
    elif config.discovery_range is DiscoveryRange.SUBNET and config.static_peers:
        fragment = (
            '<CycloneDDS><Domain id="any"><Discovery><ParticipantIndex>auto</ParticipantIndex>'
            '<MaxAutoParticipantIndex>32</MaxAutoParticipantIndex>'
            f'<Peers>{peers_xml}</Peers></Discovery></Domain></CycloneDDS>'
        )
    else:
        fragment = None
    parts = [p for p in (fragment, user_uri) if p]
    return ','.join(parts) if parts else None


# --------------------------------------------------------------------------------------------
# Names (pure)
# --------------------------------------------------------------------------------------------

_MSGTYPE_RE = re.compile(r'^([A-Za-z][A-Za-z0-9_]*)/(msg|srv|action)/([A-Za-z][A-Za-z0-9_]*)$')


def dds_topic_name(fully_qualified_topic: str) -> str:
    """Return the DDS topic of a fully qualified ROS topic: ``/tf`` -> ``rt/tf``."""
    if not fully_qualified_topic.startswith('/'):
        msg = f'topic {fully_qualified_topic!r} is not fully qualified (must start with "/")'
        raise ValueError(msg)
    return ROS_TOPIC_PREFIX + fully_qualified_topic


def ros_topic_name(dds_topic: str) -> str | None:
    """Return the ROS topic of a DDS topic (``rt/tf`` -> ``/tf``), None for non-ROS topics."""
    if dds_topic.startswith(ROS_TOPIC_PREFIX + '/'):
        return dds_topic[len(ROS_TOPIC_PREFIX) :]
    return None


def ros_type_name(dds_type: str) -> str:
    """Return the ROS type of a DDS type name (``pkg::msg::dds_::Name_`` -> ``pkg/msg/Name``)."""
    parts = dds_type.split('::')
    if len(parts) == 4 and parts[2] == 'dds_' and parts[3].endswith('_'):
        return f'{parts[0]}/{parts[1]}/{parts[3][:-1]}'
    return dds_type


def dds_type_name(ros_type: str) -> str:
    """Return the DDS type name of ``pkg/msg/Name``: ``pkg::msg::dds_::Name_``."""
    match = _MSGTYPE_RE.match(ros_type)
    if match is None:
        msg = f'{ros_type!r} is not a ROS interface type name like "tf2_msgs/msg/TFMessage"'
        raise ValueError(msg)
    package, kind, name = match.groups()
    return f'{package}::{kind}::dds_::{name}_'
