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

import argparse
import math

import pytest
from tf_demo.cli._args import c_float_range_error
from tf_demo.cli._args import count_argument
from tf_demo.cli._args import OLD_STYLE_WARNING
from tf_demo.cli._args import parse_echo_args
from tf_demo.cli._args import parse_static_transform_args
from tf_demo.cli._args import wait_time_error
from tf_demo.cli._args import whole_number
from tf_demo.core.math3d import quat_from_rpy
from tf_demo.nodes.helpers import rate_error
from tf_demo.transport.params_c_numbers import c_strtod
from tf_demo.transport.params_c_numbers import CDouble


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
            'Failed to parse --y argument as float: out of range (too large)',
        ),
        # Issue 10: a 400-digit number (stod: out_of_range; upstream aborts) is one clear line.
        (
            ['--x', '1' * 400, '--frame-id', 'a', '--child-frame-id', 'b'],
            'Failed to parse --x argument as float: out of range (too large)',
        ),
        (
            ['--qw', '0x' + 'f' * 400, '--frame-id', 'a', '--child-frame-id', 'b'],
            'Failed to parse --qw argument as float: out of range (too large)',
        ),
        (
            ['--yaw', '1e-400', '--frame-id', 'a', '--child-frame-id', 'b'],
            'Failed to parse --yaw argument as float: out of range (too small)',
        ),
        (
            ['1', '2', '9' * 5000, '0', '0', '0', 'a', 'b'],
            'Failed to parse z argument as float: out of range (too large)',
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


def test_static_zero_and_infinity_spelled_out_are_in_range():
    """A literal zero however written, and a spelled inf, are not range errors (stod agrees)."""
    for text in ('0', '0e-400', '0x0p-9999', '-0.0', '.0e5'):
        assert c_float_range_error(_strtod(text)) is None
    assert c_float_range_error(_strtod('inf')) is None
    assert c_float_range_error(_strtod('1e308')) is None
    assert c_float_range_error(_strtod('1e39')) is None
    assert (
        c_float_range_error(_strtod('1e39'), single=True) == 'out of range (too large for a float)'
    )
    assert c_float_range_error(_strtod('1e-39'), single=True) == 'out of range (too small)'


def _strtod(text: str) -> CDouble:
    parsed = c_strtod(text)
    assert parsed is not None
    return parsed


@pytest.mark.parametrize(
    ('rate', 'problem'),
    [
        ('1e-300', 'out of range (too small)'),
        ('1e-320', 'out of range (too small)'),
        ('1e-39', 'out of range (too small)'),
        ('1e39', 'out of range (too large for a float)'),
        ('1e400', 'out of range (too large)'),
        ('0x' + 'f' * 300, 'out of range (too large)'),
    ],
)
def test_echo_rate_out_of_float_range_exits_2(rate, problem):
    """tf2_echo's stof throws out_of_range (and aborts); we print one line and exit 2."""
    parsed = parse_echo_args(['a', 'b', rate])
    assert parsed.exit_code == 2
    assert parsed.error == (
        f"Failed to convert rate argument '{rate}' to a floating-point number: {problem}"
    )


def test_echo_rate_whose_period_overflows_exits_2():
    """1e-10 Hz is a float, but its period does not fit rclcpp::Rate's int64 nanoseconds."""
    parsed = parse_echo_args(['a', 'b', '1e-10'])
    assert parsed.exit_code == 2
    assert parsed.error.startswith('echo_rate is too small: the period 1/rate must be at most')
    assert parse_echo_args(['a', 'b', '1e-9']).rate_hz == 1e-9
    for rate in ('nan', 'inf', '-1', '0', '-0'):
        parsed = parse_echo_args(['a', 'b', rate])
        assert parsed.exit_code == 2
        assert 'must be a positive finite number of Hz' in parsed.error


def test_echo_huge_limit_and_precision():
    """A 5,000-digit --limit is refused in one short line; any huge precision means 17."""
    parsed = parse_echo_args(['a', 'b', '--limit', '9' * 5000])
    assert parsed.exit_code == 2
    assert parsed.error.startswith('--limit needs a whole number from 1 to 1000000000000000000')
    assert len(parsed.error) < 200
    assert parse_echo_args(['a', 'b', '--limit', '0' * 50 + '7']).limit == 7
    assert parse_echo_args(['a', 'b', '-p', '9' * 5000]).precision == 17
    assert parse_echo_args(['a', 'b', '-p', '١']).exit_code == 2  # not an ASCII digit


def test_whole_numbers_and_counts():
    """whole_number takes ASCII digits up to a maximum; count_argument is its argparse form."""
    assert whole_number('42', 100) == 42
    assert whole_number('101', 100) is None
    assert whole_number('9' * 5000, 100) is None
    assert whole_number(' 4', 100) is None
    assert whole_number('1_0', 100) is None
    assert count_argument('3') == 3
    for text in ('0', '-1', '1e3', '9' * 5000, ''):
        with pytest.raises(argparse.ArgumentTypeError):
            count_argument(text)


def test_wait_time_and_rate_limits():
    """Wait times are finite and >= 0; rates are positive, finite, with an int64-ns period."""
    assert wait_time_error(0.0) is None
    assert wait_time_error(1e6) is None
    for bad in (-1.0, math.nan, math.inf):
        assert wait_time_error(bad) is not None
    assert rate_error(1e-9) is None
    assert rate_error(1e300) is None
    for bad in (0.0, -1.0, math.nan, math.inf, 1e-10, 1e-300):
        assert rate_error(bad) is not None
