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

"""``--params-file`` read as rcl reads it: node keys and wildcards, tags, malformed files."""

from pathlib import Path

import pytest
from tf_demo.transport.ros_args import parse_ros_args
from tf_demo.transport.ros_args import RosArgsError


def test_params_file_wildcards_match_node_names(tmp_path: Path) -> None:
    """/** matches everything, /ns/* one level, /*/name any namespace of one token."""
    params = tmp_path / 'p.yaml'
    params.write_text(
        '/**:\n  ros__parameters:\n    a: 1\n'
        '/ns/*:\n  ros__parameters:\n    b: 2\n'
        '/*/talker:\n  ros__parameters:\n    c: 3\n'
        'ns:\n  talker:\n    ros__parameters:\n      d: 4\n',
        encoding='utf-8',
    )
    parsed = parse_ros_args(['--ros-args', '--params-file', str(params)])
    assert set(parsed.parameter_overrides('/ns/talker')) == {'a', 'b', 'c', 'd'}
    assert set(parsed.parameter_overrides('/talker')) == {'a'}
    assert set(parsed.parameter_overrides('/other/talker')) == {'a', 'c'}


TAGGED_PARAMS = (
    '/**:\n  ros__parameters:\n'
    '    translation: !!python/tuple [0.5, 0.0, 0.25]\n'
    '    count: !custom 5\n'
    '    label: !!str 5\n'
    '    flags: !!python/tuple [true, false]\n'
)


def _tagged_overrides(tmp_path: Path) -> dict[str, object]:
    params = tmp_path / 'tagged.yaml'
    params.write_text(TAGGED_PARAMS, encoding='utf-8')
    parsed = parse_ros_args(['--ros-args', '--params-file', str(params)])
    return {name: p.value for name, p in parsed.parameter_overrides('/n').items()}


def test_params_file_tags_are_ignored_but_str(tmp_path: Path) -> None:
    """rcl ignores YAML tags but !!str: launch_ros writes lists as !!python/tuple sequences."""
    values = _tagged_overrides(tmp_path)
    assert values == {
        'translation': [0.5, 0.0, 0.25],
        'count': 5,
        'label': '5',
        'flags': [True, False],
    }


@pytest.mark.rclpy_world
def test_params_file_tags_read_as_the_real_rcl_reads_them(tmp_path: Path, ros: None) -> None:
    """The same params file through the real rcl: every value and type is ours."""
    from tf_demo import transport

    ours = _tagged_overrides(tmp_path)
    node = transport.create_node(
        'n',
        cli_args=['--ros-args', '--params-file', str(tmp_path / 'tagged.yaml')],
        automatically_declare_parameters_from_overrides=True,
    )
    try:
        real = {name: node.get_parameter(name).value for name in ours}
    finally:
        node.destroy_node()
    assert {k: list(v) if isinstance(v, (list, tuple)) else v for k, v in real.items()} == ours
    assert {k: type(v) for k, v in real.items() if not isinstance(v, list)} == {
        k: type(v) for k, v in ours.items() if not isinstance(v, list)
    }


def test_malformed_params_file_names_the_problem(tmp_path: Path) -> None:
    """A params file that is not rcl's schema is rejected with the offending key."""
    params = tmp_path / 'bad.yaml'
    params.write_text('talker:\n  rate: 1.0\n', encoding='utf-8')
    with pytest.raises(RosArgsError, match="'talker/rate' is not a node name"):
        parse_ros_args(['--ros-args', '--params-file', str(params)])
    params.write_text('talker:\n  ros__parameters:\n    x: [1\n', encoding='utf-8')
    with pytest.raises(RosArgsError, match=r'bad\.yaml:4: invalid YAML \(column 1\)'):
        parse_ros_args(['--ros-args', '--params-file', str(params)])
