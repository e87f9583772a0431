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

"""Golden CDR bytes of ROS 2 Jazzy (rclpy serialize_message), in both directions.

Offsets in the comments are relative to the first byte after the 4-byte encapsulation header,
which is what CDR alignment is relative to.
"""

from __future__ import annotations

from array import array
import json
from pathlib import Path
from struct import pack
from typing import Any

import numpy
import pytest
from tf_demo.msgs import cdr
from tf_demo.msgs._message import message_class
from tf_demo.msgs._reference import reference_deserialize
from tf_demo.msgs._reference import reference_serialize
from tf_demo.msgs.geometry_msgs import Quaternion
from tf_demo.msgs.geometry_msgs import Transform
from tf_demo.msgs.geometry_msgs import TransformStamped
from tf_demo.msgs.geometry_msgs import Vector3
from tf_demo.msgs.sensor_msgs import JointState
from tf_demo.msgs.std_msgs import Header
from tf_demo.msgs.std_msgs import String
from tf_demo.msgs.tf2_msgs import TFMessage

GOLDEN = Path(__file__).resolve().parent.parent / 'data' / 'golden'
INDEX: dict[str, Any] = json.loads((GOLDEN / 'index.json').read_text())


def h(text: str) -> bytes:
    """Return the bytes written as hex pairs."""
    return bytes.fromhex(text)


def f64(*values: float) -> bytes:
    """Return ``values`` as little-endian float64s."""
    return pack(f'<{len(values)}d', *values)


# Each string is its uint32 length (NUL included), its bytes and NUL, then the padding before
# the next item: a uint32 is 4-aligned, a float64 8-aligned in XCDR1.
TF_ONE = b''.join(
    [
        h('00 01 00 00'),  # header: encapsulation CDR_LE (00 01), options 00 00
        h('01 00 00 00'),  # off 0: transforms: sequence length 1
        h('01 00 00 00 02 00 00 00'),  # off 4: [0].header.stamp: sec = 1, nanosec = 2
        # off 12: [0].header.frame_id: length 10, 'base_link' + NUL, 2 bytes of padding at 26
        h('0a 00 00 00') + b'base_link\x00' + h('00 00'),
        # off 28: [0].child_frame_id: length 12, 'camera_link' + NUL, 4 bytes of padding at 44
        h('0c 00 00 00') + b'camera_link\x00' + h('00 00 00 00'),
        f64(0.5, 0.0, 0.2),  # off 48: [0].transform.translation (x, y, z)
        f64(0.0, 0.0, 0.0, 1.0),  # off 72: [0].transform.rotation (x, y, z, w)
    ]
)
TF_THREE = b''.join(
    [
        h('00 01 00 00'),  # header: encapsulation CDR_LE (00 01), options 00 00
        h('03 00 00 00'),  # off 0: transforms: sequence length 3
        h('00 f1 53 65 15 cd 5b 07'),  # off 4: [0].header.stamp = 1700000000 s, 123456789 ns
        h('04 00 00 00') + b'map\x00',  # off 12: [0].header.frame_id: length 4, 'map' + NUL
        # off 20: [0].child_frame_id: length 5, 'odom' + NUL, 3 bytes of padding at 29
        h('05 00 00 00') + b'odom\x00' + h('00 00 00'),
        f64(1.25, -2.5, 0.0),  # off 32: [0].transform.translation
        # off 56: [0].transform.rotation: 45 degrees about z
        f64(0.0, 0.0, 0.3826834323650898, 0.9238795325112867),
        h('00 f1 53 65 15 cd 5b 07'),  # off 88: [1].header.stamp = 1700000000 s, 123456789 ns
        # off 96: [1].header.frame_id: length 5, 'odom' + NUL, 3 bytes of padding at 105
        h('05 00 00 00') + b'odom\x00' + h('00 00 00'),
        # off 108: [1].child_frame_id: length 15, 'base_footprint' + NUL, 1 byte of padding at 127
        h('0f 00 00 00') + b'base_footprint\x00' + h('00'),
        f64(0.1, 0.2, 0.0),  # off 128: [1].transform.translation
        # off 152: [1].transform.rotation: -90 degrees about z
        f64(0.0, 0.0, -0.7071067811865476, 0.7071067811865476),
        h('00 00 00 00 00 00 00 00'),  # off 184: [2].header.stamp = 0 s, 0 ns
        # off 192: [2].header.frame_id: length 15, 'base_footprint' + NUL, 1 byte of padding at 211
        h('0f 00 00 00') + b'base_footprint\x00' + h('00'),
        # off 212: [2].child_frame_id: length 44, the name + NUL, 4 bytes of padding at 260
        h('2c 00 00 00') + b'a_frame_with_a_rather_long_name_for_padding\x00' + h('00 00 00 00'),
        f64(-1e-09, 1000000000.0, 3.141592653589793),  # off 264: [2].transform.translation
        f64(0.5, 0.5, 0.5, 0.5),  # off 288: [2].transform.rotation
    ]
)
JOINT_STATE = b''.join(
    [
        h('00 01 00 00'),  # header: encapsulation CDR_LE (00 01), options 00 00
        h('2a 00 00 00 07 00 00 00'),  # off 0: header.stamp: sec = 42, nanosec = 7
        # off 8: header.frame_id: length 1, '' (just the NUL), 3 bytes of padding at 13
        h('01 00 00 00') + b'\x00' + h('00 00 00'),
        h('03 00 00 00'),  # off 16: name: sequence length 3
        # off 20: name[0]: length 9, 'shoulder' + NUL, 3 bytes of padding at 33
        h('09 00 00 00') + b'shoulder\x00' + h('00 00 00'),
        h('06 00 00 00') + b'elbow\x00' + h('00 00'),  # off 36: name[1], 2 bytes of padding
        h('08 00 00 00') + b'wrist_1\x00',  # off 48: name[2] = 'wrist_1' (ends 4-aligned)
        h('03 00 00 00'),  # off 60: position: length 3 (no padding: 64 is 8-aligned)
        f64(0.1, -1.5707963267948966, 3.0),  # off 64: position = 0.1, -pi/2, 3.0
        h('00 00 00 00'),  # off 88: velocity: length 0 (empty: no padding to 8 follows)
        h('03 00 00 00'),  # off 92: effort: sequence length 3
        f64(0.0, 1.0, -2.0),  # off 96: effort
    ]
)
STRING = b''.join(
    [
        h('00 01 00 00'),  # header: encapsulation CDR_LE (00 01), options 00 00
        h('29 00 00 00'),  # off 0: data: length 41
        b'<robot name="r"><link name="a"/></robot>\x00',  # off 4: data + NUL (no trailing pad)
    ]
)
ODOMETRY = b''.join(
    [
        h('00 01 00 00'),  # header: encapsulation CDR_LE (00 01), options 00 00
        h('05 00 00 00 00 65 cd 1d'),  # off 0: header.stamp: sec = 5, nanosec = 500000000
        # off 8: header.frame_id: length 5, 'odom' + NUL, 3 bytes of padding at 17
        h('05 00 00 00') + b'odom\x00' + h('00 00 00'),
        # off 20: child_frame_id: length 10, 'base_link' + NUL, 6 bytes of padding at 34
        h('0a 00 00 00') + b'base_link\x00' + h('00 00 00 00 00 00'),
        f64(1.0, 2.0, 0.0),  # off 40: pose.pose.position
        f64(0.0, 0.0, 0.0998334166, 0.9950041653),  # off 64: pose.pose.orientation
        f64(*[i / 10 for i in range(36)]),  # off 96: pose.covariance = 0.0, 0.1, ..., 3.5
        f64(0.5, 0.0, 0.0),  # off 384: twist.twist.linear
        f64(0.0, 0.0, 0.1),  # off 408: twist.twist.angular
        bytes(36 * 8),  # off 432: twist.covariance = 36 zeros
    ]
)

ANNOTATED = {
    'tf2_msgs__TFMessage__one': TF_ONE,
    'tf2_msgs__TFMessage__three': TF_THREE,
    'sensor_msgs__JointState': JOINT_STATE,
    'std_msgs__String': STRING,
    'nav_msgs__Odometry': ODOMETRY,
}


def golden_bytes(name: str) -> bytes:
    """Return the bytes of golden file ``name``."""
    return (GOLDEN / f'{name}.cdr').read_bytes()


def from_plain(msgtype: str, value: dict[str, Any]) -> Any:
    """Build one of our messages from index.json's plain dictionary form."""
    cls = message_class(msgtype)
    kwargs = {}
    for field in cls._spec.fields:
        item = value[field.name]
        if field.is_nested and field.kind == 'single':
            item = from_plain(field.base, item)
        elif field.is_nested:
            item = [from_plain(field.base, element) for element in item]
        kwargs[field.name] = item
    return cls(**kwargs)


def to_plain(message: Any) -> Any:
    """Turn a message into index.json's plain form (nested dicts, lists of numbers)."""
    if hasattr(message, 'get_fields_and_field_types'):
        return {
            name: to_plain(getattr(message, name)) for name in message.get_fields_and_field_types()
        }
    if isinstance(message, list | tuple | array | numpy.ndarray):
        return [to_plain(item) for item in message]
    return message


@pytest.mark.parametrize('name', sorted(ANNOTATED))
def test_annotated_bytes_are_the_golden_files(name: str) -> None:
    """The field-by-field annotated byte strings are exactly the golden files."""
    assert ANNOTATED[name] == golden_bytes(name)
    assert len(ANNOTATED[name]) == INDEX[name]['bytes']


@pytest.mark.parametrize('name', sorted(INDEX))
def test_serialize_reproduces_golden_bytes(name: str) -> None:
    """Encoding the index.json values gives rclpy's bytes exactly."""
    entry = INDEX[name]
    message = from_plain(entry['type'], entry['value'])
    assert cdr.serialize(message) == golden_bytes(name)


@pytest.mark.parametrize('name', sorted(INDEX))
def test_deserialize_recovers_golden_values(name: str) -> None:
    """Decoding rclpy's bytes gives the index.json values and our class."""
    entry = INDEX[name]
    message = cdr.deserialize(entry['type'], golden_bytes(name))
    assert type(message) is message_class(entry['type'])
    assert to_plain(message) == entry['value']
    assert message == from_plain(entry['type'], entry['value'])


@pytest.mark.parametrize('name', sorted(INDEX))
def test_reference_codec_agrees_on_golden_bytes(name: str) -> None:
    """The slow reference codec encodes and decodes the goldens like the generated one."""
    entry = INDEX[name]
    data = golden_bytes(name)
    message = from_plain(entry['type'], entry['value'])
    assert reference_serialize(entry['type'], message) == data
    assert reference_deserialize(entry['type'], data) == message


def test_tf_message_built_field_by_field_encodes_to_annotated_bytes() -> None:
    """A TFMessage assembled like node code does encodes to the annotated bytes."""
    transform = TransformStamped()
    transform.header.stamp.sec = 1
    transform.header.stamp.nanosec = 2
    transform.header.frame_id = 'base_link'
    transform.child_frame_id = 'camera_link'
    transform.transform.translation.x = 0.5
    transform.transform.translation.z = 0.2
    assert cdr.serialize(TFMessage(transforms=[transform])) == TF_ONE
    nested = TransformStamped(
        header=Header(frame_id='base_link'),
        child_frame_id='camera_link',
        transform=Transform(translation=Vector3(x=0.5, z=0.2), rotation=Quaternion()),
    )
    nested.header.stamp.sec, nested.header.stamp.nanosec = 1, 2
    assert cdr.deserialize(TFMessage, TF_ONE) == TFMessage(transforms=[nested])


def test_joint_state_and_string_round_trip_through_annotated_bytes() -> None:
    """JointState with an empty velocity and the robot_description String decode and re-encode."""
    joint_state = cdr.deserialize(JointState, JOINT_STATE)
    assert list(joint_state.name) == ['shoulder', 'elbow', 'wrist_1']
    assert list(joint_state.velocity) == []
    assert cdr.serialize(joint_state) == JOINT_STATE
    text = cdr.deserialize(String, STRING)
    assert text.data == '<robot name="r"><link name="a"/></robot>'
    assert cdr.serialize(text) == STRING


@pytest.mark.parametrize(
    'name',
    ['tf2_msgs__TFMessage__one', 'tf2_msgs__TFMessage__three', 'tf2_msgs__TFMessage__empty'],
)
def test_tf_fast_path_matches_full_decode(name: str) -> None:
    """decode_tf_message_transforms gives the same frames, stamps and poses as deserialize."""
    data = golden_bytes(name)
    expected = [
        (
            t.header.frame_id,
            t.child_frame_id,
            t.header.stamp.sec * 10**9 + t.header.stamp.nanosec,
            (t.transform.translation.x, t.transform.translation.y, t.transform.translation.z),
            (
                t.transform.rotation.x,
                t.transform.rotation.y,
                t.transform.rotation.z,
                t.transform.rotation.w,
            ),
        )
        for t in cdr.deserialize(TFMessage, data).transforms
    ]
    assert cdr.decode_tf_message_transforms(data) == expected
    assert cdr.decode_tf_message_transforms(memoryview(data)) == expected
