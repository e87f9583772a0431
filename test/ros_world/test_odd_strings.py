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

"""
Odd CDR strings decode as a real ROS 2 Jazzy rclpy node (rmw_cyclonedds_cpp) decodes them.

A string on the wire is a uint32 length (NUL included), the bytes and a NUL. What the real
stack does with the odd ones, measured by :func:`test_real_rclpy_receives_what_every_decoder_gives`
(raw bytes written over DDS by a standalone process, read by a real rclpy subscriber that prints
``repr`` of what it got; ROS 2 Jazzy built from source, rmw_cyclonedds_cpp), and explained by its
sources (rmw_cyclonedds_cpp ``serdes.hpp`` ``cycdeser::deserialize(std::string &)``, then
``rosidl_runtime_c__String__assign`` of ``c_str()``; rosidl_python's ``_msg_support.c.em``:
``PyUnicode_DecodeUTF8(data, strlen(data), "replace")``):

- length 0 (no bytes, no NUL): received as ``''`` (Cyclone reads a zero length as empty);
- invalid UTF-8: received, decoded with ``errors='replace'`` (U+FFFD per bad sequence, as
  Python's own codec does: rclpy calls it);
- a NUL inside: received, cut at the first NUL (C ``strlen``), before the UTF-8 decoding;
- no NUL at the end: Cyclone's deserialiser throws ("string data is not null-terminated"), but
  the sample is still handed to rclpy, half filled: the fields before the bad string hold their
  values, the rest their defaults (``RCLPY_HALF_FILLED``). tf_demo does not copy that defect: it
  raises CdrError and the node drops the message (``EXPECTED`` says DROPPED).

Big-endian (CDR_BE) payloads are checked against the same expectations by the decoders only:
the standalone writer sends every payload with a CDR_LE header (cyclonedds-python rewrites it),
and Cyclone reads CDR_BE by swapping the length only (``cycdeserbase``), not the string rules.

``EXPECTED`` records those results; :func:`test_every_decoder_gives_what_rclpy_gives` holds
every decoder of :mod:`tf_demo.msgs` to them in both worlds (the generated decoders of both byte
orders, the TFMessage whole-message layouts, the tf fast path and the reference decoder).
"""

from __future__ import annotations

import ast
from collections.abc import Callable
from collections.abc import Iterator
import json
import struct
import sys
from typing import Any

from conftest import run_captured
import pytest
from ros_world.jazzy import require_package
from ros_world.jazzy import standalone_env
from ros_world.jazzy import standalone_python
from ros_world.jazzy import started
from tf_demo.msgs import cdr
from tf_demo.msgs._message import Message
from tf_demo.msgs._reference import reference_deserialize
from tf_demo.msgs.std_msgs import String

#: A message the real stack drops (rclpy's callback never sees it).
DROPPED = None

#: name: (CDR length field, the bytes after it, what rclpy gives: a str or DROPPED).
EXPECTED: dict[str, tuple[int, bytes, str | None]] = {
    'plain': (4, b'abc\x00', 'abc'),
    'empty': (1, b'\x00', ''),
    'UTF-8': (8, 'h\u00e9\u20ac!'.encode() + b'\x00', 'h\u00e9\u20ac!'),
    'length 0': (0, b'', ''),
    'invalid UTF-8': (4, b'a\xffb\x00', 'a\ufffdb'),
    'cut UTF-8 sequence': (5, b'ab\xe2\x82\x00', 'ab\ufffd'),
    'UTF-8 surrogate': (4, b'\xed\xa0\x80\x00', '\ufffd\ufffd\ufffd'),
    'overlong NUL': (3, b'\xc0\x80\x00', '\ufffd\ufffd'),
    'NUL inside': (4, b'a\x00b\x00', 'a'),
    'leading NUL': (5, b'\x00abc\x00', ''),
    'NUL then invalid UTF-8': (4, b'a\x00\xff\x00', 'a'),
    'invalid UTF-8 then NUL': (4, b'\xff\x00b\x00', '\ufffd'),
    'no NUL at the end': (3, b'abc', DROPPED),
}
#: Transforms per TFMessage sent: one (the generated decoder) and four (whole-message layouts).
TF_SIZES = (1, 4)
ENDIANS = ('<', '>')
#: The byte order sent over DDS (see the module docstring).
WIRE_ENDIAN = '<'

pytestmark = pytest.mark.timeout(300)


def _align(data: bytearray, alignment: int) -> None:
    """Pad ``data`` (header included) to ``alignment`` relative to the end of the header."""
    data += bytes(-(len(data) - 4) % alignment)


def _header(endian: str) -> bytearray:
    return bytearray(b'\x00\x01\x00\x00' if endian == '<' else b'\x00\x00\x00\x00')


def _string(data: bytearray, endian: str, length: int, raw: bytes) -> None:
    _align(data, 4)
    data += struct.pack(endian + 'I', length) + raw


def _finish(data: bytearray) -> bytes:
    """Pad to 4 as a DDS writer does (the decoders ignore it)."""
    data += bytes(-len(data) % 4)
    return bytes(data)


def string_message(endian: str, length: int, raw: bytes) -> bytes:
    """A std_msgs/String whose ``data`` is the given wire string."""
    data = _header(endian)
    _string(data, endian, length, raw)
    return _finish(data)


def tf_message(
    endian: str, count: int, length: int, raw: bytes, *, parent: str = '', child: str = ''
) -> bytes:
    """
    A TFMessage of ``count`` transforms; frame ids not given are the wire string.

    The stamp is ``sec=i, nanosec=0`` and the translation ``(i, 0, 0)`` for transform ``i``.
    """
    data = _header(endian)
    data += struct.pack(endian + 'I', count)
    for index in range(count):
        data += struct.pack(endian + 'iI', index, 0)
        for name in (parent, child):
            if name:
                encoded = name.encode() + b'\x00'
                _string(data, endian, len(encoded), encoded)
            else:
                _string(data, endian, length, raw)
        _align(data, 8)
        data += struct.pack(endian + '7d', index, 0, 0, 0, 0, 0, 1)
    return _finish(data)


def _string_data(message: Message) -> str:
    """The ``data`` of ``message``, a std_msgs/String."""
    assert isinstance(message, String)
    return message.data


def _outcomes(decoders: dict[str, Callable[[], object]]) -> dict[str, object]:
    """What each decoder gives: its result, or DROPPED where it raises CdrError."""
    results: dict[str, object] = {}
    for name, decode in decoders.items():
        try:
            results[name] = decode()
        except cdr.CdrError:
            results[name] = DROPPED
    return results


def _decoded_string(data: bytes) -> dict[str, object]:
    """What each decoder of std_msgs/String gives for ``data``: the string or DROPPED."""
    return _outcomes(
        {
            'deserialize': lambda: _string_data(cdr.deserialize('std_msgs/msg/String', data)),
            'reference': lambda: _string_data(reference_deserialize('std_msgs/msg/String', data)),
        }
    )


def _frames(message: Any) -> list[tuple[str, str]]:
    return [(t.header.frame_id, t.child_frame_id) for t in message.transforms]


def _decoded_tf(data: bytes) -> dict[str, object]:
    """What each TFMessage decoder gives for ``data``: the (parent, child) list or DROPPED."""
    return _outcomes(
        {
            'deserialize': lambda: _frames(cdr.deserialize('tf2_msgs/msg/TFMessage', data)),
            'reference': lambda: _frames(reference_deserialize('tf2_msgs/msg/TFMessage', data)),
            'tf fast path': lambda: [t[:2] for t in cdr.decode_tf_message_transforms(data)],
        }
    )


def _arm_layout(
    endian: str, count: int, length: int, *, parent: str = '', child: str = ''
) -> bool:
    """
    Decode twice a clean TFMessage with the wire lengths of a case: its layout is compiled.

    Returns whether a whole-message layout now exists for that size.
    """
    clean = tf_message(
        endian, count, length, b'x' * (length - 1) + b'\x00', parent=parent, child=child
    )
    for _ in range(2):
        cdr.deserialize('tf2_msgs/msg/TFMessage', clean)
        cdr.decode_tf_message_transforms(clean)
    shapes = cdr._TF_SHAPES[0 if endian == '>' else 1]
    layout = shapes.layouts.get(len(clean))
    return layout is not None and layout[2] is not None


def _tf_cases(endians: tuple[str, ...] = ENDIANS) -> Iterator[tuple[str, str, int, str, str]]:
    """(case, endian, count, parent, child) of every TFMessage: the odd string as either id."""
    for name in EXPECTED:
        for endian in endians:
            for count in TF_SIZES:
                yield name, endian, count, '', 'child'
                yield name, endian, count, 'parent', ''


#: What rclpy gets for a std_msgs/String whose ``data`` has no NUL (measured, see above).
RCLPY_HALF_FILLED_STRING = ''


def rclpy_half_filled(count: int, parent: str, child: str) -> list[tuple[str, str]]:
    """
    What rclpy gets for a TFMessage whose first odd string has no NUL (measured, see above).

    The sequence holds ``count`` default transforms, filled up to the bad string.
    """
    del child  # the parent comes first: either it or the child is the bad string
    return [(parent, '')] + [('', '')] * (count - 1)


def _expected_frames(name: str, count: int, parent: str, child: str) -> Any:
    expected = EXPECTED[name][2]
    if expected is DROPPED:
        return DROPPED
    return [(parent or expected, child or expected)] * count


@pytest.mark.parametrize('name', EXPECTED)
@pytest.mark.parametrize('endian', ENDIANS)
def test_every_decoder_gives_what_rclpy_gives_for_a_string(name: str, endian: str) -> None:
    """std_msgs/String with an odd ``data``: every decoder gives what rclpy gave (EXPECTED)."""
    length, raw, expected = EXPECTED[name]
    decoded = _decoded_string(string_message(endian, length, raw))
    assert decoded == dict.fromkeys(decoded, expected)


@pytest.mark.parametrize('name', EXPECTED)
@pytest.mark.parametrize('endian', ENDIANS)
@pytest.mark.parametrize('count', TF_SIZES)
@pytest.mark.parametrize('odd', ['frame_id', 'child_frame_id'])
def test_every_decoder_gives_what_rclpy_gives_for_a_frame_id(
    name: str, endian: str, count: int, odd: str
) -> None:
    """
    TFMessage with an odd frame id: every decoder gives what rclpy gave (EXPECTED).

    Four transforms are decoded twice: first through the generated decoder, then (after a
    clean message of the same wire lengths armed it) through the whole-message layout.
    """
    length, raw, _ = EXPECTED[name]
    parent, child = ('', 'child') if odd == 'frame_id' else ('parent', '')
    data = tf_message(endian, count, length, raw, parent=parent, child=child)
    expected = _expected_frames(name, count, parent, child)
    decoded = _decoded_tf(data)
    assert decoded == dict.fromkeys(decoded, expected)
    if count >= 4 and length >= 1:
        assert _arm_layout(endian, count, length, parent=parent, child=child)
        decoded = _decoded_tf(data)
        assert decoded == dict.fromkeys(decoded, expected)


#: A standalone process: publishes the raw CDR of each message in the plan file, each followed by
#: a valid marker, on /odd_string and /odd_tf (reliable, transient local), then waits.
PUBLISHER = """
import json, sys, time
from tf_demo import transport
from tf_demo.transport.messages import std_msgs, tf2_msgs
from tf_demo.transport.qos import DurabilityPolicy, QoSProfile, ReliabilityPolicy
with open(sys.argv[1]) as file:
    plan = json.load(file)
transport.init(args=['odd_strings_talker'])
node = transport.create_node('odd_strings_talker')
qos = QoSProfile(depth=1000, reliability=ReliabilityPolicy.RELIABLE,
                 durability=DurabilityPolicy.TRANSIENT_LOCAL)
publishers = {'string': node.create_publisher(std_msgs.String, '/odd_string', qos),
              'tf': node.create_publisher(tf2_msgs.TFMessage, '/odd_tf', qos)}
while min(p.get_subscription_count() for p in publishers.values()) < 1:
    time.sleep(0.05)
for topic, payload in plan:
    publishers[topic].publish(bytes.fromhex(payload))
print('sent', len(plan), flush=True)
while True:
    time.sleep(1)
"""

#: A real rclpy node: prints ``<topic> <repr>`` per message received until both ``end`` markers.
SUBSCRIBER = """
import rclpy
from rclpy.qos import DurabilityPolicy, QoSProfile, ReliabilityPolicy
from std_msgs.msg import String
from tf2_msgs.msg import TFMessage
rclpy.init()
node = rclpy.create_node('odd_strings_listener')
qos = QoSProfile(depth=1000, reliability=ReliabilityPolicy.RELIABLE,
                 durability=DurabilityPolicy.TRANSIENT_LOCAL)
ended = set()
def on_string(message):
    print('string', repr(message.data), flush=True)
    if message.data == 'end':
        ended.add('string')
def on_tf(message):
    frames = [(t.header.frame_id, t.child_frame_id) for t in message.transforms]
    print('tf', repr(frames), flush=True)
    if frames == [('end', 'end')]:
        ended.add('tf')
node.create_subscription(String, '/odd_string', on_string, qos)
node.create_subscription(TFMessage, '/odd_tf', on_tf, qos)
while len(ended) < 2:
    rclpy.spin_once(node, timeout_sec=0.1)
node.destroy_node()
rclpy.shutdown()
"""


def _marker(topic: str, text: str) -> bytes:
    encoded = text.encode() + b'\x00'
    if topic == 'string':
        return string_message('<', len(encoded), encoded)
    return tf_message('<', 1, len(encoded), encoded)


def _between_markers(lines: list[str], topic: str) -> list[Any]:
    """The messages received on ``topic`` between consecutive markers: each a value or DROPPED."""
    values = [ast.literal_eval(line.split(' ', 1)[1]) for line in lines if line.startswith(topic)]
    results: list[Any] = []
    pending: list[Any] = []
    for value in values:
        if value in ('mark', [('mark', 'mark')]):
            assert len(pending) <= 1, pending
            results.append(pending[0] if pending else DROPPED)
            pending = []
        elif value not in ('end', [('end', 'end')]):
            pending.append(value)
    return results


@pytest.mark.rclpy_world
def test_real_rclpy_receives_what_every_decoder_gives(
    world_env: dict[str, str], tmp_path: Any
) -> None:
    """
    Raw odd strings over DDS from a standalone process; a real rclpy node prints what it got.

    What rclpy got equals the record of the module docstring (EXPECTED, RCLPY_HALF_FILLED), and
    every decoder of tf_demo.msgs gives the same for the same bytes (DROPPED where rclpy's
    message came half filled).
    """
    require_package(world_env, 'tf2_msgs')
    string_plan = [string_message(WIRE_ENDIAN, *EXPECTED[name][:2]) for name in EXPECTED]
    tf_cases = list(_tf_cases((WIRE_ENDIAN,)))
    tf_plan = [
        tf_message(endian, count, *EXPECTED[name][:2], parent=parent, child=child)
        for name, endian, count, parent, child in tf_cases
    ]
    plan = []
    for topic, payloads in (('string', string_plan), ('tf', tf_plan)):
        for payload in payloads:
            plan += [(topic, payload.hex()), (topic, _marker(topic, 'mark').hex())]
        plan.append((topic, _marker(topic, 'end').hex()))
    plan_file = tmp_path / 'plan.json'
    plan_file.write_text(json.dumps(plan))
    command = [standalone_python(), '-c', PUBLISHER, str(plan_file)]
    with started(command, standalone_env(world_env)) as talker:
        listener = run_captured([sys.executable, '-c', SUBSCRIBER], world_env, timeout=180)
        assert talker.poll() is None, talker.stdout.read() if talker.stdout else ''
    assert listener.returncode == 0, (listener.stdout, listener.stderr)
    lines = listener.stdout.splitlines()
    got_strings = _between_markers(lines, 'string')
    got_frames = _between_markers(lines, 'tf')
    assert len(got_strings) == len(string_plan), lines
    assert len(got_frames) == len(tf_plan), lines

    measured = dict(zip(EXPECTED, got_strings, strict=True))
    assert measured == {
        name: RCLPY_HALF_FILLED_STRING if expected is DROPPED else expected
        for name, (_, _, expected) in EXPECTED.items()
    }
    measured_tf = dict(zip(tf_cases, got_frames, strict=True))
    assert measured_tf == {
        case: (
            rclpy_half_filled(case[2], case[3], case[4])
            if EXPECTED[case[0]][2] is DROPPED
            else _expected_frames(case[0], *case[2:])
        )
        for case in tf_cases
    }
    for name, payload in zip(EXPECTED, string_plan, strict=True):
        decoded = _decoded_string(payload)
        assert decoded == dict.fromkeys(decoded, EXPECTED[name][2]), name
    for case, payload in zip(tf_cases, tf_plan, strict=True):
        decoded = _decoded_tf(payload)
        assert decoded == dict.fromkeys(decoded, _expected_frames(case[0], *case[2:])), case
