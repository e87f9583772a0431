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

"""The reference XCDR1 codec: the plain wire rules, and errors that name the field and byte."""

from __future__ import annotations

from struct import pack

import pytest
from tf_demo.msgs._reference import c_string
from tf_demo.msgs._reference import CdrError
from tf_demo.msgs._reference import check_header
from tf_demo.msgs._reference import reference_deserialize
from tf_demo.msgs._reference import reference_serialize
from tf_demo.msgs.geometry_msgs import Vector3
from tf_demo.msgs.std_msgs import String

LITTLE_ENDIAN = b'\x00\x01\x00\x00'


def test_encoding_follows_the_wire_rules_and_decodes_back() -> None:
    """Doubles little-endian after the header; a string is length, bytes and NUL, padded."""
    vector = Vector3(x=1.0, y=-2.0, z=0.5)
    encoded = reference_serialize('geometry_msgs/msg/Vector3', vector)
    assert encoded == LITTLE_ENDIAN + pack('<3d', 1.0, -2.0, 0.5)
    assert reference_deserialize('geometry_msgs/msg/Vector3', encoded) == vector
    text = reference_serialize('std_msgs/msg/String', String(data='ab'))
    assert text == LITTLE_ENDIAN + pack('<I', 3) + b'ab\x00'
    big_endian = b'\x00\x00\x00\x00' + pack('>I', 3) + b'ab\x00'
    assert reference_deserialize('std_msgs/msg/String', big_endian) == String(data='ab')


@pytest.mark.parametrize(
    ('body', 'problem'),
    [
        (pack('<I', 3) + b'ab!', 'field data at byte 10: string does not end with NUL'),
        (pack('<H', 3), 'field data at byte 4: uint32 needs 4 bytes but only 2 remain'),
    ],
)
def test_a_bad_encoding_names_the_type_field_and_byte(body: bytes, problem: str) -> None:
    """The first problem is reported with the type, the field path and its byte offset."""
    with pytest.raises(CdrError, match=f'^cannot decode std_msgs/msg/String: {problem}'):
        reference_deserialize('std_msgs/msg/String', LITTLE_ENDIAN + body)


def test_only_plain_cdr_headers_are_accepted() -> None:
    """A short buffer or an XCDR2/PL_CDR header is refused naming the type."""
    check_header('rosgraph_msgs/msg/Clock', LITTLE_ENDIAN)
    with pytest.raises(CdrError, match='2 bytes is shorter than the CDR header'):
        check_header('rosgraph_msgs/msg/Clock', b'\x00\x01')
    with pytest.raises(CdrError, match='encapsulation header 00 07 is not plain CDR'):
        check_header('rosgraph_msgs/msg/Clock', b'\x00\x07\x00\x00')


def test_odd_strings_read_as_rclpy_reads_them() -> None:
    """The text ends at the first NUL and invalid UTF-8 becomes U+FFFD, as in rclpy."""
    assert c_string(b'') == ''
    assert c_string(b'a\x00b\x00') == 'a'
    assert c_string(b'\xff\x00') == '\ufffd'
