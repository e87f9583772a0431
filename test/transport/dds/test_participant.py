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

"""The process' DDS participant: endpoints announced as rmw_cyclonedds', topics, config errors."""

from __future__ import annotations

import time

from conftest import STANDALONE_ONLY
import pytest

pytest.importorskip('cyclonedds', reason=STANDALONE_ONLY)

from cyclonedds.builtin import BuiltinDataReader
from cyclonedds.builtin import BuiltinTopicDcpsPublication
from cyclonedds.builtin import BuiltinTopicDcpsSubscription
from cyclonedds.builtin_types import DcpsEndpoint
from cyclonedds.qos import Policy
from tf_demo.msgs import tf2_msgs
from tf_demo.transport.dds import wire as dds_wire

TF_TYPE = 'tf2_msgs::msg::dds_::TFMessage_'


def _discovered(reader: BuiltinDataReader, topic: str) -> list[DcpsEndpoint]:
    deadline = time.monotonic() + 10
    while time.monotonic() < deadline:
        found = [s for s in reader.read(N=1000) if s.topic_name == topic]
        if found:
            return found
        time.sleep(0.05)
    return []


@pytest.mark.dds
def test_endpoints_are_announced_like_rmw_cyclonedds(dds_participant):
    """Writers and readers carry the ROS type name, no type information, XCDR1 and the typehash."""
    typehash = tf2_msgs.TFMessage.__typehash__
    user_data = f'typehash={typehash};'.encode()
    dds_participant.create_writer(
        'rt/announce', TF_TYPE, dds_wire.EndpointQos(depth=100), user_data
    )
    dds_participant.create_reader(
        'rt/announce', TF_TYPE, dds_wire.EndpointQos(depth=100), user_data
    )
    for builtin_topic in (BuiltinTopicDcpsPublication, BuiltinTopicDcpsSubscription):
        reader = BuiltinDataReader(dds_participant._participant, builtin_topic)
        (endpoint,) = _discovered(reader, 'rt/announce')
        assert endpoint.type_name == TF_TYPE
        assert endpoint.type_id is None
        assert Policy.DataRepresentation(use_cdrv0_representation=True) in set(endpoint.qos)
        assert Policy.Userdata(user_data) in set(endpoint.qos)


@pytest.mark.dds
def test_one_topic_cannot_carry_two_types(dds_participant):
    """Reusing a DDS topic with another type is refused with both type names in the error."""
    dds_participant.create_writer('rt/typed', TF_TYPE, dds_wire.EndpointQos(), b'')
    with pytest.raises(dds_wire.DdsWireError, match='std_msgs::msg::dds_::String_'):
        dds_participant.create_writer(
            'rt/typed', 'std_msgs::msg::dds_::String_', dds_wire.EndpointQos(), b''
        )


@pytest.mark.dds
def test_unusable_cyclonedds_uri_is_a_config_error_naming_it(dds_env):
    """A CYCLONEDDS_URI that Cyclone rejects gives a ValueError quoting it, not a crash."""
    env = dict(dds_env, CYCLONEDDS_URI='<CycloneDDS><Domain><Bogus/></Domain></CycloneDDS>')
    with pytest.raises(ValueError, match=r'cannot create the DDS participant .*Bogus'):
        dds_wire.DdsParticipant(env)
