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

"""tf_saver with tf_loader as real processes over DDS: round trip, chosen frames, odd outputs."""

from __future__ import annotations

import os
from pathlib import Path
import signal
import stat

import pytest
from tf_demo.cli._snapshot import read_snapshot
from tool_runs import dynamic
from tool_runs import run
from tool_runs import static

pytestmark = [pytest.mark.dds]


def test_saver_loader_round_trip(spawn, tf_peers, tmp_path):
    """Save a live tree, republish it with tf_loader, save again: the same transforms."""
    source = tf_peers(
        static('map', 'odom', t=(1.0, 2.0, 0.0)),
        dynamic('odom', 'base_link', rate=20.0, t=[0.5, 0.0, 0.0]),
        static('base_link', 'laser', t=(0.1, 0.0, 0.2), q=(0.0, 0.0, 1.0, 0.0)),
    )
    code, _, err = run(spawn, 'tf_saver', '-t', '3', '-o', 'first.yaml')
    assert code == 0, err
    first = read_snapshot(tmp_path / 'first.yaml')
    assert [(e.parent, e.child, e.is_static) for e in first.transforms] == [
        ('map', 'odom', True),
        ('odom', 'base_link', False),
        ('base_link', 'laser', True),
    ]
    rate_hz = first.transforms[1].rate_hz
    assert rate_hz is not None
    assert rate_hz > 5
    source.send_signal(signal.SIGINT)
    source.wait(timeout=30)
    loader = spawn.start('tf_loader', 'first.yaml')
    code, _, err = run(spawn, 'tf_saver', '-t', '3', '-o', 'second.yaml')
    assert code == 0, err
    second = read_snapshot(tmp_path / 'second.yaml')
    assert [(e.parent, e.child, e.translation, e.rotation) for e in second.transforms] == [
        (e.parent, e.child, e.translation, e.rotation) for e in first.transforms
    ]
    assert all(e.is_static for e in second.transforms)
    loader.send_signal(signal.SIGINT)
    assert loader.wait(timeout=30) == 0  # a bound, generous for a loaded 2-core machine


def test_saver_chosen_frames_and_flatten(spawn, tf_peers, tmp_path):
    """Frames select the connecting links; --flatten composes them relative to the first."""
    tf_peers(
        static('map', 'odom', t=(1.0, 0.0, 0.0)),
        static('odom', 'base_link', t=(0.0, 2.0, 0.0)),
        static('base_link', 'laser', t=(0.0, 0.0, 3.0)),
        static('base_link', 'cam'),
    )
    code, _, err = run(spawn, 'tf_saver', '-t', '3', '-o', 'part.yaml', 'odom', 'laser')
    assert code == 0, err
    part = read_snapshot(tmp_path / 'part.yaml')
    assert [(e.parent, e.child) for e in part.transforms] == [
        ('odom', 'base_link'),
        ('base_link', 'laser'),
    ]
    code, _, err = run(
        spawn, 'tf_saver', '-t', '3', '-o', 'flat.yaml', '--flatten', 'map', 'laser'
    )
    assert code == 0, err
    flat = read_snapshot(tmp_path / 'flat.yaml')
    assert [(e.parent, e.child, e.translation) for e in flat.transforms] == [
        ('map', 'laser', (1.0, 2.0, 3.0))
    ]


def test_saver_writes_through_a_link_and_refuses_a_device(spawn, tf_peers, tmp_path):
    """
    -o through a symbolic link updates the file it names and keeps the link (issue 10, 7).

    A device is refused before listening: exit 2, one line, the node untouched (a private
    /dev/full-like node when root may make one, else a FIFO).
    """
    tf_peers(static('map', 'odom', t=(1.0, 2.0, 0.0)))
    (tmp_path / 'kept').mkdir()
    (tmp_path / 'kept' / 'real.yaml').write_text('old\n', encoding='utf-8')
    (tmp_path / 'latest.yaml').symlink_to(Path('kept') / 'real.yaml')
    code, _, err = run(spawn, 'tf_saver', '-t', '3', '-o', 'latest.yaml')
    assert code == 0, err
    assert (tmp_path / 'latest.yaml').is_symlink()
    saved = read_snapshot(tmp_path / 'kept' / 'real.yaml')
    assert [(e.parent, e.child) for e in saved.transforms] == [('map', 'odom')]

    device = tmp_path / 'device'
    try:
        os.mknod(device, 0o666 | stat.S_IFCHR, os.makedev(1, 7))
        is_kind = stat.S_ISCHR
    except PermissionError:
        os.mkfifo(device)
        is_kind = stat.S_ISFIFO
    for target in (device, tmp_path / 'latest_device'):
        if target != device:
            target.symlink_to(device)
        code, out, err = run(spawn, 'tf_saver', '-t', '3', '-o', str(target))
        assert (code, out) == (2, '')
        assert err == (
            f'tf_saver: error: {target}: not a regular file (a device, FIFO or socket); '
            'nothing was written\n'
        )
        assert is_kind(os.lstat(device).st_mode)
