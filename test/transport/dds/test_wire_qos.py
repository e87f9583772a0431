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

"""ROS QoS on DDS: profiles resolved and mapped to Cyclone QoS as rmw_cyclonedds does."""

from __future__ import annotations

from conftest import STANDALONE_ONLY
import pytest

pytest.importorskip('cyclonedds', reason=STANDALONE_ONLY)

from cyclonedds.qos import Policy
from tf_demo.transport.clock import Duration
from tf_demo.transport.dds import wire as dds_wire
from tf_demo.transport.qos import DurabilityPolicy
from tf_demo.transport.qos import HistoryPolicy
from tf_demo.transport.qos import LivelinessPolicy
from tf_demo.transport.qos import QoSProfile
from tf_demo.transport.qos import ReliabilityPolicy
from tf_demo.transport.qos import StaticBroadcasterQoS

INFINITY = dds_wire.DDS_INFINITY


def test_tf_static_profile_maps_to_reliable_transient_local_depth_1():
    """tf2's static broadcaster QoS becomes RELIABLE, TRANSIENT_LOCAL, KEEP_LAST 1."""
    qos = dds_wire.endpoint_qos_from_profile(StaticBroadcasterQoS())
    assert qos == dds_wire.EndpointQos(reliable=True, transient_local=True, depth=1)


def test_system_defaults_and_zero_depth_resolve_as_rmw_cyclonedds():
    """SYSTEM_DEFAULT policies become RELIABLE/VOLATILE/KEEP_LAST and depth 0 becomes 1."""
    profile = QoSProfile(
        history=HistoryPolicy.SYSTEM_DEFAULT,
        depth=0,
        reliability=ReliabilityPolicy.SYSTEM_DEFAULT,
        durability=DurabilityPolicy.SYSTEM_DEFAULT,
    )
    assert dds_wire.endpoint_qos_from_profile(profile) == dds_wire.EndpointQos(depth=1)


def test_durations_and_liveliness_are_carried_over():
    """Deadline, lifespan and liveliness lease pass through in ns; best effort and KEEP_ALL too."""
    profile = QoSProfile(
        history=HistoryPolicy.KEEP_ALL,
        reliability=ReliabilityPolicy.BEST_EFFORT,
        deadline=Duration(seconds=0.5),
        lifespan=Duration(seconds=10),
        liveliness=LivelinessPolicy.MANUAL_BY_TOPIC,
        liveliness_lease_duration=Duration(seconds=2),
    )
    qos = dds_wire.endpoint_qos_from_profile(profile)
    assert not qos.reliable
    assert qos.keep_all
    assert (qos.deadline_ns, qos.lifespan_ns, qos.liveliness_lease_ns) == (
        500_000_000,
        10_000_000_000,
        2_000_000_000,
    )
    assert qos.liveliness_manual_by_topic


def test_best_available_is_refused_with_the_policy_named():
    """BEST_AVAILABLE cannot be resolved here and the error says which policy."""
    profile = QoSProfile(depth=1, reliability=ReliabilityPolicy.BEST_AVAILABLE)
    with pytest.raises(ValueError, match='reliability BEST_AVAILABLE'):
        dds_wire.endpoint_qos_from_profile(profile)


def test_cyclone_qos_has_every_rmw_cyclonedds_policy():
    """Transient-local gets a matching DURABILITY_SERVICE; XCDR1, no autodispose, user data."""
    qos = dds_wire.cyclone_qos(
        dds_wire.EndpointQos(transient_local=True, depth=1), b'typehash=RIHS01_x;'
    )
    policies = set(qos)
    assert Policy.Reliability.Reliable(INFINITY) in policies
    assert Policy.Durability.TransientLocal in policies
    assert Policy.History.KeepLast(1) in policies
    assert (
        Policy.DurabilityService(
            cleanup_delay=0,
            history=Policy.History.KeepLast(1),
            max_samples=-1,
            max_instances=-1,
            max_samples_per_instance=-1,
        )
        in policies
    )
    assert Policy.WriterDataLifecycle(autodispose=False) in policies
    assert Policy.DataRepresentation(use_cdrv0_representation=True) in policies
    assert Policy.Userdata(b'typehash=RIHS01_x;') in policies
    assert Policy.Liveliness.Automatic(INFINITY) in policies


def test_incompatible_policy_names_match_rclpy():
    """DDS policy ids become rclpy's names; the ones rmw does not map print INVALID."""
    assert dds_wire.incompatible_policy_name(2) == 'DURABILITY'
    assert dds_wire.incompatible_policy_name(11) == 'RELIABILITY'
    assert dds_wire.incompatible_policy_name(4) == 'DEADLINE'
    assert dds_wire.incompatible_policy_name(25) == 'INVALID'


@pytest.mark.parametrize(
    'profile',
    [
        QoSProfile(
            depth=7,
            reliability=ReliabilityPolicy.RELIABLE,
            durability=DurabilityPolicy.VOLATILE,
            deadline=Duration(seconds=2, nanoseconds=500_000_000),
            liveliness=LivelinessPolicy.AUTOMATIC,
        ),
        QoSProfile(
            history=HistoryPolicy.KEEP_ALL,
            reliability=ReliabilityPolicy.BEST_EFFORT,
            durability=DurabilityPolicy.TRANSIENT_LOCAL,
            lifespan=Duration(nanoseconds=5),
            liveliness=LivelinessPolicy.MANUAL_BY_TOPIC,
            liveliness_lease_duration=Duration(seconds=3),
        ),
    ],
)
def test_a_discovered_endpoints_qos_reads_back_as_the_profile_it_came_from(
    profile: QoSProfile,
) -> None:
    """Profile -> Cyclone QoS on the wire -> the profile again (unset durations: infinite)."""
    wire = dds_wire.cyclone_qos(dds_wire.endpoint_qos_from_profile(profile), b'')
    back = dds_wire.profile_from_cyclone(wire)
    infinite = 2**63 - 1
    for name in ('history', 'reliability', 'durability', 'liveliness'):
        assert getattr(back, name) == getattr(profile, name), name
    assert back.depth == (0 if profile.history == HistoryPolicy.KEEP_ALL else profile.depth)
    for name in ('deadline', 'lifespan', 'liveliness_lease_duration'):
        wanted = getattr(profile, name).nanoseconds or infinite
        assert getattr(back, name).nanoseconds == wanted, name
