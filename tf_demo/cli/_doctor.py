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
tf_doctor's analysis: a pure function from observed tf messages to plain-language findings.

The shell (``tf_doctor.py``) records every message it receives on ``/tf`` and ``/tf_static`` as
an :class:`Observation` (topic, reception time on the listener's clock, publisher identity when
the transport knows it, and the transforms). :func:`diagnose` turns those records into
:class:`Finding` s, each with what is wrong, which frames, and the fix. Nothing here does I/O, so
every check is tested with hand-made observations, and the multi-process tests check that real
faults produce the same findings.

The checks of parents, publishers and QoS are here; the others are by concept in
:mod:`~tf_demo.cli._doctor_tree` (trees, loops, REP 105), :mod:`~tf_demo.cli._doctor_robot`
(joints without positions, missing frames), :mod:`~tf_demo.cli._doctor_expected` (frames
that failed lookups, the robot or REP 105 expect) and :mod:`~tf_demo.cli._doctor_timing` (stamps,
rates); :mod:`~tf_demo.cli._doctor_report` prints the result.
"""

from __future__ import annotations

from collections.abc import Mapping
from collections.abc import Sequence
import itertools

from tf_demo.cli._doctor_expected import expected_frames
from tf_demo.cli._doctor_model import distinct_values
from tf_demo.cli._doctor_model import Finding
from tf_demo.cli._doctor_model import FrameStats
from tf_demo.cli._doctor_model import gather
from tf_demo.cli._doctor_model import same_value
from tf_demo.cli._doctor_model import seconds
from tf_demo.cli._doctor_model import Thresholds
from tf_demo.cli._doctor_robot import joint_states_missing
from tf_demo.cli._doctor_robot import links_without_joint_positions
from tf_demo.cli._doctor_robot import missing_frames
from tf_demo.cli._doctor_robot import MOVING_JOINT_TYPES
from tf_demo.cli._doctor_robot import RobotInfo
from tf_demo.cli._doctor_timing import stamps_went_back
from tf_demo.cli._doctor_timing import stopped
from tf_demo.cli._doctor_timing import timing
from tf_demo.cli._doctor_tree import disconnected
from tf_demo.cli._doctor_tree import leading_slashes
from tf_demo.cli._doctor_tree import loop
from tf_demo.cli._doctor_tree import rep105
from tf_demo.cli._observations import buffer_from_observations
from tf_demo.cli._observations import Observation
from tf_demo.cli._observations import TF_STATIC_TOPIC
from tf_demo.cli._observations import TF_TOPIC
from tf_demo.core.exceptions import TransformException
from tf_demo.core.math3d import Quat
from tf_demo.core.math3d import Vec3


def diagnose(
    observations: Sequence[Observation],
    *,
    listen_ns: int = 0,
    frames: Sequence[str] = (),
    check_timing: bool = True,
    thresholds: Thresholds | None = None,
    unmatched_publishers: Mapping[str, int] | None = None,
    robot: RobotInfo | None = None,
    looked_up: Sequence[str] = (),
) -> list[Finding]:
    """
    Find every tf problem the observations show.

    :param observations: the received messages, in any order.
    :param listen_ns: how long the recording lasted (for the messages that mention it).
    :param frames: frames the user wants to use (``--frames``): each must exist and all must be
        connected.
    :param check_timing: False for snapshots, which carry no reception times.
    :param unmatched_publishers: per topic, publishers seen in the graph whose QoS never matched
        the listener (see ``TfRecorder.unmatched_publishers``).
    :param robot: the robot_description's joints and the joint names /joint_states gave, when
        known: links below a moving joint without a position are explained by that.
    :param looked_up: frames that failed lookups named lately (in /rosout), repeats counted.
    :return: findings, errors first, in a stable order.
    """
    limits = thresholds or Thresholds()
    findings: list[Finding] = _qos_mismatches(unmatched_publishers or {})
    if not observations or not any(o.transforms for o in observations):
        findings.append(
            Finding(
                'no_data',
                'error',
                tuple(frames),
                f'No transforms were received on {TF_TOPIC} or {TF_STATIC_TOPIC}'
                + (f' in {seconds(listen_ns)}.' if listen_ns else '.'),
                'Start the nodes that broadcast tf, and check that they use the same '
                'ROS_DOMAIN_ID and ROS_AUTOMATIC_DISCOVERY_RANGE as this tool; listen longer '
                'with -t if they publish slowly.',
            )
        )
        findings.extend(missing_frames(frames, set(), {}, robot))
        return findings

    stats = gather(observations)
    parent_of = {child: entry.latest_parent for child, entry in stats.items()}
    known = set(parent_of) | set(parent_of.values())
    blocked = links_without_joint_positions(robot, known) if robot is not None else {}

    findings.extend(missing_frames(frames, known, blocked, robot))
    if robot is not None:
        findings.extend(joint_states_missing(blocked, robot, listen_ns))
    findings.extend(_parent_conflicts(stats, limits))
    findings.extend(loop(parent_of))
    findings.extend(disconnected(parent_of, frames))
    findings.extend(rep105(parent_of))
    findings.extend(
        expected_frames(parent_of, looked_up=looked_up, robot=robot, blocked=blocked, asked=frames)
    )
    findings.extend(leading_slashes(known))
    if check_timing:
        moving = {j.child for j in (robot.joints if robot else ()) if j.type in MOVING_JOINT_TYPES}
        findings.extend(timing(stats, listen_ns, limits, moving))
        findings.extend(stopped(stats, max(o.receive_ns for o in observations)))
        findings.extend(stamps_went_back(stats, limits))
        if not any(f.kind in ('missing_frame', 'disconnected', 'loop') for f in findings):
            findings.extend(_lookups(observations, frames))
    order = {'error': 0, 'warning': 1, 'info': 2}
    findings.sort(key=lambda f: order[f.severity])
    return findings


_QOS_FIX = {
    TF_STATIC_TOPIC: 'Publish static transforms with StaticTransformBroadcaster (or QoS depth 1, '
    'RELIABLE, TRANSIENT_LOCAL); a VOLATILE /tf_static publisher never reaches tf listeners.',
    TF_TOPIC: "Publish /tf with RELIABLE reliability (TransformBroadcaster's default); tf "
    'listeners request reliable delivery, so a BEST_EFFORT /tf publisher never reaches them.',
}


def _qos_mismatches(unmatched: Mapping[str, int]) -> list[Finding]:
    """Report publishers whose QoS never matches tf2's listener."""
    return [
        Finding(
            'qos_mismatch',
            'error',
            (),
            f'{count} publisher{"s" if count != 1 else ""} on {topic} '
            f"{'do' if count != 1 else 'does'} not match tf2's listener QoS, so "
            'neither this tool nor any tf listener receives anything from '
            f'{"them" if count != 1 else "it"} (incompatible QoS).',
            _QOS_FIX.get(topic, "Use the QoS of tf2's broadcasters."),
        )
        for topic, count in sorted(unmatched.items())
        if count > 0
    ]


def _parent_conflicts(stats: dict[str, FrameStats], limits: Thresholds) -> list[Finding]:
    """Report frames with two parents, on both topics, or fought over by publishers."""
    findings = []
    for child in sorted(stats):
        entry = stats[child]
        if len(entry.parents) > 1:
            described = ', '.join(
                f"'{parent}' ({count} message{'s' if count != 1 else ''}"
                + ''.join(
                    f' on {topic}'
                    for topic, parents in sorted(entry.parent_by_topic.items())
                    if parent in parents
                )
                + ')'
                for parent, count in sorted(entry.parents.items())
            )
            findings.append(
                Finding(
                    'two_parents',
                    'error',
                    (child, *sorted(entry.parents)),
                    f"Frame '{child}' has {len(entry.parents)} parents: {described}. tf2 keeps "
                    'one parent per frame and switches to whichever arrived last, so the tree '
                    'jumps and lookups through it flicker.',
                    f'Every frame has exactly one parent. Stop one of the nodes publishing '
                    f"'{child}', or give one of them a different child frame name (for example "
                    'a namespace prefix per robot).',
                )
            )
        if len(entry.topics) > 1:
            findings.append(
                Finding(
                    'static_and_dynamic',
                    'error',
                    (child,),
                    f"Frame '{child}' arrives on both {TF_TOPIC} ({entry.topics[TF_TOPIC]} "
                    f'messages) and {TF_STATIC_TOPIC} ({entry.topics[TF_STATIC_TOPIC]}). '
                    'The static transform is valid for all time and the dynamic one only at its '
                    'stamps, so lookups give different answers depending on the time asked.',
                    'Publish each frame on one topic only: /tf_static for fixed mounts '
                    '(static_transform_publisher, robot_state_publisher for fixed joints), /tf '
                    'for moving frames.',
                )
            )
        distinct_static = distinct_values(entry.static_values, limits.value_tolerance)
        if len(distinct_static) > 1:
            findings.append(
                Finding(
                    'publishers_fighting',
                    'error',
                    (child,),
                    f"Frame '{child}' has {len(distinct_static)} different static transforms "
                    f'on {TF_STATIC_TOPIC}; which one a listener keeps depends on arrival '
                    'order.',
                    'Run one static publisher per frame: stop the duplicate '
                    'static_transform_publisher or remove the frame from one URDF.',
                )
            )
        senders = [p for p in entry.dynamic_publishers if p]
        dynamic_publishers = len(set(senders))
        switches = sum(1 for a, b in itertools.pairwise(senders) if a != b)
        if switches < 3:
            dynamic_publishers = 0  # one sender after another (a restart) is not a fight
        flips = _value_flips(entry.dynamic, limits.value_tolerance)
        regressions = sum(
            1 for a, b in zip(entry.dynamic, entry.dynamic[1:], strict=False) if b[1] < a[1]
        )
        if dynamic_publishers > 1 or flips >= 3 or regressions >= 3:
            evidence = []
            if dynamic_publishers > 1:
                evidence.append(f'{dynamic_publishers} different publishers send it, taking turns')
            if flips >= 3:
                evidence.append(f'its value jumped back and forth {flips} times')
            if regressions >= 3:
                evidence.append(f'its stamps went backwards {regressions} times')
            first_back = (b[0] for a, b in itertools.pairwise(entry.dynamic) if b[1] < a[1])
            findings.append(
                Finding(
                    'publishers_fighting',
                    'error',
                    (child,),
                    f"Frame '{child}' looks published by more than one node on {TF_TOPIC}: "
                    + ', '.join(evidence)
                    + ". Listeners see it jump between the publishers' values.",
                    f"Keep a single publisher for '{child}' (for example do not run both "
                    'robot_state_publisher and another broadcaster for the same joint, or two '
                    'odometry sources with publish_tf enabled).',
                    next(first_back, entry.dynamic[0][0] if entry.dynamic else None),
                )
            )
    return findings


def _value_flips(dynamic: list[tuple[int, int, Vec3, Quat]], tolerance: float) -> int:
    """Count A, B, A patterns: a value that returns right after a different one."""
    flips = 0
    for first, second, third in zip(dynamic, dynamic[1:], dynamic[2:], strict=False):
        a, b, c = (first[2], first[3]), (second[2], second[3]), (third[2], third[3])
        if same_value(a, c, tolerance) and not same_value(a, b, tolerance):
            flips += 1
    return flips


def _lookups(observations: Sequence[Observation], frames: Sequence[str]) -> list[Finding]:
    """Try the lookups the user needs (first frame to each other one, latest data) as tf2 would."""
    if len(frames) < 2:
        return []
    core = buffer_from_observations(observations, authority='tf_doctor')
    findings = []
    for frame in frames[1:]:
        try:
            core.lookup_transform(frames[0], frame, 0)
        except TransformException as error:
            findings.append(
                Finding(
                    'lookup_fails',
                    'error',
                    (frames[0], frame),
                    f"Looking up '{frame}' in '{frames[0]}' with the latest data fails: {error}",
                    'The links of this chain have no common time: every dynamic link must have '
                    'data covering the same moment (check the rates and stamps of the links '
                    'named above).',
                )
            )
    return findings
