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
tf_doctor's check of the frames a tree should have and lacks, unasked.

A frame is expected when a node's lookup failed on it lately (tf2's "does not exist" error in
``/rosout``), when it is a link of the heard ``/robot_description`` and tf has none of its links,
or when REP 105 names it and the tree has the frames below it (``odom`` without ``map``: RViz's
default fixed frame). Each finding says what is missing, the usual cause and the command that
publishes it.
"""

from __future__ import annotations

from collections.abc import Iterable
from collections.abc import Mapping
from collections.abc import Sequence
import re

from tf_demo.cli._doctor_model import Finding
from tf_demo.cli._doctor_model import format_members
from tf_demo.cli._doctor_robot import RobotInfo
from tf_demo.cli._doctor_tree import BASE_FRAMES

# tf2's errors name a frame so: '"map" passed to lookupTransform argument target_frame does not
# exist.' and 'Invalid frame ID "map" passed to canTransform argument target_frame - frame does
# not exist'.
_MISSING_IN_LOOKUP = re.compile(r'"([^"\s]+)" passed to \w+ argument \w+')

_STATIC = (
    'ros2 run tf_demo static_transform_publisher --frame-id {parent} --child-frame-id {child}'
)
_RSP_FIX = (
    'Start robot_state_publisher with the robot: '
    'ros2 run tf_demo robot_state_publisher --ros-args -p urdf_file:=<your robot>.urdf.'
)
_RSP_WHY = (
    'robot_state_publisher, which publishes those links, is not running (or runs with another '
    'frame_prefix)'
)


def frames_in_failed_lookups(messages: Iterable[str]) -> list[str]:
    """Return the frames that tf2's "does not exist" errors in log ``messages`` name, in order."""
    return [frame for message in messages for frame in _MISSING_IN_LOOKUP.findall(message)]


def _rep105_gap(frame: str, parent_of: Mapping[str, str], known: set[str]) -> str | None:
    """Return REP 105's frame below ``frame`` when the tree has it (``map`` → ``odom``)."""
    if frame == 'map' and 'odom' in known:
        return 'odom'
    if frame == 'odom' and 'map' not in known:
        # the base frame that is a root: nothing above it yet
        return next((b for b in BASE_FRAMES if b in known and b not in parent_of), None)
    return None


def _why_and_fix(frame: str, below: str | None, robot_link: bool) -> tuple[str, str]:
    """Return the usual cause of ``frame`` missing and the fix, with the command."""
    if below is not None and frame == 'map':
        return (
            f"the tree has '{below}' but nothing publishes map→{below}: no localisation "
            '(AMCL, slam_toolbox, robot_localization) and no static map→odom publisher is '
            'running, so RViz with Fixed Frame \'map\' says "Fixed Frame [map] does not exist"',
            'Start your localisation; without a map, publish an identity map→odom: '
            + _STATIC.format(parent='map', child=below)
            + " (or set RViz's Fixed Frame to 'odom').",
        )
    if below is not None:
        return (
            f"the tree has '{below}' but nothing publishes odom→{below}: the odometry source "
            '(base driver, diff-drive controller or robot_localization) is not running',
            'Start the odometry source; for a robot that does not move, publish an identity '
            f'odom→{below}: ' + _STATIC.format(parent='odom', child=below) + '.',
        )
    if robot_link:
        return (
            f'it is a link of /robot_description, and {_RSP_WHY}',
            _RSP_FIX,
        )
    return ('no node publishes it', f"Start the node that should publish '{frame}'.")


def rep105_advice(frame: str, parent_of: Mapping[str, str]) -> str | None:
    """Return why REP 105's ``frame`` is missing from this tree and the fix, if it names it."""
    known = set(parent_of) | set(parent_of.values())
    below = None if frame in known else _rep105_gap(frame, parent_of, known)
    if below is None:
        return None
    why, fix = _why_and_fix(frame, below, robot_link=False)
    return f'{why[0].upper()}{why[1:]}. {fix}'


def expected_frames(
    parent_of: Mapping[str, str],
    *,
    looked_up: Sequence[str] = (),
    robot: RobotInfo | None = None,
    blocked: Iterable[str] = (),
    asked: Iterable[str] = (),
) -> list[Finding]:
    """
    Report frames the tree lacks that something expects.

    :param parent_of: each child's latest parent.
    :param looked_up: frames named by failed lookups heard on /rosout (repeats count).
    :param robot: the heard robot_description, if any.
    :param blocked: robot links already explained by missing joint positions.
    :param asked: frames of ``--frames``, reported by the missing-frame check instead.
    """
    known = set(parent_of) | set(parent_of.values())
    skip = known | set(blocked) | set(asked)
    links = {j.child for j in robot.joints} | {j.parent for j in robot.joints} if robot else set()
    findings = []
    for frame in sorted(set(looked_up) - skip):
        times = looked_up.count(frame)
        why, fix = _why_and_fix(frame, _rep105_gap(frame, parent_of, known), frame in links)
        findings.append(
            Finding(
                'looked_up_frame_missing',
                'error',
                (frame,),
                f"Frame '{frame}' does not exist in the tf tree, yet lookups asked for it "
                f'({times} failed lookup{"s" if times != 1 else ""} in /rosout): {why}.',
                fix,
            )
        )
    unlinked = sorted(links - skip - set(looked_up))
    if unlinked and not links & known:  # some links in tf: robot_state_publisher runs
        findings.append(
            Finding(
                'robot_links_missing',
                'error',
                tuple(unlinked),
                'The robot_description has links that tf lacks: '
                f'{format_members(unlinked)}: {_RSP_WHY}.',
                _RSP_FIX,
            )
        )
    for frame in ('map', 'odom'):
        below = _rep105_gap(frame, parent_of, known)
        if frame in skip or frame in looked_up or below is None:
            continue
        why, fix = _why_and_fix(frame, below, robot_link=False)
        findings.append(
            Finding(
                'rep105_frame_missing',
                'info',
                (frame,),
                f"Frame '{frame}' does not exist (REP 105's {frame}→{below}): {why}. Lookups "
                f"in '{frame}' fail until it does.",
                fix,
            )
        )
    return findings
