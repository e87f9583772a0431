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


"""Install hints for the optional extras: pip standalone, ROS 2's venv recipe inside ROS 2."""

from __future__ import annotations

import os
import sys

from conftest import run_captured
from tf_demo.core.extras import extra_requirements
from tf_demo.core.extras import install_hint

REQUIRES = [
    'numpy>=1.24',
    'viser>=1.0; extra == "view"',
    'rosbags>=0.10; extra == "bag"',
    "matplotlib >= 3.6 ; extra == 'bag'",
]


def test_an_extras_requirements_are_read_from_the_metadata() -> None:
    """Only the extra's own lines, without their markers."""
    assert extra_requirements('bag', REQUIRES) == ['rosbags>=0.10', 'matplotlib>=3.6']
    assert extra_requirements('view', REQUIRES) == ['viser>=1.0']
    assert extra_requirements('nope', REQUIRES) == []


def test_standalone_the_hint_is_pip() -> None:
    """Without ROS 2, pip installs the extra."""
    hint = install_hint('bag', ['rosbags>=0.10'], inside_ros=False, venv_python=None)
    assert hint == "pip install 'tf_demo[bag]'"


def test_inside_ros_the_hint_is_a_system_site_packages_venv() -> None:
    """Inside ROS 2, outside a venv: ROS 2's recipe (PEP 668 refuses the system's pip)."""
    hint = install_hint('bag', ['rosbags>=0.10', 'mcap'], inside_ros=True, venv_python=None)
    assert 'python3 -m venv --system-site-packages venv' in hint
    assert 'touch venv/COLCON_IGNORE' in hint
    assert "venv/bin/pip install 'rosbags>=0.10' mcap" in hint
    assert 'venv/bin/python -m colcon build' in hint
    assert "pip install 'tf_demo[" not in hint


def test_inside_ros_in_a_venv_the_hint_is_its_pip() -> None:
    """Inside ROS 2, run from a venv: that venv's pip."""
    hint = install_hint('view', ['viser>=1.0'], inside_ros=True, venv_python='/ws/venv/bin/python')
    assert hint == "/ws/venv/bin/python -m pip install 'viser>=1.0'"


BLOCK_ROSBAGS = """
import importlib.abc, sys
class Block(importlib.abc.MetaPathFinder):
    def find_spec(self, name, path=None, target=None):
        if name.split('.')[0] == 'rosbags':
            raise ImportError(f'{name} is blocked for this test')
sys.meta_path.insert(0, Block())
from tf_demo.bag import BagError, open_tf_bag
try:
    open_tf_bag('missing.mcap')
except BagError as error:
    print(error)
"""


def test_a_tool_without_the_extra_prints_the_worlds_hint() -> None:
    """A real process inside ROS 2 (ROS_DISTRO set) names the packages, not tf_demo[bag]."""
    completed = run_captured(
        [sys.executable, '-c', BLOCK_ROSBAGS],
        {**os.environ, 'ROS_DISTRO': 'jazzy'},
    )
    assert completed.returncode == 0, completed.stderr
    if sys.prefix != sys.base_prefix:
        assert f'{sys.executable} -m pip install ' in completed.stdout, completed.stdout
    else:
        assert 'python3 -m venv --system-site-packages venv' in completed.stdout
    assert "'rosbags>=0.10'" in completed.stdout, completed.stdout
