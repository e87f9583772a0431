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
  (``rcl_yaml_param_parser``, see :mod:`tf_demo.transport.params_typing`): ``true``/``y``/``on``
  are bools, what ``strtoll`` reads whole an int (``0x1F``, ``010``), what ``strtod`` reads
  whole a double (``1e3``, ``inf``, ``nan``), anything else or quoted a string (``1_000``,
  ``0b11``, ``'1'``); ``[1, 2]`` is an int array.
* ``--params-file file.yaml``: rcl's schema (:mod:`tf_demo.transport.params_file`).
* ``-r``/``--remap [node:]from:=to``, including ``__node:=``/``__name:=`` and ``__ns:=``.
* ``--log-level [logger:=]level``, ``--log-config-file``, ``-e``/``--enclave``, and the
  ``--enable-``/``--disable-`` ``stdout-logs``/``rosout-logs``/``external-lib-logs`` flags.

Later sources of a parameter override earlier ones, in command-line order, as rcl merges them.
YAML is read as events (:mod:`tf_demo.transport.params_yaml`), never constructed. Errors raise
:class:`RosArgsError` with rcl's texts (a long value shortened, advice for a URDF given with
``-p``); ``run_node`` prints them on one line. One rule's text is read by
:mod:`tf_demo.transport.ros_args_rules`. In the rclpy world rcl parses the arguments itself
(:func:`explain_rcl_error` words its refusal).
"""

from __future__ import annotations

from collections.abc import Callable
from collections.abc import Iterator
from collections.abc import Sequence
from dataclasses import dataclass
import itertools
import re
from typing import TypeVar

from tf_demo.transport.dds.log_format import LoggingSeverity
from tf_demo.transport.dds.parameters import Parameter
from tf_demo.transport.params_file import node_key_matches
from tf_demo.transport.params_file import ParamsFile
from tf_demo.transport.params_file import read_params_file
from tf_demo.transport.params_typing import RuleError
from tf_demo.transport.params_yaml import parse_param_value
from tf_demo.transport.params_yaml import PureYamlEventLoader
from tf_demo.transport.params_yaml import shorten
from tf_demo.transport.params_yaml import YAML_EVENT_LOADER
from tf_demo.transport.ros_args_rules import param_value_advice
from tf_demo.transport.ros_args_rules import ParamRule
from tf_demo.transport.ros_args_rules import parse_enclave
from tf_demo.transport.ros_args_rules import parse_log_level_rule
from tf_demo.transport.ros_args_rules import parse_param_rule
from tf_demo.transport.ros_args_rules import parse_remap_rule
from tf_demo.transport.ros_args_rules import RemapRule

__all__ = [
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

_T = TypeVar('_T')


class RosArgsError(ValueError):
    """A ``--ros-args`` argument that rcl would reject; the text says which and why."""


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
    params_files: tuple[str, ...] = ()

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
                if source.node is None or node_key_matches(source.node, node_fqn):
                    overrides[source.name] = Parameter(source.name, value=source.value)
                continue
            for key, values in source.entries:
                if node_key_matches(key, node_fqn):
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
            sources.append(_wrap(arg, value, 'parameter override rule', parse_param_rule))
        elif arg in _REMAP_FLAGS:
            value = _flag_value(items, arg, 'No remap rule found.')
            remaps.append(_wrap(arg, value, 'remap rule', parse_remap_rule))
        elif arg == _PARAMS_FILE_FLAG:
            value = _flag_value(items, arg, 'No file path provided.')
            sources.append(_wrap(arg, value, 'params file', read_params_file))
            files.append(value)
        elif arg == _LOG_LEVEL_FLAG:
            level_text = next(items, None)
            if level_text is None:
                msg = f"Couldn't parse trailing log level flag: '{arg}'. No log level provided."
                raise RosArgsError(msg)
            log_levels.append(_wrap(arg, level_text, 'log level', parse_log_level_rule))
        elif arg == _LOG_CONFIG_FLAG:
            log_config_file = _flag_value(items, arg, 'No file path provided.')
        elif arg in _ENCLAVE_FLAGS:
            value = _flag_value(items, arg, 'No enclave path found.')
            enclave = _wrap(arg, value, 'enclave name', parse_enclave)
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


def _wrap(flag: str, value: str, what: str, parse: Callable[[str], _T]) -> _T:
    """Run ``parse(value)``; turn its error into rcl's "Couldn't parse ..." text."""
    try:
        return parse(value)
    except RuleError as error:
        msg = f"Couldn't parse {what}: '{flag} {_shown(value)}'. Error: {error}"
        raise RosArgsError(msg) from None


def _shown(argument: str) -> str:
    """Return an argument as an error quotes it: whole, unless multi-line or very long."""
    return argument if len(argument) <= 200 and '\n' not in argument else shorten(argument)


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
            advice = param_value_advice(name.rpartition(':')[2], value)
        elif flag == _PARAMS_FILE_FLAG:
            try:
                read_params_file(rule)
            except RuleError as error:
                advice = f'here: {error}'
        break
    text = ' '.join(text.split())
    return f'{text}; {advice}' if advice else text


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
