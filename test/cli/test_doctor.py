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

"""Tests of tf_doctor's pure analysis: each fault in hand-made observations gives its finding."""

import json

from tf_demo.cli._doctor import diagnose
from tf_demo.cli._doctor_report import exit_code
from tf_demo.cli._doctor_report import format_report
from tf_demo.cli._doctor_report import format_report_json
from tf_demo.cli._doctor_report import summarize
from tf_demo.cli._doctor_robot import RobotInfo
from tf_demo.cli._doctor_robot import RobotJoint
from tf_demo.cli._observations import Observation
from tf_demo.cli._observations import observations_from_snapshot
from tf_demo.cli._observations import ObservedTransform
from tf_demo.cli._observations import TF_STATIC_TOPIC
from tf_demo.cli._observations import TF_TOPIC
from tf_demo.cli._snapshot import parse_snapshot

S = 1_000_000_000
T0 = 1_700_000_000 * S


def static(parent, child, t=(0.0, 0.0, 0.0), publisher=''):
    return Observation(TF_STATIC_TOPIC, T0, (ObservedTransform(parent, child, T0, t),), publisher)


def stream(parent, child, *, rate_hz=20.0, seconds=2.0, delay_ns=1_000_000, values=None, pub=''):
    count = int(rate_hz * seconds)
    result = []
    for i in range(count):
        stamp = T0 + int(i * S / rate_hz)
        t = values[i % len(values)] if values else (i * 0.01, 0.0, 0.0)
        transform = ObservedTransform(parent, child, stamp, t)
        result.append(Observation(TF_TOPIC, stamp + delay_ns, (transform,), pub))
    return result


def later(observations, seconds):
    """The same messages, received and stamped ``seconds`` later."""
    shift = seconds * S
    return [
        Observation(
            o.topic,
            o.receive_ns + shift,
            tuple(
                ObservedTransform(t.parent, t.child, t.stamp_ns + shift, t.translation)
                for t in o.transforms
            ),
            o.publisher,
        )
        for o in observations
    ]


def healthy():
    return [
        static('map', 'odom'),
        *stream('odom', 'base_link'),
        static('base_link', 'laser'),
        static('base_link', 'camera'),
    ]


def kinds(findings):
    return sorted(f.kind for f in findings)


def test_healthy_tree_has_no_findings():
    """A REP-105 tree with steady data is healthy and exits 0."""
    findings = diagnose(healthy(), listen_ns=2 * S, frames=['map', 'laser'])
    assert findings == []
    assert exit_code(findings) == 0
    report = format_report(findings, summarize(healthy()), 'listened 2.0 s')
    assert report.endswith('Healthy: no problems found.\n')
    assert '5 frames, 1 tree.' in report


def test_no_data():
    """Nothing received is an error that names both topics."""
    findings = diagnose([], listen_ns=3 * S)
    assert kinds(findings) == ['no_data']
    assert '/tf or /tf_static in 3.000 s' in findings[0].message
    assert exit_code(findings) == 1


def test_missing_frame_with_close_match_and_slash():
    """Unknown frames get close matches; a leading slash is explained."""
    findings = diagnose(healthy(), frames=['base_lnk', '/laser', 'zzz'])
    messages = [f.message for f in findings if f.kind == 'missing_frame']
    assert "Frame 'base_lnk' does not exist in the tf tree: did you mean 'base_link'?" in messages
    assert any("'laser' exists: tf2 frame ids must not start with '/'" in m for m in messages)
    assert "Frame 'zzz' does not exist in the tf tree." in messages


def test_disconnected_names_islands_and_missing_odom_link():
    """Two trees: each island is named and odom→base_link is suggested."""
    observations = [static('map', 'odom'), static('base_link', 'laser')]
    findings = diagnose(observations, frames=['map', 'laser'])
    assert kinds(findings) == ['disconnected']
    finding = findings[0]
    assert 'tree 1 (root base_link): base_link, laser' in finding.message
    assert 'tree 2 (root map): map, odom' in finding.message
    assert "'map' in tree 2, 'laser' in tree 1" in finding.message
    assert 'odom→base_link' in finding.fix
    assert '--frame-id odom --child-frame-id base_link' in finding.fix


def test_disconnected_without_rep105_names_roots():
    """Islands outside REP 105 get a generic fix naming the roots to connect."""
    findings = diagnose([static('a', 'b'), static('a', 'c'), static('x', 'y')])
    assert kinds(findings) == ['disconnected']
    assert 'root (x)' in findings[0].fix


def test_two_parents():
    """A child published under two parents is reported with both parents and topics."""
    observations = [*healthy(), static('map', 'laser')]
    findings = diagnose(observations)
    finding = next(f for f in findings if f.kind == 'two_parents')
    assert finding.frames == ('laser', 'base_link', 'map')
    assert "'base_link' (1 message on /tf_static)" in finding.message


def test_static_and_dynamic():
    """A frame on both /tf and /tf_static is an error."""
    observations = [*healthy(), static('odom', 'base_link')]
    assert 'static_and_dynamic' in kinds(diagnose(observations))


def test_conflicting_static_values():
    """Two different static transforms for one child are a fight."""
    observations = [*healthy(), static('base_link', 'laser', (1.0, 0.0, 0.0))]
    finding = next(f for f in diagnose(observations) if f.kind == 'publishers_fighting')
    assert '2 different static transforms' in finding.message


def test_dynamic_fight_from_flipping_values_and_publishers():
    """Values jumping back and forth, or two publisher ids, reveal two publishers on /tf."""
    flipping = stream('odom', 'base_link', values=[(0.0, 0.0, 0.0), (5.0, 0.0, 0.0)])
    findings = diagnose([static('map', 'odom'), *flipping])
    finding = next(f for f in findings if f.kind == 'publishers_fighting')
    assert 'jumped back and forth' in finding.message
    two = stream('odom', 'base_link', pub='p1')[::2] + stream('odom', 'base_link', pub='p2')[1::2]
    finding = next(f for f in diagnose(two) if f.kind == 'publishers_fighting')
    assert '2 different publishers' in finding.message


def test_future_and_old_stamps():
    """Stamps ahead of or far behind the listener's clock point at the clocks."""
    future = stream('odom', 'base_link', delay_ns=-3 * S)
    finding = next(f for f in diagnose(future) if f.kind == 'future_stamps')
    assert '3.000 s in the future' in finding.message
    assert 'use_sim_time' in finding.fix
    sim = [
        Observation(
            TF_TOPIC, T0 + i * S // 10, (ObservedTransform('odom', 'base_link', i * S // 10),)
        )
        for i in range(1, 30)
    ]
    finding = next(f for f in diagnose(sim) if f.kind == 'old_stamps')
    assert 'simulation time' in finding.message


def test_zero_stamps():
    """Dynamic transforms stamped 0 are reported."""
    zero = [
        Observation(TF_TOPIC, T0 + i, (ObservedTransform('odom', 'base_link', 0),))
        for i in range(5)
    ]
    assert kinds(diagnose(zero)) == ['zero_stamps']


def test_sparse_data():
    """Slow or single-sample dynamic data is an extrapolation risk."""
    slow = stream('odom', 'base_link', rate_hz=1.0, seconds=4.0)
    finding = next(f for f in diagnose(slow) if f.kind == 'sparse_data')
    assert 'gaps up to 1.000 s' in finding.message
    once = stream('odom', 'base_link', rate_hz=1.0, seconds=1.0)
    finding = next(f for f in diagnose(once, listen_ns=3 * S) if f.kind == 'sparse_data')
    assert 'Only one stamp' in finding.message


def test_loop():
    """A cycle of parent links is an error naming the loop."""
    findings = diagnose([static('a', 'b'), static('b', 'c'), static('c', 'a')])
    finding = next(f for f in findings if f.kind == 'loop')
    assert set(finding.frames) == {'a', 'b', 'c'}
    assert '→' in finding.message


def test_rep105_inverted_and_bypassed():
    """odom below base_link is inverted; map→base_link beside odom is a warning."""
    inverted = [static('map', 'base_link'), static('base_link', 'odom')]
    findings = diagnose(inverted)
    assert any(f.kind == 'rep105_order' and f.frames == ('odom', 'base_link') for f in findings)
    bypass = [static('map', 'odom'), static('map', 'base_link')]
    finding = next(f for f in diagnose(bypass) if f.kind == 'rep105_order')
    assert finding.severity == 'warning'
    assert exit_code([finding]) == 1


def test_json_report():
    """--json gives one object with healthy, summary and findings."""
    observations = [static('map', 'odom'), static('base_link', 'laser')]
    findings = diagnose(observations)
    record = json.loads(format_report_json(findings, summarize(observations), 'x'))
    assert record['healthy'] is False
    assert record['summary'] == {'messages': 2, 'frames': 4, 'trees': 2}
    assert record['findings'][0]['kind'] == 'disconnected'


def test_snapshot_observations():
    """A snapshot is diagnosed structurally (no timing checks)."""
    snapshot = parse_snapshot(
        'tf_demo_transforms: 1\ntransform_count: 2\ntransforms:\n'
        '  - {parent: map, child: odom, translation: [0, 0, 0], rotation: [0, 0, 0, 1]}\n'
        '  - {parent: base_link, child: laser, translation: [0, 0, 0], rotation: [0, 0, 0, 1],'
        ' static: false, stamp: {sec: 1, nanosec: 0}}\n'
    )
    findings = diagnose(observations_from_snapshot(snapshot), check_timing=False)
    assert kinds(findings) == ['disconnected']


def test_leading_slash_frames():
    """Frames published with a leading '/' are an error with the fixed name."""
    findings = diagnose([static('map', '/odom')])
    finding = next(f for f in findings if f.kind == 'leading_slash')
    assert finding.frames == ('/odom',)
    assert "'odom' instead of '/odom'" in finding.fix


def test_stopped_stream():
    """A stream that stops long before the recording ends is reported as stopped."""
    stopped = stream('odom', 'base_link', seconds=1.0)
    later = stream('map', 'odom', seconds=4.0)
    finding = next(f for f in diagnose(stopped + later) if f.kind == 'stopped')
    assert finding.frames == ('base_link',)
    assert 'stopped arriving 3.000 s' in finding.message


def test_publisher_restart_is_not_a_fight():
    """One publisher replaced by another (a restart) is not reported as fighting."""
    first = stream('odom', 'base_link', pub='p1')
    second = later(stream('odom', 'base_link', pub='p2'), 3)
    assert diagnose([static('map', 'odom'), *first, *second]) == []


def test_qos_mismatch_is_reported_even_without_data():
    """Publishers that never matched the listener are named with tf2's QoS as the fix."""
    findings = diagnose([], unmatched_publishers={'/tf_static': 2})
    assert kinds(findings) == ['no_data', 'qos_mismatch']
    finding = next(f for f in findings if f.kind == 'qos_mismatch')
    assert finding.message.startswith('2 publishers on /tf_static do not match')
    assert 'TRANSIENT_LOCAL' in finding.fix


def test_text_report_golden():
    """The text report wraps at 99 columns, lists each tree on its own line, and counts."""
    observations = [static('map', 'odom'), static('base_link', 'laser')]
    report = format_report(diagnose(observations), summarize(observations), 'file.yaml')
    assert report == (
        'tf_doctor: file.yaml: 2 messages, 4 frames, 2 trees.\n'
        '\n'
        'ERROR [disconnected] The frames form 2 separate trees; lookups between trees fail:\n'
        '    tree 1 (root base_link): base_link, laser\n'
        '    tree 2 (root map): map, odom\n'
        '  Fix: The likely missing link is odom→base_link, published by the odometry source '
        '(base driver,\n'
        '    diff-drive controller or robot_localization). Start that publisher, or for a fixed '
        'offset run\n'
        '    static_transform_publisher --frame-id odom --child-frame-id base_link\n'
        '\n'
        'Found 1 error and 0 warnings.\n'
    )


def test_lookup_without_common_time_fails():
    """Two dynamic links whose data never overlap give tf2's extrapolation error for --frames."""
    early = stream('map', 'odom', seconds=1.0)
    late = later(stream('odom', 'base_link', seconds=1.0), 20)
    findings = diagnose(early + late, frames=['map', 'base_link'])
    finding = next(f for f in findings if f.kind == 'lookup_fails')
    assert 'extrapolation into the past' in finding.message
    assert diagnose(healthy(), frames=['map', 'laser', 'camera']) == []


# --- issue 10, point 13: advice that names the real cause ----------------------------------------

REVOLUTE_ROBOT = (
    RobotJoint('world_to_frame_1', 'fixed', 'world', 'frame_1'),
    RobotJoint('frame_1_to_frame_2', 'revolute', 'frame_1', 'frame_2'),
    RobotJoint('frame_2_to_tool', 'fixed', 'frame_2', 'tool'),
    RobotJoint('follower', 'revolute', 'frame_2', 'finger', mimic='frame_1_to_frame_2'),
)


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
    """With the position (a mimic follows its source) or with no robot link in tf: no blame."""
    named = RobotInfo(REVOLUTE_ROBOT, 5, frozenset({'frame_1_to_frame_2'}))
    findings = diagnose([static('world', 'frame_1')], frames=['frame_2'], robot=named)
    assert kinds(findings) == ['missing_frame']
    assert 'did you mean' in findings[0].message
    unrelated = diagnose(
        [static('map', 'odom')], frames=['frame_2'], robot=RobotInfo(REVOLUTE_ROBOT)
    )
    assert kinds(unrelated) == ['missing_frame']


def test_a_fixed_mount_sent_repeatedly_on_tf_belongs_on_tf_static():
    """Not 'publish faster': a transform that never changes is published once on /tf_static."""
    observations = [
        static('map', 'odom'),
        *stream('odom', 'base_link', seconds=5.0),
        *stream('base_link', 'laser', rate_hz=1.0, seconds=5.0, values=[(0.1, 0.0, 0.2)]),
    ]
    findings = diagnose(observations, listen_ns=5 * S)
    assert kinds(findings) == ['fixed_mount_on_tf']
    finding = findings[0]
    assert finding.severity == 'warning'
    assert 'base_link→laser arrived 5 times on /tf with the same value' in finding.message
    assert finding.fix.startswith('Publish a fixed mount once on /tf_static')
    assert 'faster' not in finding.fix
    fast = diagnose([*stream('base_link', 'laser', values=[(0.1, 0.0, 0.2)])], listen_ns=2 * S)
    assert [(f.kind, f.severity) for f in fast] == [('fixed_mount_on_tf', 'info')]
    assert exit_code(fast) == 0


def test_standing_still_is_not_a_fixed_mount():
    """Odometry of a robot at rest and a robot joint at rest keep the usual advice."""
    resting = stream('odom', 'base_link', rate_hz=1.0, seconds=4.0, values=[(1.0, 0.0, 0.0)])
    assert kinds(diagnose(resting)) == ['sparse_data']
    joint = stream('frame_1', 'frame_2', rate_hz=1.0, seconds=4.0, values=[(1.0, 0.0, 0.0)])
    robot = RobotInfo(REVOLUTE_ROBOT, 4, frozenset({'frame_1_to_frame_2'}))
    assert kinds(diagnose(joint, robot=robot)) == ['sparse_data']
