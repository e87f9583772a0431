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

"""Real-process tests of the tf tools over DDS on loopback (each test on its own domain)."""

from __future__ import annotations

from collections.abc import Callable
from collections.abc import Iterator
import json
import os
from pathlib import Path
import re
import select
import signal
import stat
import subprocess
import sys
import time
from typing import IO
from typing import Protocol
from typing import TypedDict

from conftest import Processes
from conftest import run_captured
import pytest
from tf_demo.cli._snapshot import read_snapshot
from tf_demo.cli.formatting import ECHO_USAGE
from tf_demo.cli.formatting import STATIC_USAGE

pytestmark = [pytest.mark.dds]
PEER = Path(__file__).with_name('tf_fault_peer.py')
LOG_PREFIX = r'\[(INFO|WARN|ERROR)\] \[\d+\.\d{9}\] \[[^\]]*\]: '
Entry = dict[str, object]  # one transform of a tf_fault_peer scenario (see its docstring)


class StartPeer(Protocol):
    """The ``peers`` fixture: start a tf_fault_peer publishing ``entries``."""

    def __call__(self, *entries: Entry) -> subprocess.Popen[str]: ...


@pytest.fixture
def peers(world_env: dict[str, str]) -> Iterator[StartPeer]:
    """Start tf_fault_peer processes publishing a JSON scenario; stop them at the end."""
    started: list[subprocess.Popen[str]] = []

    def start(*entries: Entry) -> subprocess.Popen[str]:
        process = subprocess.Popen(
            [sys.executable, str(PEER), json.dumps(list(entries))],
            env=world_env,
            stdout=subprocess.PIPE,
            stderr=subprocess.PIPE,
            text=True,
        )
        started.append(process)
        assert process.stdout is not None
        assert process.stderr is not None
        assert process.stdout.readline().strip() == 'ready', process.stderr.read()
        return process

    yield start
    for process in started:
        process.send_signal(signal.SIGINT)
    for process in started:
        try:
            process.wait(timeout=5)
        except subprocess.TimeoutExpired:
            process.kill()
            process.wait()


def run(spawn: Processes, name: str, *args: str, timeout: float = 60) -> tuple[int, str, str]:
    """Run one of our executables to completion; return (exit code, stdout, stderr)."""
    process = spawn.start(name, *args)
    out, err = process.communicate(timeout=timeout)
    return process.returncode, out, err


def static(
    parent: str,
    child: str,
    t: tuple[float, float, float] = (0.0, 0.0, 0.0),
    group: str = 'main',
    q: tuple[float, float, float, float] = (0.0, 0.0, 0.0, 1.0),
) -> Entry:
    return {
        'parent': parent,
        'child': child,
        't': list(t),
        'q': list(q),
        'static': True,
        'group': group,
    }


def dynamic(parent: str, child: str, **extra: object) -> Entry:
    return {'parent': parent, 'child': child, 'static': False, **extra}


# --- static_transform_publisher: usage, errors and exit codes --------------------------------


def test_static_publisher_help_exits_0_with_usage(spawn):
    """--help prints upstream's usage on stdout and exits 0."""
    code, out, _ = run(spawn, 'static_transform_publisher', '--help')
    assert code == 0
    assert out == STATIC_USAGE


@pytest.mark.parametrize(
    ('args', 'error'),
    [
        (['--x'], 'Not enough arguments for --x'),
        (
            ['--x', 'one', '--frame-id', 'a', '--child-frame-id', 'b'],
            'Failed to parse --x argument as float',
        ),
        (['--frame-id', 'a'], 'Child frame id must not be empty'),
        (['1', '2', '3'], 'Extra unparsed arguments on command-line'),
        (
            ['--qx', '0', '--yaw', '1', '--frame-id', 'a', '--child-frame-id', 'b'],
            'Cannot specify both quaternion and Euler rotations',
        ),
    ],
)
def test_static_publisher_errors_exit_1(spawn, args, error):
    """Each parse error logs upstream's ERROR line with an empty logger, prints usage, exits 1."""
    code, out, err = run(spawn, 'static_transform_publisher', *args)
    assert code == 1
    assert out == STATIC_USAGE
    assert re.fullmatch(
        LOG_PREFIX + re.escape(f'error parsing command line arguments: {error}\n'), err
    )
    assert '[]: ' in err


def test_static_publisher_old_style_warns_and_conflict_fails(spawn):
    """Old-style arguments with a frame flag: the deprecation WARN, then the conflict error."""
    code, _, err = run(
        spawn,
        'static_transform_publisher',
        '1',
        '2',
        '3',
        '0',
        '0',
        '0',
        'a',
        'b',
        '--frame-id',
        'c',
    )
    assert code == 1
    lines = err.splitlines()
    assert lines[0].endswith(
        '[]: Old-style arguments are deprecated; see --help for new-style arguments'
    )
    assert lines[1].endswith(
        'error parsing command line arguments: Cannot specify both new-style (flags) and '
        'old-style (arguments)'
    )


def test_static_publisher_same_frames_exit_1(spawn):
    """frame_id == child_frame_id logs upstream's ERROR and exits 1."""
    code, _, err = run(
        spawn, 'static_transform_publisher', '--frame-id', 'a', '--child-frame-id', 'a'
    )
    assert code == 1
    assert "cannot publish static transform from 'a' to 'a', exiting" in err


# --- tf_echo ------------------------------------------------------------------------------------


def test_echo_usage_and_rate_exit_codes(spawn):
    """Wrong counts print the usage (exit 1); bad rates exit 2 and 3 with upstream's message."""
    code, out, _ = run(spawn, 'tf_echo', 'only_one')
    assert (code, out) == (1, ECHO_USAGE)
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


def test_echo_json_and_inverse_direction(spawn, peers):
    """--json prints one object per line; the pose of target in source (inverse direction)."""
    peers(static('base', 'laser', t=(1.0, 0.0, 0.0)))
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


def test_echo_failure_block_when_the_tree_changes(spawn, peers):
    """When 'laser' gets another parent, tf_echo prints tf2_echo's failure block and goes on."""
    peers(static('base', 'laser', t=(1.0, 0.0, 0.0)))
    echo = spawn.start('tf_echo', 'base', 'laser', '10')
    read_until(echo, 'At time')
    peers(dynamic('other', 'laser', rate=20.0))
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


def test_echo_stops_quietly_when_the_reader_goes_away(spawn, peers):
    """Like `tf_echo a b | head -1`: a closed stdout ends tf_echo with 0 and no traceback."""
    peers(static('base', 'laser'))
    echo = spawn.start('tf_echo', 'base', 'laser', '50')
    read_until(echo, 'At time')
    echo.stdout.close()
    assert echo.wait(timeout=30) == 0
    assert 'Traceback' not in echo.stderr.read()


# --- view_frames ---------------------------------------------------------------------------------


def test_view_frames_writes_upstream_dot_and_pdf(spawn, peers, tmp_path):
    """view_frames -o writes upstream's DOT for a live static tree and renders the PDF."""
    peers(static('map', 'odom'), static('odom', 'base_link'))
    code, _, err = run(spawn, 'view_frames', '-t', '2', '-o', 'tree')
    assert code == 0, err
    assert 'Listening to tf data for 2.0 seconds...' in err
    dot = (tmp_path / 'tree.gv').read_text()
    label = (
        '[label=" Broadcaster: default_authority\\nAverage rate: 10000.0\\nBuffer length: '
        '0.0\\nMost recent transform: 0.0\\nOldest transform: 0.0\\n"];\n'
    )
    assert re.fullmatch(
        re.escape(
            'digraph G {\n"map" -> "odom"'
            + label
            + '"odom" -> "base_link"'
            + label
            + 'edge [style=invis];\n subgraph cluster_legend { style=bold; color=black; '
            'label ="view_frames Result";\n"Recorded at time: '
        )
        + r'\d+\.\d+'
        + re.escape('"[ shape=plaintext ] ;\n}->"map";\n}'),
        dot,
    )
    assert (tmp_path / 'tree.pdf').read_bytes().startswith(b'%PDF')


def test_view_frames_snapshot_with_two_trees(spawn, tmp_path):
    """--snapshot draws a saved file with two trees without listening."""
    snapshot = tmp_path / 'two.yaml'
    snapshot.write_text(
        'tf_demo_transforms: 1\ntransform_count: 2\ntransforms:\n'
        '  - {parent: map, child: odom, translation: [0, 0, 0], rotation: [0, 0, 0, 1]}\n'
        '  - {parent: base_link, child: laser, translation: [0, 0, 0], rotation: [0, 0, 0, 1]}\n'
    )
    code, _, err = run(spawn, 'view_frames', '--snapshot', str(snapshot), '-o', 'two')
    assert code == 0, err
    assert (tmp_path / 'two.gv').read_text().endswith('}->{"map" "base_link"};\n}')
    assert (tmp_path / 'two.pdf').read_bytes().startswith(b'%PDF')


def test_view_frames_without_data(spawn, tmp_path):
    """With nothing published view_frames writes upstream's placeholder graph, and a PDF."""
    code, _, err = run(spawn, 'view_frames', '-t', '0.5', '-o', 'empty')
    assert code == 0, err
    assert (tmp_path / 'empty.gv').read_text() == 'digraph G { "No tf data received" }'
    assert (tmp_path / 'empty.pdf').read_bytes().startswith(b'%PDF')


# --- tf_doctor ---------------------------------------------------------------------------------


class FindingRecord(TypedDict):
    """One finding of ``tf_doctor --json``."""

    kind: str
    severity: str
    frames: list[str]
    message: str
    fix: str


class DoctorReport(TypedDict):
    """The report ``tf_doctor --json`` prints."""

    source: str
    healthy: bool
    summary: dict[str, int]
    findings: list[FindingRecord]


def doctor(spawn: Processes, *args: str) -> tuple[int, DoctorReport]:
    code, out, err = run(spawn, 'tf_doctor', '-t', '2.5', '--json', *args)
    assert err == '' or 'error' not in err.lower(), err
    report: DoctorReport = json.loads(out)
    return code, report


def test_doctor_calls_a_healthy_tree_healthy(spawn, peers):
    """A REP-105 tree with a 20 Hz odometry stream is healthy: exit 0, no findings."""
    peers(
        static('map', 'odom'),
        dynamic('odom', 'base_link', rate=20.0),
        static('base_link', 'laser'),
    )
    code, report = doctor(spawn, '--frames', 'map', 'laser')
    assert report['findings'] == []
    assert (code, report['healthy']) == (0, True)
    assert report['summary']['frames'] == 4


def test_doctor_finds_disconnected_tree_and_missing_frame(spawn, peers):
    """Without odom→base_link: two islands, the missing link named, and a typo matched."""
    peers(static('map', 'odom'), static('base_link', 'laser'))
    code, report = doctor(spawn, '--frames', 'map', 'lazer')
    assert code == 1
    by_kind = {f['kind']: f for f in report['findings']}
    assert 'odom→base_link' in by_kind['disconnected']['fix']
    assert "did you mean 'laser'?" in by_kind['missing_frame']['message']


def test_doctor_finds_two_parents_and_loop(spawn, peers):
    """Two static publishers give 'laser' two parents; a→b→a is a loop."""
    peers(static('map', 'odom'), static('odom', 'laser'), static('x', 'y'), static('y', 'x'))
    peers(static('map', 'laser', group='other'))
    code, report = doctor(spawn)
    kinds = {f['kind'] for f in report['findings']}
    assert code == 1
    assert {'two_parents', 'loop'} <= kinds


def test_doctor_finds_timing_and_publisher_faults(spawn, peers):
    """Future stamps, sparse data, static-and-dynamic and two fighting publishers are found."""
    peers(
        static('map', 'odom'),
        dynamic('map', 'odom', rate=20.0),
        dynamic('odom', 'base_link', rate=20.0, stamp_offset=5.0),
        dynamic('odom', 'slow', rate=1.0, values=[[0, 0, 0], [0.1, 0, 0], [0.2, 0, 0]]),
        dynamic('odom', 'arm', rate=20.0, values=[[0, 0, 0], [1, 0, 0]]),
        dynamic('odom', 'mount', rate=1.8),
    )
    code, report = doctor(spawn)
    found = {(f['kind'], f['frames'][0]) for f in report['findings']}
    assert code == 1
    assert ('static_and_dynamic', 'odom') in found
    assert ('future_stamps', 'base_link') in found
    assert ('sparse_data', 'slow') in found
    assert ('publishers_fighting', 'arm') in found
    # A fixed mount sent again and again on /tf: "publish it once on /tf_static", not "faster".
    assert ('fixed_mount_on_tf', 'mount') in found
    assert ('sparse_data', 'mount') not in found


def test_doctor_blames_the_missing_joint_state_publisher(spawn):
    """
    robot_state_publisher alone: frame_2 hangs below a revolute joint and no /joint_states come.

    The advice names joint_state_publisher (or the driver), not "did you mean 'frame_1'".
    """
    urdf = Path(__file__).resolve().parents[2] / 'urdf' / 'example_revolute.urdf'
    publisher = spawn.start('robot_state_publisher', '--ros-args', '-p', f'urdf_file:={urdf}')
    for line in publisher.stderr:  # bounded by the process's own output
        if 'Robot initialized' in line:
            break
    code, report = doctor(spawn, '--frames', 'world', 'frame_2')
    assert code == 1
    by_kind = {f['kind']: f for f in report['findings']}
    assert set(by_kind) == {'missing_frame', 'no_joint_states'}, report
    missing = by_kind['missing_frame']
    assert 'did you mean' not in missing['message']
    assert "revolute joint 'frame_1_to_frame_2'" in missing['message']
    assert missing['fix'].startswith("joint_state_publisher (or the robot's driver) is missing")
    assert by_kind['no_joint_states']['frames'] == ['frame_2']


# rclpy Jazzy's MessageInfo carries no publisher GID, so only the standalone world's tf_doctor
# can tell two publishers of one frame apart (README).
@pytest.mark.standalone
def test_doctor_names_two_publishers_of_one_frame(spawn, peers):
    """Two nodes sending odom→base_link with smoothly moving values are told apart by writer."""
    moving = [[0.01 * i, 0.0, 0.0] for i in range(200)]
    peers(static('map', 'odom'), dynamic('odom', 'base_link', rate=20.0, values=moving))
    peers(
        dynamic(
            'odom',
            'base_link',
            rate=20.0,
            values=[[5 + v[0], 0, 0] for v in moving],
            group='second',
        )
    )
    code, report = doctor(spawn)
    fights = [f for f in report['findings'] if f['kind'] == 'publishers_fighting']
    assert code == 1
    assert fights
    assert '2 different publishers send it' in fights[0]['message']


def test_doctor_finds_publishers_with_incompatible_qos(spawn, peers):
    """A VOLATILE /tf_static and a BEST_EFFORT /tf publisher are in the graph but unmatched."""
    peers(static('map', 'odom'))
    peers(
        static('odom', 'lost', group='volatile') | {'volatile': True},
        dynamic('odom', 'gone', rate=20.0, group='be', best_effort=True),
    )
    code, report = doctor(spawn)
    found = {
        f['message'].split(' do')[0] for f in report['findings'] if f['kind'] == 'qos_mismatch'
    }
    assert code == 1
    assert found == {'1 publisher on /tf', '1 publisher on /tf_static'}
    assert report['summary']['frames'] == 2


# --- tf_saver / tf_loader -----------------------------------------------------------------------


def test_saver_loader_round_trip(spawn, peers, tmp_path):
    """Save a live tree, republish it with tf_loader, save again: the same transforms."""
    source = peers(
        static('map', 'odom', t=(1.0, 2.0, 0.0)),
        dynamic('odom', 'base_link', rate=20.0, t=[0.5, 0.0, 0.0]),
        static('base_link', 'laser', t=(0.1, 0.0, 0.2), q=(0.0, 0.0, 1.0, 0.0)),
    )
    code, _, err = run(spawn, 'tf_saver', '-t', '3', '-o', 'first.yaml')
    assert code == 0, err
    first = read_snapshot(tmp_path / 'first.yaml')
    assert [(e.parent, e.child, e.is_static) for e in first.transforms] == [
        ('map', 'odom', True),
        ('odom', 'base_link', False),
        ('base_link', 'laser', True),
    ]
    rate_hz = first.transforms[1].rate_hz
    assert rate_hz is not None
    assert rate_hz > 5
    source.send_signal(signal.SIGINT)
    source.wait(timeout=30)
    loader = spawn.start('tf_loader', 'first.yaml')
    code, _, err = run(spawn, 'tf_saver', '-t', '3', '-o', 'second.yaml')
    assert code == 0, err
    second = read_snapshot(tmp_path / 'second.yaml')
    assert [(e.parent, e.child, e.translation, e.rotation) for e in second.transforms] == [
        (e.parent, e.child, e.translation, e.rotation) for e in first.transforms
    ]
    assert all(e.is_static for e in second.transforms)
    loader.send_signal(signal.SIGINT)
    assert loader.wait(timeout=30) == 0  # a bound, generous for a loaded 2-core machine


def test_saver_chosen_frames_and_flatten(spawn, peers, tmp_path):
    """Frames select the connecting links; --flatten composes them relative to the first."""
    peers(
        static('map', 'odom', t=(1.0, 0.0, 0.0)),
        static('odom', 'base_link', t=(0.0, 2.0, 0.0)),
        static('base_link', 'laser', t=(0.0, 0.0, 3.0)),
        static('base_link', 'cam'),
    )
    code, _, err = run(spawn, 'tf_saver', '-t', '3', '-o', 'part.yaml', 'odom', 'laser')
    assert code == 0, err
    part = read_snapshot(tmp_path / 'part.yaml')
    assert [(e.parent, e.child) for e in part.transforms] == [
        ('odom', 'base_link'),
        ('base_link', 'laser'),
    ]
    code, _, err = run(
        spawn, 'tf_saver', '-t', '3', '-o', 'flat.yaml', '--flatten', 'map', 'laser'
    )
    assert code == 0, err
    flat = read_snapshot(tmp_path / 'flat.yaml')
    assert [(e.parent, e.child, e.translation) for e in flat.transforms] == [
        ('map', 'laser', (1.0, 2.0, 3.0))
    ]


def test_saver_writes_through_a_link_and_refuses_a_device(spawn, peers, tmp_path):
    """
    -o through a symbolic link updates the file it names and keeps the link (issue 10, 7).

    A device is refused before listening: exit 2, one line, the node untouched (a private
    /dev/full-like node when root may make one, else a FIFO).
    """
    peers(static('map', 'odom', t=(1.0, 2.0, 0.0)))
    (tmp_path / 'kept').mkdir()
    (tmp_path / 'kept' / 'real.yaml').write_text('old\n', encoding='utf-8')
    (tmp_path / 'latest.yaml').symlink_to(Path('kept') / 'real.yaml')
    code, _, err = run(spawn, 'tf_saver', '-t', '3', '-o', 'latest.yaml')
    assert code == 0, err
    assert (tmp_path / 'latest.yaml').is_symlink()
    saved = read_snapshot(tmp_path / 'kept' / 'real.yaml')
    assert [(e.parent, e.child) for e in saved.transforms] == [('map', 'odom')]

    device = tmp_path / 'device'
    try:
        os.mknod(device, 0o666 | stat.S_IFCHR, os.makedev(1, 7))
        is_kind = stat.S_ISCHR
    except PermissionError:
        os.mkfifo(device)
        is_kind = stat.S_ISFIFO
    for target in (device, tmp_path / 'latest_device'):
        if target != device:
            target.symlink_to(device)
        code, out, err = run(spawn, 'tf_saver', '-t', '3', '-o', str(target))
        assert (code, out) == (2, '')
        assert err == (
            f'tf_saver: error: {target}: not a regular file (a device, FIFO or socket); '
            'nothing was written\n'
        )
        assert is_kind(os.lstat(device).st_mode)


def test_loader_refuses_bad_file_and_publishes_nothing(spawn, tmp_path):
    """A hostile file is refused with its line, exit 1, before anything is published."""
    bad = tmp_path / 'bad.yaml'
    bad.write_text(
        'tf_demo_transforms: 1\ntransform_count: 1\ntransforms:\n'
        '  - {parent: a, child: b, translation: [0, .nan, 0], rotation: [0, 0, 0, 1]}\n'
    )
    code, out, err = run(spawn, 'tf_loader', str(bad))
    assert code == 1
    assert out == ''
    assert err == (
        f'tf_loader: error: {bad}:4: transforms[0].translation[1] must be finite, got nan\n'
    )
    code, _, err = run(spawn, 'tf_loader', str(tmp_path / 'missing.yaml'))
    assert code == 1
    assert 'missing.yaml: no such file' in err


# --- tf_monitor -------------------------------------------------------------------------------


def test_monitor_reports_chain_and_frames(spawn, peers):
    """tf_monitor framea frameb prints the chain, net delay and the chain's frames."""
    peers(
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


def test_monitor_all_frames(spawn, peers):
    """Without arguments tf_monitor reports every frame, sorted, and one broadcaster line."""
    peers(static('map', 'odom'), dynamic('odom', 'base_link', rate=20.0))
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
