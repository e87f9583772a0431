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
Course code written for rclpy and tf2_ros runs with only its imports changed (README's table).

The table is read from README.md, so what the README promises is what is run: the nodes in
``test/data/course/`` are rewritten module for module, checked to import nothing from ROS, and
run as real processes. Standalone: rewritten broadcasters and listener talk over DDS. ROS world:
each rewritten node runs in the standalone world against the unchanged original on real rclpy
and tf2_ros.
"""

from __future__ import annotations

from collections.abc import Iterator
import contextlib
from pathlib import Path
import re
import signal
import sys

from conftest import ChildProcess
from conftest import REPO_ROOT
from conftest import WORLD
import pytest

COURSE = REPO_ROOT / 'test' / 'data' / 'course'
SECTION = '### From rclpy and tf2_ros'
ROW = re.compile(r'^\| `([\w.]+)` \| `([\w.]+)` \|')
ROS_MODULES = re.compile(
    r'^\s*(from|import)\s+(rclpy|tf2_ros|tf2_geometry_msgs|tf2_py|\w+_msgs|builtin_interfaces)\b',
    re.MULTILINE,
)
# The listener's line once it has looked camera_link up in odom: static z 0.2 of the static
# broadcaster (the dynamic one moves in the plane), the point moved into odom, one static frame.
EXPECTED_RESULT = 'RESULT odom camera_link z=0.200 point_frame=odom static_count=1'


def readme_module_map() -> dict[str, str]:
    """The README's rclpy/tf2_ros -> tf_demo module table."""
    text = (REPO_ROOT / 'README.md').read_text(encoding='utf-8')
    section = text.split(SECTION, 1)[1].split('\n#', 1)[0]
    return {m.group(1): m.group(2) for line in section.splitlines() if (m := ROW.match(line))}


def rewrite_imports(source: str, modules: dict[str, str]) -> str:
    """Change only the import lines of ``source``, module for module, by ``modules``."""

    def rewritten(line: str) -> str:
        if match := re.match(r'^from ([\w.]+) import (.*)$', line):
            return f'from {modules.get(match.group(1), match.group(1))} import {match.group(2)}'
        if (match := re.match(r'^import (\w+)(.*)$', line)) and match.group(1) in modules:
            return f'import {modules[match.group(1)]} as {match.group(1)}{match.group(2)}'
        return line

    return '\n'.join(rewritten(line) for line in source.splitlines()) + '\n'


def test_the_readme_table_maps_every_name_the_course_code_imports() -> None:
    """Every ROS module the course's nodes import has a row, and its names exist there."""
    modules = readme_module_map()
    assert modules['rclpy.time'] == 'tf_demo.transport.clock'
    for path in sorted(COURSE.glob('*.py')):
        rewritten = rewrite_imports(path.read_text(encoding='utf-8'), modules)
        leftover = ROS_MODULES.findall(rewritten)
        assert not leftover, f'{path.name}: ROS imports without a README row: {leftover}'


def test_every_readme_row_names_a_tf_demo_module_with_its_names() -> None:
    """The tf_demo side of each row imports (standalone modules only where DDS is used)."""
    import importlib

    text = (REPO_ROOT / 'README.md').read_text(encoding='utf-8')
    section = text.split(SECTION, 1)[1].split('\n#', 1)[0]
    for line in section.splitlines():
        if not (match := ROW.match(line)):
            continue
        module = importlib.import_module(match.group(2))
        names = re.findall(r'`([A-Za-z_]\w*)`', line.split('|')[3])
        missing = [n for n in names if not hasattr(module, n)]
        assert not missing, f'{match.group(2)} lacks {missing} (README row {match.group(1)})'


def rclpy_rows() -> dict[str, tuple[str, list[str]]]:
    """README rows of rclpy's submodules: ``{'time': ('tf_demo.transport.clock', ['Time'])}``."""
    text = (REPO_ROOT / 'README.md').read_text(encoding='utf-8')
    section = text.split(SECTION, 1)[1].split('\n#', 1)[0]
    rows = {}
    for line in section.splitlines():
        if (match := ROW.match(line)) and match.group(1).startswith('rclpy.'):
            names = re.findall(r'`([A-Za-z_]\w*)`', line.split('|')[3])
            rows[match.group(1).removeprefix('rclpy.')] = (match.group(2), names)
    return rows


def test_the_import_map_answers_rclpys_submodules_by_attribute() -> None:
    """``import tf_demo.transport as rclpy``: ``rclpy.time.Time()`` and every row's path work."""
    import importlib

    import tf_demo.transport as rclpy
    from tf_demo.transport.node import Node

    rows = rclpy_rows()
    assert sorted(rows) == sorted(rclpy.RCLPY_SUBMODULES)
    for name, (module, names) in rows.items():
        row_module = importlib.import_module(module)
        for attribute in names:
            assert getattr(getattr(rclpy, name), attribute) is getattr(row_module, attribute)
    assert rclpy.time.Time().nanoseconds == 0  # "the latest", as tf2 reads it
    assert rclpy.duration.Duration(seconds=0.5).nanoseconds == 500_000_000
    assert rclpy.node.Node is Node


@pytest.mark.rclpy_world
def test_the_rows_attribute_paths_are_real_rclpys() -> None:
    """Each ``rclpy.<name>`` of the README's rows is a real rclpy submodule with those names."""
    import importlib

    text = (REPO_ROOT / 'README.md').read_text(encoding='utf-8')
    for name in rclpy_rows():
        row = next(line for line in text.splitlines() if line.startswith(f'| `rclpy.{name}` |'))
        # After "; also" or " (and": names rclpy keeps elsewhere or tf_demo adds.
        rclpys_part = re.split(r'; also| \(and', row.split('|')[3])[0]
        names = re.findall(r'`([A-Za-z_]\w*)`', rclpys_part)
        module = importlib.import_module(f'rclpy.{name}')
        missing = [n for n in names if not hasattr(module, n)]
        assert not missing, f'rclpy.{name} lacks {missing}'


def write_rewritten(tmp_path: Path) -> Path:
    """The course's nodes with their imports changed, in ``tmp_path``."""
    modules = readme_module_map()
    for path in COURSE.glob('*.py'):
        text = rewrite_imports(path.read_text(encoding='utf-8'), modules)
        (tmp_path / path.name).write_text(text, encoding='utf-8')
    return tmp_path


def standalone_python_and_env(env: dict[str, str]) -> tuple[str, dict[str, str]]:
    """The Python and environment of a standalone (no ROS) process in this test's domain."""
    if WORLD == 'dds':
        return sys.executable, env
    from ros_world.jazzy import standalone_env
    from ros_world.jazzy import standalone_python

    return standalone_python(), standalone_env(env)


@contextlib.contextmanager
def running(python: str, script: Path, env: dict[str, str]) -> Iterator[ChildProcess]:
    """Run ``script``; at the end Ctrl-C it and check it ends with exit 0 and no traceback."""
    child = ChildProcess([python, str(script)], env, finish_timeout=20)
    try:
        yield child
    finally:
        if child.process.poll() is None:
            child.process.send_signal(signal.SIGINT)
        try:
            code = child.finish()
        finally:
            child.stop()
    output = '\n'.join(child.lines)
    assert code == 0, output
    assert 'Traceback' not in output, output


@pytest.mark.standalone
def test_the_rewritten_course_nodes_work_together_without_ros(
    dds_env: dict[str, str], tmp_path: Path
) -> None:
    """Static and dynamic broadcasters and the listener, rewritten, over DDS: the lookup works."""
    folder = write_rewritten(tmp_path)
    python, env = standalone_python_and_env(dds_env)
    with (
        running(python, folder / 'static_broadcaster.py', env),
        running(python, folder / 'dynamic_broadcaster.py', env),
        running(python, folder / 'frame_listener.py', env) as listener,
    ):
        listener.wait_for_line(EXPECTED_RESULT, timeout=30)


@pytest.mark.rclpy_world
@pytest.mark.parametrize('rewritten', ['listener', 'broadcasters'])
def test_rewritten_course_nodes_talk_to_the_originals_on_real_rclpy(
    world_env: dict[str, str], tmp_path: Path, rewritten: str
) -> None:
    """One side rewritten (standalone world), the other the unchanged rclpy/tf2_ros original."""
    folder = write_rewritten(tmp_path)
    python, env = standalone_python_and_env(world_env)
    ros_python, ros_env = sys.executable, dict(world_env)  # this run's Python sees rclpy
    if rewritten == 'listener':
        broadcasters = (ros_python, COURSE, ros_env)
        listener = (python, folder, env)
    else:
        broadcasters = (python, folder, env)
        listener = (ros_python, COURSE, ros_env)
    with (
        running(broadcasters[0], broadcasters[1] / 'static_broadcaster.py', broadcasters[2]),
        running(broadcasters[0], broadcasters[1] / 'dynamic_broadcaster.py', broadcasters[2]),
        running(listener[0], listener[1] / 'frame_listener.py', listener[2]) as child,
    ):
        child.wait_for_line(EXPECTED_RESULT, timeout=40)


def test_a_rewrite_leaves_everything_but_imports_alone() -> None:
    """Only import lines change: the rest of each node is byte for byte the course's."""
    modules = readme_module_map()
    for path in COURSE.glob('*.py'):
        original = path.read_text(encoding='utf-8').splitlines()
        rewritten = rewrite_imports('\n'.join(original), modules).splitlines()
        changed = [(a, b) for a, b in zip(original, rewritten, strict=True) if a != b]
        assert changed, path.name
        assert all(a.startswith(('from ', 'import ')) for a, _ in changed), changed


def test_rewriting_a_missing_module_is_seen() -> None:
    """A module with no row stays as it was and is reported by the leftover check."""
    text = rewrite_imports('from rclpy.action import ActionServer\n', readme_module_map())
    assert ROS_MODULES.findall(text) == [('from', 'rclpy')]
