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
ROS QoS on DDS: a profile resolved to what rmw_cyclonedds puts on an endpoint, as Cyclone QoS.

:class:`EndpointQos` is what ROS' profile means on the wire (``rmw_cyclonedds``' mapping: depth,
reliability, durability, deadline, lifespan, liveliness); :func:`cyclone_qos` builds the Cyclone
policies; :func:`incompatible_policy_name` names a refused policy as rclpy prints it.
"""

from __future__ import annotations

from typing import Any
from typing import NamedTuple

from cyclonedds.qos import BasePolicy
from cyclonedds.qos import Policy
from cyclonedds.qos import Qos
from tf_demo.transport.dds.qos import DurabilityPolicy
from tf_demo.transport.dds.qos import HistoryPolicy
from tf_demo.transport.dds.qos import LivelinessPolicy
from tf_demo.transport.dds.qos import QoSProfile
from tf_demo.transport.dds.qos import ReliabilityPolicy
from tf_demo.transport.dds.time import Duration

__all__ = [
    'DDS_INFINITY',
    'EndpointQos',
    'cyclone_qos',
    'endpoint_qos_from_profile',
    'incompatible_policy_name',
    'profile_from_cyclone',
]

DDS_INFINITY = 0x7FFFFFFFFFFFFFFF
"""Cyclone's infinite duration (``DDS_INFINITY``)."""

_RMW_DURATION_INFINITE_NS = 9223372036 * 1_000_000_000 + 854775807
"""``RMW_DURATION_INFINITE`` ({9223372036 s, 854775807 ns}) in nanoseconds."""


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
    """
    Nanoseconds of a ROS duration, None when unspecified (0).

    ``value`` is what a duck-typed profile holds, untyped: an rclpy-like ``Duration``
    (``nanoseconds``), a ``Duration`` message (``sec``, ``nanosec``) or nanoseconds (``int()``).
    """
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


def _policy_name(value: object) -> str:
    name = getattr(value, 'name', None)
    return str(name if name is not None else value).upper()


def endpoint_qos_from_profile(profile: QoSProfile) -> EndpointQos:
    """
    Resolve a ``QoSProfile`` (or an rclpy-like one: policies with rclpy's enum names, duck-typed).

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
    policies: list[BasePolicy] = [
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


def profile_from_cyclone(qos: Qos) -> QoSProfile:
    """
    Read a discovered endpoint's Cyclone QoS back as the ROS profile it offers (rmw's view).

    Infinite durations read as ``RMW_DURATION_INFINITE``, as ``ros2 topic info -v`` and rosbag2
    report them.
    """
    policies = {type(policy).__name__.rsplit('.', 1)[-1]: policy for policy in qos}

    def duration(name: str, field: str) -> Duration:
        nanoseconds = getattr(policies.get(name), field, DDS_INFINITY)
        infinite = nanoseconds is None or nanoseconds >= DDS_INFINITY
        return Duration(nanoseconds=_RMW_DURATION_INFINITE_NS if infinite else nanoseconds)

    keep_all = 'KeepAll' in policies
    liveliness = policies.get('ManualByTopic')
    return QoSProfile(
        history=HistoryPolicy.KEEP_ALL if keep_all else HistoryPolicy.KEEP_LAST,
        depth=0 if keep_all else int(getattr(policies.get('KeepLast'), 'depth', 1)),
        reliability=ReliabilityPolicy.RELIABLE
        if 'Reliable' in policies
        else ReliabilityPolicy.BEST_EFFORT,
        durability=DurabilityPolicy.TRANSIENT_LOCAL
        if 'TransientLocal' in policies
        else DurabilityPolicy.VOLATILE,
        deadline=duration('Deadline', 'deadline'),
        lifespan=duration('Lifespan', 'lifespan'),
        liveliness=LivelinessPolicy.MANUAL_BY_TOPIC
        if liveliness is not None
        else LivelinessPolicy.AUTOMATIC,
        liveliness_lease_duration=duration(
            'ManualByTopic' if liveliness is not None else 'Automatic', 'lease_duration'
        ),
    )


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
