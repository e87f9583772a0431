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

"""The CDR codec: round trips, big-endian input, and clear errors for every kind of bad input."""

from __future__ import annotations

from pathlib import Path
from struct import pack
from typing import Any

from hypothesis import given
from hypothesis import settings
from hypothesis import strategies as st
from msgs_strategies import message_strategy
import pytest
from tf_demo.msgs import cdr
from tf_demo.msgs._reference import reference_deserialize
from tf_demo.msgs._reference import reference_serialize
from tf_demo.msgs._schema import DEFINITIONS
from tf_demo.msgs.builtin_interfaces import Time
from tf_demo.msgs.convert import fill_transform_stamped
from tf_demo.msgs.geometry_msgs import Point32
from tf_demo.msgs.geometry_msgs import TransformStamped
from tf_demo.msgs.geometry_msgs import Vector3
from tf_demo.msgs.rmw_dds_common import Gid
from tf_demo.msgs.rmw_dds_common import NodeEntitiesInfo
from tf_demo.msgs.rmw_dds_common import ParticipantEntitiesInfo
from tf_demo.msgs.rosgraph_msgs import Clock
from tf_demo.msgs.sensor_msgs import JointState
from tf_demo.msgs.std_msgs import String
from tf_demo.msgs.tf2_msgs import TFMessage

GOLDEN = Path(__file__).resolve().parent.parent / 'data' / 'golden'
GOLDEN_FILES = sorted(GOLDEN.glob('*.cdr'))
TYPE_OF_GOLDEN = {
    path.name: '/msg/'.join(path.stem.split('__')[:2]) for path in GOLDEN_FILES
}  # e.g. tf2_msgs__TFMessage__one.cdr -> tf2_msgs/msg/TFMessage


def test_point32_is_float32_on_the_wire() -> None:
    """Point32 fields are 4-byte floats: values round to float32."""
    encoded = cdr.serialize(Point32(x=0.1, y=-2.0, z=1e-3))
    assert encoded == b'\x00\x01\x00\x00' + pack('<3f', 0.1, -2.0, 1e-3)
    decoded = cdr.deserialize(Point32, encoded)
    assert decoded.x == pytest.approx(0.1, rel=1e-7)
    assert decoded.x != 0.1


def test_participant_entities_info_layout() -> None:
    """ros_discovery_info's message: 16 raw gid bytes, bounded strings, gid sequences."""
    gid = bytes(range(1, 17))
    info = ParticipantEntitiesInfo(
        gid=Gid(data=gid),
        node_entities_info_seq=[
            NodeEntitiesInfo(
                node_namespace='/',
                node_name='talker',
                writer_gid_seq=[Gid(data=bytes(range(16, 32)))],
            )
        ],
    )
    expected = b''.join(
        [
            b'\x00\x01\x00\x00',  # CDR_LE
            gid,  # off 0: gid.data (uint8[16], no length)
            pack('<I', 1),  # off 16: node_entities_info_seq length 1
            pack('<I', 2) + b'/\x00',  # off 20: node_namespace '/'
            b'\x00\x00',  # off 26: padding to 4
            pack('<I', 7) + b'talker\x00',  # off 28: node_name 'talker'
            b'\x00',  # off 39: padding to 4
            pack('<I', 0),  # off 40: reader_gid_seq length 0
            pack('<I', 1),  # off 44: writer_gid_seq length 1
            bytes(range(16, 32)),  # off 48: writer_gid_seq[0].data
        ]
    )
    assert cdr.serialize(info) == expected
    decoded = cdr.deserialize(ParticipantEntitiesInfo, expected)
    assert bytes(decoded.gid.data) == gid
    assert decoded.node_entities_info_seq[0].node_name == 'talker'


def test_big_endian_input_is_accepted() -> None:
    """CDR_BE (header 00 00) decodes to the same message, including arrays and the tf path."""
    big_endian = b''.join(
        [
            b'\x00\x00\x00\x00',  # CDR_BE
            pack('>I', 1),  # transforms: length 1
            pack('>iI', 1, 2),  # header.stamp = 1 s 2 ns
            pack('>I', 10) + b'base_link\x00' + b'\x00\x00',  # frame_id + padding
            pack('>I', 12) + b'camera_link\x00',  # child_frame_id
            b'\x00\x00\x00\x00',  # padding to 8
            pack('>7d', 0.5, 0.0, 0.2, 0.0, 0.0, 0.0, 1.0),  # translation, rotation
        ]
    )
    little_endian = (GOLDEN / 'tf2_msgs__TFMessage__one.cdr').read_bytes()
    assert cdr.deserialize(TFMessage, big_endian) == cdr.deserialize(TFMessage, little_endian)
    assert cdr.decode_tf_message_transforms(big_endian) == cdr.decode_tf_message_transforms(
        little_endian
    )
    joint_state = b''.join(
        [
            b'\x00\x00\x00\x00',  # CDR_BE
            pack('>iI', 3, 4) + pack('>I', 1) + b'\x00',  # header: stamp, frame_id ''
            b'\x00\x00\x00',  # padding to 4
            pack('>I', 0),  # name: empty
            pack('>I', 2) + pack('>2d', 1.5, -2.5),  # position (already 8-aligned at off 16)
            pack('>I', 0) + pack('>I', 0),  # velocity, effort: empty
        ]
    )
    decoded = cdr.deserialize(JointState, joint_state)
    assert list(decoded.position) == [1.5, -2.5]
    assert decoded.header.stamp.nanosec == 4


@pytest.mark.parametrize(
    ('header', 'match'),
    [
        (b'\x00\x07\x00\x00', 'encapsulation header 00 07 is not plain CDR'),
        (b'\x00\x03\x00\x00', 'encapsulation header 00 03 is not plain CDR'),
        (b'\x01\x01\x00\x00', 'encapsulation header 01 01 is not plain CDR'),
    ],
)
def test_other_encapsulations_are_rejected(header: bytes, match: str) -> None:
    """XCDR2, PL_CDR and garbage headers raise CdrError naming the header."""
    body = (GOLDEN / 'rosgraph_msgs__Clock.cdr').read_bytes()[4:]
    with pytest.raises(cdr.CdrError, match=f'rosgraph_msgs/msg/Clock: {match}'):
        cdr.deserialize(Clock, header + body)


def test_short_input_is_rejected() -> None:
    """Fewer bytes than the header is a CdrError, not an IndexError."""
    with pytest.raises(cdr.CdrError, match='shorter than the CDR header'):
        cdr.deserialize(Clock, b'\x00\x01')
    with pytest.raises(cdr.CdrError, match='shorter than the CDR header'):
        cdr.decode_tf_message_transforms(b'')


#: Length 0, a NUL inside and invalid UTF-8 are not errors: they read as a real rclpy node reads
#: them (measured against ROS 2 Jazzy in test/ros_world/test_odd_strings.py).
MALFORMED_STRINGS = {
    'no NUL': (pack('<I', 3) + b'ab!', r'field data at byte 10: string does not end with NUL'),
    'absurd length': (
        pack('<I', 2**32 - 1) + b'ab\x00',
        r'field data at byte 8: string of length 4294967295',
    ),
    'truncated length': (pack('<H', 3), r'field data at byte 4: uint32 needs 4 bytes but only 2'),
}


@pytest.mark.parametrize(('body', 'match'), MALFORMED_STRINGS.values(), ids=MALFORMED_STRINGS)
def test_malformed_strings_name_the_field_and_byte(body: bytes, match: str) -> None:
    """Missing NUL, absurd length and truncation each get a precise error."""
    with pytest.raises(cdr.CdrError, match=r'cannot decode std_msgs/msg/String: ' + match):
        cdr.deserialize(String, b'\x00\x01\x00\x00' + body)


def test_absurd_sequence_length_is_bounded_by_the_remaining_bytes() -> None:
    """A huge element count fails at once, naming the sequence, without allocating."""
    data = b'\x00\x01\x00\x00' + pack('<I', 2**31) + bytes(100)
    with pytest.raises(
        cdr.CdrError, match='TFMessage: field transforms at byte 8: sequence length'
    ):
        cdr.deserialize(TFMessage, data)
    with pytest.raises(cdr.CdrError, match='field transforms at byte 8: sequence length'):
        cdr.decode_tf_message_transforms(data)
    joint_state = bytearray((GOLDEN / 'sensor_msgs__JointState.cdr').read_bytes())
    joint_state[64:68] = pack('<I', 10**6)  # position's count
    with pytest.raises(
        cdr.CdrError, match='JointState: field position at byte 68: sequence length'
    ):
        cdr.deserialize(JointState, bytes(joint_state))


def test_error_in_a_nested_element_names_its_path() -> None:
    """A broken string deep in a sequence is reported by its full field path."""
    data = bytearray((GOLDEN / 'tf2_msgs__TFMessage__three.cdr').read_bytes())
    data[263] = ord('x')  # the NUL of transforms[2].child_frame_id
    with pytest.raises(cdr.CdrError, match=r'field transforms\[2\]\.child_frame_id at byte 263'):
        cdr.deserialize(TFMessage, bytes(data))
    with pytest.raises(cdr.CdrError, match=r'transforms\[2\]\.child_frame_id.*end with NUL'):
        cdr.decode_tf_message_transforms(bytes(data))


def _decode_or_error(msgtype: str, data: bytes, *, tf_fast_path: bool = False) -> Any:
    """Return the decoded message (or tf tuples), or the CdrError raised."""
    try:
        if tf_fast_path:
            return cdr.decode_tf_message_transforms(data)
        return cdr.deserialize(msgtype, data)
    except cdr.CdrError as error:
        return error


@pytest.mark.parametrize('path', GOLDEN_FILES, ids=lambda path: path.stem)
def test_every_truncation_of_every_golden_raises_cdr_error_or_decodes(path: Path) -> None:
    """Cutting a golden message anywhere gives CdrError (or a valid prefix), nothing else."""
    data = path.read_bytes()
    msgtype = TYPE_OF_GOLDEN[path.name]
    full = cdr.deserialize(msgtype, data)
    for end in range(len(data)):
        outcome = _decode_or_error(msgtype, data[:end])
        if isinstance(outcome, cdr.CdrError):
            assert msgtype in str(outcome)
        else:
            assert outcome != full  # only a shorter valid message could decode from a prefix
        if msgtype == 'tf2_msgs/msg/TFMessage':
            with pytest.raises(cdr.CdrError):
                cdr.decode_tf_message_transforms(data[:end])


@pytest.mark.property
@pytest.mark.parametrize('msgtype', sorted(DEFINITIONS))
@settings(max_examples=150, deadline=None)
@given(body=st.binary(max_size=120), big_endian=st.booleans())
def test_random_bytes_raise_cdr_error_or_decode(
    msgtype: str, body: bytes, big_endian: bool
) -> None:
    """Garbage after a valid header decodes or raises CdrError; the fast and slow paths agree."""
    data = (b'\x00\x00\x00\x00' if big_endian else b'\x00\x01\x00\x00') + body
    outcome = _decode_or_error(msgtype, data)
    if isinstance(outcome, cdr.CdrError):
        assert str(outcome).startswith(f'cannot decode {msgtype}')
        with pytest.raises(cdr.CdrError):
            reference_deserialize(msgtype, data)
    else:
        assert repr(outcome) == repr(reference_deserialize(msgtype, data))  # NaN-safe
    if msgtype == 'tf2_msgs/msg/TFMessage':
        fast = _decode_or_error(msgtype, data, tf_fast_path=True)
        assert isinstance(fast, cdr.CdrError) == isinstance(outcome, cdr.CdrError)


@pytest.mark.property
@settings(max_examples=200, deadline=None)
@given(data=st.data())
def test_mutated_golden_bytes_raise_cdr_error_or_decode(data: Any) -> None:
    """Flipping bytes of real messages never raises anything but CdrError."""
    path = data.draw(st.sampled_from(GOLDEN_FILES))
    raw = bytearray(path.read_bytes())
    for _ in range(data.draw(st.integers(1, 4))):
        index = data.draw(st.integers(4, len(raw) - 1))
        raw[index] = data.draw(st.integers(0, 255))
    msgtype = TYPE_OF_GOLDEN[path.name]
    try:
        decoded = cdr.deserialize(msgtype, bytes(raw))
    except cdr.CdrError:
        return
    assert repr(decoded) == repr(reference_deserialize(msgtype, bytes(raw)))  # NaN-safe


@pytest.mark.parametrize(
    ('message', 'match'),
    [
        # Wrong types on purpose (the type: ignores): the encoder's refusal is what is tested.
        (Clock(clock=Vector3()), r'Clock: field clock\.sec: Vector3 object has no field'),  # type: ignore[arg-type]
        (String(data=b'bytes'), r'String: field data: expected str'),  # type: ignore[arg-type]
        (Vector3(x='1.0'), r'Vector3: field x: expected float64'),  # type: ignore[arg-type]
        (Point32(x=1e39), r'Point32: field x: 1e\+39 is out of the float32 range'),
        (Gid(data=bytes(15)), r'Gid: field data: expected exactly 16 elements, got 15'),
        (JointState(name=['a', 3]), r'JointState: field name\[1\]: expected str'),  # type: ignore[list-item]
        (Clock(clock=Time(sec=2**31)), r'Clock: field clock\.sec: 2147483648 is out of the int32'),
        (String(data='\ud800'), r'String: field data: string cannot be encoded as UTF-8'),
    ],
)  # fmt: skip
def test_unencodable_values_raise_cdr_error_naming_the_field(message: Any, match: str) -> None:
    """Wrong types, ranges and lengths are reported with the field's path."""
    with pytest.raises(cdr.CdrError, match=r'cannot encode [a-z_]+/msg/' + match):
        cdr.serialize(message)


class _RclpyStyleVector3:
    """Stand-in with the module layout of an rclpy message class (geometry_msgs.msg._vector3)."""

    __module__ = 'geometry_msgs.msg._vector3'

    def __init__(self) -> None:
        self.x, self.y, self.z = 1.0, 2.0, 3.0


_RclpyStyleVector3.__name__ = 'Vector3'


def test_rclpy_style_objects_are_encoded_by_field_names() -> None:
    """Objects shaped like rclpy messages serialise by their class's ROS name and fields."""
    assert cdr.msgtype_of(_RclpyStyleVector3) == 'geometry_msgs/msg/Vector3'
    assert cdr.serialize(_RclpyStyleVector3()) == cdr.serialize(Vector3(x=1.0, y=2.0, z=3.0))
    decoded = cdr.deserialize(_RclpyStyleVector3, cdr.serialize(_RclpyStyleVector3()))
    assert decoded == Vector3(x=1.0, y=2.0, z=3.0)
    with pytest.raises(cdr.CdrError, match='is not a ROS message type'):
        cdr.serialize(object())


def test_long_and_many_distinct_strings_round_trip() -> None:
    """Strings longer than the struct cache covers, and many distinct lengths, still round-trip."""
    for length in (0, 1, 3, 4, 5, 1023, 1024, 1025, 5000):
        text = 'é' * (length // 2) + 'x' * (length % 2)
        encoded = cdr.serialize(String(data=text))
        assert encoded == reference_serialize('std_msgs/msg/String', String(data=text))
        assert cdr.deserialize(String, encoded).data == text
    names = [f'{"n" * (i % 37)}{i}' for i in range(300)]
    joint_state = JointState(name=names, position=[float(i) for i in range(300)])
    assert cdr.deserialize(JointState, cdr.serialize(joint_state)) == joint_state


def test_unknown_types_are_a_cdr_error() -> None:
    """Asking for a type outside the table is a CdrError naming it, for names and classes."""
    with pytest.raises(cdr.CdrError, match="'foo_msgs/msg/Bar' is not a ROS message type"):
        cdr.deserialize('foo_msgs/msg/Bar', b'\x00\x01\x00\x00')
    assert cdr.msgtype_of('geometry_msgs/Vector3') == 'geometry_msgs/msg/Vector3'


def _big_endian_tf_message(message: Any) -> bytes:
    """Write a TFMessage as CDR_BE by the layout rules (a second, independent writer)."""
    transforms: list[tuple[str, str, int, int, tuple[float, ...]]] = [
        (
            t.header.frame_id,
            t.child_frame_id,
            t.header.stamp.sec,
            t.header.stamp.nanosec,
            (
                t.transform.translation.x,
                t.transform.translation.y,
                t.transform.translation.z,
                t.transform.rotation.x,
                t.transform.rotation.y,
                t.transform.rotation.z,
                t.transform.rotation.w,
            ),
        )
        for t in message.transforms
    ]
    out = bytearray(b'\x00\x00\x00\x00' + pack('>I', len(transforms)))

    def align(alignment: int) -> None:
        out.extend(bytes(-(len(out) - 4) % alignment))

    for parent, child, sec, nanosec, pose in transforms:
        align(4)
        out += pack('>iI', sec, nanosec)
        for text in (parent.encode(), child.encode()):
            align(4)
            out += pack('>I', len(text) + 1) + text + b'\x00'
        align(8)
        out += pack('>7d', *pose)
    return bytes(out)


@pytest.mark.property
@settings(max_examples=60, deadline=None)
@given(message=message_strategy('tf2_msgs/msg/TFMessage'))
def test_big_endian_tf_messages_decode_like_little_endian(message: Any) -> None:
    """Multi-transform CDR_BE input decodes to the same message on both decode paths."""
    big_endian = _big_endian_tf_message(message)
    assert cdr.deserialize(TFMessage, big_endian) == message
    assert cdr.decode_tf_message_transforms(big_endian) == cdr.decode_tf_message_transforms(
        cdr.serialize(message)
    )


def test_deserialize_accepts_an_instance_as_the_type() -> None:
    """An (unhashable) message instance names its type as well as its class does."""
    data = cdr.serialize(Vector3(x=2.0))
    assert cdr.deserialize(Vector3(), data) == Vector3(x=2.0)
    assert cdr.deserialize('geometry_msgs/Vector3', data) == Vector3(x=2.0)


def _learn_layout(data: bytes) -> None:
    """Decode ``data`` twice, so that its whole-message layout is compiled, and check it is."""
    cdr.deserialize(TFMessage, data)
    cdr.deserialize(TFMessage, data)
    assert cdr._TF_SHAPES[data[1]].layouts[len(data)][2] is not None  # the layout path is armed


@pytest.mark.property
@settings(max_examples=150, deadline=None)
@given(data=st.data(), big_endian=st.booleans())
def test_known_tf_layouts_decode_mutated_bytes_like_the_reference(
    data: Any, big_endian: bool
) -> None:
    """With its layout learnt, a same-size message with flipped bytes decodes as the reference."""
    transforms = data.draw(
        st.lists(message_strategy('geometry_msgs/msg/TransformStamped'), min_size=4, max_size=7)
    )
    message = TFMessage(transforms=transforms)
    original = cdr.serialize(message)
    if big_endian:
        original = b'\x00\x00\x00\x00' + reference_serialize_big_endian(message)
    _learn_layout(original)
    assert cdr.deserialize(TFMessage, original) == message
    raw = bytearray(original)
    for _ in range(data.draw(st.integers(1, 4))):
        raw[data.draw(st.integers(4, len(raw) - 1))] = data.draw(st.integers(0, 255))
    mutated = bytes(raw)
    outcome = _decode_or_error('tf2_msgs/msg/TFMessage', mutated)
    try:
        reference: Any = reference_deserialize('tf2_msgs/msg/TFMessage', mutated)
    except cdr.CdrError as error:
        reference = error
    if isinstance(reference, cdr.CdrError):
        assert str(outcome) == str(reference)
        assert isinstance(_decode_or_error('', mutated, tf_fast_path=True), cdr.CdrError)
    else:
        assert repr(outcome) == repr(reference)  # NaN-safe
        tuples = cdr.decode_tf_message_transforms(mutated)
        assert [(t[0], t[1]) for t in tuples] == [
            (t.header.frame_id, t.child_frame_id) for t in reference.transforms
        ]


def reference_serialize_big_endian(message: Any) -> bytes:
    """Return the CDR_BE body of a TFMessage, written by the layout rules."""
    return _big_endian_tf_message(message)[4:]


def _tf_message(*frames: tuple[str, str]) -> TFMessage:
    """Return a TFMessage with one transform per (parent, child) pair, distinct poses."""
    return TFMessage(
        transforms=[
            fill_transform_stamped(
                TransformStamped(), parent, child, 10**9 * index + 7, (float(index), 2.0, 3.0),
                (0.0, 0.0, 0.0, 1.0),
            )
            for index, (parent, child) in enumerate(frames)
        ]
    )  # fmt: skip


#: More transforms, so that the messages of these tests are long enough to get layouts.
_MORE = (('base_link', 'laser'), ('base_link', 'camera'))


def test_a_different_layout_of_the_same_size_is_decoded_by_its_own_layout() -> None:
    """Names of other lengths but the same total size are not read with the learnt layout."""
    learnt = cdr.serialize(_tf_message(('map', 'odom'), ('odom', 'base_link'), *_MORE))
    _learn_layout(learnt)
    for frames in [
        (('map', 'odo'), ('odom', 'base_link')),
        (('map', 'odom'), ('odom', 'base_lin')),
        (('m', 'o'), ('odom', 'base_link')),
        (('ma', 'odom'), ('odom', 'base_link')),
    ]:
        other = _tf_message(*frames, *_MORE)
        data = cdr.serialize(other)
        assert len(data) == len(learnt)
        assert cdr.deserialize(TFMessage, data) == other
        assert [t[:2] for t in cdr.decode_tf_message_transforms(data)] == [*frames, *_MORE]
    assert cdr.deserialize(TFMessage, learnt) == cdr.deserialize(TFMessage, learnt)


def test_a_known_layout_rejects_a_missing_nul_and_reads_odd_strings_as_rclpy() -> None:
    """The layout path checks the NULs; bad UTF-8 and a NUL inside read as rclpy reads them."""
    learnt = cdr.serialize(_tf_message(('map', 'odom'), ('odom', 'base_link'), *_MORE))
    _learn_layout(learnt)
    nul = learnt.index(b'base_link') + len('base_link')
    missing_nul = learnt[:nul] + b'x' + learnt[nul + 1 :]
    with pytest.raises(cdr.CdrError, match=r'transforms\[1\]\.child_frame_id'):
        cdr.deserialize(TFMessage, missing_nul)
    with pytest.raises(cdr.CdrError, match=r'transforms\[1\]\.child_frame_id'):
        cdr.decode_tf_message_transforms(missing_nul)
    frames = [('map', 'odom'), ('odom', 'base_link'), *_MORE]
    for odd, name in [(b'od\xffm\x00', 'od\ufffdm'), (b'o\x00dm\x00', 'o')]:
        data = learnt.replace(b'odom\x00', odd, 1)
        expected = [('map', name), *frames[1:]]
        assert [t[:2] for t in cdr.decode_tf_message_transforms(data)] == expected
        decoded = cdr.deserialize(TFMessage, data)
        assert [(t.header.frame_id, t.child_frame_id) for t in decoded.transforms] == expected


@pytest.mark.property
@settings(max_examples=100, deadline=None)
@given(
    transforms=st.lists(
        message_strategy('geometry_msgs/msg/TransformStamped'), min_size=4, max_size=7
    )
)
def test_known_tf_layouts_encode_like_the_reference(transforms: list[Any]) -> None:
    """Encoding the same frames again (through the learnt layout) gives the reference bytes."""
    message = TFMessage(transforms=transforms)
    expected = reference_serialize('tf2_msgs/msg/TFMessage', message)
    assert [cdr.serialize(message) for _ in range(3)] == [expected] * 3
    changed = TFMessage(transforms=[*transforms[1:], transforms[0]])  # other lengths, maybe
    assert cdr.serialize(changed) == reference_serialize('tf2_msgs/msg/TFMessage', changed)


def test_a_known_tf_layout_still_rejects_bad_values_naming_the_field() -> None:
    """Wrong types and ranges in a message with a learnt layout are reported by field path."""
    message = _tf_message(('map', 'odom'), ('odom', 'base_link'), *_MORE)
    cdr.serialize(message)
    cdr.serialize(message)
    message.transforms[1].header.stamp.sec = 2**31
    with pytest.raises(cdr.CdrError, match=r'transforms\[1\]\.header\.stamp\.sec: 2147483648'):
        cdr.serialize(message)
    message.transforms[1].header.stamp.sec = 0
    message.transforms[2].transform.rotation.w = '1'  # type: ignore[assignment]  # on purpose
    with pytest.raises(cdr.CdrError, match=r'transforms\[2\]\.transform\.rotation\.w: expected'):
        cdr.serialize(message)
    message.transforms[2].transform.rotation.w = 1.0
    message.transforms[3].child_frame_id = b'camera'  # type: ignore[assignment]  # on purpose
    with pytest.raises(cdr.CdrError, match=r'transforms\[3\]\.child_frame_id: expected str'):
        cdr.serialize(message)


def test_a_known_tf_layout_encodes_new_and_non_ascii_names() -> None:
    """Names met for the first time, str subclasses and UTF-8 names encode as the reference."""

    class FrameName(str):
        __slots__ = ()

    message = _tf_message(('map', 'odom'), ('odom', 'base_link'), *_MORE)
    cdr.serialize(message)
    cdr.serialize(message)
    message.transforms[0].header.frame_id = FrameName('wörld')
    message.transforms[1].child_frame_id = 'base_link_' + 'x' * 300
    for _ in range(3):
        assert cdr.serialize(message) == reference_serialize('tf2_msgs/msg/TFMessage', message)
    assert cdr.deserialize(TFMessage, cdr.serialize(message)) == message


def test_tf_layout_caches_stay_within_their_budget(monkeypatch: pytest.MonkeyPatch) -> None:
    """Compiled layouts never cover more transforms than the budget; decoding stays right."""
    monkeypatch.setattr(cdr, '_TF_LAYOUT_BUDGET', 12)
    shapes = cdr._TF_SHAPES[1]
    for length in range(1, 9):
        message = _tf_message(*[('p' * length, f'child_{index}') for index in range(5)])
        data = cdr.serialize(message)
        for _ in range(3):
            assert cdr.deserialize(TFMessage, data) == message
            assert cdr.serialize(message) == reference_serialize('tf2_msgs/msg/TFMessage', message)
        assert shapes.layouts[len(data)][2] is not None
        assert shapes.compiled <= 12
