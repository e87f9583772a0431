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

"""tf_relay's rules: namespaces and the loop guard, frame prefixes, the static union."""

from __future__ import annotations

import pytest
from tf_demo.core.relay import check_shared_frames
from tf_demo.core.relay import DEFAULT_SHARED_FRAMES
from tf_demo.core.relay import frame_prefix
from tf_demo.core.relay import FramePrefixer
from tf_demo.core.relay import relay_namespaces
from tf_demo.core.relay import RelayConfigError
from tf_demo.core.relay import StaticUnion

POSE = ((1.0, 2.0, 3.0), (0.0, 0.0, 0.0, 1.0))


def test_namespaces_are_absolute_and_kept_in_order() -> None:
    assert relay_namespaces(['/robot2', 'robot1', '/fleet/robot3']) == (
        '/robot2',
        '/robot1',
        '/fleet/robot3',
    )


@pytest.mark.parametrize(
    ('given', 'problem'),
    [
        ([], 'no namespace to relay'),
        (['/'], 'is the global one'),
        ([''], 'is the global one'),
        (['/robot1', '/robot1'], '/robot1 is given twice'),
        (['robot1', '/robot1'], '/robot1 is given twice'),
    ],
)
def test_bad_namespace_lists_are_one_line_errors(given: list[str], problem: str) -> None:
    with pytest.raises(RelayConfigError, match=problem) as caught:
        relay_namespaces(given)
    assert '\n' not in str(caught.value)


def test_frame_prefix_drops_the_leading_slash() -> None:
    assert frame_prefix('/robot1') == 'robot1/'
    assert frame_prefix('/fleet/robot1') == 'fleet/robot1/'


def test_frames_are_prefixed_unless_shared_or_already_prefixed() -> None:
    name = FramePrefixer('/robot1', DEFAULT_SHARED_FRAMES)
    assert name('odom') == 'robot1/odom'
    assert name('base_link') == 'robot1/base_link'
    assert name('robot1/base_link') == 'robot1/base_link'
    assert name('robot10/base_link') == 'robot1/robot10/base_link'
    assert [name(f) for f in ('map', 'world', 'earth')] == ['map', 'world', 'earth']
    assert name('map') == 'map'  # remembered
    assert FramePrefixer('/robot1', ['odom'])('map') == 'robot1/map'


def test_the_remembered_names_are_bounded() -> None:
    name = FramePrefixer('/r', ())
    for index in range(FramePrefixer.MAX_NAMES + 10):
        assert name(f'f{index}') == f'r/f{index}'
    assert len(name._names) <= FramePrefixer.MAX_NAMES


@pytest.mark.parametrize('frame', ['', '/map'])
def test_shared_frames_must_be_tf2_names(frame: str) -> None:
    with pytest.raises(RelayConfigError, match='shared frame'):
        check_shared_frames(['map', frame])
    assert check_shared_frames([]) == frozenset()


def test_static_union_keeps_every_child_and_replaces_per_child() -> None:
    union = StaticUnion()
    assert union.update([('r1/base', 'r1/laser', 1, *POSE), ('r1/base', 'r1/cam', 1, *POSE)])
    assert union.update([('r2/base', 'r2/laser', 2, *POSE)])
    assert not union.update([('r1/base', 'r1/laser', 1, *POSE)])  # the same: nothing to send
    assert union.update([('r1/base', 'r1/laser', 3, *POSE)])  # a new stamp replaces it
    assert union.update([('r1/other', 'r1/cam', 4, *POSE)])  # a new parent too
    assert union.transforms() == [
        ('r1/base', 'r1/laser', 3, *POSE),
        ('r1/other', 'r1/cam', 4, *POSE),
        ('r2/base', 'r2/laser', 2, *POSE),
    ]
    assert len(union) == 3
