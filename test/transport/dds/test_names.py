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

from conftest import STANDALONE_ONLY
import pytest

pytest.importorskip('cyclonedds', reason=STANDALONE_ONLY)

from tf_demo.transport import dds_backend


@pytest.mark.parametrize(
    ('topic', 'namespace', 'expanded'),
    [
        ('tf', '/', '/tf'),
        ('/tf', '/robot', '/tf'),
        ('tf', '/robot', '/robot/tf'),
        ('a/b', '/robot', '/robot/a/b'),
        ('~', '/robot', '/robot/talker'),
        ('~/status', '/', '/talker/status'),
        ('~/status', '/robot', '/robot/talker/status'),
        ('{node}/x', '/', '/talker/x'),
        ('{ns}/x', '/robot', '/robot/x'),
    ],
)
def test_topic_names_expand_like_rcl(topic, namespace, expanded):
    """Relative names join the namespace, ~ is the node's FQN, {node}/{ns} are substituted."""
    assert dds_backend.expand_topic_name(topic, 'talker', namespace) == expanded


@pytest.mark.parametrize(
    ('topic', 'reason', 'index'),
    [
        ('', 'must not be empty', 0),
        ('a//b', "repeated '/'", 1),
        ('a/1b', 'must not start with a number', 2),
        ('a b', 'characters other than', 1),
        ('tf/', "must not end with '/'", 2),
        ('~x', "'~' must be followed by '/'", 1),
        ('a~', "'~' must only be the first character", 1),
        ('{bogus}/x', 'unknown substitution', 6),
    ],
)
def test_invalid_topic_names_are_refused_with_a_pointer(topic, reason, index):
    """Each rcl topic-name rule yields InvalidNameError naming the rule and the position."""
    with pytest.raises(dds_backend.InvalidNameError) as caught:
        dds_backend.expand_topic_name(topic, 'talker', '/')
    assert reason in str(caught.value)
    assert caught.value.index == index


def test_node_name_and_namespace_rules():
    """Node names are alphanumerics/underscore not starting with a digit; namespaces absolute."""
    dds_backend.validate_node_name('my_node2')
    dds_backend.validate_namespace('/')
    dds_backend.validate_namespace('/a/b_c')
    with pytest.raises(dds_backend.InvalidNameError, match='must not start with a number'):
        dds_backend.validate_node_name('2node')
    with pytest.raises(dds_backend.InvalidNameError, match='other than alphanumerics') as caught:
        dds_backend.validate_node_name('my-node')
    assert "\n  'my-node'\n     ^" in str(caught.value)
    with pytest.raises(dds_backend.InvalidNameError, match='must be absolute'):
        dds_backend.validate_namespace('robot')
    with pytest.raises(dds_backend.InvalidNameError, match="must not end with '/'"):
        dds_backend.validate_namespace('/robot/')
