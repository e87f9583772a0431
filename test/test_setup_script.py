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

"""tools/setup.sh: the demo job installs what the demo runs, not the test extras."""

from __future__ import annotations

import re
import subprocess

from conftest import REPO_ROOT

SETUP = REPO_ROOT / 'tools' / 'setup.sh'


def pip_packages(job: str) -> list[str]:
    """Run the script's own lines that choose the pip packages for ``job``; return them."""
    lines = SETUP.read_text(encoding='utf-8').splitlines()
    first = next(i for i, line in enumerate(lines) if line.startswith('pip_packages=('))
    chosen = [line for line in lines[first : first + 2] if 'pip_packages=' in line]
    assert len(chosen) == 2, 'setup.sh chooses its pip packages in two lines, demo then test'
    script = '\n'.join([f'job={job}', *chosen, 'printf "%s\\n" "${pip_packages[@]}"'])
    result = subprocess.run(
        ['bash', '-c', script], capture_output=True, text=True, check=True, timeout=30
    )
    return result.stdout.splitlines()


def extras(packages: list[str]) -> set[str]:
    """The extras of the ``.[a,b]`` requirement among ``packages``."""
    [spec] = [p for p in packages if p.startswith('.[')]
    match = re.fullmatch(r'\.\[([a-z,]+)\]', spec)
    assert match is not None, spec
    return set(match.group(1).split(','))


def test_the_demo_installs_the_dds_backend_and_the_viewer_only():
    """demo: -e .[dds,view], no test or bag extras, no colcon; test: every extra and colcon."""
    demo = pip_packages('demo')
    assert extras(demo) == {'dds', 'view'}
    assert not any('colcon' in p for p in demo), demo
    test = pip_packages('test')
    assert extras(test) == {'dds', 'test', 'view', 'bag', 'docs'}
    assert 'colcon-common-extensions' in test
