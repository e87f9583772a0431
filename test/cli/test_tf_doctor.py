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

"""tf_doctor as a real process: its JSON report on healthy and broken trees over DDS."""

from __future__ import annotations

import json
from pathlib import Path
from typing import TypedDict

from conftest import Processes
import pytest
from tool_runs import dynamic
from tool_runs import run
from tool_runs import static

pytestmark = [pytest.mark.dds]

MAP_ODOM_COMMAND = (
    'ros2 run tf_demo static_transform_publisher --frame-id map --child-frame-id odom'
)


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


def test_doctor_calls_a_healthy_tree_healthy(spawn, tf_peers):
    """A REP-105 tree with a 20 Hz odometry stream is healthy: exit 0, no findings."""
    tf_peers(
        static('map', 'odom'),
        dynamic('odom', 'base_link', rate=20.0),
        static('base_link', 'laser'),
    )
    code, report = doctor(spawn, '--frames', 'map', 'laser')
    assert report['findings'] == []
    assert (code, report['healthy']) == (0, True)
    assert report['summary']['frames'] == 4


def test_doctor_finds_disconnected_tree_and_missing_frame(spawn, tf_peers):
    """Without odom→base_link: two islands, the missing link named, and a typo matched."""
    tf_peers(static('map', 'odom'), static('base_link', 'laser'))
    code, report = doctor(spawn, '--frames', 'map', 'lazer')
    assert code == 1
    by_kind = {f['kind']: f for f in report['findings']}
    assert 'odom→base_link' in by_kind['disconnected']['fix']
    assert "did you mean 'laser'?" in by_kind['missing_frame']['message']


def test_doctor_finds_two_parents_and_loop(spawn, tf_peers):
    """Two static publishers give 'laser' two parents; a→b→a is a loop."""
    tf_peers(static('map', 'odom'), static('odom', 'laser'), static('x', 'y'), static('y', 'x'))
    tf_peers(static('map', 'laser', group='other'))
    code, report = doctor(spawn)
    kinds = {f['kind'] for f in report['findings']}
    assert code == 1
    assert {'two_parents', 'loop'} <= kinds


def test_doctor_finds_timing_and_publisher_faults(spawn, tf_peers):
    """Future stamps, sparse data, static-and-dynamic and two fighting publishers are found."""
    tf_peers(
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
def test_doctor_names_two_publishers_of_one_frame(spawn, tf_peers):
    """Two nodes sending odom→base_link with smoothly moving values are told apart by writer."""
    moving = [[0.01 * i, 0.0, 0.0] for i in range(200)]
    tf_peers(static('map', 'odom'), dynamic('odom', 'base_link', rate=20.0, values=moving))
    tf_peers(
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


def test_doctor_finds_publishers_with_incompatible_qos(spawn, tf_peers):
    """A VOLATILE /tf_static and a BEST_EFFORT /tf publisher are in the graph but unmatched."""
    tf_peers(static('map', 'odom'))
    tf_peers(
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


def test_doctor_explains_rvizs_missing_map_fixed_frame(spawn, tf_peers):
    """
    odom→base_link with no map (the guide's "Fixed Frame [map] does not exist"): a note with the
    command; once a node's lookups of 'map' fail (its warnings on /rosout), an error.
    """
    tf_peers(dynamic('odom', 'base_link', rate=20.0), static('base_link', 'laser'))
    code, report = doctor(spawn)
    assert (code, report['healthy']) == (0, True)
    [note] = report['findings']
    assert (note['kind'], note['severity'], note['frames']) == (
        'rep105_frame_missing',
        'info',
        ['map'],
    )
    assert MAP_ODOM_COMMAND in note['fix']

    listener = spawn.start(
        'tf_listener',
        '--ros-args',
        '-p',
        'target_frame:=map',
        '-p',
        'source_frame:=laser',
        '-p',
        'period:=0.2',
    )
    for line in listener.stderr:  # bounded by the process's own output
        if '"map" passed to lookupTransform argument target_frame does not exist' in line:
            break
    code, report = doctor(spawn)
    assert (code, report['healthy']) == (1, False)
    [error] = report['findings']
    assert (error['kind'], error['frames']) == ('looked_up_frame_missing', ['map'])
    assert 'no localisation' in error['message']
    assert MAP_ODOM_COMMAND in error['fix']
