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

"""Raw-bytes writers and readers and the waitset: our codec's bytes go over DDS untouched."""

from __future__ import annotations

from conftest import STANDALONE_ONLY
import pytest

pytest.importorskip('cyclonedds', reason=STANDALONE_ONLY)

from tf_demo.msgs import cdr
from tf_demo.msgs import tf2_msgs
from tf_demo.transport.dds import wire as dds_wire

TF_TYPE = 'tf2_msgs::msg::dds_::TFMessage_'


@pytest.mark.dds
def test_raw_payload_round_trips_byte_for_byte(dds_participant):
    """What a raw writer sends is what a raw reader takes: our codec's bytes, untouched."""
    qos = dds_wire.EndpointQos(depth=10)
    writer = dds_participant.create_writer('rt/raw', TF_TYPE, qos, b'typehash=x;')
    reader = dds_participant.create_reader('rt/raw', TF_TYPE, qos, b'typehash=x;')
    waitset = dds_wire.WaitSet(dds_participant)
    waitset.attach(reader.read_condition)
    payload = cdr.serialize(tf2_msgs.TFMessage())
    writer.write(payload)
    assert waitset.wait(5_000_000_000) == [reader.read_condition]
    assert reader.take() == [payload]
    assert reader.take() == []
    waitset.close()
