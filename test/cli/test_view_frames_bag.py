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

"""``view_frames --bag``: the tree of a recording as upstream's DOT, with the bag's rates."""

from __future__ import annotations

import os
from pathlib import Path
import shutil

import pytest
from tf_demo.cli.view_frames import main
from tf_demo.testing.bags import tf_bytes
from tf_demo.testing.bags import transform
from tf_demo.testing.bags import write_bag

pytest.importorskip('rosbags.rosbag2', reason="view_frames --bag needs the 'bag' extra (rosbags)")

SECOND = 1_000_000_000
T0 = 1_700_000_000 * SECOND


def test_the_recorded_tree_is_drawn(tmp_path: Path, monkeypatch: pytest.MonkeyPatch):
    """map -> odom (static) and odom -> base_link at 10 Hz for 2 s: both edges, 10 Hz average."""
    messages = [('/tf_static', T0, tf_bytes(transform('map', 'odom', T0, (1, 0, 0))))]
    messages += [
        (
            '/tf',
            T0 + k * SECOND // 10,
            tf_bytes(transform('odom', 'base_link', T0 + k * SECOND // 10, (k, 0, 0))),
        )
        for k in range(21)
    ]
    path = write_bag(tmp_path / 'run', 'mcap', messages)
    monkeypatch.chdir(tmp_path)
    code = main(['--bag', str(path), '-o', 'frames'])
    dot = (tmp_path / 'frames.gv').read_text()
    assert '"map" -> "odom"' in dot
    assert '"odom" -> "base_link"' in dot
    assert 'Average rate: 10.5' in dot  # tf2's rate: 21 samples over 2 s
    if shutil.which('dot'):
        assert code == 0
        assert os.path.getsize(tmp_path / 'frames.pdf') > 0


def test_a_bag_without_tf_is_one_line(tmp_path: Path, capsys: pytest.CaptureFixture[str]):
    path = write_bag(
        tmp_path / 'other', 'mcap', [('/chatter', T0, b'\x00\x01\x00\x00')], 'std_msgs/msg/String'
    )
    assert main(['--bag', str(path)]) == 1
    assert (
        capsys.readouterr()
        .err.strip()
        .endswith('no /tf or /tf_static topic in the bag (topics: /chatter)')
    )
