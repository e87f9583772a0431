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

"""tf_doctor's check of expected frames: failed lookups, robot links and REP 105's map and odom."""

from __future__ import annotations

from doctor_cases import REVOLUTE_ROBOT
from doctor_cases import S
from doctor_cases import static
from doctor_cases import stream
from tf_demo.cli._doctor import diagnose
from tf_demo.cli._doctor_expected import frames_in_failed_lookups
from tf_demo.cli._doctor_report import exit_code
from tf_demo.cli._doctor_report import format_report
from tf_demo.cli._doctor_report import summarize
from tf_demo.cli._doctor_robot import RobotInfo
from tf_demo.cli._observations import Observation

MAP_FIX = 'ros2 run tf_demo static_transform_publisher --frame-id map --child-frame-id odom'


def odometry_only() -> list[Observation]:
    return [*stream('odom', 'base_link'), static('base_link', 'laser')]


def test_the_frames_of_tf2s_does_not_exist_errors_are_read_from_log_lines():
    """Both of tf2's spellings name the frame; other log lines name none."""
    lines = [
        'Could not transform map to base_link: "map" passed to lookupTransform argument '
        'target_frame does not exist. ',
        'Invalid frame ID "odom" passed to canTransform argument source_frame - frame does not '
        'exist',
        'Robot initialized',
    ]
    assert frames_in_failed_lookups(lines) == ['map', 'odom']


def test_odom_without_map_is_a_note_with_the_static_publisher_command():
    """RViz's "Fixed Frame [map] does not exist": the tree is healthy, the report says why."""
    findings = diagnose(odometry_only(), listen_ns=2 * S)
    assert [(f.kind, f.severity, f.frames) for f in findings] == [
        ('rep105_frame_missing', 'info', ('map',))
    ]
    assert 'Fixed Frame [map] does not exist' in findings[0].message
    assert MAP_FIX in findings[0].fix
    assert exit_code(findings) == 0
    report = format_report(findings, summarize(odometry_only()), 'listened 2.0 s')
    assert report.endswith('Healthy: no problems found (1 note above).\n')


def test_a_base_frame_without_odom_or_map_is_a_note_about_odometry():
    """base_link as a root: odom→base_link is what is missing (map waits for odom)."""
    findings = diagnose([static('base_link', 'laser')], check_timing=False)
    assert [(f.kind, f.frames) for f in findings] == [('rep105_frame_missing', ('odom',))]
    assert '--frame-id odom --child-frame-id base_link' in findings[0].fix


def test_a_failed_lookup_of_map_is_an_error_with_the_cause_and_the_command():
    """A node looked up 'map' and failed: an error, not a note, once."""
    findings = diagnose(odometry_only(), listen_ns=2 * S, looked_up=['map', 'map', 'laser'])
    assert [(f.kind, f.severity) for f in findings] == [('looked_up_frame_missing', 'error')]
    assert '(2 failed lookups in /rosout)' in findings[0].message
    assert 'no localisation' in findings[0].message
    assert MAP_FIX in findings[0].fix
    assert exit_code(findings) == 1


def test_robot_links_absent_from_tf_blame_robot_state_publisher():
    """/robot_description heard, none of its links in tf: robot_state_publisher is not running."""
    robot = RobotInfo(REVOLUTE_ROBOT)
    findings = diagnose(odometry_only(), listen_ns=2 * S, robot=robot, looked_up=['frame_1'])
    by_kind = {f.kind: f for f in findings}
    assert set(by_kind) == {
        'looked_up_frame_missing',
        'robot_links_missing',
        'rep105_frame_missing',
    }
    assert 'link of /robot_description' in by_kind['looked_up_frame_missing'].message
    assert by_kind['robot_links_missing'].frames == ('finger', 'frame_2', 'tool', 'world')
    assert 'urdf_file:=' in by_kind['robot_links_missing'].fix


def test_links_explained_by_missing_joint_states_are_not_reported_twice():
    """frame_2 and below wait for /joint_states: that check reports them, not this one."""
    robot = RobotInfo(REVOLUTE_ROBOT)
    findings = diagnose([static('world', 'frame_1')], check_timing=False, robot=robot)
    assert [f.kind for f in findings] == ['no_joint_states']
