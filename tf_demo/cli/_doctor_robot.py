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
tf_doctor's checks against the robot: links missing because their joints got no position.

What was heard on ``/robot_description`` and ``/joint_states`` (:class:`RobotInfo`) explains a
robot link that tf lacks: robot_state_publisher publishes a moving joint only once
``/joint_states`` gives its position. A frame the user asked for that does not exist is reported
here too, with that reason or with close matches.
"""

from __future__ import annotations

from collections.abc import Mapping
from collections.abc import Sequence
from dataclasses import dataclass
import difflib

from tf_demo.cli._doctor_model import Finding
from tf_demo.cli._doctor_model import format_members
from tf_demo.cli._doctor_model import seconds

MOVING_JOINT_TYPES = ('revolute', 'continuous', 'prismatic')


@dataclass(frozen=True)
class RobotJoint:
    """One joint of the robot_description: ``parent`` link, ``child`` link, ``mimic`` source."""

    name: str
    type: str
    parent: str
    child: str
    mimic: str | None = None


@dataclass(frozen=True)
class RobotInfo:
    """What was heard about the robot: /robot_description's joints and /joint_states' names."""

    joints: tuple[RobotJoint, ...]
    joint_state_messages: int = 0
    joint_state_names: frozenset[str] = frozenset()

    def has_position(self, joint: RobotJoint) -> bool:
        """Whether /joint_states gave ``joint`` a position (a mimic joint follows its source)."""
        return (joint.mimic or joint.name) in self.joint_state_names


def missing_frames(
    frames: Sequence[str],
    known: set[str],
    blocked: Mapping[str, RobotJoint],
    robot: RobotInfo | None,
) -> list[Finding]:
    """Report the frames the user asked for that tf lacks, with the reason or close names."""
    findings = []
    for frame in frames:
        if frame in known:
            continue
        if frame in blocked and robot is not None:
            joint = blocked[frame]
            why = (
                'no /joint_states message arrived'
                if robot.joint_state_messages == 0
                else f"/joint_states never gave a position for '{joint.mimic or joint.name}'"
            )
            findings.append(
                Finding(
                    'missing_frame',
                    'error',
                    (frame,),
                    f"Frame '{frame}' does not exist in the tf tree: it hangs below the "
                    f"{joint.type} joint '{joint.name}', which robot_state_publisher publishes "
                    f'only with a position from /joint_states, and {why}.',
                    _joint_states_fix(robot),
                )
            )
            continue
        hints = []
        if frame.startswith('/') and frame.lstrip('/') in known:
            hints.append(f"'{frame.lstrip('/')}' exists: tf2 frame ids must not start with '/'")
        close = difflib.get_close_matches(frame, sorted(known), n=3, cutoff=0.6)
        if close and not hints:
            hints.append('did you mean ' + ' or '.join(f"'{c}'" for c in close) + '?')
        message = f"Frame '{frame}' does not exist in the tf tree"
        message += f': {hints[0]}' if hints else '.'
        findings.append(
            Finding(
                'missing_frame',
                'error',
                (frame,),
                message,
                'Use one of the existing frame names (view_frames lists them), or start the '
                f"node that should publish '{frame}'.",
            )
        )
    return findings


def links_without_joint_positions(robot: RobotInfo, known: set[str]) -> dict[str, RobotJoint]:
    """
    Map each robot link missing from tf to the moving joint that keeps it out, if any.

    Walking up from the link to the first frame tf knows, the topmost moving joint without a
    position is the one to fix first. Nothing is reported when no link of the robot is in tf at
    all (robot_state_publisher not running, or a frame prefix): that is another problem.
    """
    parent_joint = {joint.child: joint for joint in robot.joints}
    links = set(parent_joint) | {joint.parent for joint in robot.joints}
    if not links & known:
        return {}
    blocked: dict[str, RobotJoint] = {}
    for link in sorted(set(parent_joint) - known):
        frame, blocking, seen = link, None, {link}
        while frame in parent_joint and frame not in known:
            joint = parent_joint[frame]
            if joint.type in MOVING_JOINT_TYPES and not robot.has_position(joint):
                blocking = joint
            frame = joint.parent
            if frame in seen:
                break
            seen.add(frame)
        if blocking is not None and frame in known:
            blocked[link] = blocking
    return blocked


def _joint_states_fix(robot: RobotInfo) -> str:
    """Return the fix for joint positions that never arrived."""
    if robot.joint_state_messages == 0:
        return (
            "joint_state_publisher (or the robot's driver) is missing: nothing publishes "
            '/joint_states. Without hardware start joint_state_publisher (ros2 run tf_demo '
            'joint_state_publisher, or joint_state_publisher_gui to move the joints); on the '
            "robot start its driver or ros2_control's joint_state_broadcaster."
        )
    return (
        'Publish a position for these joints in /joint_states, with the joint names exactly as '
        "in the URDF: from the robot's driver, or joint_state_publisher for joints without "
        'hardware.'
    )


def joint_states_missing(
    blocked: Mapping[str, RobotJoint], robot: RobotInfo, listen_ns: int
) -> list[Finding]:
    """One finding for the robot links that tf lacks because joint positions never arrived."""
    if not blocked:
        return []
    joints = sorted({joint.mimic or joint.name for joint in blocked.values()})
    links = sorted(blocked)
    shown_links = format_members(links)
    shown_joints = ', '.join(f"'{j}'" for j in joints[:8])
    if len(joints) > 8:
        shown_joints += f', … ({len(joints) - 8} more)'
    if robot.joint_state_messages == 0:
        heard = 'no /joint_states message arrived' + (
            f' in {seconds(listen_ns)}' if listen_ns else ''
        )
        kind = 'no_joint_states'
    else:
        count = robot.joint_state_messages
        heard = (
            f'/joint_states arrived ({count} message{"s" if count != 1 else ""}) but never '
            'named them'
        )
        kind = 'joint_positions_missing'
    return [
        Finding(
            kind,
            'error',
            tuple(links),
            f'The robot_description has links that tf lacks: {shown_links}. They hang below '
            f'the moving joint(s) {shown_joints}; robot_state_publisher publishes a moving '
            f'joint only when /joint_states gives its position, and {heard}.',
            _joint_states_fix(robot),
        )
    ]
