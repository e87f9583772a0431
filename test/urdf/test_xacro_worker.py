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

"""xacro is code: the worker process expanding it is bounded in time, memory and nesting."""

from __future__ import annotations

import os
from pathlib import Path
import re

import pytest
from test_loading import write_xacro
from tf_demo.urdf import expand_xacro
from tf_demo.urdf import RobotModel
from tf_demo.urdf import UrdfError
from tf_demo.urdf import UrdfMalformedError
from tf_demo.urdf.xacro_worker import MAX_INCLUDE_DEPTH
from tf_demo.urdf.xacro_worker import MAX_MACRO_DEPTH


def worker_children() -> list[str]:
    """Command lines of this process's children still alive that run the xacro worker."""
    found = []
    for entry in Path('/proc').iterdir():
        if not entry.name.isdigit():
            continue
        try:
            fields = (entry / 'stat').read_text().rsplit(')', 1)[1].split()
            command = (entry / 'cmdline').read_bytes().replace(b'\0', b' ').decode()
        except OSError:
            continue
        if int(fields[1]) == os.getpid() and 'xacro_worker' in command:
            found.append(command)
    return found


def test_a_huge_expression_is_stopped_at_the_time_limit(tmp_path: Path) -> None:
    """${9**9**9} does not hang: the child is killed at the limit and nothing is left running."""
    path = write_xacro(tmp_path / 'big.xacro', '<link name="${9**9**9}"/>')
    with pytest.raises(
        UrdfMalformedError,
        match=r'big\.xacro: xacro: expansion did not finish within 2 s and was stopped',
    ):
        expand_xacro(path, timeout_s=2.0)
    assert worker_children() == []


def test_a_macro_calling_itself_is_refused_at_the_nesting_limit(tmp_path: Path) -> None:
    """A recursive macro is a clear error naming it, not a RecursionError."""
    path = write_xacro(
        tmp_path / 'rec.xacro',
        '<link name="a"/><xacro:macro name="again"><xacro:again/></xacro:macro><xacro:again/>',
    )
    with pytest.raises(
        UrdfMalformedError,
        match=rf'rec\.xacro: xacro: xacro failed: macros nested deeper than {MAX_MACRO_DEPTH} '
        r'\(again -> again -> again -> \.\.\. -> again -> again\)',
    ):
        RobotModel.from_file(path)


def test_files_including_each_other_are_refused_at_the_nesting_limit(tmp_path: Path) -> None:
    """A file including itself, and two files including each other: clear errors."""
    itself = write_xacro(tmp_path / 'self.xacro', '<xacro:include filename="self.xacro"/>')
    with pytest.raises(
        UrdfMalformedError, match=rf'includes nested deeper than {MAX_INCLUDE_DEPTH} \(.*self'
    ):
        RobotModel.from_file(itself)
    write_xacro(tmp_path / 'b.xacro', '<xacro:include filename="a.xacro"/>')
    pair = write_xacro(tmp_path / 'a.xacro', '<xacro:include filename="b.xacro"/>')
    with pytest.raises(UrdfMalformedError, match=r'a\.xacro: xacro: .*includes nested deeper'):
        RobotModel.from_file(pair)


def test_a_macro_chain_within_the_limit_expands(tmp_path: Path) -> None:
    """Macros nested 60 deep (below the limit) expand into a 60-link chain."""
    body = ['<link name="l0"/>']
    for level in range(1, 61):
        inner = f'<xacro:m{level + 1}/>' if level < 60 else ''
        body.append(
            f'<xacro:macro name="m{level}"><link name="l{level}"/>'
            f'<joint name="j{level}" type="fixed"><parent link="l{level - 1}"/>'
            f'<child link="l{level}"/></joint>{inner}</xacro:macro>'
        )
    body.append('<xacro:m1/>')
    model = RobotModel.from_file(write_xacro(tmp_path / 'deep.xacro', '\n'.join(body)))
    assert len(model.static_transforms()) == 60


@pytest.mark.parametrize(
    ('body', 'pattern'),
    [
        ('<link name="${1/0}"/>', r'xacro failed: .*division by zero'),
        ('<link name="${nothing}"/>', r'xacro failed: .*nothing'),
        ('<link name="${\'x\' * 10**10}"/>', r'(needs more than \d+ MiB of memory|killed by)'),
        ('<xacro:include filename="/dev/zero"/>', r'/dev/zero: not a regular file'),
        ('<link name="${load_yaml(\'/dev/zero\')}"/>', r'unacceptable character'),
        ('<link name="${[].pop()}"/>', r'xacro failed: .*pop from empty list'),
    ],
    ids=['zero-division', 'undefined', 'huge-string', 'include-device', 'yaml-device', 'index'],
)
def test_errors_inside_xacro_code_are_urdf_errors(tmp_path: Path, body: str, pattern: str) -> None:
    """Whatever the expressions raise (or exhaust) comes back as one UrdfError naming the file."""
    path = write_xacro(tmp_path / 'code.xacro', body)
    with pytest.raises(UrdfError, match=rf'^{re.escape(str(path))}: xacro: ') as caught:
        RobotModel.from_file(path)
    assert re.search(pattern, str(caught.value)), str(caught.value)


def test_an_include_through_a_symlink_to_a_device_is_refused(tmp_path: Path) -> None:
    """The included file is read with the bounded reader too."""
    (tmp_path / 'parts.xacro').symlink_to('/dev/zero')
    path = write_xacro(tmp_path / 'main.xacro', '<xacro:include filename="parts.xacro"/>')
    with pytest.raises(UrdfError, match=r'parts\.xacro: not a regular file'):
        RobotModel.from_file(path)
