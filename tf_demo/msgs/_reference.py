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
A slow, obviously-correct XCDR1 codec that walks the schema field by field.

It defines the wire rules in the plainest form and checks every step, so it can say exactly
which field at which byte is wrong. :mod:`tf_demo.msgs.cdr` uses it to explain failures of the
fast generated codec, and the tests compare the two.
"""

from __future__ import annotations

from array import array
from collections.abc import Iterable
import math
import struct
from typing import cast
from typing import TYPE_CHECKING

from tf_demo.core.lazy_import import lazy_module
from tf_demo.msgs._message import Message
from tf_demo.msgs._message import message_class
from tf_demo.msgs._schema import FieldSpec
from tf_demo.msgs._schema import MessageSpec
from tf_demo.msgs._schema import PRIMITIVES
from tf_demo.msgs._schema import spec_for

if TYPE_CHECKING:
    import numpy
else:
    numpy = lazy_module('numpy')

_HEADER_SIZE = 4
_INT_RANGES = {
    'int8': (-(2**7), 2**7 - 1),
    'uint8': (0, 2**8 - 1),
    'char': (0, 2**8 - 1),
    'int16': (-(2**15), 2**15 - 1),
    'uint16': (0, 2**16 - 1),
    'int32': (-(2**31), 2**31 - 1),
    'uint32': (0, 2**32 - 1),
    'int64': (-(2**63), 2**63 - 1),
    'uint64': (0, 2**64 - 1),
}
_FLOAT32_MAX = 3.4028234663852886e38


class CdrError(ValueError):
    """Bytes that are not a valid CDR encoding of the type, or a message that cannot be encoded."""


def c_string(raw: bytes) -> str:
    """
    Return the text of a CDR string's bytes (its final NUL excluded) as rclpy gives it.

    rmw_cyclonedds_cpp copies the bytes as a C string and rclpy decodes them with
    ``PyUnicode_DecodeUTF8(data, strlen(data), "replace")``: the text ends at the first NUL,
    and each invalid UTF-8 sequence becomes U+FFFD.
    """
    end = raw.find(0)
    return (raw if end < 0 else raw[:end]).decode(errors='replace')


def _join(path: str, name: str) -> str:
    """Return the dotted path of field ``name`` under ``path``."""
    return f'{path}.{name}' if path else name


class _Reader:
    """Read one message from ``buf`` checking every step."""

    def __init__(self, msgtype: str, buf: bytes) -> None:
        self.msgtype = msgtype
        self.buf = buf
        self.pos = _HEADER_SIZE
        self.endian = '<' if buf[1] == 1 else '>'

    def fail(self, path: str, what: str) -> CdrError:
        """Return the error for field ``path`` at the current position."""
        field = f'field {path}' if path else 'message'
        return CdrError(f'cannot decode {self.msgtype}: {field} at byte {self.pos}: {what}')

    def take(self, size: int, path: str, what: str) -> bytes:
        """Consume ``size`` bytes, or fail naming ``what`` was truncated."""
        remaining = len(self.buf) - self.pos
        if size > remaining:
            msg = f'{what} needs {size} bytes but only {remaining} remain (truncated)'
            raise self.fail(path, msg)
        chunk = self.buf[self.pos : self.pos + size]
        self.pos += size
        return chunk

    def align(self, alignment: int, path: str) -> None:
        """Skip the padding before an item of ``alignment``."""
        pad = -(self.pos - _HEADER_SIZE) % alignment
        self.take(pad, path, 'alignment padding')

    def primitive(self, base: str, path: str) -> bool | int | float | bytes:
        """Read one primitive."""
        prim = PRIMITIVES[base]
        self.align(prim.size, path)
        chunk = self.take(prim.size, path, base)
        value: bool | int | float | bytes = struct.unpack(self.endian + prim.code, chunk)[0]
        return value

    def count(self, path: str) -> int:
        """Read one uint32: a string's length or a sequence's count."""
        return int(self.primitive('uint32', path))

    def string(self, path: str) -> str:
        """
        Read one string: uint32 length including the NUL, the bytes, the NUL.

        Odd strings read as a ROS 2 Jazzy rclpy node reads them (see :func:`c_string`); only a
        string without its final NUL is an error, as in rmw_cyclonedds_cpp.
        """
        length = self.count(path)
        if length == 0:
            return ''  # rmw_cyclonedds_cpp reads a zero length as the empty string
        start = self.pos
        chunk = self.take(length, path, f'string of length {length}')
        if chunk[-1] != 0:
            self.pos = start + length - 1
            raise self.fail(path, 'string does not end with NUL')
        return c_string(chunk[:-1])

    def value(self, field: FieldSpec, path: str) -> object:
        """Read one element of ``field``'s type."""
        if field.is_nested:
            return self.message(spec_for(field.base), path)
        if field.base == 'string':
            return self.string(path)
        return self.primitive(field.base, path)

    def field(self, field: FieldSpec, path: str) -> object:
        """Read the whole of ``field``."""
        if field.kind == 'single':
            return self.value(field, path)
        if field.kind == 'sequence':
            count = self.count(path)
            remaining = len(self.buf) - self.pos
            if count > remaining:
                msg = f'sequence length {count} exceeds the {remaining} remaining bytes'
                raise self.fail(path, msg)
        else:
            count = field.size
        prim = PRIMITIVES.get(field.base)
        items = [self.value(field, f'{path}[{index}]') for index in range(count)]
        if prim is not None and field.kind == 'sequence' and prim.array_code:
            return array(prim.array_code, cast('list[float]', items))  # or ints: array takes both
        if prim is not None and field.kind == 'array' and prim.numpy_dtype:
            return numpy.array(items, dtype=prim.numpy_dtype)
        return items

    def message(self, spec: MessageSpec, path: str) -> Message:
        """Read one message of ``spec``."""
        values = {field.name: self.field(field, _join(path, field.name)) for field in spec.fields}
        return message_class(spec.msgtype)(**values)


def check_header(msgtype: str, buf: bytes) -> None:
    """
    Check the 4-byte encapsulation header (CDR_LE ``00 01`` or CDR_BE ``00 00``).

    :raises CdrError: too short, or another encapsulation (XCDR2, PL_CDR...).
    """
    if len(buf) < _HEADER_SIZE:
        msg = f'cannot decode {msgtype}: {len(buf)} bytes is shorter than the CDR header'
        raise CdrError(msg)
    if buf[0] != 0 or buf[1] > 1:
        msg = (
            f'cannot decode {msgtype}: encapsulation header {buf[:2].hex(" ")} is not plain CDR '
            '(expected 00 01 little-endian or 00 00 big-endian; XCDR2 and PL_CDR are not ROS 2)'
        )
        raise CdrError(msg)


def reference_deserialize(msgtype: str, buf: bytes) -> Message:
    """
    Decode ``buf`` (header included) as ``msgtype``, checking every field.

    :raises CdrError: naming the field and byte offset of the first problem.
    """
    check_header(msgtype, buf)
    return _Reader(msgtype, buf).message(spec_for(msgtype), '')


class _Writer:
    """Write one message little-endian, checking every value."""

    def __init__(self, msgtype: str) -> None:
        self.msgtype = msgtype
        self.out = bytearray(b'\x00\x01\x00\x00')

    def fail(self, path: str, what: str) -> CdrError:
        """Return the error for field ``path``."""
        return CdrError(f'cannot encode {self.msgtype}: field {path}: {what}')

    def align(self, alignment: int) -> None:
        """Append the padding before an item of ``alignment``."""
        self.out += bytes(-(len(self.out) - _HEADER_SIZE) % alignment)

    def primitive(self, base: str, value: object, path: str) -> None:
        """Write one primitive after checking its type and range."""
        prim = PRIMITIVES[base]
        if base == 'bool':
            if not isinstance(value, bool | numpy.bool_ | int):
                raise self.fail(path, f'expected bool, got {value!r}')
        elif base == 'byte':
            if not isinstance(value, bytes) or len(value) != 1:
                raise self.fail(path, f'expected byte (a bytes of length 1), got {value!r}')
        elif base in _INT_RANGES:
            low, high = _INT_RANGES[base]
            if isinstance(value, bool) or not isinstance(value, int | numpy.integer):
                raise self.fail(path, f'expected {base} (an int), got {value!r}')
            if not low <= value <= high:
                raise self.fail(path, f'{value} is out of the {base} range [{low}, {high}]')
        else:
            if isinstance(value, bool) or not isinstance(value, int | float | numpy.number):
                raise self.fail(path, f'expected {base} (a float), got {value!r}')
            if base == 'float32' and math.isfinite(value) and abs(value) > _FLOAT32_MAX:
                raise self.fail(path, f'{value} is out of the float32 range')
        self.align(prim.size)
        self.out += struct.pack('<' + prim.code, value)

    def string(self, value: object, path: str) -> None:
        """Write one string."""
        if not isinstance(value, str):
            raise self.fail(path, f'expected str, got {value!r}')
        try:
            encoded = value.encode()
        except UnicodeEncodeError as exc:
            raise self.fail(path, f'string cannot be encoded as UTF-8 ({exc.reason})') from None
        self.primitive('uint32', len(encoded) + 1, path)
        self.out += encoded + b'\x00'

    def value(self, field: FieldSpec, value: object, path: str) -> None:
        """Write one element of ``field``'s type."""
        if field.is_nested:
            self.message(spec_for(field.base), value, path)
        elif field.base == 'string':
            self.string(value, path)
        else:
            self.primitive(field.base, value, path)

    def field(self, field: FieldSpec, value: object, path: str) -> None:
        """Write the whole of ``field``."""
        if field.kind == 'single':
            self.value(field, value, path)
            return
        try:
            items = list(cast('Iterable[object]', value))  # whatever list() takes
        except TypeError:
            raise self.fail(path, f'expected a sequence, got {value!r}') from None
        if field.kind == 'array' and len(items) != field.size:
            raise self.fail(path, f'expected exactly {field.size} elements, got {len(items)}')
        if field.kind == 'sequence':
            if field.size and len(items) > field.size:
                raise self.fail(path, f'{len(items)} elements exceed the bound {field.size}')
            self.primitive('uint32', len(items), path)
        for index, item in enumerate(items):
            self.value(field, item, f'{path}[{index}]')

    def message(self, spec: MessageSpec, value: object, path: str) -> None:
        """Write one message, reading its fields by name (duck-typed)."""
        for field in spec.fields:
            child = _join(path, field.name)
            try:
                item = getattr(value, field.name)
            except AttributeError:
                kind = type(value).__name__
                raise self.fail(child, f'{kind} object has no field {field.name!r}') from None
            self.field(field, item, child)


def reference_serialize(msgtype: str, message: object) -> bytes:
    """
    Encode ``message`` as ``msgtype`` (little-endian, header included), checking every value.

    :raises CdrError: naming the first field whose value cannot be encoded.
    """
    writer = _Writer(msgtype)
    writer.message(spec_for(msgtype), message, '')
    return bytes(writer.out)
