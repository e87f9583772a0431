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
The tf snapshot file: a versioned YAML schema, its writer and a strict, line-aware reader.

``tf_saver`` writes it, ``tf_loader`` republishes it, and ``view_frames --snapshot`` and
``tf_doctor --snapshot`` read it. The full description is in ``doc/tf_snapshot_format.md``.

Schema, version 1 (keys in this order; ``#`` comments are allowed anywhere)::

    tf_demo_transforms: 1              # schema version (required, integer)
    recorded_at: {sec: 1700000000, nanosec: 250000000}   # optional, clock time of the recording
    transform_count: 2                 # required, must equal the number of entries below
    transforms:                        # required, a list (may be empty)
      - parent: map                    # required, non-empty frame ids, parent != child
        child: odom
        translation: [1.0, 2.0, 0.0]   # required, 3 finite numbers, metres
        rotation: [0.0, 0.0, 0.0, 1.0] # required, 4 finite numbers x y z w, |q|^2 within 0.01 of 1
        static: false                  # optional (default true): it came from /tf_static
        stamp: {sec: 1700000000, nanosec: 0}   # optional, the transform's header stamp
        authority: some_node           # optional, free text
        rate_hz: 20.0                  # optional, finite and >= 0, observed publishing rate
        sample_count: 200              # optional, integer >= 0

Rules the reader enforces, each refusal naming the file, the line and the problem: the file exists,
is at most :data:`MAX_FILE_BYTES` long and is UTF-8 YAML (``yaml.safe_load`` semantics, at most
:data:`MAX_NESTING` levels deep, no anchors, aliases, tags or duplicate keys); the version is
known; every key is known and of the right type; numbers are finite; there are at most
:data:`MAX_TRANSFORMS` entries; no frame is its own parent, no child appears twice and the parent
links have no cycle; ``transform_count`` matches (a file cut at an entry boundary is caught here).
Nothing is returned unless the whole file is valid, so a caller never half-loads a file. Pickle is
never used.
"""

from __future__ import annotations

from collections.abc import Iterable
from collections.abc import Sequence
from dataclasses import dataclass
import json
import math
import os

from tf_demo.core.files import InputFileError
from tf_demo.core.files import read_text_file
from tf_demo.core.files import write_text_atomically
from tf_demo.core.files import yaml_flow_too_deep
import yaml

SCHEMA_KEY = 'tf_demo_transforms'
SCHEMA_VERSION = 1
MAX_FILE_BYTES = 4 * 1024 * 1024
MAX_TRANSFORMS = 10_000
MAX_FRAME_ID_LENGTH = 1024
MAX_NESTING = 16
TOP_KEYS = (SCHEMA_KEY, 'recorded_at', 'transform_count', 'transforms')
ENTRY_KEYS = (
    'parent',
    'child',
    'translation',
    'rotation',
    'static',
    'stamp',
    'authority',
    'rate_hz',
    'sample_count',
)
_REQUIRED_ENTRY_KEYS = ('parent', 'child', 'translation', 'rotation')
MAX_NUMBER_CHARACTERS = 64
MAX_INTEGER = 2**63 - 1
_NUMBER_TAGS = ('tag:yaml.org,2002:int', 'tag:yaml.org,2002:float')


def _cut(text: str, limit: int = 40) -> str:
    """``text`` for an error message, cut to ``limit`` characters."""
    return text if len(text) <= limit else f'{text[:limit]}... ({len(text)} characters)'


class SnapshotError(ValueError):
    """A snapshot file that cannot be used; the message names the file, the line and the reason."""


@dataclass(frozen=True)
class SnapshotTransform:
    """One saved transform: ``parent_T_child`` plus what was observed about it."""

    parent: str
    child: str
    translation: tuple[float, float, float]
    rotation: tuple[float, float, float, float]
    is_static: bool = True
    stamp_ns: int | None = None
    authority: str | None = None
    rate_hz: float | None = None
    sample_count: int | None = None


@dataclass(frozen=True)
class Snapshot:
    """A whole snapshot file."""

    transforms: tuple[SnapshotTransform, ...]
    recorded_at_ns: int | None = None
    version: int = SCHEMA_VERSION


# ---------------------------------------------------------------------------------------------
# writing


def _yaml_string(text: str) -> str:
    """Quote as a YAML double-quoted scalar (JSON's escapes are a subset of YAML's)."""
    return json.dumps(text, ensure_ascii=False)


def _yaml_float(value: float) -> str:
    """Format a float that reads back bit-exactly (``repr``), with a point or exponent."""
    number = float(value)
    if math.isnan(number):
        return '.nan'
    if math.isinf(number):
        return '.inf' if number > 0 else '-.inf'
    mantissa, _, exponent = repr(number).partition('e')
    if '.' not in mantissa:
        mantissa += '.0'
    if not exponent:
        return mantissa
    sign = '' if exponent[0] in '+-' else '+'
    return f'{mantissa}e{sign}{exponent}'


def _yaml_stamp(stamp_ns: int) -> str:
    seconds, nanoseconds = divmod(stamp_ns, 1_000_000_000)
    return f'{{sec: {seconds}, nanosec: {nanoseconds}}}'


def dump_snapshot(snapshot: Snapshot) -> str:
    """Render ``snapshot`` as schema-version-1 YAML text (deterministic, round-trips exactly)."""
    lines = [
        '# tf_demo transform snapshot; schema: doc/tf_snapshot_format.md',
        f'{SCHEMA_KEY}: {SCHEMA_VERSION}',
    ]
    if snapshot.recorded_at_ns is not None:
        lines.append(f'recorded_at: {_yaml_stamp(snapshot.recorded_at_ns)}')
    lines.append(f'transform_count: {len(snapshot.transforms)}')
    if not snapshot.transforms:
        lines.append('transforms: []')
    else:
        lines.append('transforms:')
    for entry in snapshot.transforms:
        lines.append(f'  - parent: {_yaml_string(entry.parent)}')
        lines.append(f'    child: {_yaml_string(entry.child)}')
        lines.append(f'    translation: [{", ".join(_yaml_float(v) for v in entry.translation)}]')
        lines.append(f'    rotation: [{", ".join(_yaml_float(v) for v in entry.rotation)}]')
        lines.append(f'    static: {"true" if entry.is_static else "false"}')
        if entry.stamp_ns is not None:
            lines.append(f'    stamp: {_yaml_stamp(entry.stamp_ns)}')
        if entry.authority is not None:
            lines.append(f'    authority: {_yaml_string(entry.authority)}')
        if entry.rate_hz is not None:
            lines.append(f'    rate_hz: {_yaml_float(entry.rate_hz)}')
        if entry.sample_count is not None:
            lines.append(f'    sample_count: {entry.sample_count}')
    return '\n'.join(lines) + '\n'


def write_snapshot(path: str | os.PathLike[str], snapshot: Snapshot) -> None:
    """
    Write ``snapshot`` atomically over a regular file (or a new one) at ``path``.

    The rules of :func:`tf_demo.cli._output.write_text_atomically`: devices, FIFOs and folders
    are refused, a symbolic link is followed and stays a link; :class:`OutputFileError` else.
    """
    write_text_atomically(path, dump_snapshot(snapshot))


# ---------------------------------------------------------------------------------------------
# reading


class _Reader:
    """Walks the composed YAML node tree, converting and checking every value with its line."""

    def __init__(self, source: str) -> None:
        self.source = source
        self._constructor = yaml.constructor.SafeConstructor()
        self._seen: set[int] = set()

    def fail(self, node: yaml.Node | None, problem: str) -> SnapshotError:
        if node is None:
            return SnapshotError(f'{self.source}: {problem}')
        return SnapshotError(f'{self.source}:{node.start_mark.line + 1}: {problem}')

    def visit(self, node: yaml.Node) -> None:
        """Refuse a node reached twice (an alias) so hostile files cannot blow up the walk."""
        if id(node) in self._seen:
            raise self.fail(node, 'anchors and aliases (&, *) are not allowed')
        self._seen.add(id(node))
        if node.tag.startswith('!') or node.tag.startswith('tag:yaml.org,2002:python'):
            raise self.fail(node, f'tag {node.tag} is not allowed')

    def mapping(self, node: yaml.Node, what: str, allowed: Sequence[str]) -> dict[str, yaml.Node]:
        self.visit(node)
        if not isinstance(node, yaml.MappingNode):
            raise self.fail(node, f'{what} must be a mapping')
        result: dict[str, yaml.Node] = {}
        for key_node, value_node in node.value:
            self.visit(key_node)
            key = self.scalar(key_node, f'{what}: key')
            if not isinstance(key, str):
                raise self.fail(key_node, f'{what}: key {_cut(repr(key))} is not a string')
            if key == '<<' or key_node.tag == 'tag:yaml.org,2002:merge':
                raise self.fail(key_node, f'{what}: merge keys (<<) are not allowed')
            if key in result:
                raise self.fail(key_node, f'{what}: duplicate key {_cut(repr(key))}')
            if key not in allowed:
                raise self.fail(
                    key_node,
                    f'{what}: unknown key {_cut(repr(key))} (known: {", ".join(allowed)})',
                )
            result[key] = value_node
        return result

    def scalar(self, node: yaml.Node, what: str) -> object:
        if not isinstance(node, yaml.ScalarNode):
            raise self.fail(node, 'expected a single value, found a list or mapping')
        if node.tag in _NUMBER_TAGS and len(node.value) > MAX_NUMBER_CHARACTERS:
            # A 4,300-digit integer cannot even be converted (ValueError), a long 1:2:3... one
            # takes quadratic time, and no value this file holds needs more than 25 characters.
            raise self.fail(
                node,
                f'{what}: number {_cut(node.value)} is longer than {MAX_NUMBER_CHARACTERS} '
                'characters',
            )
        try:
            return self._constructor.construct_object(node, deep=True)
        except yaml.YAMLError as error:
            raise self.fail(node, f'{what}: bad value: {error}') from None
        except (ValueError, OverflowError) as error:
            raise self.fail(node, f'{what}: bad value {_cut(node.value)}: {error}') from None

    def value(self, node: yaml.Node, what: str) -> object:
        self.visit(node)
        return self.scalar(node, what)

    def integer(
        self, node: yaml.Node, what: str, minimum: int = 0, maximum: int = MAX_INTEGER
    ) -> int:
        value = self.value(node, what)
        if isinstance(value, bool) or not isinstance(value, int):
            raise self.fail(node, f'{what} must be an integer, got {_cut(repr(value))}')
        if value < minimum:
            raise self.fail(node, f'{what} must be >= {minimum}, got {value}')
        if value > maximum:
            raise self.fail(node, f'{what} must be <= {maximum}, got {value}')
        return value

    def number(self, node: yaml.Node, what: str) -> float:
        value = self.value(node, what)
        if isinstance(value, bool) or not isinstance(value, (int, float)):
            raise self.fail(node, f'{what} must be a number, got {_cut(repr(value))}')
        try:
            number = float(value)
        except OverflowError:
            number = math.inf
        if not math.isfinite(number):
            raise self.fail(node, f'{what} must be finite, got {value!r}')
        return number

    def vector(self, node: yaml.Node, what: str, length: int) -> tuple[float, ...]:
        self.visit(node)
        if not isinstance(node, yaml.SequenceNode):
            raise self.fail(node, f'{what} must be a list of {length} numbers')
        if len(node.value) != length:
            raise self.fail(node, f'{what} must have {length} numbers, got {len(node.value)}')
        return tuple(
            self.number(item, f'{what}[{index}]') for index, item in enumerate(node.value)
        )

    def frame_id(self, node: yaml.Node, what: str) -> str:
        value = self.value(node, what)
        if not isinstance(value, str):
            raise self.fail(node, f'{what} must be a string, got {_cut(repr(value))}')
        if not value:
            raise self.fail(node, f'{what} must not be empty')
        if len(value) > MAX_FRAME_ID_LENGTH:
            raise self.fail(node, f'{what} is longer than {MAX_FRAME_ID_LENGTH} characters')
        if any(ord(c) < 32 or ord(c) == 127 for c in value):
            raise self.fail(node, f'{what} {_cut(repr(value))} contains control characters')
        return value

    def stamp(self, node: yaml.Node, what: str) -> int:
        fields = self.mapping(node, what, ('sec', 'nanosec'))
        for key in ('sec', 'nanosec'):
            if key not in fields:
                raise self.fail(node, f'{what} needs {key}')
        seconds = self.integer(fields['sec'], f'{what}.sec', minimum=-(2**31))
        nanoseconds = self.integer(fields['nanosec'], f'{what}.nanosec')
        if seconds >= 2**31 or nanoseconds >= 1_000_000_000:
            raise self.fail(node, f'{what} is out of range (sec < 2^31, nanosec < 10^9)')
        return seconds * 1_000_000_000 + nanoseconds


def _entry(reader: _Reader, node: yaml.Node, index: int) -> SnapshotTransform:
    what = f'transforms[{index}]'
    fields = reader.mapping(node, what, ENTRY_KEYS)
    for key in _REQUIRED_ENTRY_KEYS:
        if key not in fields:
            raise reader.fail(node, f'{what} has no {key!r}')
    parent = reader.frame_id(fields['parent'], f'{what}.parent')
    child = reader.frame_id(fields['child'], f'{what}.child')
    if parent == child:
        raise reader.fail(fields['child'], f'{what}: frame {child!r} cannot be its own parent')
    translation = reader.vector(fields['translation'], f'{what}.translation', 3)
    rotation = reader.vector(fields['rotation'], f'{what}.rotation', 4)
    norm_squared = sum(c * c for c in rotation)
    if abs(norm_squared - 1.0) > 0.01:
        raise reader.fail(
            fields['rotation'],
            f'{what}.rotation {list(rotation)} is not a unit quaternion (x y z w); '
            f'|q|^2 = {norm_squared:.6g}',
        )
    is_static = True
    if 'static' in fields:
        flag = reader.value(fields['static'], f'{what}.static')
        if not isinstance(flag, bool):
            raise reader.fail(fields['static'], f'{what}.static must be true or false')
        is_static = flag
    stamp_ns = reader.stamp(fields['stamp'], f'{what}.stamp') if 'stamp' in fields else None
    authority = None
    if 'authority' in fields:
        authority_value = reader.value(fields['authority'], f'{what}.authority')
        if not isinstance(authority_value, str) or len(authority_value) > MAX_FRAME_ID_LENGTH:
            raise reader.fail(fields['authority'], f'{what}.authority must be a short string')
        authority = authority_value
    rate_hz = None
    if 'rate_hz' in fields:
        rate_hz = reader.number(fields['rate_hz'], f'{what}.rate_hz')
        if rate_hz < 0:
            raise reader.fail(fields['rate_hz'], f'{what}.rate_hz must be >= 0')
    sample_count = None
    if 'sample_count' in fields:
        sample_count = reader.integer(fields['sample_count'], f'{what}.sample_count')
    return SnapshotTransform(
        parent=parent,
        child=child,
        translation=(translation[0], translation[1], translation[2]),
        rotation=(rotation[0], rotation[1], rotation[2], rotation[3]),
        is_static=is_static,
        stamp_ns=stamp_ns,
        authority=authority,
        rate_hz=rate_hz,
        sample_count=sample_count,
    )


def find_cycle(edges: Iterable[tuple[str, str]]) -> list[str] | None:
    """Find a parent-link cycle among (parent, child) edges, as [a, b, ..., a], or None."""
    parent_of = {child: parent for parent, child in edges}
    finished: set[str] = set()
    for start in parent_of:
        path: list[str] = []
        on_path: set[str] = set()
        frame: str | None = start
        while frame is not None and frame not in finished:
            if frame in on_path:
                return [*path[path.index(frame) :], frame]
            path.append(frame)
            on_path.add(frame)
            frame = parent_of.get(frame)
        finished.update(path)
    return None


# libyaml's loader when PyYAML has it (about 6x faster); both are safe loaders. The nesting check
# runs first because the composers recurse (libyaml's in C, without Python's recursion limit).
_LOADER: type[yaml.SafeLoader | yaml.CSafeLoader] = getattr(yaml, 'CSafeLoader', yaml.SafeLoader)
_OPENING_TOKENS = (
    yaml.BlockMappingStartToken,
    yaml.BlockSequenceStartToken,
    yaml.FlowMappingStartToken,
    yaml.FlowSequenceStartToken,
)
_CLOSING_TOKENS = (yaml.BlockEndToken, yaml.FlowMappingEndToken, yaml.FlowSequenceEndToken)


def _check_nesting(text: str, source: str) -> None:
    """Refuse nesting deeper than :data:`MAX_NESTING` before the (recursive) composer runs."""
    deep = yaml_flow_too_deep(text, MAX_NESTING)
    if deep is not None:
        raise SnapshotError(f'{source}:{deep}: nesting is deeper than {MAX_NESTING} levels')
    depth = 0
    for token in yaml.scan(text, Loader=_LOADER):
        if isinstance(token, _OPENING_TOKENS):
            depth += 1
            if depth > MAX_NESTING:
                line = token.start_mark.line + 1
                msg = f'{source}:{line}: nesting is deeper than {MAX_NESTING} levels'
                raise SnapshotError(msg)
        elif isinstance(token, _CLOSING_TOKENS):
            depth -= 1


def parse_snapshot(text: str, source: str = '<snapshot>') -> Snapshot:
    """Parse and validate snapshot ``text``; :class:`SnapshotError` names line and problem."""
    try:
        size = len(text.encode('utf-8'))
    except UnicodeEncodeError as error:  # only a str made in Python: a file decodes strictly
        bad_line = text.count('\n', 0, error.start) + 1
        raise SnapshotError(f'{source}:{bad_line}: not UTF-8 text (a lone surrogate)') from None
    if size > MAX_FILE_BYTES:
        raise SnapshotError(f'{source}: file is larger than {MAX_FILE_BYTES} bytes')
    try:
        _check_nesting(text, source)
        root = yaml.compose(text, Loader=_LOADER)
    except RecursionError:
        raise SnapshotError(f'{source}: nesting is too deep') from None
    except yaml.MarkedYAMLError as error:
        mark = error.problem_mark or error.context_mark
        line = f':{mark.line + 1}' if mark is not None else ''
        problem = error.problem or error.context or 'malformed'
        raise SnapshotError(f'{source}{line}: not valid YAML ({problem})') from None
    except yaml.YAMLError as error:
        raise SnapshotError(f'{source}: not valid YAML ({error})') from None
    reader = _Reader(source)
    if root is None:
        raise reader.fail(None, f'empty file (expected a mapping starting with {SCHEMA_KEY}: 1)')
    top = reader.mapping(root, 'the file', TOP_KEYS)
    if SCHEMA_KEY not in top:
        raise reader.fail(root, f'not a tf_demo snapshot: missing {SCHEMA_KEY!r}')
    version = reader.integer(top[SCHEMA_KEY], SCHEMA_KEY)
    if version != SCHEMA_VERSION:
        raise reader.fail(
            top[SCHEMA_KEY],
            f'unsupported schema version {version} (this tool reads version {SCHEMA_VERSION})',
        )
    recorded_at = reader.stamp(top['recorded_at'], 'recorded_at') if 'recorded_at' in top else None
    for key in ('transform_count', 'transforms'):
        if key not in top:
            raise reader.fail(root, f'missing {key!r} (is the file truncated?)')
    count = reader.integer(top['transform_count'], 'transform_count')
    if count > MAX_TRANSFORMS:
        raise reader.fail(top['transform_count'], f'more than {MAX_TRANSFORMS} transforms')
    list_node = top['transforms']
    reader.visit(list_node)
    if not isinstance(list_node, yaml.SequenceNode):
        raise reader.fail(list_node, 'transforms must be a list')
    if len(list_node.value) > MAX_TRANSFORMS:
        raise reader.fail(list_node, f'more than {MAX_TRANSFORMS} transforms')
    entries: list[SnapshotTransform] = []
    child_line: dict[str, int] = {}
    for index, node in enumerate(list_node.value):
        entry = _entry(reader, node, index)
        if entry.child in child_line:
            raise reader.fail(
                node,
                f'frame {entry.child!r} appears twice as a child '
                f'(first on line {child_line[entry.child]}); a frame has exactly one parent',
            )
        child_line[entry.child] = node.start_mark.line + 1
        entries.append(entry)
    if count != len(entries):
        raise reader.fail(
            top['transform_count'],
            f'transform_count says {count} but the file has {len(entries)} transforms '
            '(is the file truncated?)',
        )
    cycle = find_cycle((e.parent, e.child) for e in entries)
    if cycle is not None:
        loop_line = child_line[cycle[0]]
        raise SnapshotError(
            f'{source}:{loop_line}: the parent links form a loop: {" -> ".join(cycle)}'
        )
    return Snapshot(transforms=tuple(entries), recorded_at_ns=recorded_at, version=version)


def read_snapshot(path: str | os.PathLike[str]) -> Snapshot:
    """Read and validate the snapshot file at ``path`` (see :func:`parse_snapshot`)."""
    source = os.fspath(path)
    try:
        text = read_text_file(source, MAX_FILE_BYTES)
    except InputFileError as error:
        raise SnapshotError(str(error)) from None
    return parse_snapshot(text, source)


def frames_yaml_data(snapshot: Snapshot) -> dict[str, dict[str, object]]:
    """Convert the snapshot to the YAML-parsed ``all_frames_as_yaml`` map view_frames draws."""
    data: dict[str, dict[str, object]] = {}
    for entry in snapshot.transforms:
        stamp = 0.0 if entry.is_static or entry.stamp_ns is None else entry.stamp_ns / 1e9
        rate = 10000.0 if entry.is_static else round(entry.rate_hz or 0.0, 3)
        data[entry.child] = {
            'parent': entry.parent,
            'broadcaster': entry.authority or 'snapshot',
            'rate': rate,
            'most_recent_transform': stamp,
            'oldest_transform': stamp,
            'buffer_length': 0.0,
        }
    return data
