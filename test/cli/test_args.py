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

"""Tests of the pure argument parsers (tf2_echo and static_transform_publisher rules)."""

import math

import pytest
from tf_demo.cli._args import OLD_STYLE_WARNING
from tf_demo.cli._args import parse_c_float
from tf_demo.cli._args import parse_echo_args
from tf_demo.cli._args import parse_static_transform_args
from tf_demo.cli._args import split_ros_args
from tf_demo.core.math3d import quat_from_rpy


@pytest.mark.parametrize(
    ('text', 'expected'),
    [
        ('1.5', (1.5, 3)),
        ('  -2e3xyz', (-2000.0, 6)),
        ('1.0foo', (1.0, 3)),
        ('.5', (0.5, 2)),
        ('0x1p4', (16.0, 5)),
        ('1e', (1.0, 1)),
        ('abc', None),
        ('', None),
        ('-', None),
    ],
)
def test_parse_c_float_takes_the_numeric_prefix(text, expected):
    """The strtod-like parser consumes the longest numeric prefix, as std::stod does."""
    assert parse_c_float(text) == expected


def test_parse_c_float_special_values():
    """inf and nan are numbers for strtod."""
    value, _ = parse_c_float('-inf')
    assert value == -math.inf
    value, _ = parse_c_float('nan')
    assert math.isnan(value)


def test_split_ros_args():
    """--ros-args sections run to '--' and are removed from the tool's arguments."""
    tool, ros = split_ros_args(
        ['a', '--ros-args', '-p', 'x:=1', '--', 'b', '--ros-args', '-r', 'q']
    )
    assert tool == ['a', 'b']
    assert ros == ['--ros-args', '-p', 'x:=1', '--ros-args', '-r', 'q']


def test_static_flags():
    """Flags set single components; quaternions are not normalized."""
    parsed = parse_static_transform_args(
        ['--x', '1', '--z', '3.5', '--qz', '2', '--frame-id', 'a', '--child-frame-id', 'b']
    )
    assert parsed.error == ''
    assert parsed.translation == (1.0, 0.0, 3.5)
    assert parsed.rotation == (0.0, 0.0, 2.0, 1.0)
    assert (parsed.frame_id, parsed.child_frame_id) == ('a', 'b')
    assert parsed.warnings == []


def test_static_rpy_flags_use_set_rpy():
    """--roll/--pitch/--yaw give setRPY(roll, pitch, yaw); missing angles are 0."""
    parsed = parse_static_transform_args(
        ['--yaw', '1.0', '--roll', '0.5', '--frame-id', 'a', '--child-frame-id', 'b']
    )
    assert parsed.rotation == quat_from_rpy(0.5, 0.0, 1.0)


def test_static_old_style_eight_is_yaw_pitch_roll():
    """8 positional arguments are x y z yaw pitch roll frame child, and a deprecation warning."""
    parsed = parse_static_transform_args(['1', '2', '3', '0.3', '0.2', '0.1', 'a', 'b'])
    assert parsed.error == ''
    assert parsed.warnings == [OLD_STYLE_WARNING]
    assert parsed.translation == (1.0, 2.0, 3.0)
    assert parsed.rotation == quat_from_rpy(0.1, 0.2, 0.3)


def test_static_old_style_nine_is_quaternion():
    """9 positional arguments are x y z qx qy qz qw frame child."""
    parsed = parse_static_transform_args(['1', '2', '3', '0', '0', '0', '1', 'a', 'b'])
    assert parsed.rotation == (0.0, 0.0, 0.0, 1.0)
    assert (parsed.frame_id, parsed.child_frame_id) == ('a', 'b')


@pytest.mark.parametrize(
    ('args', 'error'),
    [
        (['--x'], 'Not enough arguments for --x'),
        (['--x', 'abc', '--frame-id', 'a'], 'Failed to parse --x argument as float'),
        (
            ['--qx', '1', '--roll', '1', '--frame-id', 'a', '--child-frame-id', 'b'],
            'Cannot specify both quaternion and Euler rotations',
        ),
        (
            ['--x', '1', '1', '2', '3', '0', '0', '0', 'a', 'b'],
            'Cannot specify both new-style (flags) and old-style (arguments)',
        ),
        (['1', '2', '3'], 'Extra unparsed arguments on command-line'),
        (['--child-frame-id', 'b'], 'Frame id must not be empty'),
        (['--frame-id', 'a'], 'Child frame id must not be empty'),
        ([], 'Frame id must not be empty'),
        (['x', '2', '3', '0', '0', '0', 'a', 'b'], 'Failed to parse x argument as float'),
        (['1', '2', '3', '0', '0', 'q', '1', 'a', 'b'], 'Failed to parse qz argument as float'),
        (
            ['--y', '1e999', '--frame-id', 'a', '--child-frame-id', 'b'],
            'Failed to parse --y argument as float',
        ),
    ],
)
def test_static_errors(args, error):
    """Every upstream error text."""
    assert parse_static_transform_args(args).error == error


def test_static_parse_error_wins_over_help():
    """A parse error is reported even with --help; --help alone succeeds."""
    assert parse_static_transform_args(['--help', '--x']).error == 'Not enough arguments for --x'
    parsed = parse_static_transform_args(['-h'])
    assert parsed.help
    assert parsed.error == ''


def test_static_numeric_prefix_is_accepted():
    """stod accepts '1.5m' as 1.5."""
    parsed = parse_static_transform_args(
        ['--x', '1.5m', '--frame-id', 'a', '--child-frame-id', 'b']
    )
    assert parsed.translation == (1.5, 0.0, 0.0)


def test_echo_counts_and_rates():
    """2 arguments: rate 1; 3: the rate; other counts: usage with exit code 1."""
    parsed = parse_echo_args(['a', 'b'])
    assert (parsed.source_frame, parsed.target_frame, parsed.rate_hz) == ('a', 'b', 1.0)
    assert parse_echo_args(['a', 'b', '10']).rate_hz == 10.0
    for args in ([], ['a'], ['a', 'b', 'c', 'd']):
        parsed = parse_echo_args(args)
        assert parsed.show_usage
        assert parsed.exit_code == 1


def test_echo_bad_rates():
    """A non-number exits with 2, trailing junk with 3, upstream's message in both cases."""
    parsed = parse_echo_args(['a', 'b', 'fast'])
    assert parsed.exit_code == 2
    assert parsed.error == "Failed to convert rate argument 'fast' to a floating-point number"
    parsed = parse_echo_args(['a', 'b', '1.0foo'])
    assert parsed.exit_code == 3
    assert parsed.error == "Failed to convert rate argument '1.0foo' to a floating-point number"
    assert parse_echo_args(['a', 'b', '0']).exit_code == 2


def test_echo_extras():
    """-p, --limit and --json are recognised anywhere; a negative rate is not a flag."""
    parsed = parse_echo_args(['--json', 'a', '-p', '5', 'b', '--limit', '2'])
    assert (parsed.json, parsed.precision, parsed.limit) == (True, 5, 2)
    assert (parsed.source_frame, parsed.target_frame) == ('a', 'b')
    assert parse_echo_args(['a', 'b', '--limit', '0']).exit_code == 2
    assert parse_echo_args(['a', 'b', '-p']).exit_code == 2
    assert parse_echo_args(['a', 'b', '-p', 'x']).exit_code == 2
