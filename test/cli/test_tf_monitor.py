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

"""tf_monitor (and the tf2_monitor/tf2_echo aliases) as real processes over DDS."""

from __future__ import annotations

import os
from pathlib import Path
import re
import sys

from conftest import run_captured
import pytest
from tf_demo.cli.formatting import ECHO_USAGE
from tool_runs import dynamic
from tool_runs import run
from tool_runs import static

pytestmark = [pytest.mark.dds]


def test_monitor_reports_chain_and_frames(spawn, tf_peers):
    """tf_monitor framea frameb prints the chain, net delay and the chain's frames."""
    tf_peers(
        static('map', 'odom'),
        dynamic('odom', 'base_link', rate=20.0),
        static('base_link', 'laser'),
    )
    code, out, err = run(spawn, 'tf_monitor', 'map', 'laser', '--interval', '1.5', '--limit', '1')
    assert code == 0, err
    lines = out.splitlines()
    assert lines[0] == 'Gathering data on map -> laser for 10 seconds...'
    assert lines[1:4] == ['', '', '']
    assert lines[4] == 'RESULTS: for map to laser'
    assert lines[5] == 'Chain is: map -> odom -> base_link -> laser'
    assert re.fullmatch(r'Net delay     avg = \S+: max = \S+', lines[6])
    assert lines[7:9] == ['', 'Frames:']
    assert re.fullmatch(
        r'Frame: base_link, published by <no authority available>, '
        r'Average Delay: \S+, Max Delay: \S+',
        lines[9],
    )
    assert re.fullmatch(
        r'Node: <no authority available> \S+ Hz, Average Delay: \S+ '
        r'Max Delay: \S+',
        lines[-1],
    )
    assert '\nAll Broadcasters:\n' in err


def test_monitor_usage_exit_255(spawn):
    """One frame is a usage error: upstream's INFO line and exit code -1 (255)."""
    code, _, err = run(spawn, 'tf_monitor', 'only_one')
    assert code == 255
    assert err.endswith('[]: TF_Monitor: usage: tf2_monitor framea frameb\n')


def installed_script(name: str) -> Path:
    """The installed console script ``name``: in the venv's bin, else the overlay's lib/tf_demo."""
    candidates = [Path(sys.executable).parent / name]
    candidates += [
        Path(prefix) / 'lib' / 'tf_demo' / name
        for prefix in os.environ.get('AMENT_PREFIX_PATH', '').split(os.pathsep)
        if prefix
    ]
    for candidate in candidates:
        if candidate.is_file():
            return candidate
    pytest.skip(f'{name} is not installed here (pip install -e . or colcon build)')
    return None


@pytest.mark.parametrize(
    ('alias', 'tool'), [('tf2_monitor', 'tf_monitor'), ('tf2_echo', 'tf_echo')]
)
def test_upstream_names_are_aliases_of_the_tools(world_env, alias, tool):
    """tf2_monitor and tf2_echo are installed and run tf_monitor and tf_echo (issue 10, 13)."""
    from importlib.metadata import entry_points

    scripts = {e.name: e.value for e in entry_points(group='console_scripts')}
    assert scripts[alias] == scripts[tool] == f'tf_demo.cli.{tool}:main'
    completed = run_captured([str(installed_script(alias)), 'only_one'], world_env)
    if tool == 'tf_monitor':
        assert completed.returncode == 255
        assert completed.stderr.endswith('[]: TF_Monitor: usage: tf2_monitor framea frameb\n')
    else:
        assert (completed.returncode, completed.stdout) == (1, ECHO_USAGE)


def test_monitor_all_frames(spawn, tf_peers):
    """Without arguments tf_monitor reports every frame, sorted, and one broadcaster line."""
    tf_peers(static('map', 'odom'), dynamic('odom', 'base_link', rate=20.0))
    code, out, err = run(spawn, 'tf_monitor', '--interval', '1.5', '--limit', '1')
    assert code == 0, err
    lines = out.splitlines()
    assert lines[:5] == [
        'Gathering data on all frames for 10 seconds...',
        '',
        '',
        '',
        'RESULTS: for all Frames',
    ]
    assert lines[5:7] == ['', 'Frames:']
    assert [line.split(',')[0] for line in lines[7:9]] == ['Frame: base_link', 'Frame: odom']
    assert lines[-1].startswith('Node: <no authority available> ')
