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

"""The DDS wire layer: discovery configuration, names, rmw_cyclonedds' QoS mapping, endpoints."""

from __future__ import annotations

from collections.abc import Iterator
import time

from conftest import STANDALONE_ONLY
import pytest

pytest.importorskip('cyclonedds', reason=STANDALONE_ONLY)

from cyclonedds.builtin import BuiltinDataReader
from cyclonedds.builtin import BuiltinTopicDcpsPublication
from cyclonedds.builtin import BuiltinTopicDcpsSubscription
from cyclonedds.builtin_types import DcpsEndpoint
from cyclonedds.qos import Policy
from tf_demo.msgs import cdr
from tf_demo.msgs import tf2_msgs
from tf_demo.transport.clock import Duration
from tf_demo.transport.dds import wire as dds_wire
from tf_demo.transport.qos import DurabilityPolicy
from tf_demo.transport.qos import HistoryPolicy
from tf_demo.transport.qos import LivelinessPolicy
from tf_demo.transport.qos import QoSProfile
from tf_demo.transport.qos import ReliabilityPolicy
from tf_demo.transport.qos import StaticBroadcasterQoS

TF_TYPE = 'tf2_msgs::msg::dds_::TFMessage_'
INFINITY = dds_wire.DDS_INFINITY


# -- configuration ------------------------------------------------------------------------------


def test_domain_id_defaults_to_zero_and_rejects_garbage():
    """ROS_DOMAIN_ID: unset means 0, numbers are used as is, garbage is a clear error."""
    assert dds_wire.domain_id_from_env({}) == 0
    assert dds_wire.domain_id_from_env({'ROS_DOMAIN_ID': '42'}) == 42
    assert dds_wire.domain_id_from_env({'ROS_DOMAIN_ID': '0x10'}) == 16
    assert dds_wire.domain_id_from_env({'ROS_DOMAIN_ID': '010'}) == 8
    with pytest.raises(dds_wire.DdsConfigError, match=r"ROS_DOMAIN_ID='abc' is not a valid"):
        dds_wire.domain_id_from_env({'ROS_DOMAIN_ID': 'abc'})
    with pytest.raises(dds_wire.DdsWireError, match=r'0\.\.232'):
        dds_wire.domain_id_from_env({'ROS_DOMAIN_ID': '300'})


@pytest.mark.parametrize(
    ('env', 'expected_range', 'warns'),
    [
        ({}, dds_wire.DiscoveryRange.SUBNET, False),
        ({'ROS_AUTOMATIC_DISCOVERY_RANGE': ''}, dds_wire.DiscoveryRange.SUBNET, False),
        ({'ROS_AUTOMATIC_DISCOVERY_RANGE': 'LOCALHOST'}, dds_wire.DiscoveryRange.LOCALHOST, False),
        ({'ROS_AUTOMATIC_DISCOVERY_RANGE': 'OFF'}, dds_wire.DiscoveryRange.OFF, False),
        (
            {'ROS_AUTOMATIC_DISCOVERY_RANGE': 'SYSTEM_DEFAULT'},
            dds_wire.DiscoveryRange.SYSTEM_DEFAULT,
            False,
        ),
        ({'ROS_AUTOMATIC_DISCOVERY_RANGE': 'galaxy'}, dds_wire.DiscoveryRange.LOCALHOST, True),
        ({'ROS_LOCALHOST_ONLY': '1'}, dds_wire.DiscoveryRange.LOCALHOST, True),
        (
            {'ROS_LOCALHOST_ONLY': '1', 'ROS_AUTOMATIC_DISCOVERY_RANGE': 'SUBNET'},
            dds_wire.DiscoveryRange.LOCALHOST,
            True,
        ),
        ({'ROS_LOCALHOST_ONLY': '0'}, dds_wire.DiscoveryRange.SUBNET, False),
    ],
)
def test_discovery_range_is_resolved_like_rcl(env, expected_range, warns):
    """The range follows rcl: SUBNET default, unknown -> LOCALHOST, ROS_LOCALHOST_ONLY=1 wins."""
    config = dds_wire.discovery_config_from_env(env)
    assert config.discovery_range is expected_range
    assert bool(config.warnings) is warns


def test_localhost_only_drops_static_peers_and_warns_about_deprecation():
    """ROS_LOCALHOST_ONLY=1 discards ROS_STATIC_PEERS and says it is deprecated."""
    config = dds_wire.discovery_config_from_env(
        {'ROS_LOCALHOST_ONLY': '1', 'ROS_STATIC_PEERS': '10.0.0.1;10.0.0.2'}
    )
    assert config.static_peers == ()
    assert 'ROS_LOCALHOST_ONLY is deprecated' in config.warnings[0]


def test_localhost_config_is_the_loopback_unicast_config():
    """LOCALHOST selects lo, disables multicast, uses participant indexes and peers 127.0.0.1."""
    config = dds_wire.discovery_config_from_env({'ROS_AUTOMATIC_DISCOVERY_RANGE': 'LOCALHOST'})
    xml = dds_wire.cyclone_config(config, None, 1234)
    assert xml is not None
    for fragment in (
        '<NetworkInterface name="lo"/>',
        '<AllowMulticast>false</AllowMulticast>',
        '<ParticipantIndex>auto</ParticipantIndex>',
        '<MaxAutoParticipantIndex>32</MaxAutoParticipantIndex>',
        '<Peer address="127.0.0.1"/>',
    ):
        assert fragment in xml


def test_user_cyclonedds_uri_is_kept_after_our_fragment():
    """A user's CYCLONEDDS_URI is appended (so it wins), and is used alone under SUBNET."""
    localhost = dds_wire.discovery_config_from_env({'ROS_AUTOMATIC_DISCOVERY_RANGE': 'LOCALHOST'})
    combined = dds_wire.cyclone_config(localhost, 'file:///etc/my.xml', 1)
    assert combined is not None
    assert combined.endswith(',file:///etc/my.xml')
    subnet = dds_wire.discovery_config_from_env({})
    assert dds_wire.cyclone_config(subnet, 'file:///etc/my.xml', 1) == 'file:///etc/my.xml'
    assert dds_wire.cyclone_config(subnet, None, 1) is None


def test_off_range_tags_the_domain_with_the_pid_and_subnet_peers_are_listed():
    """OFF makes the domain unreachable (tag with pid); SUBNET + static peers lists them."""
    off = dds_wire.discovery_config_from_env({'ROS_AUTOMATIC_DISCOVERY_RANGE': 'OFF'})
    assert '<Tag>ros_discovery_off_4321</Tag>' in (dds_wire.cyclone_config(off, None, 4321) or '')
    peers = dds_wire.discovery_config_from_env({'ROS_STATIC_PEERS': 'robot.local; 10.0.0.7'})
    xml = dds_wire.cyclone_config(peers, None, 1) or ''
    assert '<Peer address="robot.local"/><Peer address="10.0.0.7"/>' in xml


# -- names --------------------------------------------------------------------------------------


def test_topic_and_type_names_are_mangled_like_rmw():
    """/tf -> rt/tf and pkg/msg/Name -> pkg::msg::dds_::Name_, with clear errors otherwise."""
    assert dds_wire.dds_topic_name('/tf') == 'rt/tf'
    assert dds_wire.dds_topic_name('/a/b') == 'rt/a/b'
    assert dds_wire.ros_topic_name('rt/a/b') == '/a/b'
    assert dds_wire.ros_topic_name('ros_discovery_info') is None
    assert dds_wire.dds_type_name('tf2_msgs/msg/TFMessage') == TF_TYPE
    with pytest.raises(ValueError, match='not fully qualified'):
        dds_wire.dds_topic_name('tf')
    with pytest.raises(ValueError, match='not a ROS interface type name'):
        dds_wire.dds_type_name('TFMessage')


# -- QoS ----------------------------------------------------------------------------------------


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


# -- endpoints on real DDS ------------------------------------------------------------------------


@pytest.fixture
def wire(dds_env: dict[str, str]) -> Iterator[dds_wire.DdsParticipant]:
    """This process' participant on the test's private domain."""
    participant = dds_wire.get_participant()
    yield participant
    dds_wire.close_participant()


def _discovered(reader: BuiltinDataReader, topic: str) -> list[DcpsEndpoint]:
    deadline = time.monotonic() + 10
    while time.monotonic() < deadline:
        found = [s for s in reader.read(N=1000) if s.topic_name == topic]
        if found:
            return found
        time.sleep(0.05)
    return []


@pytest.mark.dds
def test_endpoints_are_announced_like_rmw_cyclonedds(wire):
    """Writers and readers carry the ROS type name, no type information, XCDR1 and the typehash."""
    typehash = tf2_msgs.TFMessage.__typehash__
    user_data = f'typehash={typehash};'.encode()
    wire.create_writer('rt/announce', TF_TYPE, dds_wire.EndpointQos(depth=100), user_data)
    wire.create_reader('rt/announce', TF_TYPE, dds_wire.EndpointQos(depth=100), user_data)
    for builtin_topic in (BuiltinTopicDcpsPublication, BuiltinTopicDcpsSubscription):
        reader = BuiltinDataReader(wire._participant, builtin_topic)
        (endpoint,) = _discovered(reader, 'rt/announce')
        assert endpoint.type_name == TF_TYPE
        assert endpoint.type_id is None
        assert Policy.DataRepresentation(use_cdrv0_representation=True) in set(endpoint.qos)
        assert Policy.Userdata(user_data) in set(endpoint.qos)


@pytest.mark.dds
def test_raw_payload_round_trips_byte_for_byte(wire):
    """What a raw writer sends is what a raw reader takes: our codec's bytes, untouched."""
    qos = dds_wire.EndpointQos(depth=10)
    writer = wire.create_writer('rt/raw', TF_TYPE, qos, b'typehash=x;')
    reader = wire.create_reader('rt/raw', TF_TYPE, qos, b'typehash=x;')
    waitset = dds_wire.WaitSet(wire)
    waitset.attach(reader.read_condition)
    payload = cdr.serialize(tf2_msgs.TFMessage())
    writer.write(payload)
    assert waitset.wait(5_000_000_000) == [reader.read_condition]
    assert reader.take() == [payload]
    assert reader.take() == []
    waitset.close()


@pytest.mark.dds
def test_one_topic_cannot_carry_two_types(wire):
    """Reusing a DDS topic with another type is refused with both type names in the error."""
    wire.create_writer('rt/typed', TF_TYPE, dds_wire.EndpointQos(), b'')
    with pytest.raises(dds_wire.DdsWireError, match='std_msgs::msg::dds_::String_'):
        wire.create_writer('rt/typed', 'std_msgs::msg::dds_::String_', dds_wire.EndpointQos(), b'')


@pytest.mark.dds
def test_unusable_cyclonedds_uri_is_a_config_error_naming_it(dds_env):
    """A CYCLONEDDS_URI that Cyclone rejects gives a ValueError quoting it, not a crash."""
    env = dict(dds_env, CYCLONEDDS_URI='<CycloneDDS><Domain><Bogus/></Domain></CycloneDDS>')
    with pytest.raises(ValueError, match=r'cannot create the DDS participant .*Bogus'):
        dds_wire.DdsParticipant(env)
