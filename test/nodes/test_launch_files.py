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

"""The launch files and the rviz configuration the nodes are started with."""

from __future__ import annotations

import ast
from pathlib import Path

import pytest
import yaml

REPO = Path(__file__).resolve().parents[2]


@pytest.mark.parametrize('name', ['tf_demo.launch.py', 'rep105.launch.py'])
def test_launch_files_parse_and_define_generate_launch_description(name: str) -> None:
    """The launch files are valid Python with generate_launch_description() (run inside ROS)."""
    tree = ast.parse((REPO / 'launch' / name).read_text(encoding='utf-8'))
    functions = {n.name for n in tree.body if isinstance(n, ast.FunctionDef)}
    assert 'generate_launch_description' in functions
    executables = {
        kw.value.value
        for node in ast.walk(tree)
        if isinstance(node, ast.Call)
        for kw in node.keywords
        if kw.arg == 'executable' and isinstance(kw.value, ast.Constant)
    }
    assert {'static_tf_pub', 'dynamic_tf_pub', 'rviz2'} <= executables


def test_mobile_robot_launch_runs_rsp_on_the_xacro_with_jsp_and_odometry() -> None:
    """mobile_robot.launch.py: RSP on urdf/mobile_robot.urdf.xacro, JSP, odom -> base_footprint."""
    tree = ast.parse((REPO / 'launch' / 'mobile_robot.launch.py').read_text(encoding='utf-8'))
    functions = {n.name for n in tree.body if isinstance(n, ast.FunctionDef)}
    assert 'generate_launch_description' in functions
    keywords = {
        (kw.arg, kw.value.value)
        for node in ast.walk(tree)
        if isinstance(node, ast.Call)
        for kw in node.keywords
        if isinstance(kw.value, ast.Constant)
    }
    executables = {value for arg, value in keywords if arg == 'executable'}
    assert {'robot_state_publisher', 'joint_state_publisher', 'dynamic_tf_pub'} <= executables
    constants = {n.value for n in ast.walk(tree) if isinstance(n, ast.Constant)}
    assert {'mobile_robot.urdf.xacro', 'odom', 'base_footprint'} <= constants
    assert (REPO / 'urdf' / 'mobile_robot.urdf.xacro').is_file()


def test_rviz_config_shows_tf_with_fixed_frame_odom() -> None:
    """config/tf_demo.rviz: a TF display and the fixed frame odom."""
    config = yaml.safe_load((REPO / 'config' / 'tf_demo.rviz').read_text(encoding='utf-8'))
    manager = config['Visualization Manager']
    assert manager['Global Options']['Fixed Frame'] == 'odom'
    assert 'rviz_default_plugins/TF' in [d['Class'] for d in manager['Displays']]
