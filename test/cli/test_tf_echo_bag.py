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

"""``tf_echo --bag``: tf2_echo's blocks at the times of a recording, without ROS or DDS."""

from __future__ import annotations

import math
from pathlib import Path

import pytest
from tf_demo.cli.formatting import format_echo_transform
from tf_demo.cli.tf_echo import main
from tf_demo.testing.bags import tf_bytes
from tf_demo.testing.bags import transform
from tf_demo.testing.bags import write_bag

pytest.importorskip('rosbags.rosbag2', reason="tf_echo --bag needs the 'bag' extra (rosbags)")

SECOND = 1_000_000_000
T0 = 1_700_000_000 * SECOND


def circle_bag(path: Path) -> Path:
    """The static camera at T0, then odom -> base_link's circle at 20 Hz from 0.5 s to 2.5 s."""
    messages = [
        ('/tf_static', T0, tf_bytes(transform('base_link', 'camera_link', T0, (0.5, 0, 0.2))))
    ]
    for k in range(10, 51):
        t = k / 20
        stamp = T0 + k * SECOND // 20
        pose = transform('odom', 'base_link', stamp, (math.cos(t), math.sin(t), 0.0), t)
        messages.append(('/tf', stamp, tf_bytes(pose)))
    return write_bag(path, 'mcap', messages)


def test_at_one_instant_prints_the_recorded_transform(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
):
    """--at 1.5 (seconds from the bag's start): the sample recorded then, in tf2_echo's block."""
    assert (
        main(['--bag', str(circle_bag(tmp_path / 'b')), 'odom', 'base_link', '--at', '1.5']) == 0
    )
    t = 30 / 20
    expected = format_echo_transform(
        1_700_000_001,
        500_000_000,
        (math.cos(t), math.sin(t), 0.0),
        (0.0, 0.0, math.sin(t / 2), math.cos(t / 2)),
    )
    assert capsys.readouterr().out == expected


def test_absolute_time_and_chained_static(tmp_path: Path, capsys: pytest.CaptureFixture[str]):
    """--at an absolute time inside the bag; odom -> camera_link goes through the static."""
    at = f'{T0 // SECOND + 2}.0'
    assert main(['--bag', str(circle_bag(tmp_path / 'b')), 'odom', 'camera_link', '--at', at]) == 0
    out = capsys.readouterr().out
    assert out.startswith('At time 1700000002.0\n')
    assert '- Translation: [' in out


def test_the_rate_walks_the_bag_and_fails_before_the_data(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
):
    """At 4 Hz from the bag's start: two failure blocks (no /tf yet), then blocks to the end."""
    assert main(['--bag', str(circle_bag(tmp_path / 'b')), 'odom', 'base_link', '4']) == 0
    out = capsys.readouterr().out
    assert out.count('Failure at ') == 2
    assert out.count('Exception thrown:Lookup would require extrapolation into the past.') == 2
    assert out.count('At time ') == 9  # 0.5 s ... 2.5 s every 0.25 s
    assert 'At time 1700000002.500000000' in out  # the last sample, 2.5 s after the start
    assert out.rstrip().endswith('0.000  0.000  0.000  1.000')


def test_limit_and_json(tmp_path: Path, capsys: pytest.CaptureFixture[str]):
    assert (
        main(
            [
                '--bag',
                str(circle_bag(tmp_path / 'b')),
                'odom',
                'camera_link',
                '20',
                '--limit',
                '3',
                '--json',
            ]
        )
        == 0
    )
    lines = [line for line in capsys.readouterr().out.splitlines() if '"translation"' in line]
    assert len(lines) == 3


def test_bag_problems_are_one_line(tmp_path: Path, capsys: pytest.CaptureFixture[str]):
    assert main(['--bag', str(tmp_path / 'nowhere'), 'a', 'b']) == 1
    err = capsys.readouterr().err
    assert err.splitlines() == [
        f'tf2_echo: {tmp_path / "nowhere"}: no such bag '
        '(a directory with metadata.yaml, or a .mcap or .db3 file)'
    ]
    assert main(['a', 'b', '--at', '3']) == 2
    assert capsys.readouterr().err.strip() == '--at needs --bag PATH (an instant of a recording)'
    assert main(['--bag', 'x', 'a', 'b', '--at', 'soon']) == 2
    assert capsys.readouterr().err.strip() == '--at needs a number of seconds, got soon'


def test_a_damaged_bag_echoes_what_came_before_then_says_where(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    """One second of a -> b, then garbage: 11 blocks (every 0.1 s), one error line, exit 1."""
    stamps = [T0 + k * SECOND // 10 for k in range(11)]
    messages = [
        ('/tf', stamp, tf_bytes(transform('a', 'b', stamp, (k, 0, 0))))
        for k, stamp in enumerate(stamps)
    ]
    messages.append(('/tf', T0 + 2 * SECOND, b'\x00\x01\x00\x00\xff\xff\xff\x7f'))
    bag = write_bag(tmp_path / 'damaged', 'sqlite3', messages)
    assert main(['--bag', str(bag), 'a', 'b', '10']) == 1
    captured = capsys.readouterr()
    assert captured.out.count('- Translation: [') == 11  # up to the last good message
    assert 'Lookup would require extrapolation' not in captured.out
    errors = captured.err.splitlines()
    assert len(errors) == 1
    assert errors[0].startswith(f'tf2_echo: error: {bag}: message on /tf at bag time 1700000002')
    assert errors[0].endswith('(the output used what came before it)')
