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

"""static_transform_publisher as a real process: usage, errors and exit codes."""

from __future__ import annotations

import re

import pytest
from tf_demo.cli.formatting import STATIC_USAGE
from tool_runs import LOG_PREFIX
from tool_runs import run

pytestmark = [pytest.mark.dds]


def test_static_publisher_help_exits_0_with_usage(spawn):
    """--help prints upstream's usage on stdout and exits 0."""
    code, out, _ = run(spawn, 'static_transform_publisher', '--help')
    assert code == 0
    assert out == STATIC_USAGE


@pytest.mark.parametrize(
    ('args', 'error'),
    [
        (['--x'], 'Not enough arguments for --x'),
        (
            ['--x', 'one', '--frame-id', 'a', '--child-frame-id', 'b'],
            'Failed to parse --x argument as float',
        ),
        (['--frame-id', 'a'], 'Child frame id must not be empty'),
        (['1', '2', '3'], 'Extra unparsed arguments on command-line'),
        (
            ['--qx', '0', '--yaw', '1', '--frame-id', 'a', '--child-frame-id', 'b'],
            'Cannot specify both quaternion and Euler rotations',
        ),
    ],
)
def test_static_publisher_errors_exit_1(spawn, args, error):
    """Each parse error logs upstream's ERROR line with an empty logger, prints usage, exits 1."""
    code, out, err = run(spawn, 'static_transform_publisher', *args)
    assert code == 1
    assert out == STATIC_USAGE
    assert re.fullmatch(
        LOG_PREFIX + re.escape(f'error parsing command line arguments: {error}\n'), err
    )
    assert '[]: ' in err


def test_static_publisher_old_style_warns_and_conflict_fails(spawn):
    """Old-style arguments with a frame flag: the deprecation WARN, then the conflict error."""
    code, _, err = run(
        spawn,
        'static_transform_publisher',
        '1',
        '2',
        '3',
        '0',
        '0',
        '0',
        'a',
        'b',
        '--frame-id',
        'c',
    )
    assert code == 1
    lines = err.splitlines()
    assert lines[0].endswith(
        '[]: Old-style arguments are deprecated; see --help for new-style arguments'
    )
    assert lines[1].endswith(
        'error parsing command line arguments: Cannot specify both new-style (flags) and '
        'old-style (arguments)'
    )


def test_static_publisher_same_frames_exit_1(spawn):
    """frame_id == child_frame_id logs upstream's ERROR and exits 1."""
    code, _, err = run(
        spawn, 'static_transform_publisher', '--frame-id', 'a', '--child-frame-id', 'a'
    )
    assert code == 1
    assert "cannot publish static transform from 'a' to 'a', exiting" in err
