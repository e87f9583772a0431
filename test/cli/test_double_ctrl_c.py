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

"""
A double Ctrl-C stops every executable like a single one: exit 0, no traceback, clean-up done.

Issue 10, point 9: a second SIGINT within 50 ms killed some tools with exit -2 (Python's
finalisation had put SIGINT back to ``SIG_DFL``) or interrupted their clean-up. Each executable
runs as a real process in this run's world (rclpy inside ROS 2, DDS standalone); once its node is
in the graph (it publishes ``/rosout``) it gets two SIGINTs, the second after a short pause so it
lands while the first one's shutdown is under way.
"""

from __future__ import annotations

import os
from pathlib import Path
import signal
import subprocess
import time
from typing import Any

import pytest
from tf_demo import transport
from tf_demo.cli._snapshot import Snapshot
from tf_demo.cli._snapshot import SnapshotTransform
from tf_demo.cli._snapshot import write_snapshot

pytestmark = [pytest.mark.dds, pytest.mark.timeout(180)]

REPO_ROOT = Path(__file__).resolve().parents[2]
SNAPSHOT = Snapshot((SnapshotTransform('a', 'b', (0.0, 0.0, 0.0), (0.0, 0.0, 0.0, 1.0)),))


def executable_arguments(tmp_path: Path) -> dict[str, list[str]]:
    """Every executable of setup.py, with arguments that keep it running until stopped."""
    snapshot = tmp_path / 'snapshot.yaml'
    write_snapshot(snapshot, SNAPSHOT)
    urdf = str(REPO_ROOT / 'urdf' / 'example_revolute.urdf')
    return {
        'static_tf_pub': [],
        'dynamic_tf_pub': [],
        'frame_broadcaster': [],
        'tf_listener': [],
        'odom_tf_broadcaster': [],
        'point_transformer': [],
        'robot_state_publisher': ['--ros-args', '-p', f'urdf_file:={urdf}'],
        'joint_state_publisher': [urdf],
        'tf_relay': ['/robot1', '/robot2'],
        'tf_echo': ['a', 'b'],
        'static_transform_publisher': ['--frame-id', 'a', '--child-frame-id', 'b'],
        'view_frames': ['-t', '600', '-o', str(tmp_path / 'frames')],
        'tf_monitor': [],
        'tf_doctor': ['-t', '600'],
        'tf_saver': ['-t', '600', '-o', str(tmp_path / 'saved.yaml')],
        'tf_loader': [str(snapshot)],
        'tf_demo_live': ['--quiet', '--duration', '600', '--view-port', '0'],
        'tf_view': ['--port', '0', '--urdf', urdf],
        'tf_topic': ['hz', '/tf'],
        'tf_record': ['-o', str(tmp_path / 'recorded')],
        'tf_plot': ['a', 'b', '--duration', '600', '-o', str(tmp_path / 'plot.png')],
        'tf_play': [str(looped_bag(tmp_path / 'bag')), '--loop', '--clock'],
    }


def looped_bag(path: Path) -> Path:
    """A bag for tf_play: one static and ten /tf messages (written when tf_play is tested)."""
    if path.exists():
        return path
    from tf_demo.testing.bags import tf_bytes
    from tf_demo.testing.bags import transform
    from tf_demo.testing.bags import write_bag

    start = 1_700_000_000_000_000_000
    messages = [('/tf_static', start, tf_bytes(transform('a', 'b', start, (1, 0, 0))))]
    for k in range(10):
        stamp = start + k * 100_000_000
        messages.append(('/tf', stamp, tf_bytes(transform('b', 'c', stamp, (k, 0, 0)))))
    return write_bag(path, 'mcap', messages)


def setup_py_executables() -> set[str]:
    """The console scripts setup.py installs (aliases left out: they share a main)."""
    text = (REPO_ROOT / 'setup.py').read_text(encoding='utf-8')
    names: set[str] = set()
    for block in ('NODES', 'TOOLS'):
        body = text.split(f'{block} = [', 1)[1].split(']', 1)[0]
        names.update(item.strip().strip("',") for item in body.split() if item.strip("',"))
    return names


#: Every node and tool setup.py installs (read from it, not a second list).
EXECUTABLES = sorted(setup_py_executables())


def test_every_executable_is_covered(tmp_path: Path) -> None:
    """The double Ctrl-C test runs every node and tool setup.py installs."""
    assert set(EXECUTABLES) == set(executable_arguments(tmp_path))
    assert {'static_tf_pub', 'tf_echo'} <= set(EXECUTABLES)  # the setup.py lists were read


def catches_stop_signals(pid: int) -> bool:
    """Whether the process has handlers for both SIGINT and SIGTERM (``SigCgt`` in /proc)."""
    try:
        status = Path(f'/proc/{pid}/status').read_text(encoding='utf-8')
    except OSError:
        return False
    caught = next(
        int(line.split()[1], 16) for line in status.splitlines() if line.startswith('SigCgt:')
    )
    wanted = (1 << (signal.SIGINT - 1)) | (1 << (signal.SIGTERM - 1))
    return caught & wanted == wanted


def wait_until_running(watcher: Any, process: subprocess.Popen[str]) -> None:
    """
    Wait until the executable handles stop signals and a node besides the watcher is up.

    Python's own start-up leaves SIGTERM to the default action, so a caught SIGTERM shows the
    executable's handlers are installed; a second ``/rosout`` publisher on the test's private
    domain shows its node (or, for tf_demo_live, a child's) is in the graph.
    """
    deadline = time.monotonic() + 90  # a hang guard, not a timing requirement
    while not (catches_stop_signals(process.pid) and watcher.count_publishers('/rosout') >= 2):
        if process.poll() is not None:
            pytest.fail(f'exited early with {process.returncode}: {process.communicate()}')
        if time.monotonic() > deadline:
            pytest.fail('the executable never started its node')
        time.sleep(0.05)


def live_children(domain: str) -> list[int]:
    """Processes of this test's DDS domain started by tf_demo_live (its node children)."""
    found = []
    for entry in Path('/proc').iterdir():
        if not entry.name.isdigit() or int(entry.name) == os.getpid():
            continue
        try:
            environ = (entry / 'environ').read_bytes().split(b'\0')
            cmdline = (entry / 'cmdline').read_bytes()
        except OSError:
            continue
        if f'ROS_DOMAIN_ID={domain}'.encode() in environ and b'tf_demo.nodes.' in cmdline:
            found.append(int(entry.name))
    return found


@pytest.mark.usefixtures('ros')
@pytest.mark.parametrize('pause_s', [0.005, 0.03])
@pytest.mark.parametrize('name', EXECUTABLES)
def test_a_second_sigint_during_shutdown_is_ignored(
    spawn: Any, world_env: dict[str, str], tmp_path: Path, name: str, pause_s: float
) -> None:
    """Two SIGINTs a few milliseconds apart: exit 0, no traceback, no orphaned child."""
    watcher = transport.create_node('double_sigint_watcher')
    try:
        process = spawn.start(name, *executable_arguments(tmp_path)[name])
        wait_until_running(watcher, process)
        process.send_signal(signal.SIGINT)
        time.sleep(pause_s)  # the input of the scenario, not an assertion
        if process.poll() is None:
            process.send_signal(signal.SIGINT)
        _, stderr = process.communicate(timeout=60)
    finally:
        watcher.destroy_node()
    assert process.returncode == 0, stderr
    assert 'Traceback' not in stderr
    assert 'Exception' not in stderr
    assert live_children(world_env['ROS_DOMAIN_ID']) == []
