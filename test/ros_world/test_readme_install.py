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
The README's ROS 2 install recipe, run as written inside the real Jazzy.

Jazzy's Python is externally managed (PEP 668): the row makes a virtual environment with the
system's packages, keeps colcon out of it, installs the pip-only dependency there and builds
with its Python. Run in a fresh home with the repository cloned as the row says, then the
workshop's xacro route on the result.
"""

from __future__ import annotations

import os
from pathlib import Path
import re

from conftest import REPO_ROOT
import pytest
from ros_world.jazzy import running

pytestmark = pytest.mark.rclpy_world

RECIPE_ROW = re.compile(r'^\| ROS 2 Jazzy workspace \| `([^`]+)`', re.MULTILINE)


def readme_ros_recipe() -> str:
    """The command of the README's "ROS 2 Jazzy workspace" row."""
    match = RECIPE_ROW.search((REPO_ROOT / 'README.md').read_text(encoding='utf-8'))
    assert match is not None, 'README has no "ROS 2 Jazzy workspace" row'
    return match.group(1)


def fresh_shell_env(home: Path, jazzy_env: dict[str, str]) -> dict[str, str]:
    """A login-like environment: no ROS sourced, no venv, this test's DDS domain."""
    keep = ('ROS_DOMAIN_ID', 'ROS_AUTOMATIC_DISCOVERY_RANGE', 'RMW_IMPLEMENTATION', 'LANG')
    env = {key: jazzy_env[key] for key in keep if key in jazzy_env}
    return {**env, 'HOME': str(home), 'PATH': '/usr/local/bin:/usr/bin:/bin'}


def test_the_readmes_ros_recipe_builds_and_runs_the_xacro_route(
    tmp_path: Path, jazzy_env: dict[str, str]
) -> None:
    """The row as written (its ``<this repo>`` this repository) builds; RSP runs the xacro."""
    recipe = readme_ros_recipe().replace('<this repo>', str(REPO_ROOT))
    assert '--system-site-packages' in recipe
    xacro = 'src/tf_demo/urdf/mobile_robot.urdf.xacro'
    rsp = f'ros2 run tf_demo robot_state_publisher --ros-args -p urdf_file:={xacro}'
    script = f'{recipe} && exec {rsp}'
    env = fresh_shell_env(tmp_path, jazzy_env)
    with running(['bash', '-c', script], env, cwd=tmp_path) as output:
        output.wait_for_line('Robot initialized', timeout=600, anywhere=True)
    text = '\n'.join(output.lines)
    assert 'externally-managed-environment' not in text, text
    assert (tmp_path / 'ws' / 'venv' / 'COLCON_IGNORE').exists()
    assert os.access(
        tmp_path / 'ws' / 'install' / 'tf_demo' / 'lib' / 'tf_demo' / 'tf_echo', os.X_OK
    )
