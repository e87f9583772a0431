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

"""Node names, namespaces and topic names: rcl's validation and expansion rules (pure)."""

from __future__ import annotations

import re


class InvalidNameError(ValueError):
    """A node name, namespace or topic name breaks ROS 2's naming rules; says where and why."""

    def __init__(self, kind: str, name: str, reason: str, index: int) -> None:
        pointer = ' ' * (index + 3) + '^'
        super().__init__(f"Invalid {kind}: {reason}:\n  '{name}'\n{pointer}")
        self.name = name
        self.reason = reason
        self.index = index


_NODE_NAME_RE = re.compile(r'[A-Za-z0-9_]*')
_TOKEN_CHARS_RE = re.compile(r'[A-Za-z0-9_/~{}]')


def validate_node_name(name: str) -> None:
    """Check a node name as ``rmw_validate_node_name``; raise :class:`InvalidNameError`."""
    if not name:
        raise InvalidNameError('node name', name, 'node name must not be empty', 0)
    match = _NODE_NAME_RE.match(name)
    end = match.end() if match else 0
    if end != len(name):
        raise InvalidNameError(
            'node name',
            name,
            'node name must not contain characters other than alphanumerics or "_"',
            end,
        )
    if name[0].isdigit():
        raise InvalidNameError('node name', name, 'node name must not start with a number', 0)
    if len(name) > 255:
        raise InvalidNameError('node name', name, 'node name length must not exceed 255', 255)


def validate_namespace(namespace: str) -> None:
    """Check an absolute namespace as ``rmw_validate_namespace``."""
    kind = 'namespace'
    if not namespace:
        raise InvalidNameError(kind, namespace, 'namespace must not be empty', 0)
    if not namespace.startswith('/'):
        raise InvalidNameError(kind, namespace, 'namespace must be absolute', 0)
    if namespace == '/':
        return
    if namespace.endswith('/'):
        raise InvalidNameError(kind, namespace, "namespace must not end with '/'", len(namespace))
    _validate_tokens(kind, namespace)


def _validate_tokens(kind: str, name: str, extra_chars: str = '') -> None:
    allowed = '_/' + extra_chars
    for index, char in enumerate(name):
        if not (char.isascii() and (char.isalnum() or char in allowed)):
            raise InvalidNameError(
                kind,
                name,
                f'{kind} must not contain characters other than alphanumerics, "_" or "/"',
                index,
            )
    if '//' in name:
        raise InvalidNameError(kind, name, "must not contain repeated '/'", name.index('//'))
    position = 0
    for token in name.split('/'):
        if token and token[0].isdigit():
            raise InvalidNameError(kind, name, 'a token must not start with a number', position)
        position += len(token) + 1


def expand_topic_name(topic: str, node_name: str, namespace: str) -> str:
    """
    Expand and validate a topic name as rcl and rmw do (``rcl_expand_topic_name``).

    ``~`` is the node's fully qualified name, relative names are put in the namespace, and
    ``{node}``/``{ns}``/``{namespace}`` substitutions are replaced.

    :raises InvalidNameError: naming the offending character.
    """
    kind = 'topic name'
    if not topic:
        raise InvalidNameError(kind, topic, 'topic name must not be empty', 0)
    for index, char in enumerate(topic):
        if not (char.isascii() and _TOKEN_CHARS_RE.match(char)):
            raise InvalidNameError(
                kind,
                topic,
                'topic name must not contain characters other than alphanumerics, '
                '"_", "~", "{", "}" or "/"',
                index,
            )
    if '~' in topic[1:]:
        raise InvalidNameError(
            kind, topic, "'~' must only be the first character", topic.index('~', 1)
        )
    if topic.startswith('~') and len(topic) > 1 and topic[1] != '/':
        raise InvalidNameError(kind, topic, "'~' must be followed by '/'", 1)
    if topic.endswith('/'):
        raise InvalidNameError(kind, topic, "topic name must not end with '/'", len(topic) - 1)
    _validate_tokens(kind, topic, '~{}')
    node_fqn = namespace.rstrip('/') + '/' + node_name
    expanded = topic
    for key, value in (('{node}', node_name), ('{ns}', namespace), ('{namespace}', namespace)):
        expanded = expanded.replace(key, value)
    if '{' in expanded or '}' in expanded:
        index = max(expanded.find('{'), expanded.find('}'))
        raise InvalidNameError(kind, topic, 'unknown substitution', index)
    if expanded.startswith('~'):
        expanded = node_fqn + expanded[1:]
    elif not expanded.startswith('/'):
        expanded = namespace.rstrip('/') + '/' + expanded
    if expanded.endswith('/') and expanded != '/':
        raise InvalidNameError(kind, expanded, "topic name must not end with '/'", len(expanded))
    _validate_tokens(kind, expanded)
    return expanded
