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

"""Tests of tf_doctor's robot checks: missing frames, and links whose joints got no position."""

from doctor_cases import healthy
from doctor_cases import kinds
from doctor_cases import REVOLUTE_ROBOT
from doctor_cases import S
from doctor_cases import static
from tf_demo.cli._doctor import diagnose
from tf_demo.cli._doctor_robot import RobotInfo


def test_missing_frame_with_close_match_and_slash():
    """Unknown frames get close matches; a leading slash is explained."""
    findings = diagnose(healthy(), frames=['base_lnk', '/laser', 'zzz'])
    messages = [f.message for f in findings if f.kind == 'missing_frame']
    assert "Frame 'base_lnk' does not exist in the tf tree: did you mean 'base_link'?" in messages
    assert any("'laser' exists: tf2 frame ids must not start with '/'" in m for m in messages)
    assert "Frame 'zzz' does not exist in the tf tree." in messages


def test_a_frame_below_a_moving_joint_without_joint_states_names_the_missing_publisher():
    """Not 'did you mean frame_1': frame_2 waits for /joint_states, which nobody publishes."""
    robot = RobotInfo(REVOLUTE_ROBOT, joint_state_messages=0)
    findings = diagnose(
        [static('world', 'frame_1')], frames=['world', 'frame_2'], robot=robot, listen_ns=3 * S
    )
    assert kinds(findings) == ['missing_frame', 'no_joint_states']
    missing = next(f for f in findings if f.kind == 'missing_frame')
    assert 'did you mean' not in missing.message
    assert "revolute joint 'frame_1_to_frame_2'" in missing.message
    assert 'no /joint_states message arrived' in missing.message
    assert missing.fix.startswith("joint_state_publisher (or the robot's driver) is missing")
    summary = next(f for f in findings if f.kind == 'no_joint_states')
    assert summary.frames == ('finger', 'frame_2', 'tool')
    assert 'no /joint_states message arrived in 3.000 s' in summary.message
    assert "'frame_1_to_frame_2'" in summary.message


def test_joint_states_that_never_name_the_joint_are_reported_as_such():
    """/joint_states arrives but without the joint: say so, with the names to check."""
    robot = RobotInfo(REVOLUTE_ROBOT, 12, frozenset({'other_joint'}))
    findings = diagnose([static('world', 'frame_1')], frames=['frame_2'], robot=robot)
    assert kinds(findings) == ['joint_positions_missing', 'missing_frame']
    missing = next(f for f in findings if f.kind == 'missing_frame')
    assert "/joint_states never gave a position for 'frame_1_to_frame_2'" in missing.message
    assert 'joint names exactly as in the URDF' in missing.fix


def test_a_joint_with_a_position_or_a_robot_not_in_tf_is_not_blamed():
    """
    With the position (a mimic follows its source) or with no robot link in tf: no joint blamed.

    A robot none of whose links tf has is robot_state_publisher's absence (test_doctor_expected).
    """
    named = RobotInfo(REVOLUTE_ROBOT, 5, frozenset({'frame_1_to_frame_2'}))
    findings = diagnose([static('world', 'frame_1')], frames=['frame_2'], robot=named)
    assert kinds(findings) == ['missing_frame']
    assert 'did you mean' in findings[0].message
    unrelated = diagnose(
        [static('map', 'odom')], frames=['frame_2'], robot=RobotInfo(REVOLUTE_ROBOT)
    )
    assert kinds(unrelated) == ['missing_frame', 'robot_links_missing']
