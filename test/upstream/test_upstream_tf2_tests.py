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
geometry2's own Python tests (Jazzy) pass against ``tf_demo.ros`` through import shims.

The test files are run from a geometry2 source checkout (never copied here):
``$TF_DEMO_GEOMETRY2_SRC``, else the checkout that ROS 2's from-source instructions make
(``~/ros2_jazzy/src/ros2/geometry2``).
``shims/`` maps ``tf2_ros``, its submodules and ``tf2_geometry_msgs`` to this package.
"""

from __future__ import annotations

import os
from pathlib import Path
import re
import subprocess
import sys

from conftest import PACKAGE_ROOT
import pytest

pytestmark = [pytest.mark.rclpy_world, pytest.mark.timeout(240)]

SHIMS = Path(__file__).resolve().parent / 'shims'
UPSTREAM_TESTS = (
    'tf2_ros_py/test/test_buffer.py',
    'tf2_ros_py/test/test_listener_and_broadcaster.py',
    'tf2_geometry_msgs/test/test_tf2_geometry_msgs.py',
)


def geometry2_sources() -> Path | None:
    """The geometry2 checkout to take the upstream tests from, if there is one."""
    candidates = [os.environ.get('TF_DEMO_GEOMETRY2_SRC', ''), '~/ros2_jazzy/src/ros2/geometry2']
    for candidate in candidates:
        path = Path(candidate).expanduser() if candidate else None
        if path is not None and all((path / name).is_file() for name in UPSTREAM_TESTS):
            return path
    return None


def shimmed_env(env: dict[str, str]) -> dict[str, str]:
    paths = [str(SHIMS), str(PACKAGE_ROOT), env.get('PYTHONPATH', '')]
    return dict(
        env, PYTHONPATH=os.pathsep.join(p for p in paths if p), PYTHONDONTWRITEBYTECODE='1'
    )


def test_the_shims_give_tf_demo_not_tf2_ros(world_env: dict[str, str]) -> None:
    """Under the shims, tf2_ros and tf2_geometry_msgs are this package, not the installed ones."""
    code = (
        'import tf2_ros, tf2_ros.buffer, tf2_geometry_msgs, tf_demo.ros as ours; '
        'assert tf2_ros.Buffer is ours.Buffer is tf2_ros.buffer.Buffer; '
        'assert tf2_geometry_msgs.do_transform_point is ours.do_transform_point; print("ours")'
    )
    completed = subprocess.run(
        [sys.executable, '-c', code],
        env=shimmed_env(world_env),
        capture_output=True,
        text=True,
        timeout=60,
        check=False,
    )
    assert completed.stdout.strip() == 'ours', completed.stderr


def test_geometry2s_python_tests_pass_against_tf_demo(
    world_env: dict[str, str], tmp_path: Path
) -> None:
    """tf2_ros_py's buffer and listener/broadcaster tests and tf2_geometry_msgs': 10 of 10."""
    sources = geometry2_sources()
    if sources is None:
        pytest.skip(
            'no geometry2 (jazzy) checkout: set TF_DEMO_GEOMETRY2_SRC or check it out at '
            '~/ros2_jazzy/src/ros2/geometry2'
        )
    (tmp_path / 'pytest.ini').write_text('[pytest]\n', encoding='utf-8')
    completed = subprocess.run(
        [
            sys.executable,
            '-m',
            'pytest',
            '-p',
            'no:cacheprovider',
            '-c',
            str(tmp_path / 'pytest.ini'),
            '--rootdir',
            str(tmp_path),
            '-v',
            *(str(sources / name) for name in UPSTREAM_TESTS),
        ],
        env=shimmed_env(world_env),
        cwd=tmp_path,
        capture_output=True,
        text=True,
        timeout=200,
        check=False,
    )
    output = completed.stdout + completed.stderr
    assert completed.returncode == 0, output
    summary = re.search(r'=+ (.*) in [0-9.]+s', output)
    assert summary is not None, output
    assert summary.group(1) == '10 passed', output
