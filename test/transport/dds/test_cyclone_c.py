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

"""The Cyclone C calls cyclonedds-python does not wrap: return codes, GUIDs, matches, types."""

from __future__ import annotations

from conftest import STANDALONE_ONLY
import pytest

pytest.importorskip('cyclonedds', reason=STANDALONE_ONLY)

from dds_helpers import wait_for
from tf_demo.transport.dds import cyclone_c
from tf_demo.transport.dds import wire as dds_wire

TF_TYPE = 'tf2_msgs::msg::dds_::TFMessage_'


def test_check_passes_results_and_names_the_failed_call() -> None:
    """A negative DDS return code becomes DdsWireError naming the call; others pass through."""
    assert cyclone_c.check(0, 'dds_x') == 0
    assert cyclone_c.check(5, 'dds_x') == 5
    with pytest.raises(dds_wire.DdsWireError, match=r'^dds_x failed \(DDS return code -3\)$'):
        cyclone_c.check(-3, 'dds_x')


def test_a_placeholder_type_carries_the_dds_type_name_and_type_information() -> None:
    """Each placeholder is a fresh class named as asked, with serialized XTypes information."""
    first = cyclone_c.placeholder_type(TF_TYPE)
    second = cyclone_c.placeholder_type(TF_TYPE)
    assert first is not second
    assert first.__idl_typename__ == TF_TYPE
    assert cyclone_c.type_information(first)


@pytest.mark.dds
def test_guids_and_matched_handles_of_real_entities(dds_participant: dds_wire.DdsParticipant):
    """Entities have 16-byte GUIDs under the participant's prefix; a matched reader is listed."""
    qos = dds_wire.EndpointQos(depth=10)
    writer = dds_participant.create_writer('rt/cyclone_c', TF_TYPE, qos, b'')
    reader = dds_participant.create_reader('rt/cyclone_c', TF_TYPE, qos, b'')
    guid = cyclone_c.entity_guid(writer.handle)
    assert guid == writer.guid
    assert len(guid) == 16
    assert guid[:12] == dds_participant.guid[:12]  # one participant: one GUID prefix
    assert wait_for(lambda: cyclone_c.matched_handles(writer.handle, subscriptions=True))
    [matched] = cyclone_c.matched_handles(writer.handle, subscriptions=True)
    assert matched == cyclone_c.instance_handle(reader.handle)
