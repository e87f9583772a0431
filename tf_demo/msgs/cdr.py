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
CDR (XCDR1) serialisation byte-identical to ROS 2 Jazzy's rmw, with a fast tf path.

:func:`serialize` writes the ``00 01 00 00`` (CDR_LE) header and the plain-CDR body;
:func:`deserialize` reads CDR_LE and CDR_BE. Both run straight-line code generated once per
type (see :mod:`tf_demo.msgs._codegen`). Any malformed input raises :class:`CdrError`, whose
message names the type, the field and the byte offset.

Odd strings read as a ROS 2 Jazzy rclpy node (rmw_cyclonedds_cpp) reads them: a length of 0 is
``''``, the text ends at the first NUL, invalid UTF-8 becomes U+FFFD (see
:func:`~tf_demo.msgs._reference.c_string`). The fast paths check for them (one ``0 in raw`` per
string, a strict UTF-8 decode) and leave them to the reference decoder.

TFMessages, the hot path, also have whole-message layouts: once the same frame-name lengths come
twice, one precompiled struct reads or writes the whole message in one call (see
:class:`_TfShapes` and :func:`_tf_encoder`); :func:`decode_tf_message_transforms` skips the
message objects altogether, as :class:`TfMessageEncoder` does for robot_state_publisher's
transform tuples.
"""

from __future__ import annotations

from collections.abc import Callable
from collections.abc import Sequence
import functools
from struct import error as struct_error
from struct import Struct
from typing import Any
from typing import cast
from typing import overload
from typing import Protocol
from typing import TypeVar

from tf_demo.core.math3d import Quat
from tf_demo.core.math3d import Vec3
from tf_demo.msgs import _codegen
from tf_demo.msgs._codegen import Decoder
from tf_demo.msgs._codegen import Encoder
from tf_demo.msgs._codegen import StructValues
from tf_demo.msgs._message import blank_instance_maker
from tf_demo.msgs._message import Message
from tf_demo.msgs._message import message_class
from tf_demo.msgs._reference import CdrError
from tf_demo.msgs._reference import check_header
from tf_demo.msgs._reference import reference_deserialize
from tf_demo.msgs._reference import reference_serialize
from tf_demo.msgs._schema import spec_for
from tf_demo.msgs.builtin_interfaces import Time
from tf_demo.msgs.convert import TransformStampedLike
from tf_demo.msgs.geometry_msgs import Quaternion
from tf_demo.msgs.geometry_msgs import Transform
from tf_demo.msgs.geometry_msgs import TransformStamped
from tf_demo.msgs.geometry_msgs import Vector3
from tf_demo.msgs.std_msgs import Header
from tf_demo.msgs.tf2_msgs import TFMessage

__all__ = [
    'CdrError',
    'FrameTransform',
    'TfMessageEncoder',
    'TransformTuple',
    'decode_tf_message_transforms',
    'deserialize',
    'msgtype_of',
    'serialize',
]

MessageT = TypeVar('MessageT', bound=Message)

#: ``(parent, child, stamp_ns, (tx, ty, tz), (qx, qy, qz, qw))``.
TransformTuple = tuple[
    str, str, int, tuple[float, float, float], tuple[float, float, float, float]
]

_TF_MESSAGE = 'tf2_msgs/msg/TFMessage'


def msgtype_of(message_or_type: object) -> str:
    """
    Return ``pkg/msg/Name`` for a type name, our class, an rclpy class, or an instance.

    ``'pkg/Name'`` is accepted too; rclpy classes are recognised by their module
    (``geometry_msgs.msg._vector3``).

    :raises CdrError: the object is no ROS message type this package knows.
    """
    if isinstance(message_or_type, str):
        msgtype, what = message_or_type, repr(message_or_type)
    else:
        cls = message_or_type if isinstance(message_or_type, type) else type(message_or_type)
        declared = getattr(cls, '__msgtype__', None)
        if isinstance(declared, str):
            msgtype = declared
        else:
            module = str(getattr(cls, '__module__', ''))
            interface = 'srv' if '.srv' in module else 'msg'
            package, _, _ = module.partition(f'.{interface}')
            msgtype = f'{package}/{interface}/{cls.__name__}'
        what = f'{cls.__module__}.{cls.__name__}'
    try:
        return spec_for(msgtype).msgtype
    except KeyError:
        msg = f'{what} is not a ROS message type tf_demo.msgs knows'
        raise CdrError(msg) from None


@functools.cache
def _encoder(msgtype: str) -> Encoder:
    """Return the encoder of ``msgtype`` (generated; for TFMessage with whole-message layouts)."""
    generated = _codegen.generate_encoder(msgtype)
    return _tf_encoder(generated) if msgtype == _TF_MESSAGE else generated


@functools.cache
def _decoders(msgtype: str) -> tuple[Decoder, Decoder]:
    """Return the (big-endian, little-endian) decoders of ``msgtype`` (generated; tf: layouts)."""
    big, little = _codegen.generate_decoder(msgtype, '>'), _codegen.generate_decoder(msgtype, '<')
    if msgtype == _TF_MESSAGE:
        return _tf_decoder(big, _TF_SHAPES[0]), _tf_decoder(little, _TF_SHAPES[1])
    return big, little


#: (msgtype, encoder, (big-endian decoder, little-endian decoder)) of one type.
_Codecs = tuple[str, Encoder, tuple[Decoder, Decoder]]
# Per message class (or type name), so that a call costs one dict lookup.
_CODECS: dict[str | type, _Codecs] = {}


def _codecs(key: object) -> _Codecs:
    """Return (msgtype, encoder, decoder pair) for a class, instance's class or type name."""
    msgtype = msgtype_of(key)
    entry = (msgtype, _encoder(msgtype), _decoders(msgtype))
    if isinstance(key, str | type):
        _CODECS[key] = entry
    return entry


def serialize(message: object) -> bytes:
    """
    Encode ``message`` as ROS 2 does: ``00 01 00 00`` then the little-endian CDR body.

    ``message`` may be one of our classes or an rclpy message (fields read by name).

    :raises CdrError: a field holds a value that cannot be encoded (wrong type, out of range).
    """
    cls = type(message)
    msgtype, encoder, _ = _CODECS.get(cls) or _codecs(cls)
    try:
        return encoder(message)
    except Exception as exc:
        reference_serialize(msgtype, message)  # raises with the field's name
        msg = f'cannot encode {msgtype}: {exc}'
        raise CdrError(msg) from exc


def _slow_path(msgtype: str, buf: bytes) -> Message:
    """
    Decode bytes the fast decoder turned down with the reference decoder.

    They hold an odd string a ROS node accepts (see the module docstring), or are malformed.

    :raises CdrError: malformed; the reference's error names the field and byte.
    """
    try:
        return reference_deserialize(msgtype, buf)
    except CdrError as error:
        raise error from None


@overload
def deserialize(msg_type: type[MessageT], data: bytes | bytearray | memoryview) -> MessageT: ...


@overload
def deserialize(msg_type: object, data: bytes | bytearray | memoryview) -> Message: ...


def deserialize(msg_type: object, data: bytes | bytearray | memoryview) -> Message:
    """
    Decode ``data`` (encapsulation header included) into a message of ``msg_type``.

    ``msg_type`` is one of our classes, an rclpy class of the same name, or ``'pkg/msg/Name'``;
    the result is always an instance of our class. Trailing bytes (DDS pads to 4) are ignored.

    :raises CdrError: wrong header, truncated or malformed bytes; the message names the field
        and byte offset.
    """
    known = _CODECS.get(msg_type) if isinstance(msg_type, str | type) else None
    msgtype, _, decoders = known or _codecs(msg_type)
    buf = data if type(data) is bytes else bytes(data)
    if len(buf) < 4 or buf[0] or buf[1] > 1:
        check_header(msgtype, buf)
    try:
        return decoders[buf[1]](buf, 4)[0]
    except Exception:
        return _slow_path(msgtype, buf)


_MIN_TRANSFORM_SIZE = _codegen.min_wire_size('geometry_msgs/msg/TransformStamped')


class _TfLayouts:
    """The structs of the tf fast path for one byte order (see ``DynamicStructs``)."""

    def __init__(self, endian: _codegen.Endian) -> None:
        self.count = Struct(endian + 'I').unpack_from
        self.header = Struct(endian + 'iII').unpack_from
        # parent characters, NUL, padding, child length
        self.parent = _codegen.DynamicStructs(endian, [('I', 4, 4)])
        # child characters, NUL, padding, pose; for all but the last transform also the next
        # transform's stamp and frame_id length (one unpack fewer per transform)
        pose = ('7d', 8, 56)
        self.last_child = _codegen.DynamicStructs(endian, [pose])
        self.child = _codegen.DynamicStructs(endian, [pose, ('i', 4, 4), ('I', 4, 4), ('I', 4, 4)])


_TF_LAYOUTS = (_TfLayouts('>'), _TfLayouts('<'))


def _tf_transforms(buf: bytes) -> list[TransformTuple]:
    """Decode the transforms of a TFMessage straight into tuples (fast path)."""
    layouts = _TF_LAYOUTS[buf[1]]
    parent_cache, make_parent = layouts.parent.cache, layouts.parent.make
    child_cache, make_child = layouts.child.cache, layouts.child.make
    (count,) = layouts.count(buf, 4)
    if count * _MIN_TRANSFORM_SIZE > len(buf) - 8:
        raise _codegen.Malformed
    if not count:
        return []
    sec, nanosec, length = layouts.header(buf, 8)
    pos = 20
    result: list[TransformTuple] = []
    append = result.append
    last = count - 1
    for index in range(count):
        unpack, size = parent_cache.get(length << 3 | pos & 7) or make_parent(length, pos)
        parent, parent_nul, length = unpack(buf, pos)
        pos += size
        stamp_ns = sec * 1_000_000_000 + nanosec
        if index != last:
            unpack, size = child_cache.get(length << 3 | pos & 7) or make_child(length, pos)
            child, nul, tx, ty, tz, qx, qy, qz, qw, sec, nanosec, length = unpack(buf, pos)
        else:
            last_child = layouts.last_child
            unpack, size = last_child.cache.get(length << 3 | pos & 7) or last_child.make(
                length, pos
            )
            child, nul, tx, ty, tz, qx, qy, qz, qw = unpack(buf, pos)
        pos += size
        if nul or parent_nul or 0 in parent or 0 in child:
            raise _codegen.Malformed
        append((parent.decode(), child.decode(), stamp_ns, (tx, ty, tz), (qx, qy, qz, qw)))
    return result


#: Items of one transform in a whole-message layout: stamp (2), parent length, characters and
#: NUL, child length, characters and NUL, pose (7).
_TF_STRIDE = 15
#: Layouts remembered per byte order (then forgotten all at once) ...
_MAX_TF_LAYOUTS = 64
#: ... for messages of this many transforms or more (fewer decode faster without) ...
_MIN_TF_LAYOUT_TRANSFORMS = 4
#: ... and at most this many.
_MAX_TF_LAYOUT_TRANSFORMS = 1024
#: Compiled layouts of one cache together cover at most this many transforms (a struct takes
#: about 300 bytes per transform), else the cache starts again.
_TF_LAYOUT_BUDGET = 8192

#: (parent lengths, child lengths, compiled whole-message ``unpack_from`` or None, its size).
_TfLayout = tuple[
    tuple[int, ...], tuple[int, ...], Callable[[bytes, int], StructValues] | None, int
]


def _tf_layout_format(
    endian: str, parents: tuple[int, ...], children: tuple[int, ...], *, encode: bool = False
) -> str:
    """
    Return the struct format of a whole TFMessage body with these string lengths (NULs in).

    A decoder's reads each NUL (``B``, to check it); an encoder's writes it (``x``) and starts
    with the encapsulation header, written as the uint32 256 (``00 01 00 00``).
    """
    parts = [endian, 'II' if encode else 'I']
    nul = 'x' if encode else 'B'
    end = 4
    for parent, child in zip(parents, children, strict=True):
        pad = -end % 4
        parts.append(f'{pad}xiII{parent - 1}s{nul}' if pad else f'iII{parent - 1}s{nul}')
        end += pad + 12 + parent
        pad = -end % 4
        parts.append(f'{pad}xI{child - 1}s{nul}' if pad else f'I{child - 1}s{nul}')
        end += pad + 4 + child
        pad = -end % 8
        parts.append(f'{pad}x7d' if pad else '7d')
        end += pad + 56
    return ''.join(parts)


class _TfShapes:
    """
    Whole-message structs of the TFMessages seen, by message size, for one byte order.

    A tf publisher sends the same frames again and again, so a TFMessage usually has the layout
    of the previous one of its size: one ``unpack_from`` of a struct compiled for that layout
    reads all of it. The count, length fields and NULs it read confirm the layout (each length
    sits where the lengths before it put it, so all equal means the same layout, to the last
    byte). A layout is compiled when it is seen the second time in a row for its size; the
    first sighting only records it, so sizes that change shape every time cost no compiling.
    """

    def __init__(self, endian: _codegen.Endian) -> None:
        self.endian = endian
        self.layouts: dict[int, _TfLayout] = {}
        self.compiled = 0  # transforms covered by the compiled layouts

    def read(self, buf: bytes) -> tuple[StructValues, int] | None:
        """
        Return every field of ``buf`` (count first) and the end of the message, or None.

        None means that ``buf`` does not have the layout known for its size (or none is), or
        holds a NUL inside a frame id (read by the slow path). The names are not decoded here
        (invalid UTF-8 raises when they are).
        """
        layout = self.layouts.get(len(buf))
        if layout is None:
            return None
        parents, children, unpack, size = layout
        if unpack is None:
            return None
        values = unpack(buf, 4)
        if (
            values[3::_TF_STRIDE] != parents
            or values[6::_TF_STRIDE] != children
            or values[0] != len(parents)
            or any(values[5::_TF_STRIDE])
            or any(values[8::_TF_STRIDE])
            or 0 in b''.join(values[4::_TF_STRIDE] + values[7::_TF_STRIDE])
        ):
            return None  # another layout, a missing NUL, or a NUL inside a frame id
        return values, 4 + size

    def learn(self, size: int, parents: tuple[int, ...], children: tuple[int, ...]) -> None:
        """Record the layout of a message of ``size`` bytes just decoded the slow way."""
        if len(parents) > _MAX_TF_LAYOUT_TRANSFORMS:
            self.layouts.pop(size, None)
            return
        layout = self.layouts.get(size)
        if layout is not None and layout[0] == parents and layout[1] == children:
            if layout[2] is None:
                if self.compiled + len(parents) > _TF_LAYOUT_BUDGET:
                    self.layouts.clear()
                    self.compiled = 0
                compiled = Struct(_tf_layout_format(self.endian, parents, children))
                self.layouts[size] = (parents, children, compiled.unpack_from, compiled.size)
                self.compiled += len(parents)
            return
        if len(self.layouts) >= _MAX_TF_LAYOUTS:
            self.layouts.clear()
            self.compiled = 0
        self.layouts[size] = (parents, children, None, 0)


_TF_SHAPES = (_TfShapes('>'), _TfShapes('<'))


def _tf_message_builder() -> Callable[[StructValues], TFMessage]:
    """Return the function that builds a TFMessage from the fields :meth:`_TfShapes.read` gave."""
    new_time = blank_instance_maker(Time)
    new_header = blank_instance_maker(Header)
    new_vector = blank_instance_maker(Vector3)
    new_quaternion = blank_instance_maker(Quaternion)
    new_transform = blank_instance_maker(Transform)
    new_stamped = blank_instance_maker(TransformStamped)
    new_message = blank_instance_maker(TFMessage)

    def build(values: StructValues) -> TFMessage:
        transforms: list[TransformStamped] = []
        append = transforms.append
        fields = iter(values)
        next(fields)  # the count
        for (
            sec, nanosec, _, parent, _, _, child, _, tx, ty, tz, qx, qy, qz, qw
        ) in zip(*(fields,) * _TF_STRIDE, strict=True):  # fmt: skip
            stamp = new_time()
            stamp.sec = sec
            stamp.nanosec = nanosec
            header = new_header()
            header.stamp = stamp
            header.frame_id = parent.decode()
            translation = new_vector()
            translation.x = tx
            translation.y = ty
            translation.z = tz
            rotation = new_quaternion()
            rotation.x = qx
            rotation.y = qy
            rotation.z = qz
            rotation.w = qw
            transform = new_transform()
            transform.translation = translation
            transform.rotation = rotation
            stamped = new_stamped()
            stamped.header = header
            stamped.child_frame_id = child.decode()
            stamped.transform = transform
            append(stamped)
        message = new_message()
        message.transforms = transforms
        return message

    return build


def _tf_decoder(generated: Decoder, shapes: _TfShapes) -> Decoder:
    """
    Wrap the generated TFMessage decoder of one byte order with the whole-message layouts.

    Layouts are of whole buffers (header included), as :func:`deserialize` passes them: a
    message at another position than 4 goes to the generated decoder.
    """
    build = _tf_message_builder()
    read, learn = shapes.read, shapes.learn
    # The generated decoder of TFMessage makes TFMessages.
    generated_tf = cast('Callable[[bytes, int], tuple[TFMessage, int]]', generated)

    def decode(buf: bytes, pos: int) -> tuple[TFMessage, int]:
        if pos != 4:
            return generated_tf(buf, pos)
        known = read(buf)
        if known is not None:
            return build(known[0]), known[1]
        message, end = generated_tf(buf, pos)
        transforms = message.transforms
        if len(transforms) < _MIN_TF_LAYOUT_TRANSFORMS:
            return message, end
        learn(
            len(buf),
            tuple([len(t.header.frame_id.encode()) + 1 for t in transforms]),
            tuple([len(t.child_frame_id.encode()) + 1 for t in transforms]),
        )
        return message, end

    return decode


#: Items of one transform in an encoder's arguments: stamp (2), parent length and bytes, child
#: length and bytes, pose (7).
_TF_ENCODE_STRIDE = 13
#: Frame names up to this long are kept encoded, up to this many (then all are forgotten).
_MAX_CACHED_NAME = 256
_MAX_CACHED_NAMES = 4096
#: The encapsulation header CDR_LE as the little-endian uint32 an encoder's layout starts with.
_CDR_LE_HEADER = 0x100


class _TFMessageLike(Protocol):
    """A ``tf2_msgs/TFMessage`` of either world."""

    @property
    def transforms(self) -> Sequence[TransformStampedLike]: ...


def _tf_encoder(generated: Encoder) -> Encoder:
    """
    Wrap the generated TFMessage encoder with whole-message layouts.

    The fields of every transform go into one argument list and one ``pack`` writes the
    message, through a struct looked up by all the string lengths. A layout is compiled the
    second time its lengths are seen (the generated encoder writes the first); at most
    ``_MAX_TF_LAYOUTS`` layouts covering ``_TF_LAYOUT_BUDGET`` transforms are kept. Whatever
    fails here fails in the generated encoder too, which :func:`serialize` then asks the
    reference codec to explain.
    """
    packs: dict[tuple[int, ...], Callable[..., bytes]] = {}
    compiled = 0  # transforms covered by ``packs``
    seen: set[tuple[int, ...]] = set()
    # Frame name -> (CDR length, UTF-8 bytes): the same few names come again and again.
    names: dict[str, tuple[int, bytes]] = {}

    def name(text: str) -> tuple[int, bytes]:
        encoded = text.encode()
        entry = (len(encoded) + 1, encoded)
        if len(text) <= _MAX_CACHED_NAME and type(text) is str:
            if len(names) >= _MAX_CACHED_NAMES:
                names.clear()
            names[text] = entry
        return entry

    def encode(message: _TFMessageLike) -> bytes:
        nonlocal compiled
        transforms = message.transforms
        count = len(transforms)
        if not _MIN_TF_LAYOUT_TRANSFORMS <= count <= _MAX_TF_LAYOUT_TRANSFORMS:
            return generated(message)
        fields: list[Any] = [_CDR_LE_HEADER, count]  # the pack's arguments
        for stamped in transforms:
            header = stamped.header
            stamp = header.stamp
            try:
                parent_length, parent = names[header.frame_id]
            except KeyError:
                parent_length, parent = name(header.frame_id)
            try:
                child_length, child = names[stamped.child_frame_id]
            except KeyError:
                child_length, child = name(stamped.child_frame_id)
            transform = stamped.transform
            translation = transform.translation
            rotation = transform.rotation
            fields += (
                stamp.sec, stamp.nanosec, parent_length, parent, child_length, child,
                translation.x, translation.y, translation.z,
                rotation.x, rotation.y, rotation.z, rotation.w,
            )  # fmt: skip
        key = tuple(fields[4::_TF_ENCODE_STRIDE] + fields[6::_TF_ENCODE_STRIDE])
        pack = packs.get(key)
        if pack is None:
            if key not in seen:
                if len(seen) >= _MAX_TF_LAYOUTS:
                    seen.clear()
                seen.add(key)
                return generated(message)
            if len(packs) >= _MAX_TF_LAYOUTS or compiled + count > _TF_LAYOUT_BUDGET:
                packs.clear()
                compiled = 0
            pack = packs[key] = Struct(
                _tf_layout_format('<', key[:count], key[count:], encode=True)
            ).pack
            compiled += count
        return pack(*fields)

    return encode


#: ``(parent, child, (tx, ty, tz), (qx, qy, qz, qw))``: a transform for :class:`TfMessageEncoder`.
FrameTransform = tuple[str, str, Vec3, Quat]
_HEADER_AND_COUNT = Struct('<II')
#: (first transform's pack, its names, later transforms' pack, their names) of one frame pair.
_PairPacks = tuple[Callable[..., bytes], bytes, Callable[..., bytes], bytes]


def _cdr_string(text: str) -> bytes:
    """Return ``text`` as a CDR string: its length with the NUL, UTF-8 bytes, the NUL."""
    data = text.encode()
    return (len(data) + 1).to_bytes(4, 'little') + data + b'\x00'


class TfMessageEncoder:
    """
    Encode ``tf2_msgs/msg/TFMessage`` CDR bytes straight from transform tuples, no objects.

    The bytes are :func:`serialize`'s (CDR_LE). Every frame name gets ``frame_prefix`` in front
    (or is renamed by ``rename``) and, with :meth:`encode`, every transform the same stamp:
    robot_state_publisher's hot path; :meth:`encode_stamped` keeps each transform's own stamp
    (tf_relay's). The names and padding of each (parent, child) pair are built once; a message
    then costs one ``pack`` per transform (faster here than one whole-message layout).
    """

    def __init__(self, frame_prefix: str = '', rename: Callable[[str], str] | None = None) -> None:
        self.frame_prefix = frame_prefix
        self._rename = rename
        self._pairs: dict[tuple[str, str], _PairPacks] = {}

    def _name(self, frame: str) -> str:
        return self.frame_prefix + frame if self._rename is None else self._rename(frame)

    def _pair(self, parent: str, child: str) -> _PairPacks:
        names = _cdr_string(self._name(parent))
        names += b'\x00' * (-len(names) % 4)
        names += _cdr_string(self._name(child))
        # The first transform starts 4 mod 8 (after the count), the rest 0 mod 8; the 8-byte
        # stamp keeps that, then the doubles need 8-byte alignment.
        first = names + b'\x00' * (-(4 + 8 + len(names)) % 8)
        later = names + b'\x00' * (-(8 + len(names)) % 8)
        packs = (
            Struct(f'<iI{len(first)}s7d').pack,
            first,
            Struct(f'<iI{len(later)}s7d').pack,
            later,
        )
        if len(self._pairs) >= _MAX_CACHED_NAMES:
            self._pairs.clear()
        self._pairs[(parent, child)] = packs
        return packs

    def encode(self, transforms: Sequence[FrameTransform], sec: int, nanosec: int) -> bytes:
        """Return the serialised TFMessage with every transform stamped ``sec.nanosec``."""
        parts = [_HEADER_AND_COUNT.pack(_CDR_LE_HEADER, len(transforms))]
        pairs = self._pairs
        first = True
        for parent, child, (tx, ty, tz), (qx, qy, qz, qw) in transforms:
            packs = pairs.get((parent, child)) or self._pair(parent, child)
            if first:
                parts.append(packs[0](sec, nanosec, packs[1], tx, ty, tz, qx, qy, qz, qw))
                first = False
            else:
                parts.append(packs[2](sec, nanosec, packs[3], tx, ty, tz, qx, qy, qz, qw))
        return b''.join(parts)

    def encode_stamped(self, transforms: Sequence[TransformTuple]) -> bytes:
        """
        Return the serialised TFMessage of decoded transforms, each with its own stamp.

        :raises OverflowError: a stamp a ``builtin_interfaces/Time`` cannot hold.
        """
        parts = [_HEADER_AND_COUNT.pack(_CDR_LE_HEADER, len(transforms))]
        pairs = self._pairs
        first = True
        for parent, child, stamp_ns, (tx, ty, tz), (qx, qy, qz, qw) in transforms:
            packs = pairs.get((parent, child)) or self._pair(parent, child)
            pack, names = (packs[0], packs[1]) if first else (packs[2], packs[3])
            first = False
            sec, nanosec = divmod(stamp_ns, 1_000_000_000)
            try:
                parts.append(pack(sec, nanosec, names, tx, ty, tz, qx, qy, qz, qw))
            except struct_error:
                msg = f'stamp {stamp_ns} ns does not fit a builtin_interfaces/Time'
                raise OverflowError(msg) from None
        return b''.join(parts)


def _tf_tuples(values: StructValues) -> list[TransformTuple]:
    """Return the transform tuples of the fields :meth:`_TfShapes.read` gave."""
    fields = iter(values)
    next(fields)  # the count
    return [
        (
            parent.decode(), child.decode(), sec * 1_000_000_000 + nanosec,
            (tx, ty, tz), (qx, qy, qz, qw),
        )
        for (
            sec, nanosec, _, parent, _, _, child, _, tx, ty, tz, qx, qy, qz, qw
        ) in zip(*(fields,) * _TF_STRIDE, strict=True)
    ]  # fmt: skip


def decode_tf_message_transforms(data: bytes | bytearray | memoryview) -> list[TransformTuple]:
    """
    Decode a serialised ``tf2_msgs/msg/TFMessage`` straight into transform tuples.

    Each tuple is ``(parent_frame, child_frame, stamp_ns, (tx, ty, tz), (qx, qy, qz, qw))``.
    No message objects are built: this is the tf listener's hot path.

    :raises CdrError: as :func:`deserialize`.
    """
    buf = data if type(data) is bytes else bytes(data)
    check_header(_TF_MESSAGE, buf)
    shapes = _TF_SHAPES[buf[1]]
    try:
        known = shapes.read(buf)
        if known is not None:
            return _tf_tuples(known[0])
        transforms = _tf_transforms(buf)
        if len(transforms) < _MIN_TF_LAYOUT_TRANSFORMS:
            return transforms
        shapes.learn(
            len(buf),
            tuple([len(t[0].encode()) + 1 for t in transforms]),
            tuple([len(t[1].encode()) + 1 for t in transforms]),
        )
        return transforms
    except Exception:
        message = cast('TFMessage', _slow_path(_TF_MESSAGE, buf))
    return [
        (
            t.header.frame_id, t.child_frame_id,
            t.header.stamp.sec * 1_000_000_000 + t.header.stamp.nanosec,
            (t.transform.translation.x, t.transform.translation.y, t.transform.translation.z),
            (
                t.transform.rotation.x, t.transform.rotation.y,
                t.transform.rotation.z, t.transform.rotation.w,
            ),
        )
        for t in message.transforms
    ]  # fmt: skip


def message_type(msgtype: str) -> type[Message]:
    """
    Return our class for ``'pkg/msg/Name'``.

    :raises KeyError: unknown type.
    """
    return message_class(spec_for(msgtype).msgtype)
