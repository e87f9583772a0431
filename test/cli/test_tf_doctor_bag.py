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

"""``tf_doctor --bag``: every check on a recording, the timing checks included."""

from __future__ import annotations

from pathlib import Path

import pytest
from tf_demo.cli.tf_doctor import main
from tf_demo.testing.bags import tf_bytes
from tf_demo.testing.bags import transform
from tf_demo.testing.bags import write_bag

pytest.importorskip('rosbags.rosbag2', reason="tf_doctor --bag needs the 'bag' extra (rosbags)")

SECOND = 1_000_000_000
T0 = 1_700_000_000 * SECOND


def recording(path: Path) -> Path:
    """10 s: odom -> base_link at 20 Hz stops after 5 s; map -> beacon at 1 Hz; an island."""
    messages = [
        ('/tf_static', T0, tf_bytes(transform('map', 'odom', T0, (1, 0, 0)))),
        ('/tf_static', T0, tf_bytes(transform('base_footprint', 'laser', T0, (0, 0, 0.3)))),
    ]
    messages += [
        (
            '/tf',
            T0 + k * SECOND // 20,
            tf_bytes(transform('odom', 'base_link', T0 + k * SECOND // 20, (k / 100, 0, 0))),
        )
        for k in range(100)
    ]
    messages += [
        ('/tf', T0 + k * SECOND, tf_bytes(transform('map', 'beacon', T0 + k * SECOND, (0, k, 0))))
        for k in range(11)
    ]
    return write_bag(path, 'sqlite3', sorted(messages, key=lambda m: m[1]))


def test_a_recording_gets_every_check(tmp_path: Path, capsys: pytest.CaptureFixture[str]):
    """The stopped stream, the sparse one and the island are found, with the bag's numbers."""
    path = recording(tmp_path / 'run')
    assert main(['--bag', str(path)]) == 1
    out = capsys.readouterr().out
    assert out.startswith(f'tf_doctor: {path}: 113 messages, 6 frames, 2 trees.')
    assert 'odom→base_link stopped arriving 5.050 s before the end of the recording' in out
    assert 'map→beacon arrives at 1 Hz, with gaps up to 1.000 s' in out
    assert '[disconnected]' in out
    # when, in bag time: the last message of the stopped stream, the first of the sparse one
    stopped = out.split('[stopped]', 1)[1].split('Fix:', 1)[0]
    assert '  At: bag time 1700000004.950 s (4.950 s in)' in stopped
    sparse = out.split('[sparse_data]', 1)[1].split('Fix:', 1)[0]
    assert '  At: bag time 1700000000.000 s (0.000 s in)' in sparse


def test_a_clock_reset_in_a_recording_is_found_with_its_time(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    """A simulation restarted 3 s into the recording: its stamps start again from 0."""
    messages = []
    for k in range(100):  # 5 s at 20 Hz; at 3 s the publisher's clock restarts at 100 s
        bag_time = T0 + k * SECOND // 20
        stamp = (
            100 * SECOND + (k - 60) * SECOND // 20 if k >= 60 else 200 * SECOND + k * SECOND // 20
        )
        messages.append(
            ('/tf', bag_time, tf_bytes(transform('odom', 'base_link', stamp, (k, 0, 0))))
        )
    path = write_bag(tmp_path / 'reset', 'mcap', messages)
    main(['--bag', str(path)])
    out = capsys.readouterr().out
    jump = out.split('[clock_jump]', 1)[1].split('Fix:', 1)[0]
    assert 'jumped back by 102.950 s' in ' '.join(jump.split())
    assert '  At: bag time 1700000003.000 s (3.000 s in)' in jump
    assert main(['--bag', str(path), '--json']) in {0, 1}
    import json

    (finding,) = [
        f for f in json.loads(capsys.readouterr().out)['findings'] if f['kind'] == 'clock_jump'
    ]
    assert finding['at_s'] == 1_700_000_003.0


def test_json_and_a_bad_bag(tmp_path: Path, capsys: pytest.CaptureFixture[str]):
    import json

    path = recording(tmp_path / 'run')
    assert main(['--bag', str(path), '--json']) == 1
    kinds = {finding['kind'] for finding in json.loads(capsys.readouterr().out)['findings']}
    assert {'stopped', 'sparse_data', 'disconnected'} <= kinds
    assert main(['--bag', str(tmp_path / 'nowhere')]) == 2
    assert 'nowhere: no such bag' in capsys.readouterr().err
