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
rmw_cyclonedds' service wire format: request/reply topics, the request header, endpoint ids.

A service ``/a/b`` is a request topic ``rq/a/bRequest`` and a reply topic ``rr/a/bReply``. Every
sample carries rmw_cyclonedds' request header in front of the CDR body: after the 4-byte
encapsulation header, the client's 64-bit id and the 64-bit sequence number, in the sample's byte
order; the body follows, its alignment unchanged (16 is a multiple of 8). Endpoints name their
peer in USER_DATA (``serviceid=<id>;`` or ``clientid=<id>;``). Pure functions.
"""

from __future__ import annotations

import itertools
import struct
import threading
from typing import TypeVar

from tf_demo.msgs import cdr
from tf_demo.msgs._message import Message

__all__ = [
    'RequestHeader',
    'client_service_id',
    'decode_sample',
    'encode_sample',
    'parse_user_data',
    'reply_topic',
    'request_topic',
]

_HEADER = {1: struct.Struct('<Qq'), 0: struct.Struct('>Qq')}
_MessageT = TypeVar('_MessageT', bound=Message)
_HEADER_SIZE = 4 + 16


class RequestHeader(tuple[int, int]):
    """rmw_cyclonedds' ``cdds_request_header_t``: ``(client id, sequence number)``."""

    __slots__ = ()

    def __new__(cls, guid: int, sequence_number: int) -> RequestHeader:
        """Make a header from the client's 64-bit id and the request's sequence number."""
        return super().__new__(cls, (guid, sequence_number))

    @property
    def guid(self) -> int:
        """The client's id: the instance handle of its request writer."""
        return self[0]

    @property
    def sequence_number(self) -> int:
        """The request's sequence number (the reply repeats it)."""
        return self[1]


def encode_sample(header: RequestHeader, message: Message) -> bytes:
    """Serialize ``message`` with rmw_cyclonedds' request header after the encapsulation."""
    payload = cdr.serialize(message)
    return payload[:4] + _HEADER[1].pack(header.guid, header.sequence_number) + payload[4:]


def decode_sample(msg_type: type[_MessageT], data: bytes) -> tuple[RequestHeader, _MessageT]:
    """
    Split a request or reply sample into its header and decoded message.

    :raises cdr.CdrError: too short, wrong encapsulation or a malformed body.
    """
    if len(data) < _HEADER_SIZE or data[0] != 0 or data[1] > 1:
        msg = f'not a ROS 2 service sample ({len(data)} bytes, header {bytes(data[:4]).hex()})'
        raise cdr.CdrError(msg)
    guid, sequence_number = _HEADER[data[1]].unpack_from(data, 4)
    message = cdr.deserialize(msg_type, bytes(data[:4]) + bytes(data[_HEADER_SIZE:]))
    return RequestHeader(guid, sequence_number), message


def request_topic(service_name: str) -> str:
    """Return the DDS request topic of the fully qualified ``service_name``."""
    return f'rq{service_name}Request'


def reply_topic(service_name: str) -> str:
    """Return the DDS reply topic of the fully qualified ``service_name``."""
    return f'rr{service_name}Reply'


_id_counter = itertools.count(1)
_id_lock = threading.Lock()


def client_service_id(participant_guid: bytes, counter: int | None = None) -> str:
    """
    Return a new client/service id as rmw_cyclonedds spells it in USER_DATA.

    The participant's 12-byte GUID prefix and a big-endian 32-bit counter, in hex, the first
    byte two characters wide (space padded), the others unpadded, separated by dots.
    """
    if counter is None:
        with _id_lock:
            counter = next(_id_counter)
    data = participant_guid[:12] + (counter & 0xFFFFFFFF).to_bytes(4, 'big')
    return f'{data[0]:2x}' + ''.join(f'.{byte:x}' for byte in data[1:])


def parse_user_data(data: bytes) -> dict[str, str]:
    """Parse ``key=value;`` USER_DATA as rmw_dds_common does (later keys win)."""
    result: dict[str, str] = {}
    for item in data.split(b';'):
        key, sep, value = item.partition(b'=')
        if sep and key:
            result[key.decode(errors='replace')] = value.decode(errors='replace')
    return result
