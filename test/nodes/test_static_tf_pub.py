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

"""Pure logic of static_tf_pub: transforms files, rotations, what it prints, one-line errors."""

from __future__ import annotations

import math
from pathlib import Path

import pytest
from tf_demo.nodes.helpers import NodeConfigError
from tf_demo.nodes.static_tf_pub import format_published
from tf_demo.nodes.static_tf_pub import load_specs_file
from tf_demo.nodes.static_tf_pub import spec_from_values
from tf_demo.nodes.static_tf_pub import specs_from_yaml
from tf_demo.nodes.static_tf_pub import StaticTransformSpec

REPO = Path(__file__).resolve().parents[2]


def test_rep105_example_file_parses_to_three_static_transforms() -> None:
    """config/rep105_static_transforms.yaml: base_footprint->base_link->{lidar,camera}."""
    specs = load_specs_file(str(REPO / 'config' / 'rep105_static_transforms.yaml'))
    assert [(s.parent, s.child) for s in specs] == [
        ('base_footprint', 'base_link'),
        ('base_link', 'lidar_link'),
        ('base_link', 'camera_link'),
    ]
    assert specs[2].translation == (0.5, 0.0, 0.2)
    assert specs[2].rotation == (0.0, 0.0, 0.0, 1.0)


def test_rotation_accepts_rpy_and_normalises_quaternions() -> None:
    """Three numbers are roll/pitch/yaw (tf2 setRPY); four are a quaternion, normalised."""
    rpy = spec_from_values('a', 'b', [0, 0, 0], [0.1, 0.2, 0.3])
    assert rpy.rotation == pytest.approx((0.034270799, 0.106020511, 0.143572175, 0.983347443))
    quat = spec_from_values('a', 'b', [0, 0, 0], [0.0, 0.0, 2.0, 2.0])
    assert quat.rotation == pytest.approx((0.0, 0.0, math.sqrt(0.5), math.sqrt(0.5)))


@pytest.mark.parametrize(
    ('text', 'message'),
    [
        ('transforms: [', r'<f>: line \d+ is not valid YAML'),
        ('frames: []', "<f>: expected a mapping with a 'transforms' list"),
        ('transforms: []', '<f>: the transforms list is empty'),
        (
            'transforms: [{parent: a, translation: [0, 0, 0]}]',
            r"transforms\[0\] is missing 'child'",
        ),
        (
            'transforms: [{parent: a, child: b, translation: [0, 0]}]',
            r'transforms\[0\] translation must be 3 numbers \[x, y, z\], got \[0, 0\]',
        ),
        (
            'transforms: [{parent: a, child: b, translation: [0, 0, 0], rotation: [1, 2]}]',
            r'transforms\[0\] rotation must be 3 numbers \[roll, pitch, yaw\] or 4',
        ),
        (
            'transforms: [{parent: a, child: b, translation: [0, 0, 0], rotation: [0, 0, 0, 0]}]',
            'quaternion .* must not be zero',
        ),
        ('transforms: [{parent: /a, child: b, translation: [0, 0, 0]}]', "cannot start with '/'"),
        ('transforms: [{parent: a, child: a, translation: [0, 0, 0]}]', "both 'a'"),
        (
            'transforms: [{parent: a, child: b, translation: [0, 0, 0]},'
            ' {parent: a, child: b, translation: [1, 0, 0]}]',
            r"transforms\[1\]: child frame 'b' appears twice",
        ),
        (
            'transforms: [{parent: a, child: b, translation: [0, 0, 0], scale: 2}]',
            r'transforms\[0\] has unknown key\(s\) scale',
        ),
        ('transforms: [{parent: a, child: b, translation: [.nan, 0, 0]}]', 'finite'),
    ],
)
def test_bad_transform_files_give_one_line_errors(text: str, message: str) -> None:
    """Every invalid file is refused with one line naming the file, entry and field."""
    with pytest.raises(NodeConfigError, match=message.replace('<f>', 'f.yaml')) as info:
        specs_from_yaml(text, 'f.yaml')
    assert '\n' not in str(info.value)


def test_format_published_lists_every_transform() -> None:
    """The start-up log line lists parent -> child with translation and rotation."""
    text = format_published([StaticTransformSpec('a', 'b', (0.5, 0.0, 0.2), (0, 0, 0, 1.0))])
    assert text == (
        'Publishing 1 static transform(s) on /tf_static:\n'
        '  a -> b: translation (0.5, 0, 0.2), rotation (0, 0, 0, 1)'
    )


@pytest.mark.parametrize(
    ('translation', 'shown'),
    [
        (f'[{"9" * 400}, 0, 0]', '<an integer of about 40'),
        (f'[1, {"9" * 5000}, 0]', 'a value cannot be converted (Exceeds the limit (4300 digits)'),
        ('[1.0e+400, 0, 0]', 'inf'),
        ('[.nan, 0, 0]', 'nan'),
    ],
)
def test_a_transforms_file_with_a_huge_or_non_finite_number_is_one_line(
    translation: str, shown: str
) -> None:
    """A 400-digit integer in a translation is refused like inf: the entry named, no traceback."""
    text = f'transforms: [{{parent: a, child: b, translation: {translation}}}]\n'
    with pytest.raises(NodeConfigError) as caught:
        specs_from_yaml(text, 'huge.yaml')
    message = str(caught.value)
    assert message.startswith('huge.yaml:'), message
    assert shown in message
    assert len(message) < 400
    assert '\n' not in message
