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
One ``--ros-args`` rule read as rcl reads it (``rcl/src/rcl/arguments.c``, ``remap.c``).

Each parser takes the text after its flag and returns the rule, or raises
:class:`~tf_demo.transport.params_typing.RuleError` with rcl's reason;
:func:`tf_demo.transport.ros_args.parse_ros_args` adds the flag and the rule to the text.
"""

from __future__ import annotations

from dataclasses import dataclass
import re

from tf_demo.transport.dds.log_format import LoggingSeverity
from tf_demo.transport.params_typing import ParamValue
from tf_demo.transport.params_typing import RuleError
from tf_demo.transport.params_yaml import parse_param_value

__all__ = [
    'ParamRule',
    'RemapRule',
    'param_value_advice',
    'parse_enclave',
    'parse_log_level_rule',
    'parse_param_rule',
    'parse_remap_rule',
]

_TOKEN = re.compile(r'[A-Za-z_][A-Za-z0-9_]*')
_NODE_TOKEN = re.compile(r'[A-Za-z0-9_]+')
# rcl: name tokens (runs of tokens and '/') joined by '.', e.g. qos_overrides./tf.publisher.depth
_PARAM_NAME_TOKEN = r'(?:[A-Za-z_][A-Za-z0-9_]*|/)+'
_PARAM_NAME = re.compile(rf'{_PARAM_NAME_TOKEN}(?:\.{_PARAM_NAME_TOKEN})*')
_RCUTILS_SEVERITIES = {'UNSET': 0, 'DEBUG': 10, 'INFO': 20, 'WARN': 30, 'WARNING': 30}
_RCUTILS_SEVERITIES.update(ERROR=40, FATAL=50)


@dataclass(frozen=True)
class ParamRule:
    """One ``-p [node:]name:=value``."""

    node: str | None
    name: str
    value: ParamValue


@dataclass(frozen=True)
class RemapRule:
    """One ``-r [node:]from:=to``; ``kind`` is ``topic``, ``node`` or ``namespace``."""

    node: str | None
    kind: str
    match: str | None
    replacement: str


def _split_rule(rule: str) -> tuple[str | None, str, str]:
    """Split ``[node:]lhs:=rhs``; the node prefix is the part before a single ``:``."""
    lhs, separator, rhs = rule.partition(':=')
    if not separator:
        msg = "Expected ':=' between name and value"
        raise RuleError(msg)
    node: str | None = None
    if ':' in lhs:
        node, _, lhs = lhs.partition(':')
        if not _NODE_TOKEN.fullmatch(node):
            msg = f"Invalid node name prefix '{node}'"
            raise RuleError(msg)
    return node, lhs, rhs


def parse_param_rule(rule: str) -> ParamRule:
    """Read ``[node:]name:=value`` (``-p``); the value typed by rcl's YAML rules."""
    node, name, value_text = _split_rule(rule)
    if not name:
        msg = 'Parameter name is empty'
        raise RuleError(msg)
    if not _PARAM_NAME.fullmatch(name):
        msg = f"Invalid parameter name '{name}'"
        raise RuleError(msg)
    try:
        value = parse_param_value(value_text)
    except RuleError as error:
        advice = param_value_advice(name, value_text)
        if not advice:
            raise
        msg = f'{error}; {advice}'
        raise RuleError(msg) from None
    return ParamRule(node=node, name=name, value=value)


def param_value_advice(name: str, value_text: str) -> str:
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


def parse_remap_rule(rule: str) -> RemapRule:
    """Read ``[node:]from:=to`` (``-r``), ``__node``/``__name`` and ``__ns`` included."""
    node, match, replacement = _split_rule(rule)
    if not match:
        msg = 'Remap rule has nothing to match'
        raise RuleError(msg)
    if not replacement:
        msg = 'Remap rule has no replacement'
        raise RuleError(msg)
    if match in ('__node', '__name'):
        if not _TOKEN.fullmatch(replacement):
            msg = f"Invalid node name '{replacement}': must be a token ([a-zA-Z_][a-zA-Z0-9_]*)"
            raise RuleError(msg)
        return RemapRule(node=node, kind='node', match=None, replacement=replacement)
    if match == '__ns':
        if not replacement.startswith('/'):
            msg = f"Namespace '{replacement}' must be absolute (start with '/')"
            raise RuleError(msg)
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
        raise RuleError(msg)


def parse_log_level_rule(rule: str) -> tuple[str | None, LoggingSeverity]:
    """Read ``[logger:=]level`` (``--log-level``); the level is an rcutils name, any case."""
    logger: str | None = None
    level_text = rule
    if ':=' in rule:
        logger, _, level_text = rule.partition(':=')
        if not logger:
            msg = 'Logger name is empty'
            raise RuleError(msg)
    level = _RCUTILS_SEVERITIES.get(level_text.upper())  # ``warning`` is WARN
    if level is None:
        msg = 'Argument does not use a valid severity level'
        raise RuleError(msg)
    return logger, LoggingSeverity(level)


def parse_enclave(value: str) -> str:
    """Read an ``-e``/``--enclave`` path: fully qualified, with topic name rules."""
    if not value.startswith('/'):
        msg = f"Enclave name '{value}' must be fully qualified (start with '/')"
        raise RuleError(msg)
    if value != '/':
        _validate_topic_name(value, 'enclave name')
    return value
