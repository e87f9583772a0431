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

"""tf_demo_live, the README demo, as a real process: the nodes it starts, their relayed lines."""

from __future__ import annotations

import importlib.util
from typing import Any

from conftest import REPO_ROOT
import pytest

pytestmark = pytest.mark.dds

STARTUP_TIMEOUT_S = 60.0


def test_tf_demo_live_shows_listener_tf_echo_and_its_own_lines(spawn: Any) -> None:
    """The README demo relays tf_listener and tf_echo, prints transforms, exits 0 after -d."""
    live = spawn.start('tf_demo_live', '--duration', '12', '--rate', '4', '--view-port', '0')
    out, err = live.communicate(timeout=STARTUP_TIMEOUT_S + 30)
    assert live.returncode == 0, err
    lines = out.splitlines()
    if importlib.util.find_spec('viser') is not None:  # the 'view' extra: tf_view, its URL
        assert any(line.startswith('[tf_view] tf_view: serving on http://') for line in lines)
    else:
        assert "tf_demo_live: tf_view not started: install the 'view' extra" in out
    own = [line for line in lines if line.startswith('odom <- camera_link @ ')]
    assert own, out
    assert own[-1].split('translation [')[1].split(']')[0].endswith('+0.200')
    assert any(
        line.startswith('[tf_listener] ') and 'Transform odom <- camera_link at ' in line
        for line in lines
    ), out
    echo_start = next(i for i, line in enumerate(lines) if line.startswith('[tf_echo] At time '))
    assert lines[echo_start + 1].startswith('[tf_echo] - Translation: [')
    assert any(line.startswith('[static_tf_pub] ') for line in lines)


def test_tf_demo_live_robot_mode_runs_the_rep105_robot_and_echoes_odom_to_lidar(
    spawn: Any,
) -> None:
    """--robot: RSP on the xacro, JSP, odometry; odom <- lidar_link lines and a tf_echo block."""
    from tf_demo.urdf import RobotModel

    model = RobotModel.from_file(REPO_ROOT / 'urdf' / 'mobile_robot.urdf.xacro')
    (_, _, lidar_height), _ = model.link_poses({})['lidar_link']
    live = spawn.start('tf_demo_live', '--robot', '--duration', '12', '--rate', '4', '--no-view')
    out, err = live.communicate(timeout=STARTUP_TIMEOUT_S + 30)
    assert live.returncode == 0, err
    lines = out.splitlines()
    own = [line for line in lines if line.startswith('odom <- lidar_link @ ')]
    assert own, out
    assert own[-1].split('translation [')[1].split(']')[0].endswith(f'{lidar_height:+.3f}')
    assert any(line.startswith('[robot_state_publisher] ') for line in lines), out
    assert any(line.startswith('[joint_state_publisher] ') for line in lines), out
    echo_start = next(i for i, line in enumerate(lines) if line.startswith('[tf_echo] At time '))
    assert lines[echo_start + 1].startswith('[tf_echo] - Translation: [')
    assert lines[echo_start + 1].endswith(f', {lidar_height:.3f}]')
