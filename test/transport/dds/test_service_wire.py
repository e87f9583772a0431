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

"""rmw_cyclonedds' service wire format: request samples, client ids, and real Jazzy samples."""

from __future__ import annotations

from collections.abc import Callable
import json
from pathlib import Path
import struct
from typing import Any

from conftest import REPO_ROOT
from conftest import STANDALONE_ONLY
import pytest

pytest.importorskip('cyclonedds', reason=STANDALONE_ONLY)

from tf_demo.msgs import cdr
from tf_demo.msgs import rcl_interfaces
from tf_demo.msgs import tf2_msgs
from tf_demo.transport.dds import service_wire

pytestmark = [pytest.mark.standalone, pytest.mark.dds]

GOLDEN = REPO_ROOT / 'test' / 'data' / 'golden' / 'services'

GOLDEN = REPO_ROOT / 'test' / 'data' / 'golden' / 'services'


def test_request_sample_layout_is_rmw_cyclonedds() -> None:
    """Encapsulation, then client id and sequence number (8 + 8 bytes), then the CDR body."""
    request = rcl_interfaces.GetParameters.Request(names=['radius'])
    header = service_wire.RequestHeader(0x0102030405060708, 7)
    sample = service_wire.encode_sample(header, request)
    body = cdr.serialize(request)
    assert sample[:4] == b'\x00\x01\x00\x00'
    assert sample[4:20] == struct.pack('<Qq', 0x0102030405060708, 7)
    assert sample[20:] == body[4:]
    decoded_header, decoded = service_wire.decode_sample(
        rcl_interfaces.GetParameters.Request, sample
    )
    assert decoded_header == header
    assert decoded == request


def test_big_endian_samples_decode() -> None:
    """The header follows the sample's byte order (byte 1 of the encapsulation)."""
    big = b'\x00\x00\x00\x00' + struct.pack('>Qq', 5, 9) + struct.pack('>I', 0)
    header, request = service_wire.decode_sample(rcl_interfaces.GetParameters.Request, big)
    assert (header.guid, header.sequence_number) == (5, 9)
    assert list(request.names) == []


@pytest.mark.parametrize('data', [b'', b'\x00\x01\x00\x00', b'\x00\x01\x00\x00' + bytes(15)])
def test_short_or_garbage_samples_raise_cdr_error(data: bytes) -> None:
    """Samples without a full header or body raise CdrError (dropped by the node)."""
    with pytest.raises(cdr.CdrError):
        service_wire.decode_sample(rcl_interfaces.GetParameters.Request, data)


def test_client_service_ids_are_spelled_as_rmw_cyclonedds() -> None:
    """GUID prefix + big-endian counter, hex, first byte width 2, dots between."""
    guid = bytes(range(1, 17))
    text = service_wire.client_service_id(guid, counter=0x0102)
    assert text == ' 1.2.3.4.5.6.7.8.9.a.b.c.0.0.1.2'
    assert service_wire.parse_user_data(f'clientid={text};typehash=RIHS01_x;'.encode()) == {
        'clientid': text,
        'typehash': 'RIHS01_x',
    }


GOLDEN_CASES = sorted(GOLDEN.glob('*.cdr'))


@pytest.mark.parametrize('path', GOLDEN_CASES, ids=[p.stem for p in GOLDEN_CASES])
def test_golden_service_samples_from_real_jazzy(path: Path) -> None:
    """Samples a real Jazzy rclpy client/server sent decode, and re-encode to the same bytes."""
    entry = json.loads((GOLDEN / 'index.json').read_text())[path.stem]
    module = {'rcl_interfaces': rcl_interfaces, 'tf2_msgs': tf2_msgs}[entry['package']]
    msg_type = getattr(getattr(module, entry['service']), entry['part'])
    data = path.read_bytes()
    assert len(data) == entry['bytes']
    header, message = service_wire.decode_sample(msg_type, data)
    assert header.sequence_number >= 1
    again = service_wire.encode_sample(header, message)
    assert again == data[: len(again)]
    assert not any(data[len(again) :])  # only DDS padding after it
    assert GOLDEN_VALUES[path.stem](message)


GOLDEN_VALUES: dict[str, Callable[[Any], bool]] = {
    'rcl_interfaces__GetParameters__Request': lambda m: m.names == ['radius', 'use_sim_time'],
    'rcl_interfaces__SetParameters__Request': lambda m: (
        [(p.name, p.value.type, p.value.double_value) for p in m.parameters]
        == [('radius', 3, 2.5)]
    ),
    'tf2_msgs__FrameGraph__Request': lambda m: m.structure_needs_at_least_one_member == 0,
    'rcl_interfaces__GetParameters__Response': lambda m: (
        [v.type for v in m.values] == [3, 4, 7]
        and m.values[0].double_value == 1.5
        and m.values[1].string_value == 'odom'
        and list(m.values[2].integer_array_value) == [1, 2, 3]
    ),
    'rcl_interfaces__DescribeParameters__Response': lambda m: (
        [d.name for d in m.descriptors] == ['radius', 'ranged']
        and m.descriptors[1].description == 'a range'
        and m.descriptors[1].floating_point_range[0].to_value == 1.0
    ),
    'rcl_interfaces__ListParameters__Response': lambda m: (
        'radius' in m.result.names and m.result.prefixes == ['nested']
    ),
}
