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
Fuzzing every CDR decoder of tf_demo.msgs with hostile bytes (issue 10).

The decoders are :func:`cdr.deserialize` (the generated decoder of every type, both byte
orders, and the TFMessage whole-message layouts), :func:`cdr.decode_tf_message_transforms`
(the listener's fast path) and the reference decoder. For arbitrary bytes, mutated valid
encodings and hostile lengths (a string or sequence length of 2**31, 2**32 - 1, ...) each one
returns a message or raises :class:`cdr.CdrError`, the package's documented decode error, and
nothing else; no input allocates more than a small multiple of its own size (a length of 2**31
must not allocate) or runs without end (pytest-timeout guards every test).
"""

from __future__ import annotations

from collections.abc import Callable
from struct import pack
import tracemalloc
from typing import Any

from hypothesis import given
from hypothesis import settings
from hypothesis import strategies as st
from msgs_strategies import filled_message
from msgs_strategies import message_strategy
import pytest
from tf_demo.msgs import cdr
from tf_demo.msgs._reference import reference_deserialize
from tf_demo.msgs._schema import DEFINITIONS
from tf_demo.msgs.tf2_msgs import TFMessage

TF = 'tf2_msgs/msg/TFMessage'
MSGTYPES = sorted(DEFINITIONS)
#: Lengths an attacker writes where a string or sequence length is expected.
HOSTILE_LENGTHS = (0, 1, 2, 3, 0xFF, 0x10000, 0x7FFFFFFF, 0x80000000, 0xFFFFFFFE, 0xFFFFFFFF)
#: A decode may allocate this many times its input, plus a fixed allowance (a message object
#: per 16 bytes of a Gid[] is the worst of the schema, about 15x).
MEMORY_FACTOR = 64
MEMORY_ALLOWANCE = 256 * 1024

pytestmark = [pytest.mark.property, pytest.mark.timeout(300)]


def _decoders(msgtype: str) -> list[tuple[str, Callable[[bytes], Any]]]:
    """Return every decoder of ``msgtype``, named."""
    decoders: list[tuple[str, Callable[[bytes], Any]]] = [
        ('deserialize', lambda data: cdr.deserialize(msgtype, data)),
        ('reference', lambda data: reference_deserialize(msgtype, data)),
    ]
    if msgtype == TF:
        decoders.append(('tf fast path', cdr.decode_tf_message_transforms))
    return decoders


def _outcome(decode: Callable[[bytes], Any], data: bytes) -> Any:
    """Return what ``decode`` gives for ``data``: the value, or the CdrError raised."""
    try:
        return decode(data)
    except cdr.CdrError as error:
        return error


def check_every_decoder(msgtype: str, data: bytes) -> None:
    """Every decoder of ``msgtype`` decodes ``data`` or raises CdrError; all agree which."""
    outcomes = {name: _outcome(decode, data) for name, decode in _decoders(msgtype)}
    failed = {name: isinstance(outcome, cdr.CdrError) for name, outcome in outcomes.items()}
    assert len(set(failed.values())) == 1, (data.hex(), outcomes)
    for outcome in outcomes.values():
        if isinstance(outcome, cdr.CdrError):
            assert str(outcome).startswith(f'cannot decode {msgtype}'), outcome
    if not failed['deserialize']:
        assert repr(outcomes['deserialize']) == repr(outcomes['reference'])  # NaN-safe


def check_bounded_memory(msgtype: str, data: bytes) -> None:
    """No decoder of ``msgtype`` allocates more than a small multiple of ``len(data)``."""
    limit = MEMORY_FACTOR * len(data) + MEMORY_ALLOWANCE
    for name, decode in _decoders(msgtype):
        _outcome(decode, data)  # warm the caches of compiled structs outside the measure
        tracemalloc.start()
        try:
            _outcome(decode, data)
            peak = tracemalloc.get_traced_memory()[1]
        finally:
            tracemalloc.stop()
        assert peak <= limit, (name, data.hex(), peak)


@st.composite
def mutated_encodings(draw: st.DrawFn, msgtype: str) -> bytes:
    """Draw a valid encoding of ``msgtype``, then damage it: flips, cuts, inserts, lengths."""
    data = bytearray(cdr.serialize(draw(message_strategy(msgtype))))
    for _ in range(draw(st.integers(1, 4))):
        action = draw(st.sampled_from(('flip', 'length', 'cut', 'insert', 'delete')))
        index = draw(st.integers(4, max(4, len(data) - 1)))
        if action == 'flip' and index < len(data):
            data[index] = draw(st.integers(0, 255))
        elif action == 'length':
            index -= index % 4  # where a uint32 length field can be
            data[index : index + 4] = pack('<I', draw(st.sampled_from(HOSTILE_LENGTHS)))
        elif action == 'cut':
            del data[index:]
        elif action == 'insert':
            data[index:index] = draw(st.binary(min_size=1, max_size=8))
        else:
            del data[index : index + draw(st.integers(1, 8))]
    if draw(st.booleans()):
        data[1] = 0  # read the same bytes as big-endian
    return bytes(data)


@pytest.mark.parametrize('msgtype', MSGTYPES)
@settings(max_examples=25, deadline=None)
@given(data=st.data())
def test_mutated_valid_encodings_give_a_message_or_cdr_error(msgtype: str, data: Any) -> None:
    """Damaged real encodings of every type: a message or CdrError, from every decoder."""
    check_every_decoder(msgtype, data.draw(mutated_encodings(msgtype)))


@pytest.mark.parametrize('msgtype', MSGTYPES)
@settings(max_examples=10, deadline=None)
@given(data=st.data())
def test_hostile_lengths_never_allocate_for_the_claimed_size(msgtype: str, data: Any) -> None:
    """A hostile length at any aligned offset: CdrError or a message, memory bounded by input."""
    encoded = bytearray(cdr.serialize(data.draw(message_strategy(msgtype))))
    offset = data.draw(st.integers(4, max(4, len(encoded) - 4)).map(lambda i: i - i % 4))
    length = data.draw(st.sampled_from(HOSTILE_LENGTHS))
    big_endian = data.draw(st.booleans())
    encoded[offset : offset + 4] = pack('>I' if big_endian else '<I', length)
    if big_endian:
        encoded[1] = 0
    check_every_decoder(msgtype, bytes(encoded))
    check_bounded_memory(msgtype, bytes(encoded))


@pytest.mark.parametrize('msgtype', MSGTYPES)
@pytest.mark.parametrize('length', [0x7FFFFFFF, 0x80000000, 0xFFFFFFFF])
def test_a_huge_length_anywhere_is_refused_without_allocating(msgtype: str, length: int) -> None:
    """2**31 (and its neighbours) as every uint32 of a full message of every type, both orders."""
    encoded = cdr.serialize(filled_message(msgtype))
    for offset in range(4, len(encoded) - 3, 4):
        for order in ('<', '>'):
            damaged = bytearray(encoded)
            damaged[offset : offset + 4] = pack(f'{order}I', length)
            damaged[1] = 1 if order == '<' else 0
            check_every_decoder(msgtype, bytes(damaged))
    bare = b'\x00\x01\x00\x00' + pack('<I', length) + bytes(64)
    check_every_decoder(msgtype, bare)
    check_bounded_memory(msgtype, bare)


@settings(max_examples=200, deadline=None)
@given(
    msgtype=st.sampled_from(MSGTYPES),
    header=st.sampled_from((b'\x00\x01\x00\x00', b'\x00\x00\x00\x00')),
    body=st.binary(max_size=300),
)
def test_arbitrary_bytes_give_a_message_or_cdr_error(
    msgtype: str, header: bytes, body: bytes
) -> None:
    """Arbitrary bodies after a valid header, for any type: a message or CdrError."""
    check_every_decoder(msgtype, header + body)


@settings(max_examples=100, deadline=None)
@given(data=st.binary(max_size=12))
def test_arbitrary_headers_give_cdr_error_or_a_message(data: bytes) -> None:
    """Short and odd headers (XCDR2, PL_CDR, garbage) never raise anything but CdrError."""
    for msgtype in ('std_msgs/msg/String', TF, 'sensor_msgs/msg/JointState'):
        for _, decode in _decoders(msgtype):
            _outcome(decode, data)


@settings(max_examples=100, deadline=None)
@given(
    transforms=st.lists(message_strategy('geometry_msgs/msg/TransformStamped'), max_size=8),
    data=st.data(),
)
def test_tf_layouts_learned_then_fed_mutations_give_a_message_or_cdr_error(
    transforms: list[Any], data: Any
) -> None:
    """After the whole-message layouts learned a shape, mutations of it are still checked."""
    encoded = cdr.serialize(TFMessage(transforms=transforms))
    for _ in range(2):  # the second sighting compiles the layout
        cdr.deserialize(TF, encoded)
        cdr.decode_tf_message_transforms(encoded)
    damaged = bytearray(encoded)
    for _ in range(data.draw(st.integers(1, 3))):
        index = data.draw(st.integers(4, len(damaged) - 1))
        damaged[index] = data.draw(st.integers(0, 255))
    check_every_decoder(TF, bytes(damaged))
