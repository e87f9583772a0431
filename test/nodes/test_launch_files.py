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
#: The module the launch files share (launch/tf_demo_launch.py), installed beside them.
SHARED = 'tf_demo_launch'


def parsed(name: str) -> ast.Module:
    return ast.parse((REPO / 'launch' / name).read_text(encoding='utf-8'))


def constant_keywords(tree: ast.AST) -> set[tuple[str | None, object]]:
    """(keyword, value) of every call in ``tree`` given a constant keyword argument."""
    return {
        (kw.arg, kw.value.value)
        for node in ast.walk(tree)
        if isinstance(node, ast.Call)
        for kw in node.keywords
        if isinstance(kw.value, ast.Constant)
    }


def launched_keywords(tree: ast.Module) -> set[tuple[str | None, object]]:
    """The constant keywords of a launch file's calls, and of the shared functions it calls."""
    shared = {
        function.name: function
        for function in parsed(f'{SHARED}.py').body
        if isinstance(function, ast.FunctionDef)
    }
    imported = {
        alias.name
        for node in tree.body
        if isinstance(node, ast.ImportFrom) and node.module == SHARED
        for alias in node.names
    }
    called = {
        node.func.id
        for node in ast.walk(tree)
        if isinstance(node, ast.Call) and isinstance(node.func, ast.Name)
    }
    found = constant_keywords(tree)
    for name in called & imported:
        found |= constant_keywords(shared[name])
    return found


@pytest.mark.parametrize('name', ['tf_demo.launch.py', 'rep105.launch.py'])
def test_launch_files_parse_and_define_generate_launch_description(name: str) -> None:
    """The launch files are valid Python with generate_launch_description() (run inside ROS)."""
    tree = parsed(name)
    functions = {n.name for n in tree.body if isinstance(n, ast.FunctionDef)}
    assert 'generate_launch_description' in functions
    executables = {value for arg, value in launched_keywords(tree) if arg == 'executable'}
    assert {'static_tf_pub', 'dynamic_tf_pub', 'rviz2'} <= executables


def test_mobile_robot_launch_runs_rsp_on_the_xacro_with_jsp_and_odometry() -> None:
    """mobile_robot.launch.py: RSP on urdf/mobile_robot.urdf.xacro, JSP, odom -> base_footprint."""
    tree = parsed('mobile_robot.launch.py')
    functions = {n.name for n in tree.body if isinstance(n, ast.FunctionDef)}
    assert 'generate_launch_description' in functions
    keywords = launched_keywords(tree)
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
