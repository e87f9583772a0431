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

"""``tf_monitor --bag``: tf2_monitor's reports over a recording, rates and delays from bag time."""

from __future__ import annotations

from pathlib import Path
import re

import pytest
from tf_demo.cli.tf_monitor import main
from tf_demo.testing.bags import tf_bytes
from tf_demo.testing.bags import transform
from tf_demo.testing.bags import write_bag

pytest.importorskip('rosbags.rosbag2', reason="tf_monitor --bag needs the 'bag' extra (rosbags)")

SECOND = 1_000_000_000
T0 = 1_700_000_000 * SECOND


def recording(path: Path) -> Path:
    """10 s of odom -> base_link at 20 Hz, each received 5 ms after its stamp; map -> odom."""
    messages = [('/tf_static', T0, tf_bytes(transform('map', 'odom', T0, (1, 0, 0))))]
    messages += [
        (
            '/tf',
            T0 + k * SECOND // 20 + 5_000_000,
            tf_bytes(transform('odom', 'base_link', T0 + k * SECOND // 20, (k, 0, 0))),
        )
        for k in range(200)
    ]
    return write_bag(path, 'mcap', messages)


def test_delays_and_rates_come_from_the_recording(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    assert main(['--bag', str(recording(tmp_path / 'run'))]) == 0
    out = capsys.readouterr().out
    assert out.startswith('Gathering data on all frames for 10 seconds...\n')
    assert 'Frame: base_link, published by <no authority available>, Average Delay: 0.005,' in out
    found = re.search(r'Node: <no authority available> ([0-9.]+) Hz', out)
    assert found is not None, out
    rate = float(found.group(1))
    assert 19.5 < rate < 20.5


def test_a_chain_reports_every_interval_of_bag_time(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    path = str(recording(tmp_path / 'run'))
    assert main(['map', 'base_link', '--bag', path, '--interval', '5']) == 0
    out = capsys.readouterr().out
    assert out.count('RESULTS: for map to base_link') == 2
    assert 'Chain is: map -> odom -> base_link' in out
    assert main(['map', 'base_link', '--bag', path, '--interval', '2', '--limit', '1']) == 0
    assert capsys.readouterr().out.count('RESULTS:') == 1
    assert main(['--bag', str(tmp_path / 'nowhere')]) == 1
    assert 'nowhere: no such bag' in capsys.readouterr().err
