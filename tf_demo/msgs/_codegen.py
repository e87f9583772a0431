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
Generate straight-line XCDR1 encoders and decoders for one message type (rosbags-style).

The generated code inlines every nested message, merges consecutive primitives (and the
padding between them, where it is known at generation time) into one precompiled
:class:`struct.Struct` call, and aligns at run time only where the alignment depends on the
length of a string or sequence. Alignment is relative to the first byte after the 4-byte
encapsulation header, so buffers always include that header and positions start at 4.

Generated code raises whatever the failing operation raises (``struct.error``,
``IndexError``, ``UnicodeDecodeError``, :class:`Malformed`...), also for the odd strings a ROS
node accepts (length 0, a NUL inside, invalid UTF-8): :mod:`tf_demo.msgs.cdr` then asks the
reference codec, which reads those as rclpy does, or raises a
:class:`~tf_demo.msgs.cdr.CdrError` that names the field.
"""

from __future__ import annotations

from array import array
from collections.abc import Callable
from struct import Struct
import sys
from types import FunctionType
from typing import Any
from typing import Literal
from typing import TYPE_CHECKING

from tf_demo.core.lazy_import import lazy_module
from tf_demo.msgs._message import blank_instance_maker
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

_MAX_ALIGN = 8
#: Zero padding of 0..7 bytes, indexed by the pad length.
ZEROS = tuple(bytes(n) for n in range(_MAX_ALIGN))

Endian = Literal['<', '>']
#: Encodes a message of one type, one of ours or rclpy's (its fields read by name): no static
#: type says which type an encoder takes, hence ``Any``.
Encoder = Callable[[Any], bytes]
Decoder = Callable[[bytes, int], tuple[Message, int]]
#: What ``struct`` unpacks: ints, floats and bytes in the order of the format (typeshed: Any).
StructValues = tuple[Any, ...]
#: A string's compiled struct: its ``unpack_from`` and the size it reads.
DynamicEntry = tuple[Callable[[bytes, int], StructValues], int]


class Malformed(Exception):  # noqa: N818 - internal signal, never leaves tf_demo.msgs
    """Raised by generated decoders for what struct cannot detect (NULs, counts): slow path."""


def _lowbit(value: int) -> int:
    """Return the largest power of two (at most 8) that divides ``value``."""
    return _MAX_ALIGN if value == 0 else min(_MAX_ALIGN, value & -value)


#: Strings up to this length get their dynamic structs cached (longer ones are rare) ...
_MAX_CACHED_STRING = 1024
#: ... and each cache stops growing at this many entries (input from the network is untrusted).
_MAX_CACHE_ENTRIES = 4096
#: One item of a run: (struct code, alignment, size).
Item = tuple[str, int, int]


class DynamicStructs:
    """
    The structs that read one string and a run of primitives after it, by length and position.

    Where the padding after a string goes depends on the string's length and on where it starts
    (modulo 8), so the generated decoder looks the compiled struct up by ``length << 3 | pos & 7``
    and asks :meth:`make` for the ones it has not seen. A struct reads the characters, the NUL
    (checked by the caller) and the run.
    """

    def __init__(self, endian: Endian, items: list[Item]) -> None:
        self.endian = endian
        self.items = tuple(items)
        self.cache: dict[int, DynamicEntry] = {}

    def make(self, length: int, pos: int) -> DynamicEntry:
        """
        Compile, cache and return ``(unpack_from, size)`` for a string starting at ``pos``.

        ``length`` is the string's CDR length (its NUL included).
        """
        if length < 1:
            raise Malformed
        fmt, end = f'{length - 1}sB', pos - 4 + length
        for code, alignment, size in self.items:
            pad = -end % alignment
            fmt += f'{pad}x{code}' if pad else code
            end += pad + size
        compiled = Struct(self.endian + fmt)
        entry = (compiled.unpack_from, end - (pos - 4))
        if length <= _MAX_CACHED_STRING and len(self.cache) < _MAX_CACHE_ENTRIES:
            self.cache[length << 3 | pos & 7] = entry
        return entry


class RunLayouts:
    """
    The ``pack`` functions of one encoder run that contains strings, by their lengths.

    The key is ``(len(bytes_1), ..., len(bytes_k), len(out) & 7)``; a string item has the code
    ``''`` in ``items`` and is written as its bytes plus a NUL (its length is a separate item).
    """

    def __init__(self, items: list[Item]) -> None:
        self.items = tuple(items)
        self.cache: dict[tuple[int, ...], Callable[..., bytes]] = {}

    def make(self, key: tuple[int, ...]) -> Callable[..., bytes]:
        """Compile, cache and return the ``pack`` for the lengths and position in ``key``."""
        *lengths, start = key
        pending = iter(lengths)
        fmt, end = '<', start - 4
        for code, alignment, size in self.items:
            if code:
                pad = -end % alignment
                fmt += f'{pad}x{code}' if pad else code
                end += pad + size
            else:
                length = next(pending)
                fmt += f'{length}sx'
                end += length + 1
        pack = Struct(fmt).pack
        if max(lengths) <= _MAX_CACHED_STRING and len(self.cache) < _MAX_CACHE_ENTRIES:
            self.cache[key] = pack
        return pack


def _known_after(items: list[Item]) -> int:
    """Return the alignment known after a string of any length followed by ``items``."""
    known = _MAX_ALIGN
    for start in range(_MAX_ALIGN):
        end = start
        for _, alignment, size in items:
            end += -end % alignment + size
        known = min(known, _lowbit(end))
    return known


def min_wire_size(msgtype: str) -> int:
    """Return a lower bound of the encoded size of one ``msgtype``, for sequence count checks."""
    total = 0
    for field in spec_for(msgtype).fields:
        if field.kind == 'sequence':
            element = 0
            total += 4
        elif field.is_nested:
            element = min_wire_size(field.base)
        elif field.base == 'string':
            element = 5
        else:
            element = PRIMITIVES[field.base].size
        total += element * (field.size if field.kind == 'array' else 1)
    return max(total, 1)


def element_min_size(field: FieldSpec) -> int:
    """Return a lower bound of the encoded size of one element of ``field``."""
    if field.is_nested:
        return min_wire_size(field.base)
    if field.base == 'string':
        return 5
    return PRIMITIVES[field.base].size


class _Builder:
    """
    Shared state of a code generator: lines, names, constants and the alignment knowledge.

    ``known`` is the largest power of two that ``pos - 4`` (decoder) or ``len(out) - 4``
    (encoder) is known to be a multiple of at the current point of the generated code, not
    counting the pending run of primitives, which starts there and is ``run_size`` bytes long.
    """

    def __init__(self, endian: Endian) -> None:
        self.endian: Endian = endian
        self.lines: list[str] = []
        self.namespace: dict[str, object] = {
            '_Malformed': Malformed,
            '_array': array,
            '_numpy': numpy,
            '_ZEROS': ZEROS,
        }
        self.indent = 1
        self.counter = 0
        self.known = _MAX_ALIGN
        self.run_format: list[str] = []
        self.run_items: list[str] = []
        self.run_size = 0
        self.structs: dict[str, str] = {}
        # A string whose characters head the pending run (its local name), and the run's items.
        self.dynamic: str | None = None
        self.dynamic_items: list[Item] = []
        # The items of a pending run without strings (for reading it ahead, see _Prefetch).
        self.run_layout: list[Item] = []

    def name(self, prefix: str) -> str:
        """Return a fresh local variable name."""
        self.counter += 1
        return f'{prefix}{self.counter}'

    def emit(self, line: str) -> None:
        """Append one line at the current indentation."""
        self.lines.append('    ' * self.indent + line)

    def constant(self, prefix: str, value: object) -> str:
        """Bind ``value`` as a global of the generated module and return its name."""
        name = self.name(f'_{prefix}')
        self.namespace[name] = value
        return name

    def struct_method(self, fmt: str, method: str) -> str:
        """Return the global name of ``Struct(endian + fmt).<method>``, compiled once."""
        key = f'{fmt}.{method}'
        if key not in self.structs:
            self.structs[key] = self.constant('s', getattr(Struct(self.endian + fmt), method))
        return self.structs[key]

    def pad_run_to(self, alignment: int) -> bool:
        """Pad the pending run to ``alignment`` if possible statically; say whether it was."""
        if alignment > self.known:
            return False
        pad = -self.run_size % alignment
        if pad:
            self.run_format.append(f'{pad}x')
            self.run_size += pad
        return True

    def settle(self) -> None:
        """Account for the flushed run in the known alignment."""
        if self.dynamic is not None:
            self.known = _known_after(self.dynamic_items)
        else:
            self.known = min(self.known, _lowbit(self.run_size))
        self.run_format, self.run_items, self.run_size = [], [], 0
        self.dynamic, self.dynamic_items = None, []
        self.run_layout = []

    def add_item(self, code: str, alignment: int, size: int, value: str) -> None:
        """Append one item (a local to read into, or an expression to write) to the run."""
        if self.dynamic is not None:
            self.dynamic_items.append((code, alignment, size))
        else:
            self.align(alignment)
            self.run_format.append(code)
            self.run_size += size
            self.run_layout.append((code, alignment, size))
        self.run_items.append(value)

    def align(self, alignment: int) -> None:
        """Make the next item start at a multiple of ``alignment``."""
        if self.string_pending():
            self.flush()
        if alignment == 1 or self.pad_run_to(alignment):
            return
        self.flush()
        self.emit(self.padding(alignment))
        self.known = alignment

    def string_pending(self) -> bool:
        """Tell whether the pending run holds a string (its padding is not known statically)."""
        raise NotImplementedError

    def padding(self, alignment: int) -> str:
        """Return the statement that skips (reads) or writes the padding to ``alignment``."""
        raise NotImplementedError

    def flush(self) -> None:
        """Emit the pending run."""
        raise NotImplementedError


class _Prefetch:
    """
    The leading run of a sequence element, read ahead with the previous element's last run.

    In a loop over elements that start with primitives (a stamp, a string length...) and end
    with a string and its following run, each iteration's last unpack also reads the next
    element's leading primitives: one unpack call fewer per element. The first element's are
    read before the loop (``lines``).
    """

    def __init__(self, body_start: int) -> None:
        self.body_start = body_start
        self.lines: list[str] | None = None
        self.items: list[Item] = []
        self.variables: list[str] = []
        self.temporaries: list[str] = []


class _DecoderBuilder(_Builder):
    """Generate ``decode(buf, pos) -> (message, pos)`` for one type and byte order."""

    def __init__(self, endian: Endian) -> None:
        super().__init__(endian)
        self.builds: list[str] = []
        self.capture: _Prefetch | None = None

    def _capture_prefix(self) -> bool:
        """Take the first run of a loop body out of the body, as its prefetch; say if done."""
        capture, self.capture = self.capture, None
        if capture is None or self.dynamic is not None or not self.run_items:
            return False
        unpack = self.struct_method(''.join(self.run_format), 'unpack_from')
        indent = '    ' * self.indent
        capture.lines = [
            *self.lines[capture.body_start :],
            f'{indent}{", ".join(self.run_items)}, = {unpack}(buf, pos)',
            f'{indent}pos += {self.run_size}',
        ]
        del self.lines[capture.body_start :]
        capture.items = list(self.run_layout)
        capture.variables = list(self.run_items)
        self.settle()
        for line in self.builds:  # objects whose fields are all in the prefix
            self.emit(line)
        self.builds = []
        return True

    def flush(self) -> None:
        """Emit the pending run as one unpack, then the object constructions waiting for it."""
        emits = self.dynamic is not None or bool(self.run_items) or bool(self.run_size)
        if self.capture is not None and emits and self._capture_prefix():
            return
        if self.dynamic is not None:
            length, string = self.dynamic.split(':')
            structs = DynamicStructs(self.endian, self.dynamic_items)
            cache = self.constant('D', structs.cache)
            make = self.constant('M', structs.make)
            unpack, size, raw, nul = (self.name(p) for p in ('u', 'z', 'r', 'n'))
            self.emit(
                f'{unpack}, {size} = {cache}.get({length} << 3 | pos & 7) or {make}({length}, pos)'
            )
            self.emit(f'{", ".join([raw, nul, *self.run_items])} = {unpack}(buf, pos)')
            self.emit(f'pos += {size}')
            self.emit(f'if {nul} or 0 in {raw}:')
            self.emit('    raise _Malformed')
            self.emit(f'{string} = {raw}.decode()')
        else:
            if self.run_items:
                unpack = self.struct_method(''.join(self.run_format), 'unpack_from')
                self.emit(f'{", ".join(self.run_items)}, = {unpack}(buf, pos)')
            if self.run_size:
                self.emit(f'pos += {self.run_size}')
        self.settle()
        for line in self.builds:
            self.emit(line)
        self.builds = []

    def string_pending(self) -> bool:
        """Tell whether a string heads the pending run."""
        return self.dynamic is not None

    def padding(self, alignment: int) -> str:
        """Return the statement that skips the padding to ``alignment``."""
        return f'pos += (4 - pos) & {alignment - 1}'

    def primitive(self, base: str) -> str:
        """Read one primitive into a new local; return its name."""
        prim = PRIMITIVES[base]
        var = self.name('v')
        self.add_item(prim.code, prim.size, prim.size, var)
        return var

    def string(self) -> str:
        """Read one string into a new local; return its name (valid after the next flush)."""
        length = self.primitive('uint32')
        self.flush()
        var = self.name('s')
        self.dynamic = f'{length}:{var}'
        return var

    def value(self, field: FieldSpec) -> str:
        """Read one element of ``field``'s type; return the local holding it."""
        if field.is_nested:
            return self.message(spec_for(field.base))
        if field.base == 'string':
            return self.string()
        return self.primitive(field.base)

    def loop(self, field: FieldSpec, count: str) -> str:
        """Read ``count`` elements of ``field`` one by one into a list; return its name."""
        result = self.name('l')
        append = self.name('a')
        self.flush()
        self.emit(f'{result} = []')
        self.emit(f'{append} = {result}.append')
        entry = self.known
        start = len(self.lines)
        while True:
            del self.lines[start:]
            index, last = self.name('i'), self.name('last')
            self.emit(f'for {index} in range({count}):')
            self.indent += 1
            self.known = entry
            prefetch = self.capture = _Prefetch(len(self.lines))
            element = self.value(field)
            prefetched = prefetch.lines is not None and self.dynamic is not None
            if prefetched:
                self._flush_with_prefetch(prefetch, index, last)
            else:
                self.capture = None
                if prefetch.lines is not None:  # not applicable after all: read it in place
                    self.lines[prefetch.body_start : prefetch.body_start] = prefetch.lines
                self.flush()
            self.emit(f'{append}({element})')
            if prefetched:
                variables = ', '.join(prefetch.variables)
                self.emit(f'{variables}, = {", ".join(prefetch.temporaries)},')
            self.indent -= 1
            if self.known >= entry:
                break
            entry = self.known
        if prefetched and prefetch.lines is not None:
            self.lines[start:start] = [
                '    ' * self.indent + f'if {count}:',
                *prefetch.lines,
                '    ' * self.indent + f'{last} = {count} - 1',
            ]
        self.known = min(self.known, entry)
        return result

    def _flush_with_prefetch(self, prefetch: _Prefetch, index: str, last: str) -> None:
        """Emit a loop body's final (string-headed) run, reading the next element's prefix too."""
        assert self.dynamic is not None
        length, string = self.dynamic.split(':')
        unpack, size, raw, nul = (self.name(p) for p in ('u', 'z', 'r', 'n'))
        prefetch.temporaries = [self.name('t') for _ in prefetch.variables]
        variants = [
            (f'if {index} != {last}:', self.dynamic_items + prefetch.items, prefetch.temporaries),
            ('else:', self.dynamic_items, []),
        ]
        for header, items, extra in variants:
            structs = DynamicStructs(self.endian, items)
            cache = self.constant('D', structs.cache)
            make = self.constant('M', structs.make)
            self.emit(header)
            self.indent += 1
            self.emit(
                f'{unpack}, {size} = {cache}.get({length} << 3 | pos & 7) or {make}({length}, pos)'
            )
            targets = ', '.join([raw, nul, *self.run_items, *extra])
            self.emit(f'{targets} = {unpack}(buf, pos)')
            if not extra:  # the last element: nothing to read ahead
                nones = ', '.join('None' for _ in prefetch.temporaries)
                self.emit(f'{", ".join(prefetch.temporaries)}, = {nones},')
            self.indent -= 1
        self.emit(f'pos += {size}')
        self.emit(f'if {nul} or 0 in {raw}:')
        self.emit('    raise _Malformed')
        self.emit(f'{string} = {raw}.decode()')
        self.settle()
        for line in self.builds:
            self.emit(line)
        self.builds = []

    def numeric_sequence(self, field: FieldSpec, count: str) -> str:
        """Read ``count`` numeric primitives into an ``array.array``; return its name."""
        prim = PRIMITIVES[field.base]
        var = self.name('q')
        entry = self.known
        self.emit(f'if {count}:')
        self.indent += 1
        if prim.size > entry:
            self.emit(self.padding(prim.size))
        end = self.name('e')
        self.emit(f'{end} = pos + {count} * {prim.size}')
        self.emit(f'if {end} > len(buf):')
        self.emit('    raise _Malformed')
        self.emit(f'{var} = _array({prim.array_code!r}, buf[pos:{end}])')
        if self.endian != ('<' if sys.byteorder == 'little' else '>') and prim.size > 1:
            self.emit(f'{var}.byteswap()')
        self.emit(f'pos = {end}')
        self.indent -= 1
        self.emit('else:')
        self.emit(f'    {var} = _array({prim.array_code!r})')
        self.known = min(entry, prim.size)
        return var

    def field_value(self, field: FieldSpec) -> str:
        """Read the whole of ``field``; return the local holding its Python value."""
        if field.kind == 'single':
            return self.value(field)
        if field.kind == 'sequence':
            count = self.primitive('uint32')
            self.flush()
            minimum = element_min_size(field)
            self.emit(f'if {count} * {minimum} > len(buf) - pos:')
            self.emit('    raise _Malformed')
            if field.base in PRIMITIVES and PRIMITIVES[field.base].array_code:
                return self.numeric_sequence(field, count)
            return self.loop(field, count)
        if field.base in PRIMITIVES and PRIMITIVES[field.base].numpy_dtype:
            prim = PRIMITIVES[field.base]
            self.align(prim.size)
            self.flush()
            var = self.name('n')
            dtype = numpy.dtype(prim.numpy_dtype).newbyteorder(self.endian)
            dtype_name = self.constant('dt', dtype)
            self.emit(
                f'{var} = _numpy.frombuffer(buf, {dtype_name}, {field.size}, pos)'
                f'.astype({prim.numpy_dtype!r})'
            )
            self.emit(f'pos += {field.size * prim.size}')
            self.known = min(self.known, _lowbit(field.size * prim.size))
            return var
        return self.loop(field, str(field.size))

    def message(self, spec: MessageSpec) -> str:
        """Read one message of ``spec`` inline; return the local that will hold the object."""
        values = [(field.name, self.field_value(field)) for field in spec.fields]
        var = self.name('m')
        make = self.constant('K', blank_instance_maker(message_class(spec.msgtype)))
        assignments = ''.join(f'; {var}.{name} = {value}' for name, value in values)
        self.builds.append(f'{var} = {make}(){assignments}')
        return var


class _EncoderBuilder(_Builder):
    """
    Generate ``encode(message) -> bytes`` (little-endian, with the encapsulation header).

    A run may hold strings: their bytes go into the same ``pack`` call, through a struct looked
    up by the strings' lengths and the start position modulo 8 (see :class:`RunLayouts`).
    """

    def __init__(self) -> None:
        super().__init__('<')
        self.strings: list[str] = []
        self.layout: list[Item] = []

    def add_item(self, code: str, alignment: int, size: int, value: str) -> None:
        """Append one item to the run; after a string its padding is left to the run's layout."""
        if self.strings:
            self.layout.append((code, alignment, size))
            self.run_items.append(value)
            return
        super().add_item(code, alignment, size, value)
        self.layout.append((code, alignment, size))

    def flush(self) -> None:
        """Emit the pending run as one pack appended to the output."""
        if self.strings:
            layouts = RunLayouts(self.layout)
            cache = self.constant('E', layouts.cache)
            make = self.constant('M', layouts.make)
            key = self.name('k')
            lengths = ''.join(f'len({encoded}), ' for encoded in self.strings)
            self.emit(f'{key} = ({lengths}len(out) & 7)')
            self.emit(f'out += ({cache}.get({key}) or {make}({key}))({", ".join(self.run_items)})')
            tail = self.layout[max(i for i, item in enumerate(self.layout) if not item[0]) + 1 :]
            self.run_format, self.run_size = [], 0
            self.run_items, self.layout, self.strings = [], [], []
            self.known = _known_after(tail)
            return
        if self.run_items:
            pack = self.struct_method(''.join(self.run_format), 'pack')
            self.emit(f'out += {pack}({", ".join(self.run_items)})')
        elif self.run_size:
            self.emit(f'out += _ZEROS[{self.run_size}]')
        self.settle()
        self.layout = []

    def string_pending(self) -> bool:
        """Tell whether the pending run holds strings."""
        return bool(self.strings)

    def padding(self, alignment: int) -> str:
        """Return the statement that writes the padding to ``alignment``."""
        return f'out += _ZEROS[(4 - len(out)) & {alignment - 1}]'

    def primitive(self, base: str, expr: str) -> None:
        """Write one primitive given by the Python expression ``expr``."""
        prim = PRIMITIVES[base]
        self.add_item(prim.code, prim.size, prim.size, expr)

    def string(self, expr: str) -> None:
        """Write one string: uint32 length with the NUL, the bytes, the NUL (all in the run)."""
        encoded = self.name('b')
        self.emit(f'{encoded} = {expr}.encode()')
        self.primitive('uint32', f'len({encoded}) + 1')
        self.strings.append(encoded)
        self.layout.append(('', 1, 0))
        self.run_items.append(encoded)

    def value(self, field: FieldSpec, expr: str) -> None:
        """Write one element of ``field``'s type."""
        if field.is_nested:
            self.message(spec_for(field.base), expr)
        elif field.base == 'string':
            self.string(expr)
        else:
            self.primitive(field.base, expr)

    def loop(self, field: FieldSpec, sequence: str) -> None:
        """Write the elements of ``sequence`` one by one."""
        self.flush()
        element = self.name('x')
        entry = self.known
        start = len(self.lines)
        while True:
            del self.lines[start:]
            self.emit(f'for {element} in {sequence}:')
            self.indent += 1
            self.known = entry
            self.value(field, element)
            self.flush()
            if len(self.lines) == start + 1:
                self.emit('pass')  # an element with nothing to write
            self.indent -= 1
            if self.known >= entry:
                break
            entry = self.known
        self.known = min(self.known, entry)

    def field(self, field: FieldSpec, expr: str) -> None:
        """Write the whole of ``field``, whose value is ``expr``."""
        if field.kind == 'single':
            self.value(field, expr)
            return
        if field.kind == 'array' and field.base in PRIMITIVES:
            prim = PRIMITIVES[field.base]
            self.add_item(
                f'{field.size}{prim.code}', prim.size, field.size * prim.size, f'*{expr}'
            )
            return
        sequence = self.name('q')
        self.emit(f'{sequence} = {expr}')
        if field.kind == 'array':
            self.emit(f'if len({sequence}) != {field.size}:')
            self.emit('    raise _Malformed')
            self.loop(field, sequence)
            return
        self.primitive('uint32', f'len({sequence})')
        if field.base in PRIMITIVES:
            prim = PRIMITIVES[field.base]
            self.flush()
            entry = self.known
            self.emit(f'if len({sequence}):')
            self.indent += 1
            if prim.size > entry:
                self.emit(self.padding(prim.size))
            if prim.array_code:
                converted = self.name('r')
                self.emit(f'{converted} = _array({prim.array_code!r}, {sequence})')
                if sys.byteorder != 'little' and prim.size > 1:
                    self.emit(f'{converted}.byteswap()')  # the wire is little-endian
                self.emit(f'out += {converted}.tobytes()')
            elif field.base == 'byte':
                joined = self.name('j')
                self.emit(f"{joined} = b''.join({sequence})")
                self.emit(f'if len({joined}) != len({sequence}):')
                self.emit('    raise _Malformed')
                self.emit(f'out += {joined}')
            else:
                self.emit(f'out += bytes([1 if x else 0 for x in {sequence}])')
            self.indent -= 1
            self.known = min(entry, prim.size)
            return
        self.loop(field, sequence)

    def message(self, spec: MessageSpec, expr: str) -> None:
        """Write one message whose value is ``expr``."""
        if spec.fields and not expr.isidentifier():
            var = self.name('m')
            self.emit(f'{var} = {expr}')
            expr = var
        for field in spec.fields:
            self.field(field, f'{expr}.{field.name}')


def _compile(builder: _Builder, header: str, footer: str, label: str) -> FunctionType:
    """Compile the generated body into a function and return it (its text as ``.source``)."""
    source = '\n'.join([header, *builder.lines, footer])
    code = compile(source, f'<tf_demo.msgs.cdr {label}>', 'exec')
    exec(code, builder.namespace)
    function = builder.namespace['generated']
    assert isinstance(function, FunctionType)
    vars(function)['source'] = source
    return function


def generate_decoder(msgtype: str, endian: Endian) -> Decoder:
    """Generate the decoder of ``msgtype`` for ``endian`` (``'<'`` or ``'>'``)."""
    builder = _DecoderBuilder(endian)
    result = builder.message(spec_for(msgtype))
    builder.flush()
    decoder: Decoder = _compile(
        builder, 'def generated(buf, pos):', f'    return {result}, pos', f'decode {msgtype}'
    )
    return decoder


def generate_encoder(msgtype: str) -> Encoder:
    """Generate the little-endian encoder of ``msgtype``, header included."""
    builder = _EncoderBuilder()
    builder.message(spec_for(msgtype), 'message')
    builder.flush()
    header = "def generated(message):\n    out = bytearray(b'\\x00\\x01\\x00\\x00')"
    encoder: Encoder = _compile(builder, header, '    return bytes(out)', f'encode {msgtype}')
    return encoder
