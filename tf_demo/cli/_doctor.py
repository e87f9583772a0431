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
"""

from __future__ import annotations

from collections import Counter
from collections.abc import Iterable
from collections.abc import Mapping
from collections.abc import Sequence
from dataclasses import dataclass
from dataclasses import field
import difflib
import itertools
import json
import statistics
import textwrap

from tf_demo.cli._snapshot import find_cycle
from tf_demo.cli._snapshot import Snapshot
from tf_demo.core.math3d import Quat
from tf_demo.core.math3d import Vec3

TF_TOPIC = '/tf'
TF_STATIC_TOPIC = '/tf_static'
NS_PER_S = 1_000_000_000
# REP 105's chain, outermost first; base_footprint may stand in for base_link.
REP105_CHAIN = ('earth', 'map', 'odom', 'base_link')
_BASE_FRAMES = ('base_link', 'base_footprint')


@dataclass(frozen=True)
class ObservedTransform:
    """One transform of a received message."""

    parent: str
    child: str
    stamp_ns: int
    translation: Vec3 = (0.0, 0.0, 0.0)
    rotation: Quat = (0.0, 0.0, 0.0, 1.0)


@dataclass(frozen=True)
class Observation:
    """One received tf message: topic, reception time (listener clock) and its transforms."""

    topic: str
    receive_ns: int
    transforms: tuple[ObservedTransform, ...]
    publisher: str = ''


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


@dataclass(frozen=True)
class Thresholds:
    """Limits of the timing checks (seconds)."""

    future_tolerance_s: float = 0.5
    old_tolerance_s: float = 5.0
    max_gap_s: float = 0.5
    """A dynamic frame whose stamps are typically further apart is sparse (< 2 Hz)."""
    value_tolerance: float = 1e-9


@dataclass(frozen=True)
class Finding:
    """One problem: a short kind, severity ('error', 'warning' or 'info'), message and fix."""

    kind: str
    severity: str
    frames: tuple[str, ...]
    message: str
    fix: str


@dataclass
class _ChildStats:
    parents: Counter[str] = field(default_factory=Counter)
    topics: Counter[str] = field(default_factory=Counter)
    publishers: set[str] = field(default_factory=set)
    dynamic_publishers: list[str] = field(default_factory=list)
    parent_by_topic: dict[str, set[str]] = field(default_factory=dict)
    static_values: list[tuple[Vec3, Quat]] = field(default_factory=list)
    dynamic: list[tuple[int, int, Vec3, Quat]] = field(default_factory=list)
    latest_parent: str = ''


def _same(a: tuple[Vec3, Quat], b: tuple[Vec3, Quat], tolerance: float) -> bool:
    return all(abs(x - y) <= tolerance for x, y in zip(a[0] + a[1], b[0] + b[1], strict=True))


def _distinct_values(
    values: Iterable[tuple[Vec3, Quat]], tolerance: float
) -> list[tuple[Vec3, Quat]]:
    distinct: list[tuple[Vec3, Quat]] = []
    for value in values:
        if not any(_same(value, seen, tolerance) for seen in distinct):
            distinct.append(value)
    return distinct


def _gather(observations: Sequence[Observation]) -> dict[str, _ChildStats]:
    stats: dict[str, _ChildStats] = {}
    for observation in sorted(observations, key=lambda o: o.receive_ns):
        for transform in observation.transforms:
            entry = stats.setdefault(transform.child, _ChildStats())
            entry.parents[transform.parent] += 1
            entry.topics[observation.topic] += 1
            entry.parent_by_topic.setdefault(observation.topic, set()).add(transform.parent)
            if observation.publisher:
                entry.publishers.add(observation.publisher)
            value = (transform.translation, transform.rotation)
            if observation.topic == TF_STATIC_TOPIC:
                entry.static_values.append(value)
            else:
                entry.dynamic.append(
                    (observation.receive_ns, transform.stamp_ns, value[0], value[1])
                )
                entry.dynamic_publishers.append(observation.publisher)
            entry.latest_parent = transform.parent
    return stats


def _islands(parent_of: dict[str, str]) -> list[list[str]]:
    """Return the connected components of the frame graph, biggest first, members sorted."""
    neighbours: dict[str, set[str]] = {}
    for child, parent in parent_of.items():
        neighbours.setdefault(child, set()).add(parent)
        neighbours.setdefault(parent, set()).add(child)
    seen: set[str] = set()
    islands: list[list[str]] = []
    for start in sorted(neighbours):
        if start in seen:
            continue
        stack, members = [start], []
        seen.add(start)
        while stack:
            frame = stack.pop()
            members.append(frame)
            for other in neighbours[frame]:
                if other not in seen:
                    seen.add(other)
                    stack.append(other)
        islands.append(sorted(members))
    islands.sort(key=lambda members: (-len(members), members[0]))
    return islands


def _ancestors(frame: str, parent_of: dict[str, str]) -> list[str]:
    chain: list[str] = []
    seen = {frame}
    while frame in parent_of:
        frame = parent_of[frame]
        if frame in seen:
            break
        seen.add(frame)
        chain.append(frame)
    return chain


def _root(frame: str, parent_of: dict[str, str]) -> str:
    chain = _ancestors(frame, parent_of)
    return chain[-1] if chain else frame


def _rep105_rank(frame: str) -> int | None:
    if frame in _BASE_FRAMES:
        return REP105_CHAIN.index('base_link')
    return REP105_CHAIN.index(frame) if frame in REP105_CHAIN else None


def _missing_link(root: str, island_of: dict[str, int], own: int) -> str | None:
    """Return the REP 105 link that likely joins ``root`` to another tree, as 'a→b'."""
    rank = _rep105_rank(root)
    if rank is None:
        return None
    for candidate in reversed(REP105_CHAIN[:rank]):
        if candidate in island_of and island_of[candidate] != own:
            return f'{candidate}→{root}'
    return None


_ODOMETRY = 'the odometry source (base driver, diff-drive controller or robot_localization)'
_LINK_PUBLISHERS = {
    'map→odom': 'localization or SLAM (AMCL, slam_toolbox, robot_localization)',
    'odom→base_link': _ODOMETRY,
    'odom→base_footprint': _ODOMETRY,
    'earth→map': 'a map server or a static_transform_publisher',
}


def _format_members(members: Sequence[str], limit: int = 8) -> str:
    shown = ', '.join(members[:limit])
    return shown + (f', … ({len(members) - limit} more)' if len(members) > limit else '')


def _seconds(ns: float) -> str:
    return f'{ns / NS_PER_S:.3f} s'


def diagnose(
    observations: Sequence[Observation],
    *,
    listen_ns: int = 0,
    frames: Sequence[str] = (),
    check_timing: bool = True,
    thresholds: Thresholds | None = None,
    unmatched_publishers: Mapping[str, int] | None = None,
    robot: RobotInfo | None = None,
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
                + (f' in {_seconds(listen_ns)}.' if listen_ns else '.'),
                'Start the nodes that broadcast tf, and check that they use the same '
                'ROS_DOMAIN_ID and ROS_AUTOMATIC_DISCOVERY_RANGE as this tool; listen longer '
                'with -t if they publish slowly.',
            )
        )
        findings.extend(_missing_frames(frames, set(), {}, robot))
        return findings

    stats = _gather(observations)
    parent_of = {child: entry.latest_parent for child, entry in stats.items()}
    known = set(parent_of) | set(parent_of.values())
    blocked = _links_without_joint_positions(robot, known) if robot is not None else {}

    findings.extend(_missing_frames(frames, known, blocked, robot))
    if robot is not None:
        findings.extend(_joint_states_missing(blocked, robot, listen_ns))
    findings.extend(_parent_conflicts(stats, limits))
    cycle = find_cycle((parent, child) for child, parent in parent_of.items())
    if cycle is not None:
        findings.append(
            Finding(
                'loop',
                'error',
                tuple(cycle[:-1]),
                f'The parent links form a loop: {" → ".join(cycle)}. tf2 cannot walk from these '
                'frames to a root, so every lookup through them fails.',
                'A loop usually means one link is published the wrong way round (child and '
                'parent swapped). Find the publisher of each link in the loop and invert or '
                'remove one of them.',
            )
        )
    findings.extend(_disconnected(parent_of, frames))
    findings.extend(_rep105(parent_of))
    findings.extend(_leading_slashes(known))
    if check_timing:
        moving = {j.child for j in (robot.joints if robot else ()) if j.type in MOVING_JOINT_TYPES}
        findings.extend(_timing(stats, listen_ns, limits, moving))
        findings.extend(_stopped(stats, max(o.receive_ns for o in observations)))
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


def _missing_frames(
    frames: Sequence[str],
    known: set[str],
    blocked: Mapping[str, RobotJoint],
    robot: RobotInfo | None,
) -> list[Finding]:
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


def _links_without_joint_positions(robot: RobotInfo, known: set[str]) -> dict[str, RobotJoint]:
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


def _joint_states_missing(
    blocked: Mapping[str, RobotJoint], robot: RobotInfo, listen_ns: int
) -> list[Finding]:
    """One finding for the robot links that tf lacks because joint positions never arrived."""
    if not blocked:
        return []
    joints = sorted({joint.mimic or joint.name for joint in blocked.values()})
    links = sorted(blocked)
    shown_links = _format_members(links)
    shown_joints = ', '.join(f"'{j}'" for j in joints[:8])
    if len(joints) > 8:
        shown_joints += f', … ({len(joints) - 8} more)'
    if robot.joint_state_messages == 0:
        heard = 'no /joint_states message arrived' + (
            f' in {_seconds(listen_ns)}' if listen_ns else ''
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


def _parent_conflicts(stats: dict[str, _ChildStats], limits: Thresholds) -> list[Finding]:
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
        distinct_static = _distinct_values(entry.static_values, limits.value_tolerance)
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
                )
            )
    return findings


def _value_flips(dynamic: list[tuple[int, int, Vec3, Quat]], tolerance: float) -> int:
    """Count A, B, A patterns: a value that returns right after a different one."""
    flips = 0
    for first, second, third in zip(dynamic, dynamic[1:], dynamic[2:], strict=False):
        a, b, c = (first[2], first[3]), (second[2], second[3]), (third[2], third[3])
        if _same(a, c, tolerance) and not _same(a, b, tolerance):
            flips += 1
    return flips


def _disconnected(parent_of: dict[str, str], frames: Sequence[str]) -> list[Finding]:
    islands = _islands(parent_of)
    if len(islands) < 2:
        return []
    island_of = {frame: index for index, members in enumerate(islands) for frame in members}
    lines = []
    links = []
    for index, members in enumerate(islands):
        root = _root(members[0], parent_of)
        lines.append(f'tree {index + 1} (root {root}): {_format_members(members)}')
        link = _missing_link(root, island_of, index)
        if link is not None:
            links.append(link)
    message = f'The frames form {len(islands)} separate trees; lookups between trees fail:\n'
    message += '\n'.join(lines)
    asked = [f for f in frames if f in island_of]
    if len({island_of[f] for f in asked}) > 1:
        message += '\nThe frames you asked about are in different trees: ' + ', '.join(
            f"'{f}' in tree {island_of[f] + 1}" for f in asked
        )
        message += '.'
    if links:
        fix = 'The likely missing link' + ('s are ' if len(links) > 1 else ' is ')
        fix += ', '.join(
            link + (f', published by {_LINK_PUBLISHERS[link]}' if link in _LINK_PUBLISHERS else '')
            for link in links
        )
        first_parent, first_child = links[0].split('→')
        fix += (
            '. Start that publisher, or for a fixed offset run static_transform_publisher '
            f'--frame-id {first_parent} --child-frame-id {first_child}'
        )
    else:
        roots = [_root(members[0], parent_of) for members in islands]
        fix = (
            'Connect each tree to the main one by publishing a transform whose child is its '
            f'root ({", ".join(roots[1:])}) and whose parent is a frame of tree 1.'
        )
    return [
        Finding(
            'disconnected', 'error', tuple(_root(m[0], parent_of) for m in islands), message, fix
        )
    ]


def _rep105(parent_of: dict[str, str]) -> list[Finding]:
    findings = []
    present = [
        f for f in ('map', 'odom', *_BASE_FRAMES) if f in parent_of or f in set(parent_of.values())
    ]
    for later in present:
        for earlier in present:
            rank_early, rank_late = _rep105_rank(earlier), _rep105_rank(later)
            if rank_early is None or rank_late is None or rank_early >= rank_late:
                continue
            if later in _ancestors(earlier, parent_of):
                findings.append(
                    Finding(
                        'rep105_order',
                        'error',
                        (earlier, later),
                        f"'{earlier}' is below '{later}' in the tree; REP 105 orders them "
                        'map → odom → base_link (each frame the parent of the next).',
                        f'Publish {earlier}→{later} instead of {later}→{earlier}: invert that '
                        "transform, or set the publisher's frame parameters the other way round.",
                    )
                )
    if 'odom' in present and any(b in present for b in _BASE_FRAMES) and 'map' in present:
        findings.extend(
            Finding(
                'rep105_order',
                'warning',
                ('map', 'odom', base),
                f"'{base}' hangs directly off 'map' although 'odom' exists; REP 105 "
                f'expects map → odom → {base}.',
                f'Let localization publish map→odom and odometry publish odom→{base}, '
                f'instead of one node publishing map→{base}.',
            )
            for base in _BASE_FRAMES
            if parent_of.get(base) == 'map'
        )
    return findings


# Links that move by nature even when a robot stands still during the recording.
_DYNAMIC_BY_NATURE = frozenset(
    (parent, child) for parent, child in (link.split('→') for link in _LINK_PUBLISHERS)
) - {('earth', 'map')}


def _timing(
    stats: dict[str, _ChildStats],
    listen_ns: int,
    limits: Thresholds,
    moving: set[str] | frozenset[str] = frozenset(),
) -> list[Finding]:
    """
    Stamp, rate and constancy findings for the frames on /tf.

    :param moving: children of the robot's moving joints (never called fixed mounts).
    """
    findings = []
    for child in sorted(stats):
        samples = stats[child].dynamic
        if not samples:
            continue
        parent = stats[child].latest_parent
        offsets = [receive - stamp for receive, stamp, _, _ in samples]
        median_offset = statistics.median(offsets)
        if all(stamp == 0 for _, stamp, _, _ in samples):
            findings.append(
                Finding(
                    'zero_stamps',
                    'error',
                    (child,),
                    f'Transforms {parent}→{child} on {TF_TOPIC} carry stamp 0. Time-based '
                    'lookups need real stamps; with 0 every lookup at a real time is an '
                    'extrapolation error.',
                    'Stamp each transform with the node clock (node.get_clock().now()), or '
                    'publish it on /tf_static if it never moves.',
                )
            )
            continue
        if -median_offset > limits.future_tolerance_s * NS_PER_S:
            findings.append(
                Finding(
                    'future_stamps',
                    'error',
                    (child,),
                    f'Transforms {parent}→{child} are stamped {_seconds(-median_offset)} in the '
                    "future of this listener's clock. Lookups at 'now' miss them and old data is "
                    'dropped as they arrive.',
                    'The publisher and listeners use different clocks: check use_sim_time (all '
                    'nodes true with a /clock source, or all false) and synchronize machine '
                    'clocks (chrony/NTP).',
                )
            )
        elif median_offset > limits.old_tolerance_s * NS_PER_S:
            sim_hint = ''
            if samples[-1][1] < 10**9 * 10**6 <= samples[-1][0]:
                sim_hint = (
                    ' The stamps look like simulation time (seconds since start) while this '
                    'listener runs on the wall clock.'
                )
            findings.append(
                Finding(
                    'old_stamps',
                    'error',
                    (child,),
                    f'Transforms {parent}→{child} are already {_seconds(median_offset)} old when '
                    f'they arrive (the buffer keeps 10 s), so lookups at now() fail with '
                    f'extrapolation into the future.{sim_hint}',
                    'Check use_sim_time: a publisher on sim time and a listener on wall time (or '
                    'the reverse) disagree by years; otherwise synchronize clocks or fix the '
                    "publisher's stamping.",
                )
            )
        stamps = sorted({stamp for _, stamp, _, _ in samples})
        window = listen_ns or (samples[-1][0] - samples[0][0])
        gaps = [b - a for a, b in itertools.pairwise(stamps)]
        sparse = (len(stamps) == 1 and window >= NS_PER_S) or bool(
            gaps and statistics.median(gaps) > limits.max_gap_s * NS_PER_S
        )
        fixed = _fixed_mount_on_tf(
            parent, child, samples, sparse=sparse, limits=limits, moving=moving
        )
        if fixed is not None:
            findings.append(fixed)
            continue  # "publish faster" is not the fix for a transform that never changes
        if len(stamps) == 1 and window >= NS_PER_S:
            findings.append(
                Finding(
                    'sparse_data',
                    'warning',
                    (child,),
                    f'Only one stamp of {parent}→{child} arrived in {_seconds(window)}. Lookups '
                    'at any other time fail with extrapolation errors.',
                    'Publish moving frames continuously (10 Hz or more), or publish a fixed '
                    'transform once on /tf_static.',
                )
            )
            continue
        if gaps and statistics.median(gaps) > limits.max_gap_s * NS_PER_S:
            rate = (len(stamps) - 1) / ((stamps[-1] - stamps[0]) / NS_PER_S)
            findings.append(
                Finding(
                    'sparse_data',
                    'warning',
                    (child,),
                    f'{parent}→{child} arrives at {rate:.3g} Hz, with gaps up to '
                    f'{_seconds(max(gaps))}. Lookups at now() need data newer than the request '
                    'and will extrapolate into the future for up to that long.',
                    'Publish faster, look up at time 0 (latest available) or with a timeout, or '
                    'interpolate at the stamp of the data you transform.',
                )
            )
    return findings


def _fixed_mount_on_tf(
    parent: str,
    child: str,
    samples: Sequence[tuple[int, int, Vec3, Quat]],
    *,
    sparse: bool,
    limits: Thresholds,
    moving: set[str] | frozenset[str],
) -> Finding | None:
    """Report a transform sent again and again on /tf with one value (a fixed mount)."""
    if len(samples) < 3 or child in moving or (parent, child) in _DYNAMIC_BY_NATURE:
        return None
    values = [(translation, rotation) for _, _, translation, rotation in samples]
    if len(_distinct_values(values, limits.value_tolerance)) != 1:
        return None
    consequence = (
        'Between its messages tf2 can only extrapolate, so lookups at now() fail'
        if sparse
        else 'It works, but listeners only find it at the stamps sent (and 10 s back)'
    )
    return Finding(
        'fixed_mount_on_tf',
        'warning' if sparse else 'info',
        (child,),
        f'{parent}→{child} arrived {len(samples)} times on {TF_TOPIC} with the same value every '
        f'time: it looks like a fixed mount. {consequence}.',
        'Publish a fixed mount once on /tf_static instead (static_transform_publisher, a '
        'StaticTransformBroadcaster, or a fixed joint in the URDF): lookups then succeed at any '
        'time. If this frame really moves and only stood still, ignore this.',
    )


def _lookups(observations: Sequence[Observation], frames: Sequence[str]) -> list[Finding]:
    """Try the lookups the user needs (first frame to each other one, latest data) as tf2 would."""
    if len(frames) < 2:
        return []
    from tf_demo.core.buffer_core import BufferCore
    from tf_demo.core.exceptions import TransformException

    def quiet(level: int, text: str) -> None:
        del level, text

    core = BufferCore(log=quiet)
    for observation in sorted(observations, key=lambda o: o.receive_ns):
        for t in observation.transforms:
            core.set_transform(
                t.parent,
                t.child,
                t.stamp_ns,
                t.translation,
                t.rotation,
                'tf_doctor',
                observation.topic == TF_STATIC_TOPIC,
            )
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


def _leading_slashes(known: set[str]) -> list[Finding]:
    slashed = sorted(frame for frame in known if frame.startswith('/'))
    if not slashed:
        return []
    return [
        Finding(
            'leading_slash',
            'error',
            tuple(slashed),
            f"Frame ids {', '.join(repr(f) for f in slashed)} start with '/'. tf2 in ROS 2 "
            'refuses such ids in lookups ("frame_ids cannot start with a \'/\'"), so nothing '
            'can be looked up through them.',
            "Drop the leading '/' where these frames are published (a ROS 1 habit): "
            f"'{slashed[0].lstrip('/')}' instead of '{slashed[0]}'.",
        )
    ]


def _stopped(stats: dict[str, _ChildStats], end_ns: int) -> list[Finding]:
    """Dynamic frames whose messages stopped well before the end of the recording."""
    findings = []
    for child in sorted(stats):
        samples = stats[child].dynamic
        if len(samples) < 3:
            continue
        receives = [receive for receive, _, _, _ in samples]
        period = statistics.median(b - a for a, b in itertools.pairwise(receives))
        silence = end_ns - receives[-1]
        if silence > max(2 * NS_PER_S, 5 * period):
            findings.append(
                Finding(
                    'stopped',
                    'warning',
                    (child,),
                    f'{stats[child].latest_parent}→{child} stopped arriving '
                    f'{_seconds(silence)} before the end of the recording (it came every '
                    f'{_seconds(period)} before). Lookups at later times will fail with '
                    'extrapolation errors.',
                    'Check that its publisher is still running and not blocked.',
                )
            )
    return findings


def observations_from_snapshot(snapshot: Snapshot) -> list[Observation]:
    """Turn a saved snapshot into observations (one message per transform, no timing)."""
    return [
        Observation(
            TF_STATIC_TOPIC if entry.is_static else TF_TOPIC,
            entry.stamp_ns or 0,
            (
                ObservedTransform(
                    entry.parent,
                    entry.child,
                    entry.stamp_ns or 0,
                    entry.translation,
                    entry.rotation,
                ),
            ),
        )
        for entry in snapshot.transforms
    ]


def summarize(observations: Sequence[Observation]) -> dict[str, int]:
    """Count for the report's first line: messages, frames and trees."""
    parent_of: dict[str, str] = {}
    for observation in sorted(observations, key=lambda o: o.receive_ns):
        for transform in observation.transforms:
            parent_of[transform.child] = transform.parent
    return {
        'messages': len(observations),
        'frames': len(set(parent_of) | set(parent_of.values())),
        'trees': len(_islands(parent_of)),
    }


def _wrapped(text: str, first: str, indent: str, width: int = 99) -> list[str]:
    lines: list[str] = []
    for index, paragraph in enumerate(text.split('\n')):
        lead = first if index == 0 else indent
        lines.extend(
            textwrap.wrap(
                paragraph,
                width=width,
                initial_indent=lead,
                subsequent_indent=indent,
                break_on_hyphens=False,
                break_long_words=False,
            )
            or [lead]
        )
    return lines


def format_report(findings: Sequence[Finding], summary: dict[str, int], source: str) -> str:
    """Format the plain-language report: each finding with its fix, then the verdict."""
    lines = [
        f'tf_doctor: {source}: {summary["messages"]} messages, {summary["frames"]} frames, '
        f'{summary["trees"]} tree{"s" if summary["trees"] != 1 else ""}.'
    ]
    for finding in findings:
        lines.append('')
        lines.extend(
            _wrapped(finding.message, f'{finding.severity.upper()} [{finding.kind}] ', '    ')
        )
        lines.extend(_wrapped(finding.fix, '  Fix: ', '    '))
    problems = [f for f in findings if f.severity != 'info']
    lines.append('')
    if problems:
        errors = sum(1 for f in problems if f.severity == 'error')
        warnings = len(problems) - errors
        lines.append(
            f'Found {errors} error{"s" if errors != 1 else ""} and '
            f'{warnings} warning{"s" if warnings != 1 else ""}.'
        )
    else:
        lines.append('Healthy: no problems found.')
    return '\n'.join(lines) + '\n'


def format_report_json(findings: Sequence[Finding], summary: dict[str, int], source: str) -> str:
    """Format the report as one JSON object (``--json``)."""
    return (
        json.dumps(
            {
                'source': source,
                'healthy': not any(f.severity != 'info' for f in findings),
                'summary': summary,
                'findings': [
                    {
                        'kind': f.kind,
                        'severity': f.severity,
                        'frames': list(f.frames),
                        'message': f.message,
                        'fix': f.fix,
                    }
                    for f in findings
                ],
            },
            ensure_ascii=False,
        )
        + '\n'
    )


def exit_code(findings: Sequence[Finding]) -> int:
    """Return 0 when healthy, 1 when an error or a warning was found."""
    return 1 if any(f.severity != 'info' for f in findings) else 0
