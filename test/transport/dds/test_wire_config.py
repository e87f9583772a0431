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

"""ROS 2's wire conventions on DDS, the pure part: domain, discovery configuration, names."""

from __future__ import annotations

from conftest import STANDALONE_ONLY
import pytest

pytest.importorskip('cyclonedds', reason=STANDALONE_ONLY)

from tf_demo.transport.dds import wire as dds_wire

TF_TYPE = 'tf2_msgs::msg::dds_::TFMessage_'


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


def test_ros_type_name_reverses_dds_type_name() -> None:
    for ros_type in ('tf2_msgs/msg/TFMessage', 'rcl_interfaces/srv/GetParameters'):
        assert dds_wire.ros_type_name(dds_wire.dds_type_name(ros_type)) == ros_type
    assert dds_wire.ros_type_name('DCPSParticipant') == 'DCPSParticipant'  # not a ROS type
