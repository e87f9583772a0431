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
ROS 2's wire conventions on DDS, the pure part: configuration, names and QoS mapping.

The domain and discovery configuration taken from ``ROS_DOMAIN_ID``,
``ROS_AUTOMATIC_DISCOVERY_RANGE``, ``ROS_LOCALHOST_ONLY`` and ``ROS_STATIC_PEERS``
(``spec/ros2_dds_wire.md``); ``rt/`` topic names and ``pkg::msg::dds_::Name_`` type names;
the mapping of ROS QoS onto Cyclone policies as ``rmw_cyclonedds`` builds it. Plain functions:
:mod:`tf_demo.transport.dds_participant` is the shell that uses them.
"""

from __future__ import annotations

from collections.abc import Mapping
import enum
import re
from typing import Any
from typing import NamedTuple

from cyclonedds.qos import Policy
from cyclonedds.qos import Qos

__all__ = [
    'DDS_INFINITY',
    'DISCOVERY_INFO_TOPIC',
    'DISCOVERY_INFO_TYPE',
    'LOOPBACK_DISCOVERY_XML',
    'DdsConfigError',
    'DdsWireError',
    'DiscoveryConfig',
    'DiscoveryRange',
    'EndpointQos',
    'cyclone_config',
    'cyclone_qos',
    'dds_topic_name',
    'dds_type_name',
    'discovery_config_from_env',
    'domain_id_from_env',
    'endpoint_qos_from_profile',
    'incompatible_policy_name',
    'ros_topic_name',
]

DDS_INFINITY = 0x7FFFFFFFFFFFFFFF
"""Cyclone's infinite duration (``DDS_INFINITY``)."""

_RMW_DURATION_INFINITE_NS = 9223372036 * 1_000_000_000 + 854775807
"""``RMW_DURATION_INFINITE`` ({9223372036 s, 854775807 ns}) in nanoseconds."""

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


def dds_type_name(ros_type: str) -> str:
    """Return the DDS type name of ``pkg/msg/Name``: ``pkg::msg::dds_::Name_``."""
    match = _MSGTYPE_RE.match(ros_type)
    if match is None:
        msg = f'{ros_type!r} is not a ROS interface type name like "tf2_msgs/msg/TFMessage"'
        raise ValueError(msg)
    package, kind, name = match.groups()
    return f'{package}::{kind}::dds_::{name}_'


# --------------------------------------------------------------------------------------------
# QoS (pure)
# --------------------------------------------------------------------------------------------


class EndpointQos(NamedTuple):
    """A ROS QoS profile resolved to what rmw_cyclonedds puts on a DDS endpoint."""

    reliable: bool = True
    transient_local: bool = False
    keep_all: bool = False
    depth: int = 10
    deadline_ns: int | None = None
    lifespan_ns: int | None = None
    liveliness_manual_by_topic: bool = False
    liveliness_lease_ns: int | None = None


def _duration_ns(value: Any) -> int | None:
    """Nanoseconds of a ROS duration (rclpy-like ``Duration``), None when unspecified (0)."""
    if value is None:
        return None
    nanoseconds = getattr(value, 'nanoseconds', None)
    if nanoseconds is None:
        sec = getattr(value, 'sec', None)
        if sec is None:
            nanoseconds = int(value)
        else:
            nanoseconds = int(sec) * 1_000_000_000 + int(getattr(value, 'nanosec', 0))
    nanoseconds = int(nanoseconds)
    if nanoseconds == 0:
        return None
    if nanoseconds >= _RMW_DURATION_INFINITE_NS:
        return DDS_INFINITY
    return nanoseconds


def _policy_name(value: Any) -> str:
    name = getattr(value, 'name', None)
    return str(name if name is not None else value).upper()


def endpoint_qos_from_profile(profile: Any) -> EndpointQos:
    """
    Resolve an rclpy-like ``QoSProfile`` (policies with rclpy's enum names) as rmw_cyclonedds.

    SYSTEM_DEFAULT reliability, durability and history become RELIABLE, VOLATILE and KEEP_LAST;
    depth 0 becomes 1; zero durations mean "unspecified" (infinite).

    :raises ValueError: for BEST_AVAILABLE or UNKNOWN policies, which this backend cannot
        resolve, naming the policy.
    """
    reliability = _policy_name(profile.reliability)
    durability = _policy_name(profile.durability)
    history = _policy_name(profile.history)
    liveliness = _policy_name(getattr(profile, 'liveliness', 'SYSTEM_DEFAULT'))
    for policy, value in (
        ('reliability', reliability),
        ('durability', durability),
        ('history', history),
        ('liveliness', liveliness),
    ):
        if value in ('BEST_AVAILABLE', 'UNKNOWN'):
            msg = f'QoS {policy} {value} is not supported by the DDS backend'
            raise ValueError(msg)
    depth = int(profile.depth)
    if depth < 0:
        msg = f'QoS depth must be >= 0, got {depth}'
        raise ValueError(msg)
    return EndpointQos(
        reliable=reliability != 'BEST_EFFORT',
        transient_local=durability == 'TRANSIENT_LOCAL',
        keep_all=history == 'KEEP_ALL',
        depth=max(depth, 1),
        deadline_ns=_duration_ns(getattr(profile, 'deadline', None)),
        lifespan_ns=_duration_ns(getattr(profile, 'lifespan', None)),
        liveliness_manual_by_topic=liveliness == 'MANUAL_BY_TOPIC',
        liveliness_lease_ns=_duration_ns(getattr(profile, 'liveliness_lease_duration', None)),
    )


def cyclone_qos(qos: EndpointQos, user_data: bytes, *, ignore_local: bool = False) -> Qos:
    """
    Build the Cyclone QoS of a reader or writer as rmw_cyclonedds' ``create_readwrite_qos``.

    Reliability (infinite max blocking), durability with DURABILITY_SERVICE for
    transient-local, history/depth, deadline, lifespan, liveliness, autodispose off, XCDR1 only,
    and ``user_data`` (``typehash=RIHS01_...;``).
    """
    history = Policy.History.KeepAll if qos.keep_all else Policy.History.KeepLast(qos.depth)
    policies: list[Any] = [
        history,
        Policy.Reliability.Reliable(DDS_INFINITY)
        if qos.reliable
        else Policy.Reliability.BestEffort,
        Policy.WriterDataLifecycle(autodispose=False),
        Policy.DataRepresentation(use_cdrv0_representation=True),
        Policy.Userdata(user_data),
    ]
    if qos.transient_local:
        policies.append(Policy.Durability.TransientLocal)
        policies.append(
            Policy.DurabilityService(
                cleanup_delay=0,
                history=history,
                max_samples=-1,
                max_instances=-1,
                max_samples_per_instance=-1,
            )
        )
    else:
        policies.append(Policy.Durability.Volatile)
    if qos.deadline_ns is not None:
        policies.append(Policy.Deadline(qos.deadline_ns))
    if qos.lifespan_ns is not None:
        policies.append(Policy.Lifespan(qos.lifespan_ns))
    lease = qos.liveliness_lease_ns if qos.liveliness_lease_ns is not None else DDS_INFINITY
    if qos.liveliness_manual_by_topic:
        policies.append(Policy.Liveliness.ManualByTopic(lease))
    else:
        policies.append(Policy.Liveliness.Automatic(lease))
    if ignore_local:
        policies.append(Policy.IgnoreLocal.Participant)
    return Qos(*policies)


_DDS_POLICY_TO_ROS = {
    2: 'DURABILITY',
    4: 'DEADLINE',
    8: 'LIVELINESS',
    11: 'RELIABILITY',
    13: 'HISTORY',
    21: 'LIFESPAN',
}


def incompatible_policy_name(dds_policy_id: int) -> str:
    """Name of a DDS QoS policy id as rclpy prints it (``RELIABILITY``; others ``INVALID``)."""
    return _DDS_POLICY_TO_ROS.get(dds_policy_id, 'INVALID')
