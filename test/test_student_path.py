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
A student's first day as a whole: the repository cloned into ``tf_demo``, the course run from its
parent, in this run's world.

Standalone the commands are the venv's executables; in the ROS world ``ros2 run`` and ``ros2
launch`` of the sourced workspace. Every process starts in the clone's parent, where the folder
``tf_demo`` (the clone, not the package) sits: the workshop's URDF route (``robot_description``
from ``$(cat ...)``) and xacro route (``urdf_file:=``), the course's listener through the
README's import map (``rclpy.time.Time()``), and the course's launch with ``rviz:=false``
(standalone, its counterpart ``tf_demo_live``).
"""

from __future__ import annotations

import os
from pathlib import Path
import shlex
import sys

from conftest import REPO_ROOT
from conftest import run_captured
from conftest import WORLD
import pytest
from ros_world.jazzy import running
from ros_world.jazzy import stop
from test_course_code import COURSE
from test_course_code import EXPECTED_RESULT
from test_course_code import standalone_python_and_env
from test_course_code import write_rewritten

pytestmark = [pytest.mark.dds, pytest.mark.timeout(240)]


@pytest.fixture
def home(tmp_path: Path) -> Path:
    """The student's home: this repository cloned into ``tf_demo``, the course's nodes beside."""
    home = tmp_path / 'home'
    home.mkdir()
    cloned = run_captured(['git', 'clone', '-q', str(REPO_ROOT), str(home / 'tf_demo')])
    assert cloned.returncode == 0, cloned.stderr
    write_rewritten(home)
    return home


@pytest.fixture
def student_env(world_env: dict[str, str]) -> dict[str, str]:
    """The test's domain, tf_demo as installed (not the source tree), its executables on PATH."""
    env = {**world_env, 'PYTHONPATH': os.environ.get('PYTHONPATH', '')}
    if WORLD == 'dds':
        env['PATH'] = f'{Path(sys.executable).parent}{os.pathsep}{env.get("PATH", "")}'
    else:
        from ros_world.jazzy import require_installed_tf_demo

        require_installed_tf_demo(env)
    return env


def run_line(executable: str, *args: str) -> str:
    """The shell line that runs one of our executables: the venv's, or ``ros2 run``'s."""
    prefix = '' if WORLD == 'dds' else 'ros2 run tf_demo '
    return prefix + shlex.join([executable, *args])


def echo_once(env: dict[str, str], home: Path, target: str, source: str) -> str:
    """``tf_echo target source --limit 1`` from ``home``: its block (the test fails without)."""
    command = ['bash', '-c', run_line('tf_echo', target, source, '--limit', '1')]
    echoed = run_captured(command, env, cwd=home, timeout=60)
    assert echoed.returncode == 0, echoed.stdout + echoed.stderr
    return echoed.stdout


@pytest.mark.parametrize(
    ('route', 'frames', 'translation'),
    [
        (
            '-p robot_description:="$(cat tf_demo/urdf/example_fixed.urdf)"',
            ('world', 'frame_1'),
            '- Translation: [0.000, 0.000, 1.000]',
        ),
        (
            '-p urdf_file:=tf_demo/urdf/mobile_robot.urdf.xacro',
            ('base_footprint', 'lidar_link'),
            '- Translation: [0.100, 0.000, 0.170]',
        ),
    ],
    ids=['urdf', 'xacro'],
)
def test_the_workshops_robot_routes_from_the_clones_parent(
    home: Path,
    student_env: dict[str, str],
    route: str,
    frames: tuple[str, str],
    translation: str,
) -> None:
    """robot_state_publisher with the workshop's URDF or xacro: its frames arrive."""
    rsp = f'{run_line("robot_state_publisher")} --ros-args {route}'
    with running(['bash', '-c', rsp], student_env, cwd=home) as publisher:
        publisher.wait_for_line('Robot initialized', timeout=60, anywhere=True)
        assert translation in echo_once(student_env, home, *frames)
        code = stop(publisher.process)
    assert code == 0, '\n'.join(publisher.lines)
    assert 'Traceback' not in '\n'.join(publisher.lines)


def test_the_course_listener_through_the_import_map_from_the_clones_parent(
    home: Path, student_env: dict[str, str]
) -> None:
    """
    The course's listener, imports rewritten, run beside the clone: rclpy.time.Time() works.

    Standalone its broadcasters are rewritten too; in the ROS world they are the unchanged
    originals on real rclpy, and the listener runs in the standalone world (the README's map is
    for code without ROS), as on a laptop beside a robot.
    """
    python, env = standalone_python_and_env(student_env)
    broadcasters = (python, home, env) if WORLD == 'dds' else (sys.executable, COURSE, student_env)
    with (
        running(
            [broadcasters[0], str(broadcasters[1] / 'static_broadcaster.py')],
            broadcasters[2],
            cwd=home,
        ) as static,
        running(
            [broadcasters[0], str(broadcasters[1] / 'dynamic_broadcaster.py')],
            broadcasters[2],
            cwd=home,
        ) as dynamic,
        running([python, 'frame_listener.py'], env, cwd=home) as listener,
    ):
        listener.wait_for_line(EXPECTED_RESULT, timeout=60)
        codes = [stop(child.process) for child in (listener, dynamic, static)]
    output = '\n'.join(listener.lines + dynamic.lines + static.lines)
    assert codes == [0, 0, 0], output
    assert 'Traceback' not in output, output


def test_the_course_launch_without_rviz_from_the_clones_parent(
    home: Path, student_env: dict[str, str]
) -> None:
    """``ros2 launch tf_demo tf_demo.launch.py rviz:=false`` (standalone: ``tf_demo_live``)."""
    if WORLD == 'dds':
        command = ['tf_demo_live', '--no-view', '--quiet', '--rate', '4']
    else:
        command = ['ros2', 'launch', 'tf_demo', 'tf_demo.launch.py', 'rviz:=false']
    with running(command, student_env, cwd=home) as launch:
        assert '- Translation:' in echo_once(student_env, home, 'odom', 'camera_link')
        code = stop(launch.process, timeout=30)
    output = '\n'.join(launch.lines)
    assert code == 0, output
    assert 'process has died' not in output, output
    assert 'rviz2' not in output, output
