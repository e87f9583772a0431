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
Child processes import the installed tf_demo whatever the working directory holds.

The course's student clones the repository into ``~/tf_demo`` and works from ``~``: that folder
(its ``urdf/`` of robot files) must not stand in for the package in any child we start — the
xacro worker, tf_demo_live's nodes. The top-level process here is started as a console script
is (the working directory off ``sys.path``), so only the children are under test.
"""

from __future__ import annotations

import os
from pathlib import Path
import shutil
import sys

from conftest import PACKAGE_ROOT
from conftest import REPO_ROOT
from conftest import run_captured
import pytest
from tf_demo.core.python_child import python_child_command


def console_script(code: str) -> list[str]:
    """Run ``code`` as an installed console script would: the working directory not on the path."""
    return [sys.executable, '-c', f'import sys; sys.path[:] = [p for p in sys.path if p]\n{code}']


@pytest.fixture
def beside_a_clone(tmp_path: Path) -> Path:
    """A working directory holding ``tf_demo/urdf/`` (a clone's robot files, no package)."""
    shutil.copytree(REPO_ROOT / 'urdf', tmp_path / 'tf_demo' / 'urdf')
    return tmp_path


def test_a_child_imports_the_installed_package(beside_a_clone: Path) -> None:
    """``python_child_command``'s child finds the package tf_demo, not the folder beside it."""
    code = 'import tf_demo.urdf.xacro_worker, tf_demo; print(tf_demo.__file__)'
    completed = run_captured(python_child_command(code), cwd=beside_a_clone)
    assert completed.returncode == 0, completed.stderr
    assert Path(completed.stdout.strip()) == PACKAGE_ROOT / 'tf_demo' / '__init__.py'


def test_the_xacro_worker_runs_beside_a_clone(beside_a_clone: Path) -> None:
    """The workshop's xacro route from ``~``: ``tf_demo/urdf/mobile_robot.urdf.xacro`` expands."""
    code = (
        'from tf_demo.urdf import RobotModel\n'
        "print(RobotModel.from_file('tf_demo/urdf/mobile_robot.urdf.xacro').root)"
    )
    completed = run_captured(console_script(code), cwd=beside_a_clone)
    assert completed.returncode == 0, completed.stderr
    assert completed.stdout.split() == ['base_footprint']


@pytest.mark.dds
def test_tf_demo_live_robot_runs_beside_a_clone(
    beside_a_clone: Path, world_env: dict[str, str]
) -> None:
    """``tf_demo_live --robot`` from ``~``: its nodes start and the robot's transforms arrive."""
    code = 'from tf_demo.cli.tf_demo_live import main; sys.exit(main())'
    command = [*console_script(code), '--robot', '--duration', '8', '--rate', '4', '--no-view']
    env = {**world_env, 'PYTHONPATH': os.environ.get('PYTHONPATH', '')}  # as installed
    completed = run_captured(command, env, cwd=beside_a_clone, timeout=120)
    assert completed.returncode == 0, completed.stdout + completed.stderr
    assert 'Error' not in completed.stdout, completed.stdout
    assert 'odom <- lidar_link @ ' in completed.stdout, completed.stdout
