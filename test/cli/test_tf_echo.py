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

"""tf_echo as a real process over DDS on loopback: usage, golden blocks, JSON, failures."""

from __future__ import annotations

from collections.abc import Callable
import json
import re
import select
import signal
import subprocess
import time
from typing import IO

import pytest
from tf_demo.cli.formatting import ECHO_USAGE
from tool_runs import dynamic
from tool_runs import LOG_PREFIX
from tool_runs import run
from tool_runs import static

pytestmark = [pytest.mark.dds]


def test_echo_usage_and_rate_exit_codes(spawn):
    """Wrong counts print the usage (exit 1); bad rates exit 2 and 3 with upstream's message."""
    code, out, _ = run(spawn, 'tf_echo', 'only_one')
    assert (code, out) == (1, ECHO_USAGE)
    for flag in ('--help', '-h'):  # upstream's usage, then our flags (exit 1 as the usage)
        code, out, err = run(spawn, 'tf_echo', flag)
        assert (code, err) == (1, '')
        assert out.startswith(ECHO_USAGE)
        for extra in ('--precision N', '--limit N', '--json', '--bag PATH', '--at T'):
            assert f' {extra} ' in out
    code, _, err = run(spawn, 'tf_echo', 'a', 'b', 'x')
    assert code == 2
    assert err == "Failed to convert rate argument 'x' to a floating-point number\n"
    code, _, err = run(spawn, 'tf_echo', 'a', 'b', '2hz')
    assert code == 3
    assert err == "Failed to convert rate argument '2hz' to a floating-point number\n"


def test_echo_prints_golden_block_from_static_publisher(spawn):
    """tf_echo against a real static_transform_publisher prints tf2_echo's block exactly."""
    publisher = spawn.start(
        'static_transform_publisher',
        '--x',
        '1',
        '--y',
        '-2.5',
        '--yaw',
        '1.5707963267948966',
        '--frame-id',
        'base',
        '--child-frame-id',
        'laser',
    )
    code, out, err = run(spawn, 'tf_echo', 'base', 'laser', '20', '--limit', '2')
    assert code == 0, err
    block = (
        'At time 0.0\n'
        '- Translation: [1.000, -2.500, 0.000]\n'
        '- Rotation: in Quaternion [0.000, 0.000, 0.707, 0.707]\n'
        '- Rotation: in RPY (radian) [0.000, -0.000, 1.571]\n'
        '- Rotation: in RPY (degree) [0.000, -0.000, 90.000]\n'
        '- Matrix:\n'
        '  0.000 -1.000  0.000  1.000\n'
        '  1.000  0.000  0.000 -2.500\n'
        '  0.000  0.000  1.000  0.000\n'
        '  0.000  0.000  0.000  1.000\n'
    )
    assert out == block + block
    publisher.send_signal(signal.SIGINT)
    _, pub_err = publisher.communicate(timeout=10)
    assert publisher.returncode == 0
    assert re.search(
        LOG_PREFIX.replace(r'[^\]]*', r'static_transform_publisher_[A-Za-z0-9]{16}')
        + re.escape(
            "Spinning until stopped - publishing transform\ntranslation: ('1.000000', "
            "'-2.500000', '0.000000')\nrotation: ('0.000000', '0.000000', '0.707107', "
            "'0.707107')\nfrom 'base' to 'laser'"
        ),
        pub_err,
    )


def test_echo_json_and_inverse_direction(spawn, tf_peers):
    """--json prints one object per line; the pose of target in source (inverse direction)."""
    tf_peers(static('base', 'laser', t=(1.0, 0.0, 0.0)))
    code, out, err = run(spawn, 'tf_echo', 'laser', 'base', '20', '--limit', '1', '--json')
    assert code == 0, err
    record = json.loads(out)
    assert record['translation'] == [-1.0, 0.0, 0.0]
    assert record['source_frame'] == 'laser'


def read_lines(
    stream: IO[str], found: Callable[[str], bool], what: str, limit_s: float = 60.0
) -> list[str]:
    """Read ``stream`` until a line ``found`` accepts (a guard against hangs); return the lines."""
    deadline = time.monotonic() + limit_s
    lines: list[str] = []
    while time.monotonic() < deadline:
        ready, _, _ = select.select([stream], [], [], 0.5)
        if not ready:
            continue
        line = stream.readline()
        if not line:
            break
        lines.append(line)
        if found(line):
            return lines
    pytest.fail(f'no line {what} in: {"".join(lines)}')
    return lines


def read_until(process: subprocess.Popen[str], marker: str) -> list[str]:
    """Read the process' stdout until a line starting with ``marker``."""
    assert process.stdout is not None
    return read_lines(
        process.stdout, lambda line: line.startswith(marker), f'starting with {marker!r}'
    )


def test_echo_failure_block_when_the_tree_changes(spawn, tf_peers):
    """When 'laser' gets another parent, tf_echo prints tf2_echo's failure block and goes on."""
    tf_peers(static('base', 'laser', t=(1.0, 0.0, 0.0)))
    echo = spawn.start('tf_echo', 'base', 'laser', '10')
    read_until(echo, 'At time')
    tf_peers(dynamic('other', 'laser', rate=20.0))
    lines = read_until(echo, 'Failure at')
    lines += [echo.stdout.readline() for _ in range(3)]
    tail = lines[-4:]
    assert re.fullmatch(r'Failure at \d+\.\d{3}\n', tail[0])
    assert tail[1] == (
        "Exception thrown:Could not find a connection between 'base' and 'laser' because "
        'they are not part of the same tree.Tf has two or more unconnected trees.\n'
    )
    assert tail[2] == 'The current list of frames is:\n'
    assert tail[3] == 'Frame laser exists with parent other.\n'
    assert echo.stdout.readline() == '\n'


def read_stderr_until(process: subprocess.Popen[str], marker: str) -> str:
    """Read the process' stderr until a line containing ``marker``; return that line."""
    assert process.stderr is not None
    return read_lines(process.stderr, lambda line: marker in line, f'with {marker!r}')[-1]


def test_echo_logs_the_waiting_line(spawn):
    """Before the frames exist tf_echo logs upstream's INFO waiting line (two spaces after ->)."""
    echo = spawn.start('tf_echo', 'nowhere', 'nothing', '5')
    line = read_stderr_until(echo, 'Waiting for transform')
    assert re.fullmatch(
        LOG_PREFIX.replace(r'[^\]]*', 'tf2_echo')
        + re.escape(
            'Waiting for transform nowhere ->  nothing: Invalid frame ID "nowhere" passed '
            'to canTransform argument target_frame - frame does not exist\n'
        ),
        line,
    )


def test_echo_stops_quietly_when_the_reader_goes_away(spawn, tf_peers):
    """Like `tf_echo a b | head -1`: a closed stdout ends tf_echo with 0 and no traceback."""
    tf_peers(static('base', 'laser'))
    echo = spawn.start('tf_echo', 'base', 'laser', '50')
    read_until(echo, 'At time')
    echo.stdout.close()
    assert echo.wait(timeout=30) == 0
    assert 'Traceback' not in echo.stderr.read()


def test_echo_and_monitor_read_a_namespaced_robot_with_namespace(spawn):
    """A robot whose TF is under /robot1 (remapped, as a fleet does) is read with --namespace."""
    spawn.start(
        'static_transform_publisher', '--x', '2', '--frame-id', 'base', '--child-frame-id',
        'laser', '--ros-args', '-r', '/tf_static:=/robot1/tf_static',
    )  # fmt: skip
    code, out, err = run(
        spawn, 'tf_echo', 'base', 'laser', '20', '--limit', '1', '--namespace', 'robot1'
    )
    assert code == 0, err
    assert '- Translation: [2.000, 0.000, 0.000]' in out
    code, out, err = run(spawn, 'tf_monitor', '--namespace', '/robot1/', '--limit', '1')
    assert code == 0, err
    assert 'laser' in out


READING_TOOLS = ['tf_echo', 'tf_monitor', 'tf_doctor', 'view_frames', 'tf_view', 'tf_record']


@pytest.mark.parametrize('tool', [*READING_TOOLS, 'tf_plot'])
def test_every_reading_tool_refuses_a_bad_namespace_in_one_line(spawn, tool):
    """--namespace takes rmw's namespace rules: a bad one is one line on stderr and exit 2."""
    frames = {
        'tf_echo': ['a', 'b'],
        'tf_plot': ['a', 'b', '-o', 'plot.png', '--duration', '1'],
        'tf_record': ['-o', 'bag'],
    }.get(tool, [])
    code, _, err = run(spawn, tool, *frames, '--namespace', 'robot 1')
    assert code == 2
    lines = err.strip().splitlines()
    assert len(lines) == 1
    assert "--namespace 'robot 1' is not a valid namespace" in lines[0]
