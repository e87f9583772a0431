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
returned unchanged as the user's arguments. Understood inside a ``--ros-args`` section:

* ``-p``/``--param [node:]name:=value``: a parameter override; the value is YAML-typed
  (``true`` is a bool, ``1`` an int, ``1.0`` a double, ``[1, 2]`` an int array, ``'1'`` a string).
* ``--params-file file.yaml``: rcl's schema, ``<node key>: {ros__parameters: {...}}`` where the
  key is ``/**``, a node name, a fully qualified name or a wildcard pattern (``*`` one token,
  ``**`` any number of tokens); nested mappings above ``ros__parameters`` are namespaces and
  nested mappings below it are dotted parameter names.
* ``-r``/``--remap [node:]from:=to``, including ``__node:=``/``__name:=`` and ``__ns:=``.
* ``--log-level [logger:=]level``, ``--log-config-file``, ``-e``/``--enclave``, and the
  ``--enable-``/``--disable-`` ``stdout-logs``/``rosout-logs``/``external-lib-logs`` flags.

Later sources of a parameter override earlier ones, in command-line order, as rcl merges them.
Errors raise :class:`RosArgsError` with rcl's texts; ``run_node`` prints them on one line.
"""

from __future__ import annotations

from collections.abc import Iterator
from collections.abc import Sequence
from dataclasses import dataclass
from dataclasses import field
import re
import threading
from typing import Any

from tf_demo.transport.logging import LoggingSeverity
from tf_demo.transport.parameters import Parameter
import yaml

__all__ = [
    'ROS_ARGS_FLAG',
    'ROS_ARGS_USAGE',
    'NodeArguments',
    'ParamRule',
    'ParamsFile',
    'RemapRule',
    'RosArgs',
    'RosArgsError',
    'expand_topic_name',
    'global_ros_args',
    'parse_param_value',
    'parse_ros_args',
    'remove_ros_args',
    'resolve_node_arguments',
    'set_global_ros_args',
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
    user_args: list[str] = []
    sources: list[ParamRule | ParamsFile] = []
    remaps: list[RemapRule] = []
    log_levels: list[tuple[str | None, LoggingSeverity]] = []
    unknown: list[str] = []
    log_config_file: str | None = None
    enclave: str | None = None
    switches: list[str] = []
    files: list[str] = []
    in_ros_args = False
    items = iter(enumerate(argv))
    for _index, arg in items:
        if not isinstance(arg, str):
            msg = f'Arguments must be strings, got {type(arg).__name__}: {arg!r}'
            raise RosArgsError(msg)
        if not in_ros_args:
            if arg == ROS_ARGS_FLAG:
                in_ros_args = True
            else:
                user_args.append(arg)
            continue
        if arg == ROS_ARGS_FLAG:
            continue
        if arg == ROS_ARGS_END:
            in_ros_args = False
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
            level_text = _next_value(items)
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


def remove_ros_args(argv: Sequence[str]) -> list[str]:
    """Return ``argv`` without its ROS arguments (``rclpy.utilities.remove_ros_args``)."""
    return list(parse_ros_args(argv).user_args)


def _next_value(items: Iterator[tuple[int, str]]) -> str | None:
    entry = next(items, None)
    return None if entry is None else entry[1]


def _flag_value(items: Iterator[tuple[int, str]], flag: str, missing: str) -> str:
    value = _next_value(items)
    if value is None:
        msg = f"Couldn't parse trailing {flag} flag. {missing}"
        raise RosArgsError(msg)
    return value


def _wrap(flag: str, value: str, what: str, parse: Any) -> Any:
    """Run ``parse(value)``; turn its error into rcl's "Couldn't parse ..." text."""
    try:
        return parse(value)
    except _RuleError as error:
        msg = f"Couldn't parse {what}: '{flag} {value}'. Error: {error}"
        raise RosArgsError(msg) from None


class _RuleError(ValueError):
    """Why one rule is malformed (wrapped into a RosArgsError)."""


# libyaml, as rcl uses, where PyYAML has it: its scanner accepts what rcl accepts (e.g. a tab
# inside a multi-line value such as a URDF given with -p robot_description:=...).
_SafeLoaderBase: type[yaml.SafeLoader] = getattr(yaml, 'CSafeLoader', yaml.SafeLoader)


class _YamlLoader(_SafeLoaderBase):  # type: ignore[valid-type,misc]
    """YAML 1.1 scalars as rcl's parser types them, without dates (they stay strings)."""


_YamlLoader.yaml_implicit_resolvers = {
    key: [(tag, regexp) for tag, regexp in resolvers if tag != 'tag:yaml.org,2002:timestamp']
    for key, resolvers in yaml.SafeLoader.yaml_implicit_resolvers.items()
}


def _ignore_tag(loader: _YamlLoader, _suffix: str, node: yaml.Node) -> Any:
    """
    Read a node whose tag the safe loader does not know as if it had no tag, as rcl does.

    rcl's parser ignores tags but ``!!str``: ``launch_ros`` writes list parameters as
    ``!!python/tuple [...]``, which rcl reads as a plain sequence.
    """
    if isinstance(node, yaml.SequenceNode):
        return loader.construct_sequence(node, deep=True)
    if isinstance(node, yaml.MappingNode):
        return loader.construct_mapping(node, deep=True)
    style = getattr(node, 'style', None)
    plain = not style  # plain scalars: None (PyYAML) or '' (libyaml)
    tag = loader.resolve(yaml.ScalarNode, node.value, (plain, not plain))
    return loader.construct_object(yaml.ScalarNode(tag, node.value, style=style))


_YamlLoader.add_multi_constructor('', _ignore_tag)


def parse_param_value(text: str) -> Any:
    """
    Type a ``-p`` value as rcl does: bool, int, double, string or a homogeneous array.

    :raises ValueError: for a value no parameter can hold (a mapping, a mixed or empty array).
    """
    try:
        value = yaml.load(text, Loader=_YamlLoader)  # a SafeLoader subclass
    except yaml.YAMLError as error:
        msg = f'invalid YAML value {text!r} ({_yaml_problem(error)})'
        raise _RuleError(msg) from None
    return _check_param_value(value, text)


def _yaml_problem(error: yaml.YAMLError) -> str:
    problem = getattr(error, 'problem', None)
    return str(problem) if problem else str(error).splitlines()[0]


def _check_param_value(value: Any, shown: Any) -> Any:
    if value is None:
        return ''  # rcl keeps an empty or null scalar as an empty string
    if isinstance(value, (bool, int, float, str)):
        return value
    if isinstance(value, list):
        if not value:
            msg = f'empty array {shown!r}: the element type cannot be determined'
            raise _RuleError(msg)
        kinds = {_scalar_kind(item) for item in value}
        if None in kinds or len(kinds) != 1:
            msg = f'Sequence should be of same type: {shown!r}'
            raise _RuleError(msg)
        return value
    if isinstance(value, bytes):
        return list(value)
    msg = f'unsupported value {shown!r}: expected a scalar or an array of scalars'
    raise _RuleError(msg)


def _scalar_kind(item: Any) -> str | None:
    if isinstance(item, bool):
        return 'bool'
    if isinstance(item, int):
        return 'int'
    if isinstance(item, float):
        return 'float'
    if isinstance(item, str):
        return 'str'
    return None


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
    return ParamRule(node=node, name=name, value=parse_param_value(value_text))


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
        with open(path, encoding='utf-8') as stream:
            document = yaml.load(stream, Loader=_YamlLoader)  # a SafeLoader subclass
    except OSError as error:
        msg = f'Error opening YAML file ({error.strerror})'
        raise _RuleError(msg) from None
    except yaml.YAMLError as error:
        mark = getattr(error, 'problem_mark', None)
        where = f' at line {mark.line + 1}' if mark is not None else ''
        msg = f'Error parsing YAML file{where}: {_yaml_problem(error)}'
        raise _RuleError(msg) from None
    if document is None:
        return ParamsFile(path=path, entries=())
    if not isinstance(document, dict):
        msg = 'the top level must be a mapping of node names'
        raise _RuleError(msg)
    entries: list[tuple[str, tuple[tuple[str, Any], ...]]] = []
    _collect_nodes(document, [], entries)
    return ParamsFile(path=path, entries=tuple(entries))


def _collect_nodes(
    mapping: dict[Any, Any],
    namespace: list[str],
    entries: list[tuple[str, tuple[tuple[str, Any], ...]]],
) -> None:
    for key, value in mapping.items():
        if not isinstance(key, str):
            msg = f'node name {key!r} is not a string'
            raise _RuleError(msg)
        if key == 'ros__parameters':
            if not namespace:
                msg = "'ros__parameters' must be inside a node name"
                raise _RuleError(msg)
            node_key = '/' + '/'.join(part.strip('/') for part in namespace)
            if not isinstance(value, dict):
                msg = f"'ros__parameters' of '{node_key}' must be a mapping"
                raise _RuleError(msg)
            flattened: list[tuple[str, Any]] = []
            _flatten_parameters(value, '', flattened)
            entries.append((node_key, tuple(flattened)))
        elif isinstance(value, dict):
            _collect_nodes(value, [*namespace, key], entries)
        else:
            where = '/'.join([*namespace, key])
            msg = f"'{where}' is not a node name: expected a mapping with 'ros__parameters'"
            raise _RuleError(msg)


def _flatten_parameters(mapping: dict[Any, Any], prefix: str, out: list[tuple[str, Any]]) -> None:
    for key, value in mapping.items():
        name = f'{prefix}{key}'
        if isinstance(value, dict):
            _flatten_parameters(value, f'{name}.', out)
        else:
            try:
                out.append((name, _check_param_value(value, value)))
            except _RuleError as error:
                msg = f"parameter '{name}': {error}"
                raise _RuleError(msg) from None


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


_GLOBAL_LOCK = threading.Lock()
_global_args: RosArgs = RosArgs()


def set_global_ros_args(arguments: RosArgs) -> None:
    """Remember the arguments given to ``init`` for the process."""
    global _global_args
    with _GLOBAL_LOCK:
        _global_args = arguments


def global_ros_args() -> RosArgs:
    """Return the arguments given to ``init`` (empty before it)."""
    with _GLOBAL_LOCK:
        return _global_args
