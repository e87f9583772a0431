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
``--params-file``: rcl's params-file schema, read from YAML events (rcl's ``parse_file_events``).

``<node key>: {ros__parameters: {...}}``, where the key is ``/**``, a node name, a fully
qualified name or a wildcard pattern (``*`` one token, ``**`` any number of tokens); nested
mappings above ``ros__parameters`` are namespaces and nested mappings below it dotted parameter
names. The file is read through :func:`tf_demo.core.files.read_text_file` (a regular file,
bounded, UTF-8 with the bad line named).
"""

from __future__ import annotations

from collections.abc import Iterator
from dataclasses import dataclass
from dataclasses import field
import re

from tf_demo.core.files import InputFileError
from tf_demo.core.files import read_text_file
from tf_demo.transport.params_typing import ParamValue
from tf_demo.transport.params_typing import RuleError
from tf_demo.transport.params_typing import Scalar
from tf_demo.transport.params_typing import Variant
from tf_demo.transport.params_yaml import event_line
from tf_demo.transport.params_yaml import event_scalar
from tf_demo.transport.params_yaml import LineError
from tf_demo.transport.params_yaml import MAX_YAML_NESTING
from tf_demo.transport.params_yaml import QUOTED_STYLES
from tf_demo.transport.params_yaml import too_deep
from tf_demo.transport.params_yaml import YAML_EVENT_LOADER
from tf_demo.transport.params_yaml import yaml_events
import yaml

__all__ = ['Entries', 'ParamsFile', 'node_key_matches', 'params_file_entries', 'read_params_file']

Entries = list[tuple[str, tuple[tuple[str, ParamValue], ...]]]
"""Each node key of a file with its flattened parameters, in file order."""


@dataclass(frozen=True)
class ParamsFile:
    """One ``--params-file``: its node keys and flattened parameters, in file order."""

    path: str
    entries: tuple[tuple[str, tuple[tuple[str, ParamValue], ...]], ...]


def read_params_file(path: str) -> ParamsFile:
    """
    Read a params file as rcl reads it.

    :raises RuleError: for a file that cannot be read, or YAML rcl refuses, with
        ``path:line: reason``.
    """
    try:
        text = read_text_file(path)
    except InputFileError as error:
        raise RuleError(str(error)) from None
    try:
        entries = params_file_entries(yaml_events(text, YAML_EVENT_LOADER))
    except LineError as error:
        msg = f'{path}:{error.line}: {error.reason}'
        raise RuleError(msg) from None
    return ParamsFile(path=path, entries=tuple(entries))


def node_key_matches(key: str, node_fqn: str) -> bool:
    """Whether a params-file node key (``/**``, ``name``, ``/ns/name``, wildcards) names it."""
    normalized = key if key.startswith('/') else '/' + key
    if normalized == node_fqn:
        return True
    if '*' not in normalized:
        return False
    pattern = ''
    index = 0
    while index < len(normalized):
        if normalized.startswith('/**', index):
            pattern += r'(/[A-Za-z0-9_]+)*'
            index += 3
        elif normalized[index] == '*':
            pattern += r'[A-Za-z0-9_]*'
            index += 1
        else:
            pattern += re.escape(normalized[index])
            index += 1
    return re.fullmatch(pattern, node_fqn) is not None


@dataclass
class _Frame:
    """One open YAML collection of a params file, with what its contents mean."""

    role: str  # 'nodes' (node names), 'params' (parameter names) or 'array' (a list value)
    names: tuple[str, ...] = ()  # the node name parts of a 'nodes' frame
    node_key: str = ''
    prefix: str = ''  # 'a.b.' inside a parameter namespace; the name itself for an 'array'
    key: str | None = None  # a mapping's key waiting for its value
    out: list[tuple[str, ParamValue]] = field(default_factory=list)
    variant: Variant | None = None


_DOCUMENT_EVENTS = (
    yaml.StreamStartEvent,
    yaml.StreamEndEvent,
    yaml.DocumentStartEvent,
    yaml.DocumentEndEvent,
)


def params_file_entries(events: Iterator[yaml.Event]) -> Entries:
    """
    Read rcl's params-file schema from YAML events, iteratively.

    ``<node key>: {ros__parameters: {...}}``; mappings above ``ros__parameters`` are
    namespaces, mappings below it dotted parameter names. As rcl: aliases, nested lists and a
    parameter without a value are refused; tags are ignored but ``!!str``.

    :raises LineError: for what rcl refuses, with the line.
    """
    entries: Entries = []
    stack: list[_Frame] = []
    for event in events:
        if isinstance(event, _DOCUMENT_EVENTS):
            continue
        line = event_line(event)
        if isinstance(event, yaml.AliasEvent):
            msg = 'aliases (*name) are not supported, as in rcl'
            raise LineError(line, msg)
        if not stack:
            _open_document(event, stack, line)
            continue
        frame = stack[-1]
        if isinstance(event, (yaml.MappingEndEvent, yaml.SequenceEndEvent)):
            _close(stack.pop(), stack, entries, line)
        elif frame.role == 'array':
            _array_item(event, frame, line)
        elif frame.key is None:
            if not isinstance(event, yaml.ScalarEvent) or not event.value:
                msg = 'a key must be a non-empty name'
                raise LineError(line, msg)
            frame.key = event.value
        else:
            child = (
                _node_value(event, frame, line)
                if frame.role == 'nodes'
                else _parameter_value(event, frame)
            )
            frame.key = None
            if child is not None:
                if len(stack) >= MAX_YAML_NESTING:
                    raise too_deep(line)
                stack.append(child)
    return entries


def _open_document(event: yaml.Event, stack: list[_Frame], line: int) -> None:
    if isinstance(event, yaml.MappingStartEvent):
        stack.append(_Frame('nodes'))
    elif not (isinstance(event, yaml.ScalarEvent) and not event.value and not event.style):
        msg = 'the top level must be a mapping of node names'
        raise LineError(line, msg)  # an empty document (a plain empty scalar) is nothing


def _close(frame: _Frame, stack: list[_Frame], entries: Entries, line: int) -> None:
    if frame.role == 'array':
        assert frame.variant is not None
        value = frame.variant.value()
        if value is None:
            msg = f"parameter '{frame.prefix}': empty array: the element type cannot be determined"
            raise LineError(line, msg)
        frame.out.append((frame.prefix, value))
    elif frame.role == 'params' and stack[-1].role != 'params':
        entries.append((frame.node_key, tuple(frame.out)))


def _file_scalar(event: yaml.ScalarEvent, name: str) -> Scalar:
    if not event.value and event.style not in QUOTED_STYLES:
        raise LineError(event_line(event), f"parameter '{name}' has no value")
    return event_scalar(event)


def _array_item(event: yaml.Event, frame: _Frame, line: int) -> None:
    if not isinstance(event, yaml.ScalarEvent):
        msg = (
            f"parameter '{frame.prefix}': a list or mapping inside a list is not a parameter value"
        )
        raise LineError(line, msg)
    assert frame.variant is not None
    try:
        frame.variant.add(_file_scalar(event, frame.prefix), True, line)
    except RuleError as error:
        raise LineError(line, f"parameter '{frame.prefix}': {error}") from None


def _node_value(event: yaml.Event, frame: _Frame, line: int) -> _Frame | None:
    """Read the value of a key above ``ros__parameters``: a node name part or the parameters."""
    key = frame.key
    assert key is not None
    if key == 'ros__parameters':
        if not frame.names:
            msg = "'ros__parameters' must be inside a node name"
            raise LineError(line, msg)
        node_key = '/' + '/'.join(part.strip('/') for part in frame.names)
        if not isinstance(event, yaml.MappingStartEvent):
            msg = f"'ros__parameters' of '{node_key}' must be a mapping"
            raise LineError(line, msg)
        return _Frame('params', node_key=node_key)
    if not isinstance(event, yaml.MappingStartEvent):
        where = '/'.join([*frame.names, key])
        msg = f"'{where}' is not a node name: expected a mapping with 'ros__parameters'"
        raise LineError(line, msg)
    return _Frame('nodes', names=(*frame.names, key))


def _parameter_value(event: yaml.Event, frame: _Frame) -> _Frame | None:
    """Read the value of a key below ``ros__parameters``: a value, a list or a namespace."""
    name = f'{frame.prefix}{frame.key}'
    if isinstance(event, yaml.ScalarEvent):
        frame.out.append((name, _file_scalar(event, name)))
        return None
    if isinstance(event, yaml.SequenceStartEvent):
        return _Frame('array', prefix=name, out=frame.out, variant=Variant())
    return _Frame('params', node_key=frame.node_key, prefix=f'{name}.', out=frame.out)
