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
The ``--ros-args`` command line, parsed as rcl parses it (``rcl/src/rcl/arguments.c``).

Arguments between ``--ros-args`` and ``--`` (or the end) are ROS arguments; everything else is
returned unchanged as the user's arguments; :func:`split_ros_args` is the package's one splitter
(the tools and nodes call it). Understood inside a ``--ros-args`` section:

* ``-p``/``--param [node:]name:=value``: a parameter override, typed by rcl's own YAML rules
  (``rcl_yaml_param_parser``, see :func:`rcl_scalar`): ``true``/``y``/``on`` are bools, what
  ``strtoll`` reads whole an int (``0x1F``, ``010``), what ``strtod`` reads whole a double
  (``1e3``, ``inf``, ``nan``), anything else or quoted a string (``1_000``, ``0b11``, ``'1'``);
  ``[1, 2]`` is an int array.
* ``--params-file file.yaml``: rcl's schema, ``<node key>: {ros__parameters: {...}}`` where the
  key is ``/**``, a node name, a fully qualified name or a wildcard pattern (``*`` one token,
  ``**`` any number of tokens); nested mappings above ``ros__parameters`` are namespaces and
  nested mappings below it are dotted parameter names.
* ``-r``/``--remap [node:]from:=to``, including ``__node:=``/``__name:=`` and ``__ns:=``.
* ``--log-level [logger:=]level``, ``--log-config-file``, ``-e``/``--enclave``, and the
  ``--enable-``/``--disable-`` ``stdout-logs``/``rosout-logs``/``external-lib-logs`` flags.

Later sources of a parameter override earlier ones, in command-line order, as rcl merges them.
YAML is read as events (libyaml, as rcl; else a pure scanner that takes tabs as libyaml does),
never constructed: aliases are refused as rcl refuses them and nesting deeper than
:data:`MAX_YAML_NESTING` is refused. Errors raise :class:`RosArgsError` with rcl's texts (a long
value shortened, advice for a URDF given with ``-p``); ``run_node`` prints them on one line.
In the rclpy world rcl parses the arguments itself (:func:`explain_rcl_error` words its refusal).
"""

from __future__ import annotations

from collections.abc import Iterator
from collections.abc import Sequence
from dataclasses import dataclass
from dataclasses import field
import decimal
import itertools
import math
import re
import sys
from typing import Any

from tf_demo.core.files import InputFileError
from tf_demo.core.files import read_text_file
from tf_demo.transport.logging import LoggingSeverity
from tf_demo.transport.parameters import Parameter
import yaml

__all__ = [
    'LIBYAML_AVAILABLE',
    'MAX_YAML_NESTING',
    'ROS_ARGS_FLAG',
    'ROS_ARGS_USAGE',
    'YAML_EVENT_LOADER',
    'NodeArguments',
    'ParamRule',
    'ParamsFile',
    'PureYamlEventLoader',
    'RemapRule',
    'RosArgs',
    'RosArgsError',
    'expand_topic_name',
    'explain_rcl_error',
    'parse_param_value',
    'parse_ros_args',
    'rcl_scalar',
    'remove_ros_args',
    'resolve_node_arguments',
    'split_ros_args',
]

ROS_ARGS_FLAG = '--ros-args'
ROS_ARGS_END = '--'
_PARAM_FLAGS = ('-p', '--param')
_REMAP_FLAGS = ('-r', '--remap')
_PARAMS_FILE_FLAG = '--params-file'
_LOG_LEVEL_FLAG = '--log-level'
_LOG_CONFIG_FLAG = '--log-config-file'
_ENCLAVE_FLAGS = ('-e', '--enclave')
_LOG_SWITCHES = frozenset(
    f'--{state}-{what}-logs'
    for state in ('enable', 'disable')
    for what in ('stdout', 'rosout', 'external-lib')
)
_VALUE_FLAGS = frozenset(
    (
        *_PARAM_FLAGS,
        *_REMAP_FLAGS,
        *_ENCLAVE_FLAGS,
        _PARAMS_FILE_FLAG,
        _LOG_LEVEL_FLAG,
        _LOG_CONFIG_FLAG,
    )
)

ROS_ARGS_USAGE = (
    'usage: <executable> [arguments] --ros-args [-p [node:]name:=value] '
    '[--params-file FILE] [-r [node:]from:=to] [--log-level [logger:=]level] '
    '[-e ENCLAVE] [--]'
)

_TOKEN = re.compile(r'[A-Za-z_][A-Za-z0-9_]*')
_NODE_TOKEN = re.compile(r'[A-Za-z0-9_]+')
# rcl: name tokens (runs of tokens and '/') joined by '.', e.g. qos_overrides./tf.publisher.depth
_PARAM_NAME_TOKEN = r'(?:[A-Za-z_][A-Za-z0-9_]*|/)+'
_PARAM_NAME = re.compile(rf'{_PARAM_NAME_TOKEN}(?:\.{_PARAM_NAME_TOKEN})*')


class RosArgsError(ValueError):
    """A ``--ros-args`` argument that rcl would reject; the text says which and why."""


@dataclass(frozen=True)
class ParamRule:
    """One ``-p [node:]name:=value``."""

    node: str | None
    name: str
    value: Any


@dataclass(frozen=True)
class ParamsFile:
    """One ``--params-file``: its node keys and flattened parameters, in file order."""

    path: str
    entries: tuple[tuple[str, tuple[tuple[str, Any], ...]], ...]


@dataclass(frozen=True)
class RemapRule:
    """One ``-r [node:]from:=to``; ``kind`` is ``topic``, ``node`` or ``namespace``."""

    node: str | None
    kind: str
    match: str | None
    replacement: str


@dataclass(frozen=True)
class RosArgs:
    """The parsed command line: the user's arguments and the ROS arguments, in order."""

    user_args: tuple[str, ...] = ()
    parameter_sources: tuple[ParamRule | ParamsFile, ...] = ()
    remap_rules: tuple[RemapRule, ...] = ()
    log_levels: tuple[tuple[str | None, LoggingSeverity], ...] = ()
    log_config_file: str | None = None
    enclave: str | None = None
    log_switches: tuple[str, ...] = ()
    params_files: tuple[str, ...] = field(default=())

    def node_name(self, default: str) -> str:
        """Return the node's name after ``__node:=`` rules (the first matching rule wins)."""
        for rule in self.remap_rules:
            if rule.kind == 'node' and rule.node in (None, default):
                return rule.replacement
        return default

    def namespace(self, default: str, node_name: str) -> str:
        """Return the node's namespace after ``__ns:=`` rules (``node_name`` is the original)."""
        for rule in self.remap_rules:
            if rule.kind == 'namespace' and rule.node in (None, node_name):
                return rule.replacement
        return default

    def parameter_overrides(self, node_fqn: str) -> dict[str, Parameter]:
        """Return the overrides that apply to the node ``node_fqn`` (later sources win)."""
        overrides: dict[str, Parameter] = {}
        for source in self.parameter_sources:
            if isinstance(source, ParamRule):
                # A node prefix is a node key as in a params file (``talker`` is ``/talker``).
                if source.node is None or _node_key_matches(source.node, node_fqn):
                    overrides[source.name] = Parameter(source.name, value=source.value)
                continue
            for key, values in source.entries:
                if _node_key_matches(key, node_fqn):
                    for name, value in values:
                        overrides[name] = Parameter(name, value=value)
        return overrides

    def log_level_for(self, logger_name: str) -> LoggingSeverity | None:
        """Return the ``--log-level`` that applies to ``logger_name`` (named rule first)."""
        default: LoggingSeverity | None = None
        named: LoggingSeverity | None = None
        for name, level in self.log_levels:
            if name is None:
                default = level
            elif name == logger_name:
                named = level
        return named if named is not None else default

    def remap_topic(self, expanded_topic: str, node_name: str, namespace: str) -> str:
        """Apply the first matching ``-r`` topic rule to an already expanded topic name."""
        for rule in self.remap_rules:
            if rule.kind != 'topic' or rule.node not in (None, node_name):
                continue
            assert rule.match is not None
            if expand_topic_name(rule.match, node_name, namespace) == expanded_topic:
                return expand_topic_name(rule.replacement, node_name, namespace)
        return expanded_topic


@dataclass(frozen=True)
class NodeArguments:
    """What the command line says about one node (what a standalone node is built from)."""

    node_name: str
    namespace: str
    parameter_overrides: dict[str, Parameter]
    log_level: LoggingSeverity | None
    arguments: RosArgs

    def remap_topic(self, expanded_topic: str, node_name: str, namespace: str) -> str:
        """Apply the ``-r`` topic rules to an expanded topic name (see RosArgs.remap_topic)."""
        return self.arguments.remap_topic(expanded_topic, node_name, namespace)


def resolve_node_arguments(args: Sequence[str], node_name: str, namespace: str) -> NodeArguments:
    """
    Resolve a node's name, namespace, overrides and log level from its argument list.

    :param args: the global ``init`` arguments followed by the node's ``cli_args``.
    :param node_name: the name the node's code asks for.
    :param namespace: the namespace the node's code asks for (``''`` for the root).
    :raises RosArgsError: for bad ROS arguments.
    """
    parsed = parse_ros_args(args)
    name = parsed.node_name(node_name)
    resolved_namespace = parsed.namespace(namespace, node_name)
    absolute = (
        resolved_namespace if resolved_namespace.startswith('/') else '/' + resolved_namespace
    )
    fqn = absolute.rstrip('/') + '/' + name
    logger_name = fqn.lstrip('/').replace('/', '.')
    return NodeArguments(
        node_name=name,
        namespace=resolved_namespace,
        parameter_overrides=parsed.parameter_overrides(fqn),
        log_level=parsed.log_level_for(logger_name),
        arguments=parsed,
    )


def parse_ros_args(argv: Sequence[str]) -> RosArgs:
    """
    Split ``argv`` into the user's arguments and parsed ROS arguments.

    :raises RosArgsError: with rcl's text for a flag without its value, a malformed rule, an
        unreadable params file or unknown ROS arguments.
    """
    user_args, ros_tokens = split_ros_args(argv)
    sources: list[ParamRule | ParamsFile] = []
    remaps: list[RemapRule] = []
    log_levels: list[tuple[str | None, LoggingSeverity]] = []
    unknown: list[str] = []
    log_config_file: str | None = None
    enclave: str | None = None
    switches: list[str] = []
    files: list[str] = []
    items = iter(ros_tokens)
    for arg in items:
        if arg == ROS_ARGS_FLAG:
            continue
        if arg in _PARAM_FLAGS:
            value = _flag_value(items, arg, 'No parameter override rule found.')
            sources.append(_wrap(arg, value, 'parameter override rule', _parse_param_rule))
        elif arg in _REMAP_FLAGS:
            value = _flag_value(items, arg, 'No remap rule found.')
            remaps.append(_wrap(arg, value, 'remap rule', _parse_remap_rule))
        elif arg == _PARAMS_FILE_FLAG:
            value = _flag_value(items, arg, 'No file path provided.')
            sources.append(_wrap(arg, value, 'params file', _parse_params_file))
            files.append(value)
        elif arg == _LOG_LEVEL_FLAG:
            level_text = next(items, None)
            if level_text is None:
                msg = f"Couldn't parse trailing log level flag: '{arg}'. No log level provided."
                raise RosArgsError(msg)
            log_levels.append(_wrap(arg, level_text, 'log level', _parse_log_level_rule))
        elif arg == _LOG_CONFIG_FLAG:
            log_config_file = _flag_value(items, arg, 'No file path provided.')
        elif arg in _ENCLAVE_FLAGS:
            value = _flag_value(items, arg, 'No enclave path found.')
            enclave = _wrap(arg, value, 'enclave name', _parse_enclave)
        elif arg in _LOG_SWITCHES:
            switches.append(arg)
        else:
            unknown.append(arg)
    if unknown:
        msg = f'Found unknown ROS arguments: {unknown!r}'
        raise RosArgsError(msg)
    return RosArgs(
        user_args=tuple(user_args),
        parameter_sources=tuple(sources),
        remap_rules=tuple(remaps),
        log_levels=tuple(log_levels),
        log_config_file=log_config_file,
        enclave=enclave,
        log_switches=tuple(switches),
        params_files=tuple(files),
    )


def split_ros_args(argv: Sequence[str]) -> tuple[list[str], list[str]]:
    """
    Split ``argv`` into (the user's arguments, the ROS arguments), as rcl walks a command line.

    Every ``--ros-args`` section runs to the next ``--`` or the end; a flag that takes a value
    (``-p``, ``-r``, ``--params-file``, ``--log-level``, ``--log-config-file``, ``-e``) takes the
    next token whatever it is, ``--`` included. The ROS arguments keep their ``--ros-args``
    markers and drop the closing ``--``s, so ``init(args=[prog, *ros])`` sees what rcl would.
    Nothing is validated here except that every argument is a string (see
    :func:`parse_ros_args`).

    :raises RosArgsError: for an argument that is not a ``str``.
    """
    user_args: list[str] = []
    ros_args: list[str] = []
    in_ros_args = False
    takes_value = False
    for arg in argv:
        if not isinstance(arg, str):
            msg = f'Arguments must be strings, got {type(arg).__name__}: {arg!r}'
            raise RosArgsError(msg)
        if takes_value:
            ros_args.append(arg)
            takes_value = False
        elif not in_ros_args:
            if arg == ROS_ARGS_FLAG:
                in_ros_args = True
                ros_args.append(arg)
            else:
                user_args.append(arg)
        elif arg == ROS_ARGS_END:
            in_ros_args = False
        else:
            ros_args.append(arg)
            takes_value = arg in _VALUE_FLAGS
    return user_args, ros_args


def remove_ros_args(argv: Sequence[str]) -> list[str]:
    """Return ``argv`` without its ROS arguments (``rclpy.utilities.remove_ros_args``)."""
    return list(parse_ros_args(argv).user_args)


def _flag_value(items: Iterator[str], flag: str, missing: str) -> str:
    value = next(items, None)
    if value is None:
        msg = f"Couldn't parse trailing {flag} flag. {missing}"
        raise RosArgsError(msg)
    return value


def _wrap(flag: str, value: str, what: str, parse: Any) -> Any:
    """Run ``parse(value)``; turn its error into rcl's "Couldn't parse ..." text."""
    try:
        return parse(value)
    except _RuleError as error:
        msg = f"Couldn't parse {what}: '{flag} {_shown(value)}'. Error: {error}"
        raise RosArgsError(msg) from None


class _RuleError(ValueError):
    """Why one rule is malformed (wrapped into a RosArgsError)."""


# ---------------------------------------------------------------------------------------------
# YAML values typed as rcl_yaml_param_parser types them (rcl's parse.c: get_value, parse_value,
# parse_value_events, parse_file_events). Values are read from the YAML event stream, as rcl
# reads them: nothing is constructed, so an alias is never expanded and nesting never recurses.

#: The deepest nesting of YAML collections a ``-p`` value or a params file may have. rcl has no
#: limit of its own; real params files nest a handful of levels.
MAX_YAML_NESTING = 64

#: Whether PyYAML has libyaml, the scanner rcl parses with (``yaml.CSafeLoader``).
LIBYAML_AVAILABLE = hasattr(yaml, 'CSafeLoader')

_INT64_MIN = -(2**63)
_INT64_MAX = 2**63 - 1
_STR_TAG = 'tag:yaml.org,2002:str'
_QUOTED_STYLES = frozenset({"'", '"'})
_BREAKS = '\r\n\x85\u2028\u2029'
_RCL_TRUE = frozenset({'Y', 'y', 'yes', 'Yes', 'YES', 'true', 'True', 'TRUE', 'on', 'On', 'ON'})
_RCL_FALSE = frozenset({'N', 'n', 'no', 'No', 'NO', 'false', 'False', 'FALSE', 'off', 'Off'})
_RCL_FALSE |= {'OFF'}
_RCL_SPECIAL_DOUBLES = {
    f'{sign}.{word}': value
    for word, value in (('inf', math.inf), ('Inf', math.inf), ('INF', math.inf))
    for sign in ('', '+')
} | {f'-.{word}': -math.inf for word in ('inf', 'Inf', 'INF')}
_RCL_SPECIAL_DOUBLES |= {f'.{word}': math.nan for word in ('nan', 'NaN', 'NAN')}
# C's strtoll (base 0) and strtod, whole-string forms; no ambiguous repetition, so linear time.
_C_SPACE = r'[ \t\n\v\f\r]*'
_C_INT = re.compile(rf'{_C_SPACE}([+-]?)(?:0[xX]([0-9a-fA-F]+)|0([0-7]*)|([1-9][0-9]*))')
_C_DOUBLE = re.compile(
    rf"""{_C_SPACE}(?P<sign>[+-]?)(?:
        (?P<hex>0[xX](?=\.?[0-9a-fA-F])[0-9a-fA-F]*(?:\.[0-9a-fA-F]*)?(?:[pP][+-]?[0-9]+)?)
      | (?P<dec>(?=\.?[0-9])[0-9]*(?:\.[0-9]*)?(?:[eE][+-]?[0-9]+)?)
      | (?P<inf>(?i:inf(?:inity)?))
      | (?P<nan>(?i:nan)(?:\([0-9A-Za-z_]*\))?)
    )""",
    re.VERBOSE,
)
# Digits beyond which an int64 has certainly overflowed (leading zeros stripped).
_INT64_DIGITS = {16: 16, 8: 22, 10: 19}


def _c_strtoll(text: str) -> int | None:
    """Return ``strtoll(text, &end, 0)`` when it reads all of ``text`` in int64, else None."""
    match = _C_INT.fullmatch(text)
    if match is None:
        return None
    sign, hex_digits, octal_digits, decimal_digits = match.groups()
    base, digits = (
        (16, hex_digits)
        if hex_digits is not None
        else (8, octal_digits)
        if octal_digits is not None
        else (10, decimal_digits)
    )
    digits = digits.lstrip('0')
    if len(digits) > _INT64_DIGITS[base]:
        return None  # ERANGE: rcl then tries the text as a double
    magnitude = int(digits, base) if digits else 0
    value = -magnitude if sign == '-' else magnitude
    return value if _INT64_MIN <= value <= _INT64_MAX else None


def _c_strtod(text: str) -> float | None:
    """Return ``strtod(text, &end)`` when it reads all of ``text`` without ERANGE, else None."""
    match = _C_DOUBLE.fullmatch(text)
    if match is None:
        return None
    value: float | None
    if match['inf'] is not None:
        value = math.inf
    elif match['nan'] is not None:
        value = math.nan
    elif match['hex'] is not None:
        value = _hex_double(match['hex'][2:])
    else:
        value = _decimal_double(match['dec'])
    if value is None:
        return None
    return -value if match['sign'] == '-' else value


def _decimal_double(body: str) -> float | None:
    """Read a decimal ``strtod`` body; None where glibc sets ERANGE (overflow, inexact tiny)."""
    value = float(body)
    if math.isinf(value):
        return None
    mantissa = body.partition('e')[0].partition('E')[0]
    if value == 0.0:
        return None if mantissa.strip('0.') else 0.0
    if value < sys.float_info.min:  # subnormal: glibc reports ERANGE unless it is exact
        try:
            exact = decimal.Decimal(body) == decimal.Decimal(value)
        except (decimal.DecimalException, ValueError):
            return None
        return value if exact else None
    return value


def _hex_double(body: str) -> float | None:
    """Read a hexadecimal ``strtod`` body (after ``0x``); None where glibc sets ERANGE."""
    mantissa_text, _, exponent_text = body.lower().partition('p')
    whole, _, fraction = mantissa_text.partition('.')
    mantissa = int((whole + fraction).lstrip('0') or '0', 16)
    if mantissa == 0:
        return 0.0
    if len(exponent_text.lstrip('+-').lstrip('0')) > 6:
        return None  # an exponent beyond a million overflows or underflows
    lowest = int(exponent_text or '0') - 4 * len(fraction)  # the exponent of mantissa's bit 0
    trailing_zeros = (mantissa & -mantissa).bit_length() - 1
    top = lowest + mantissa.bit_length() - 1
    if top >= 1024 or top < -1075:
        return None
    try:
        value = float.fromhex(f'{whole or "0"}.{fraction}p{int(exponent_text or "0")}')
    except OverflowError:
        return None
    if value < sys.float_info.min and lowest + trailing_zeros < -1074:
        return None  # an inexact subnormal
    return value


def rcl_scalar(
    text: str, *, quoted: bool = False, str_tag: bool = False
) -> bool | int | float | str:
    """
    Type one YAML scalar as rcl does: ``!!str`` or quoted stays a string; else bool, int, double.

    The bools are exactly rcl's (``y``/``n``/``yes``/``on``/``off``... in three spellings), ints
    what ``strtoll`` base 0 reads whole in int64 (``0x1F``, octal ``010``), doubles what
    ``strtod`` reads whole without ERANGE (``1e3``, ``inf``, ``nan``, ``.inf``, ``0x1p3``); an
    integer beyond int64 is a double and a number beyond a double stays a string, as in rcl.
    """
    if str_tag or quoted:
        return text
    if text in _RCL_TRUE:
        return True
    if text in _RCL_FALSE:
        return False
    integer = _c_strtoll(text)
    if integer is not None:
        return integer
    special = _RCL_SPECIAL_DOUBLES.get(text)
    if special is not None:
        return special
    double = _c_strtod(text)
    return text if double is None else double


_KIND_ORDER = (bool, int, float, str)  # rclpy's order when a value fills several slots
_RCL_KIND_NAMES = {bool: 'bool', int: 'integer', float: 'double', str: 'string'}


class _Variant:
    """
    The slots of the ``rcl_variant_t`` one value fills, and the one rclpy reads from them.

    rcl keeps a slot per type: a scalar after a sequence (``[[1], 2]``) or a second inner
    sequence (``[[1, 2], [3]]``) fills or replaces a slot, and rclpy takes the first filled
    slot in its order (scalars bool, int, double, string, then the arrays in the same order).
    """

    def __init__(self) -> None:
        self.scalars: dict[type, Any] = {}
        self.arrays: dict[type, list[Any]] = {}
        self._sequence_kind: type | None = None

    def start_sequence(self) -> None:
        self._sequence_kind = None

    def add(self, value: bool | int | float | str, in_sequence: bool, line: int) -> None:
        kind = type(value)
        if not in_sequence:
            self.scalars[kind] = value
            return
        if self._sequence_kind is None:
            self._sequence_kind = kind
            self.arrays[kind] = []
        elif self._sequence_kind is not kind:
            msg = (
                f"Sequence should be of same type. Value type '{_RCL_KIND_NAMES[kind]}' "
                f'do not belong at line_num {line}'
            )
            raise _RuleError(msg)
        self.arrays[kind].append(value)

    def value(self) -> Any:
        for kind in _KIND_ORDER:
            if kind in self.scalars:
                return self.scalars[kind]
        for kind in _KIND_ORDER:
            if kind in self.arrays:
                return self.arrays[kind]
        return None


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


#: The event parser: libyaml where PyYAML has it (rcl's own), else the pure one above.
YAML_EVENT_LOADER: Any = getattr(yaml, 'CSafeLoader', PureYamlEventLoader)


class _LineError(_RuleError):
    """A problem at one line of a YAML text (a params file names its path before the line)."""

    def __init__(self, line: int, reason: str) -> None:
        super().__init__(f'line {line}: {reason}')
        self.line = line
        self.reason = reason


def _yaml_events(text: str, loader: Any) -> Iterator[yaml.Event]:
    """Yield the YAML events of ``text``; a syntax error becomes a one-line _LineError."""
    events = yaml.parse(text, Loader=loader)
    while True:
        try:
            event = next(events)
        except StopIteration:
            return
        except yaml.YAMLError as error:
            mark = getattr(error, 'problem_mark', None) or getattr(error, 'context_mark', None)
            problem = getattr(error, 'problem', None) or str(error).splitlines()[0]
            if mark is None:
                raise _LineError(1, f'invalid YAML: {problem}') from None
            reason = f'invalid YAML (column {mark.column + 1}): {problem}'
            raise _LineError(mark.line + 1, reason) from None
        yield event


def _line(event: yaml.Event) -> int:
    mark = event.start_mark
    return mark.line + 1 if mark is not None else 0


def _event_scalar(event: yaml.ScalarEvent) -> bool | int | float | str:
    return rcl_scalar(
        event.value, quoted=event.style in _QUOTED_STYLES, str_tag=event.tag == _STR_TAG
    )


def _too_deep(line: int) -> _LineError:
    return _LineError(line, f'nesting deeper than {MAX_YAML_NESTING} levels')


def parse_param_value(text: str, *, loader: Any = None) -> Any:
    """
    Type a ``-p`` value as rcl does: bool, int, double, string or a homogeneous array.

    :param loader: the YAML event parser (default :data:`YAML_EVENT_LOADER`, libyaml).
    :raises ValueError: for a value rcl refuses (empty, a mapping, an alias, a mixed array,
        invalid YAML), for no value at all (``[]``, only a comment), or nesting deeper than
        :data:`MAX_YAML_NESTING`.
    """
    if not text:
        msg = "empty value (write '' for an empty string)"
        raise _RuleError(msg)
    variant = _Variant()
    depth = 0
    in_sequence = False
    for event in _yaml_events(text, YAML_EVENT_LOADER if loader is None else loader):
        if isinstance(event, yaml.ScalarEvent):
            if not event.value and event.style not in _QUOTED_STYLES:
                msg = f'No value at line {_line(event)}'
                raise _RuleError(msg)
            variant.add(_event_scalar(event), in_sequence, _line(event))
        elif isinstance(event, yaml.SequenceStartEvent):
            depth += 1
            if depth > MAX_YAML_NESTING:
                raise _too_deep(_line(event))
            in_sequence = True
            variant.start_sequence()
        elif isinstance(event, yaml.SequenceEndEvent):
            depth -= 1
            in_sequence = False  # as rcl: an inner sequence's end ends the array
        elif isinstance(event, yaml.MappingStartEvent):
            msg = 'a mapping is not a parameter value (nested names belong in a --params-file)'
            raise _RuleError(msg)
        elif isinstance(event, yaml.AliasEvent):
            msg = 'an alias (*name) is not a parameter value'
            raise _RuleError(msg)
    value = variant.value()
    if value is None:
        msg = f'no value in {_shorten(text)!r}: the parameter type cannot be determined'
        raise _RuleError(msg)
    return value


def _shorten(text: str, limit: int = 60) -> str:
    """Return ``text`` as it is, or on one line its start and length when long (a URDF)."""
    if len(text) <= limit and '\n' not in text:
        return text
    start = text[:limit].replace('\r', '\\r').replace('\n', '\\n').replace('\t', '\\t')
    return f'{start}... ({len(text)} characters)'


def _shown(argument: str) -> str:
    """Return an argument as an error quotes it: whole, unless multi-line or very long."""
    return argument if len(argument) <= 200 and '\n' not in argument else _shorten(argument)


_RCL_SOURCE_LOCATION = re.compile(r'\s*, at \S+\.(?:c|cpp):\d+')
_RCL_INIT_PREFIX = 'failed to initialize rcl: '


def explain_rcl_error(message: str, argv: Sequence[str]) -> str:
    """
    Return rcl's text for bad ROS arguments as one line that says what to do.

    rcl's own message (from ``rclpy.init``) echoes the whole rule, a whole URDF for
    ``-p robot_description:=...``, and ends with C source locations: the rule is shortened,
    the locations dropped and, for a value rcl could not read as YAML, advice added. For a
    params file rcl refused, our own reading's reason is added where it has one (rcl says
    "Error parsing a event near line 0" for a file that is not UTF-8); rcl's verdict stands.
    """
    text = _RCL_SOURCE_LOCATION.sub('', message.removeprefix(_RCL_INIT_PREFIX))
    advice = ''
    for flag, rule in itertools.pairwise(argv):
        quoted = f"'{flag} {rule}'"
        if quoted not in text:
            continue
        text = text.replace(quoted, f"'{flag} {_shown(rule)}'")
        if flag in _PARAM_FLAGS and ':=' in rule:
            name, _, value = rule.partition(':=')
            advice = _param_value_advice(name.rpartition(':')[2], value)
        elif flag == _PARAMS_FILE_FLAG:
            try:
                _parse_params_file(rule)
            except _RuleError as error:
                advice = f'here: {error}'
        break
    text = ' '.join(text.split())
    return f'{text}; {advice}' if advice else text


def _param_value_advice(name: str, value_text: str) -> str:
    """Say what to do instead when a long or XML value given with ``-p`` is not valid YAML."""
    stripped = value_text.lstrip()
    if name == 'robot_description' or stripped.startswith('<'):
        return (
            'rcl reads every -p value as YAML, and this XML is not a valid YAML value: '
            'pass the file instead (-p urdf_file:=<path to the .urdf or .xacro>) or put '
            "robot_description in a --params-file as a block scalar ('robot_description: |')"
        )
    if '\n' in value_text:
        return (
            'rcl reads every -p value as YAML: put a multi-line value in a --params-file '
            "as a block scalar ('name: |')"
        )
    return ''


def _check_file_scalar(event: yaml.ScalarEvent, name: str) -> bool | int | float | str:
    if not event.value and event.style not in _QUOTED_STYLES:
        raise _LineError(_line(event), f"parameter '{name}' has no value")
    return _event_scalar(event)


def _split_rule(rule: str) -> tuple[str | None, str, str]:
    """Split ``[node:]lhs:=rhs``; the node prefix is the part before a single ``:``."""
    lhs, separator, rhs = rule.partition(':=')
    if not separator:
        msg = "Expected ':=' between name and value"
        raise _RuleError(msg)
    node: str | None = None
    if ':' in lhs:
        node, _, lhs = lhs.partition(':')
        if not _NODE_TOKEN.fullmatch(node):
            msg = f"Invalid node name prefix '{node}'"
            raise _RuleError(msg)
    return node, lhs, rhs


def _parse_param_rule(rule: str) -> ParamRule:
    node, name, value_text = _split_rule(rule)
    if not name:
        msg = 'Parameter name is empty'
        raise _RuleError(msg)
    if not _PARAM_NAME.fullmatch(name):
        msg = f"Invalid parameter name '{name}'"
        raise _RuleError(msg)
    try:
        value = parse_param_value(value_text)
    except _RuleError as error:
        advice = _param_value_advice(name, value_text)
        if not advice:
            raise
        msg = f'{error}; {advice}'
        raise _RuleError(msg) from None
    return ParamRule(node=node, name=name, value=value)


def _parse_remap_rule(rule: str) -> RemapRule:
    node, match, replacement = _split_rule(rule)
    if not match:
        msg = 'Remap rule has nothing to match'
        raise _RuleError(msg)
    if not replacement:
        msg = 'Remap rule has no replacement'
        raise _RuleError(msg)
    if match in ('__node', '__name'):
        if not _TOKEN.fullmatch(replacement):
            msg = f"Invalid node name '{replacement}': must be a token ([a-zA-Z_][a-zA-Z0-9_]*)"
            raise _RuleError(msg)
        return RemapRule(node=node, kind='node', match=None, replacement=replacement)
    if match == '__ns':
        if not replacement.startswith('/'):
            msg = f"Namespace '{replacement}' must be absolute (start with '/')"
            raise _RuleError(msg)
        if replacement != '/':
            _validate_topic_name(replacement, 'namespace')
        return RemapRule(node=node, kind='namespace', match=None, replacement=replacement)
    _validate_topic_name(match, 'topic name to match')
    _validate_topic_name(replacement, 'replacement topic name')
    return RemapRule(node=node, kind='topic', match=match, replacement=replacement)


def _validate_topic_name(name: str, what: str) -> None:
    """Check ``name`` with rcl_validate_topic_name's rules; raise naming the problem."""
    problem: str | None = None
    if not name:
        problem = 'must not be empty'
    elif name.endswith('/') and name != '/':
        problem = "must not end with '/'"
    elif '//' in name:
        problem = "must not contain repeated '/'"
    elif '~' in name[1:]:
        problem = "'~' is only allowed as the first character"
    elif name.startswith('~') and len(name) > 1 and name[1] != '/':
        problem = "'~' must be followed by '/'"
    elif re.search(r'[^A-Za-z0-9_/~{}]', name):
        problem = "contains characters other than alphanumerics, '_', '/', '~' and '{}'"
    else:
        tokens = [token for token in name.lstrip('~').split('/') if token]
        if any(token[0].isdigit() for token in tokens):
            problem = 'a token must not start with a number'
    if problem:
        msg = f"Invalid {what} '{name}': {problem}"
        raise _RuleError(msg)


def _parse_log_level_rule(rule: str) -> tuple[str | None, LoggingSeverity]:
    logger: str | None = None
    level_text = rule
    if ':=' in rule:
        logger, _, level_text = rule.partition(':=')
        if not logger:
            msg = 'Logger name is empty'
            raise _RuleError(msg)
    return logger, _rcutils_severity(level_text)


_RCUTILS_SEVERITIES = {'UNSET': 0, 'DEBUG': 10, 'INFO': 20, 'WARN': 30, 'WARNING': 30}
_RCUTILS_SEVERITIES.update(ERROR=40, FATAL=50)


def _rcutils_severity(name: str) -> LoggingSeverity:
    """Return the severity of an rcutils name (any case; ``warning`` is WARN) or rcl's error."""
    level = _RCUTILS_SEVERITIES.get(name.upper())
    if level is None:
        msg = 'Argument does not use a valid severity level'
        raise _RuleError(msg)
    return LoggingSeverity(level)


def _parse_enclave(value: str) -> str:
    if not value.startswith('/'):
        msg = f"Enclave name '{value}' must be fully qualified (start with '/')"
        raise _RuleError(msg)
    if value != '/':
        _validate_topic_name(value, 'enclave name')
    return value


def _parse_params_file(path: str) -> ParamsFile:
    try:
        text = read_text_file(path)
    except InputFileError as error:
        raise _RuleError(str(error)) from None
    try:
        entries = _params_file_entries(_yaml_events(text, YAML_EVENT_LOADER))
    except _LineError as error:
        msg = f'{path}:{error.line}: {error.reason}'
        raise _RuleError(msg) from None
    return ParamsFile(path=path, entries=tuple(entries))


@dataclass
class _Frame:
    """One open YAML collection of a params file, with what its contents mean."""

    role: str  # 'nodes' (node names), 'params' (parameter names) or 'array' (a list value)
    names: tuple[str, ...] = ()  # the node name parts of a 'nodes' frame
    node_key: str = ''
    prefix: str = ''  # 'a.b.' inside a parameter namespace; the name itself for an 'array'
    key: str | None = None  # a mapping's key waiting for its value
    out: list[tuple[str, Any]] = field(default_factory=list)
    variant: _Variant | None = None


_Entries = list[tuple[str, tuple[tuple[str, Any], ...]]]
_DOCUMENT_EVENTS = (
    yaml.StreamStartEvent,
    yaml.StreamEndEvent,
    yaml.DocumentStartEvent,
    yaml.DocumentEndEvent,
)


def _params_file_entries(events: Iterator[yaml.Event]) -> _Entries:
    """
    Read rcl's params-file schema from YAML events, iteratively.

    ``<node key>: {ros__parameters: {...}}``; mappings above ``ros__parameters`` are
    namespaces, mappings below it dotted parameter names. As rcl: aliases, nested lists and a
    parameter without a value are refused; tags are ignored but ``!!str``.
    """
    entries: _Entries = []
    stack: list[_Frame] = []
    for event in events:
        if isinstance(
            event,
            _DOCUMENT_EVENTS,
        ):
            continue
        line = _line(event)
        if isinstance(event, yaml.AliasEvent):
            msg = 'aliases (*name) are not supported, as in rcl'
            raise _LineError(line, msg)
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
                raise _LineError(line, msg)
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
                    raise _too_deep(line)
                stack.append(child)
    return entries


def _open_document(event: yaml.Event, stack: list[_Frame], line: int) -> None:
    if isinstance(event, yaml.MappingStartEvent):
        stack.append(_Frame('nodes'))
    elif not (isinstance(event, yaml.ScalarEvent) and not event.value and not event.style):
        msg = 'the top level must be a mapping of node names'
        raise _LineError(line, msg)  # an empty document (a plain empty scalar) is nothing


def _close(frame: _Frame, stack: list[_Frame], entries: _Entries, line: int) -> None:
    if frame.role == 'array':
        assert frame.variant is not None
        value = frame.variant.value()
        if value is None:
            msg = f"parameter '{frame.prefix}': empty array: the element type cannot be determined"
            raise _LineError(line, msg)
        frame.out.append((frame.prefix, value))
    elif frame.role == 'params' and stack[-1].role != 'params':
        entries.append((frame.node_key, tuple(frame.out)))


def _array_item(event: yaml.Event, frame: _Frame, line: int) -> None:
    if not isinstance(event, yaml.ScalarEvent):
        msg = (
            f"parameter '{frame.prefix}': a list or mapping inside a list is not a parameter value"
        )
        raise _LineError(line, msg)
    assert frame.variant is not None
    try:
        frame.variant.add(_check_file_scalar(event, frame.prefix), True, line)
    except _RuleError as error:
        raise _LineError(line, f"parameter '{frame.prefix}': {error}") from None


def _node_value(event: yaml.Event, frame: _Frame, line: int) -> _Frame | None:
    """Read the value of a key above ``ros__parameters``: a node name part or the parameters."""
    key = frame.key
    assert key is not None
    if key == 'ros__parameters':
        if not frame.names:
            msg = "'ros__parameters' must be inside a node name"
            raise _LineError(line, msg)
        node_key = '/' + '/'.join(part.strip('/') for part in frame.names)
        if not isinstance(event, yaml.MappingStartEvent):
            msg = f"'ros__parameters' of '{node_key}' must be a mapping"
            raise _LineError(line, msg)
        return _Frame('params', node_key=node_key)
    if not isinstance(event, yaml.MappingStartEvent):
        where = '/'.join([*frame.names, key])
        msg = f"'{where}' is not a node name: expected a mapping with 'ros__parameters'"
        raise _LineError(line, msg)
    return _Frame('nodes', names=(*frame.names, key))


def _parameter_value(event: yaml.Event, frame: _Frame) -> _Frame | None:
    """Read the value of a key below ``ros__parameters``: a value, a list or a namespace."""
    name = f'{frame.prefix}{frame.key}'
    if isinstance(event, yaml.ScalarEvent):
        frame.out.append((name, _check_file_scalar(event, name)))
        return None
    if isinstance(event, yaml.SequenceStartEvent):
        return _Frame('array', prefix=name, out=frame.out, variant=_Variant())
    return _Frame('params', node_key=frame.node_key, prefix=f'{name}.', out=frame.out)


def _node_key_matches(key: str, node_fqn: str) -> bool:
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


def expand_topic_name(name: str, node_name: str, namespace: str) -> str:
    """Expand ``name`` as ``rcl_expand_topic_name``: ``~``, ``{node}``, ``{ns}``, relative."""
    namespace = namespace if namespace.startswith('/') else '/' + namespace
    base = namespace.rstrip('/')
    fqn = f'{base}/{node_name}'
    expanded = name
    if expanded.startswith('~'):
        expanded = fqn + expanded[1:]
    expanded = (
        expanded.replace('{node}', node_name)
        .replace('{ns}', base or '/')
        .replace('{namespace}', base or '/')
    )
    if not expanded.startswith('/'):
        expanded = f'{base}/{expanded}'
    return expanded
