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
YAML read as an event stream, as rcl reads ``-p`` values and params files (rcl's ``parse.c``).

Nothing is constructed, so an alias is never expanded and nesting never recurses; collections
deeper than :data:`MAX_YAML_NESTING` are refused. The events come from libyaml where PyYAML has
it (rcl's own parser), else from :class:`PureYamlEventLoader`, which takes tabs as libyaml does.
:func:`parse_param_value` types one ``-p`` value; :mod:`tf_demo.transport.params_file` reads a
params file from the same events.
"""

from __future__ import annotations

from collections.abc import Callable
from collections.abc import Iterator
from typing import Protocol

from tf_demo.core.files import yaml_flow_too_deep
from tf_demo.transport.params_typing import ParamValue
from tf_demo.transport.params_typing import rcl_scalar
from tf_demo.transport.params_typing import RuleError
from tf_demo.transport.params_typing import Scalar
from tf_demo.transport.params_typing import Variant
import yaml

__all__ = [
    'LIBYAML_AVAILABLE',
    'MAX_YAML_NESTING',
    'QUOTED_STYLES',
    'YAML_EVENT_LOADER',
    'EventLoader',
    'EventParser',
    'LineError',
    'PureYamlEventLoader',
    'event_line',
    'event_scalar',
    'parse_param_value',
    'shorten',
    'too_deep',
    'yaml_events',
]

#: The deepest nesting of YAML collections a ``-p`` value or a params file may have. rcl has no
#: limit of its own; real params files nest a handful of levels.
MAX_YAML_NESTING = 64

#: Whether PyYAML has libyaml, the scanner rcl parses with (``yaml.CSafeLoader``).
LIBYAML_AVAILABLE = hasattr(yaml, 'CSafeLoader')

#: The styles of a quoted scalar (always a string for rcl).
QUOTED_STYLES = frozenset({"'", '"'})
_STR_TAG = 'tag:yaml.org,2002:str'
_BREAKS = '\r\n\x85\u2028\u2029'


class _TabTolerantScanner(yaml.reader.Reader, yaml.scanner.Scanner):
    """
    PyYAML's pure scanner, taking tabs between the lines of a plain scalar as libyaml does.

    PyYAML refuses every tab there; libyaml (rcl's parser) takes blanks of either kind and
    refuses only a tab left of the scalar's indentation. A URDF given with ``-p`` is one plain
    scalar, and real URDFs have tab-indented lines (panda.urdf). Between tokens, a tab is a
    blank inside flow collections and after a key or value, as in libyaml.
    """

    def scan_plain_spaces(self, indent: int, start_mark: yaml.Mark) -> list[str] | None:
        length = 0
        while self.peek(length) in ' \t':
            length += 1
        blanks = self.prefix(length)
        self.forward(length)
        if self.peek() not in _BREAKS:
            return [blanks] if blanks else []
        first_break = self._line_break()
        self.allow_simple_key = True
        if self._at_document_marker():
            return None
        breaks: list[str] = []
        while self.peek() in ' \t' + _BREAKS:
            character = self.peek()
            if character == ' ':
                self.forward()
            elif character == '\t':
                if self.column < indent:
                    raise yaml.scanner.ScannerError(
                        'while scanning a plain scalar',
                        start_mark,
                        'found a tab character that violates indentation',
                        self.get_mark(),
                    )
                self.forward()
            else:
                breaks.append(self._line_break())
                if self._at_document_marker():
                    return None
        if first_break != '\n':
            return [first_break, *breaks]
        return breaks or [' ']

    def scan_to_next_token(self) -> None:
        """Skip blanks, comments and breaks; a tab counts as a blank where libyaml counts it."""
        if self.index == 0 and self.peek() == '\ufeff':
            self.forward()
        while True:
            while self.peek() == ' ' or (
                self.peek() == '\t' and (self.flow_level or not self.allow_simple_key)
            ):
                self.forward()
            if self.peek() == '#':
                while self.peek() not in '\0' + _BREAKS:
                    self.forward()
            if not self._line_break():
                return
            if not self.flow_level:
                self.allow_simple_key = True

    def _line_break(self) -> str:
        return str(self.scan_line_break())  # type: ignore[no-untyped-call]

    def _at_document_marker(self) -> bool:
        return self.prefix(3) in ('---', '...') and self.peek(3) in '\0 \t' + _BREAKS


class PureYamlEventLoader(_TabTolerantScanner, yaml.parser.Parser):
    """PyYAML's pure-Python reader and parser with :class:`_TabTolerantScanner`: events only."""

    def __init__(self, stream: str) -> None:
        yaml.reader.Reader.__init__(self, stream)
        yaml.scanner.Scanner.__init__(self)
        yaml.parser.Parser.__init__(self)


class EventParser(Protocol):
    """A YAML event parser as PyYAML's loaders are (``yaml.CSafeLoader``, the pure one)."""

    def check_event(self) -> bool:
        """Whether another event follows."""

    def get_event(self) -> yaml.Event | None:
        """Return the next event."""

    def dispose(self) -> None:
        """Release the parser's state."""


EventLoader = Callable[[str], EventParser]
"""A YAML event parser class, built from the text (what ``yaml.parse`` takes as ``Loader``)."""

#: The event parser: libyaml where PyYAML has it (rcl's own), else the pure one above.
YAML_EVENT_LOADER: EventLoader = getattr(yaml, 'CSafeLoader', PureYamlEventLoader)


class LineError(RuleError):
    """A problem at one line of a YAML text (a params file names its path before the line)."""

    def __init__(self, line: int, reason: str) -> None:
        super().__init__(f'line {line}: {reason}')
        self.line = line
        self.reason = reason


def yaml_events(text: str, loader: EventLoader) -> Iterator[yaml.Event]:
    """
    Yield the YAML events of ``text``; a syntax error becomes a one-line :class:`LineError`.

    Flow collections nested deeper than :data:`MAX_YAML_NESTING` are refused before parsing.
    """
    deep = yaml_flow_too_deep(text, MAX_YAML_NESTING)
    if deep is not None:
        raise too_deep(deep)
    try:
        parser = loader(text)
        try:
            while parser.check_event():
                event = parser.get_event()
                assert event is not None
                yield event
        finally:
            parser.dispose()
    except yaml.YAMLError as error:
        raise _line_error(error) from None


def _line_error(error: yaml.YAMLError) -> LineError:
    """Word a YAML syntax error on one line, with its line and column."""
    mark = getattr(error, 'problem_mark', None) or getattr(error, 'context_mark', None)
    problem = getattr(error, 'problem', None) or str(error).splitlines()[0]
    if mark is None:
        return LineError(1, f'invalid YAML: {problem}')
    return LineError(mark.line + 1, f'invalid YAML (column {mark.column + 1}): {problem}')


def event_line(event: yaml.Event) -> int:
    """Return the 1-based line an event starts on (0 when unknown)."""
    mark = event.start_mark
    return mark.line + 1 if mark is not None else 0


def event_scalar(event: yaml.ScalarEvent) -> Scalar:
    """Type a scalar event as rcl does (quoted or ``!!str`` stays a string)."""
    return rcl_scalar(
        event.value, quoted=event.style in QUOTED_STYLES, str_tag=event.tag == _STR_TAG
    )


def too_deep(line: int) -> LineError:
    """Return the error for nesting deeper than :data:`MAX_YAML_NESTING` at ``line``."""
    return LineError(line, f'nesting deeper than {MAX_YAML_NESTING} levels')


def parse_param_value(text: str, *, loader: EventLoader | None = None) -> ParamValue:
    """
    Type a ``-p`` value as rcl does: bool, int, double, string or a homogeneous array.

    :param loader: the YAML event parser (default :data:`YAML_EVENT_LOADER`, libyaml).
    :raises ValueError: for a value rcl refuses (empty, a mapping, an alias, a mixed array,
        invalid YAML), for no value at all (``[]``, only a comment), or nesting deeper than
        :data:`MAX_YAML_NESTING`.
    """
    if not text:
        msg = "empty value (write '' for an empty string)"
        raise RuleError(msg)
    variant = Variant()
    depth = 0
    in_sequence = False
    for event in yaml_events(text, YAML_EVENT_LOADER if loader is None else loader):
        if isinstance(event, yaml.ScalarEvent):
            if not event.value and event.style not in QUOTED_STYLES:
                msg = f'No value at line {event_line(event)}'
                raise RuleError(msg)
            variant.add(event_scalar(event), in_sequence, event_line(event))
        elif isinstance(event, yaml.SequenceStartEvent):
            depth += 1
            if depth > MAX_YAML_NESTING:
                raise too_deep(event_line(event))
            in_sequence = True
            variant.start_sequence()
        elif isinstance(event, yaml.SequenceEndEvent):
            depth -= 1
            in_sequence = False  # as rcl: an inner sequence's end ends the array
        elif isinstance(event, yaml.MappingStartEvent):
            msg = 'a mapping is not a parameter value (nested names belong in a --params-file)'
            raise RuleError(msg)
        elif isinstance(event, yaml.AliasEvent):
            msg = 'an alias (*name) is not a parameter value'
            raise RuleError(msg)
    value = variant.value()
    if value is None:
        msg = f'no value in {shorten(text)!r}: the parameter type cannot be determined'
        raise RuleError(msg)
    return value


def shorten(text: str, limit: int = 60) -> str:
    """Return ``text`` as it is, or on one line its start and length when long (a URDF)."""
    if len(text) <= limit and '\n' not in text:
        return text
    start = text[:limit].replace('\r', '\\r').replace('\n', '\\n').replace('\t', '\\t')
    return f'{start}... ({len(text)} characters)'
