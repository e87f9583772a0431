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

"""robot_state_publisher's pure rules: throttle rate table, invalid messages, CDR encoding."""

from __future__ import annotations

import json
import math
from pathlib import Path
import random

import pytest
from tf_demo.msgs.cdr import TfMessageEncoder
from tf_demo.nodes.robot_state_publisher import check_publish_frequency
from tf_demo.nodes.robot_state_publisher import DroppedMessageLog
from tf_demo.nodes.robot_state_publisher import joint_state_problem
from tf_demo.nodes.robot_state_publisher import JointStateThrottle
from tf_demo.nodes.robot_state_publisher import positions_from_joint_state
from tf_demo.nodes.robot_state_publisher import publish_interval_ns

GOLDEN = Path(__file__).resolve().parents[1] / 'data' / 'golden'
SECOND = 1_000_000_000


def output_rate(
    input_hz: float,
    publish_frequency: float,
    *,
    jitter_ms: float = 0.0,
    zero_stamps: bool = False,
    ignore_timestamp: bool = False,
    seconds: int = 100,
) -> float:
    """Feed a stream of stamped messages through the throttle and count what passes per second."""
    rng = random.Random(7)
    throttle = JointStateThrottle()
    published = 0
    period_ns = SECOND / input_hz
    names = ['joint_a', 'joint_b']
    for k in range(1, int(seconds * input_hz) + 1):
        arrival_ns = SECOND + int(k * period_ns)
        stamp_ns = 0 if zero_stamps else arrival_ns + int(rng.uniform(-jitter_ms, jitter_ms) * 1e6)
        now_ns = arrival_ns + 1_000_000  # the node sees the message 1 ms after its stamp
        if throttle.should_publish(
            names, stamp_ns, now_ns, publish_interval_ns(publish_frequency), ignore_timestamp
        ):
            published += 1
            throttle.record(names, stamp_ns)
    return published / seconds


@pytest.mark.parametrize(
    ('input_hz', 'publish_frequency', 'options', 'expected', 'tolerance'),
    [
        (100, 20, {}, 20.0, 0.0),
        (20, 20, {}, 20.0, 0.0),
        (20, 20, {'jitter_ms': 1.0}, 12.6, 0.5),
        (100, 20, {'jitter_ms': 1.0}, 17.9, 0.3),
        (50, 20, {}, 16.7, 0.05),
        (40, 30, {}, 20.0, 0.0),
        (500, 1000, {}, 500.0, 0.0),
        (100, 20, {'zero_stamps': True}, 0.0, 0.0),
        (100, 20, {'zero_stamps': True, 'ignore_timestamp': True}, 100.0, 0.0),
    ],
)
def test_throttle_reproduces_the_spec_rate_table(
    input_hz: float,
    publish_frequency: float,
    options: dict[str, object],
    expected: float,
    tolerance: float,
) -> None:
    """Output /tf rates of upstream's throttle (spec 1.5 table), with stamps as the clock."""
    rate = output_rate(input_hz, publish_frequency, **options)  # type: ignore[arg-type]
    assert rate == pytest.approx(expected, abs=tolerance)


def test_throttle_uses_least_recently_published_joint_of_the_message() -> None:
    """Sources naming disjoint joints are throttled independently; a new joint always passes."""
    throttle = JointStateThrottle()
    interval = publish_interval_ns(20.0)
    now = 10 * SECOND
    assert throttle.should_publish(['a'], now, now, interval, ignore_timestamp=False)
    throttle.record(['a'], now)
    assert not throttle.should_publish(['a'], now + interval - 1, now, interval, False)
    assert throttle.should_publish(['a'], now + interval, now, interval, False)
    assert throttle.should_publish(['b'], now + 1, now, interval, False)
    assert throttle.should_publish(['a', 'b'], now + 1, now, interval, False)


def test_backward_clock_jump_forgets_last_published_stamps() -> None:
    """A node clock moving backwards resets the throttle, so old stamps publish again."""
    throttle = JointStateThrottle()
    interval = publish_interval_ns(20.0)
    assert not throttle.clock_moved_backwards(100 * SECOND)
    throttle.record(['a'], 100 * SECOND)
    assert not throttle.should_publish(['a'], 5 * SECOND, 5 * SECOND, interval, False)
    assert throttle.clock_moved_backwards(5 * SECOND)
    assert throttle.should_publish(['a'], 5 * SECOND, 5 * SECOND, interval, False)


@pytest.mark.parametrize(
    ('frequency', 'interval_ms'), [(20.0, 50), (30.0, 33), (1000.0, 1), (0.5, 2000), (7.0, 142)]
)
def test_publish_interval_is_whole_milliseconds(frequency: float, interval_ms: int) -> None:
    """The interval is floor(1000 / publish_frequency) ms, as upstream's integer cast."""
    assert publish_interval_ns(frequency) == interval_ms * 1_000_000


@pytest.mark.parametrize(
    ('value', 'valid'),
    [(0.0, False), (-1.0, False), (1e-6, True), (1000.0, True), (1000.001, False), (20.0, True)],
)
def test_publish_frequency_range_is_open_at_zero_closed_at_1000(value: float, valid: bool) -> None:
    """Only 0 < publish_frequency <= 1000 is accepted."""
    assert check_publish_frequency(value) is valid


def test_invalid_joint_states_are_reported_with_upstream_texts() -> None:
    """Empty positions warn naming the first joint; other length mismatches are errors."""
    assert joint_state_problem(['a', 'b'], [1.0, 2.0]) is None
    assert joint_state_problem([], []) is None
    assert joint_state_problem(['a', 'b'], []) == (
        30,
        'Robot state publisher ignored a JointState message about joint(s) "a"(,...) whose '
        'position member was empty.',
    )
    assert joint_state_problem(['a'], [1.0, 2.0]) == (
        40,
        'Robot state publisher ignored an invalid JointState message',
    )


def test_velocity_or_effort_of_the_wrong_length_makes_a_joint_state_invalid() -> None:
    """velocity/effort empty or one per name; any other length drops the message (a warning)."""
    assert joint_state_problem(['a', 'b'], [1.0, 2.0], [], [0.0, 0.0]) is None
    assert joint_state_problem(['a'], [1.0], [math.nan], [math.inf]) is None  # values unused
    assert joint_state_problem(['a'], [1.0], [0.1, 0.2]) == (
        30,
        'Robot state publisher ignored a JointState message with 1 names but 2 velocity values',
    )
    assert joint_state_problem(['a', 'b'], [1.0, 2.0], [], [3.0]) == (
        30,
        'Robot state publisher ignored a JointState message with 2 names but 1 effort values',
    )


def test_dropped_message_warnings_are_throttled_with_a_count() -> None:
    """First of a kind at once; then one line per interval saying how many went unlogged."""
    log = DroppedMessageLog(interval_s=5.0)
    assert log.text('nan', 'dropped', 100.0) == 'dropped'
    assert [log.text('nan', 'dropped', 100.0 + i / 10) for i in range(1, 40)] == [None] * 39
    assert log.text('other', 'another kind', 101.0) == 'another kind'
    assert log.text('nan', 'dropped', 105.0) == (
        'dropped (39 more such message(s) dropped in the last 5 s)'
    )
    assert log.text('nan', 'dropped', 111.0) == 'dropped'
    assert log.text('nan', 'dropped', 112.0) is None


def test_repeated_joint_name_keeps_its_first_position() -> None:
    """When a name repeats, the first position wins (std::map::emplace)."""
    assert positions_from_joint_state(['a', 'b', 'a'], [1.0, 2.0, 3.0]) == {'a': 1.0, 'b': 2.0}


def golden(name: str) -> tuple[bytes, dict[str, object]]:
    index = json.loads((GOLDEN / 'index.json').read_text())
    return (GOLDEN / f'{name}.cdr').read_bytes(), index[name]['value']


def test_encoder_matches_golden_bytes_from_ros2() -> None:
    """One transform and an empty message encode byte for byte as rclpy does."""
    data, _ = golden('tf2_msgs__TFMessage__one')
    encoded = TfMessageEncoder().encode(
        [('base_link', 'camera_link', (0.5, 0.0, 0.2), (0.0, 0.0, 0.0, 1.0))], 1, 2
    )
    assert encoded == data
    empty, _ = golden('tf2_msgs__TFMessage__empty')
    assert TfMessageEncoder().encode([], 5, 6) == empty


def test_encoder_prefix_and_padding_agree_with_the_message_codec() -> None:
    """Random frame-name lengths and prefixes encode as the package's general CDR codec does."""
    cdr = pytest.importorskip('tf_demo.msgs.cdr')
    from tf_demo.msgs import geometry_msgs
    from tf_demo.msgs import tf2_msgs

    rng = random.Random(3)
    for prefix in ('', 'r/', 'robot_two_'):
        encoder = TfMessageEncoder(prefix)
        for count in range(6):
            transforms = []
            for _ in range(count):
                parent = 'p' * rng.randint(1, 11)
                child = 'c' * rng.randint(1, 13)
                t = (rng.uniform(-5, 5), rng.uniform(-5, 5), rng.uniform(-5, 5))
                q = (rng.random(), rng.random(), rng.random(), rng.random())
                transforms.append((parent, child, t, q))
            sec, nanosec = rng.randint(0, 2**31 - 1), rng.randint(0, SECOND - 1)
            expected = tf2_msgs.TFMessage(transforms=[])
            for parent, child, t, q in transforms:
                message = geometry_msgs.TransformStamped()
                message.header.stamp.sec = sec
                message.header.stamp.nanosec = nanosec
                message.header.frame_id = prefix + parent
                message.child_frame_id = prefix + child
                tr = message.transform.translation
                tr.x, tr.y, tr.z = t
                ro = message.transform.rotation
                ro.x, ro.y, ro.z, ro.w = q
                expected.transforms.append(message)
            assert encoder.encode(transforms, sec, nanosec) == cdr.serialize(expected)


def test_encoder_agrees_with_the_codec_beyond_cached_layouts() -> None:
    """More transforms than a cached layout holds, and a layout met again, encode as serialize."""
    from tf_demo.msgs import cdr
    from tf_demo.msgs import geometry_msgs
    from tf_demo.msgs import tf2_msgs
    from tf_demo.msgs.convert import fill_transform_stamped

    for count in (1, 1100, 1100, 3, 3):
        transforms = [
            (f'p{i}', f'child_{i}', (float(i), 0.5, -1.0), (0.0, 0.0, 0.6, 0.8))
            for i in range(count)
        ]
        stamped = [
            fill_transform_stamped(geometry_msgs.TransformStamped(), p, c, 9 * SECOND + 8, t, q)
            for p, c, t, q in transforms
        ]
        expected = cdr.serialize(tf2_msgs.TFMessage(transforms=stamped))
        assert TfMessageEncoder().encode(transforms, 9, 8) == expected


def test_encoder_output_decodes_back_to_the_transforms() -> None:
    """Decoding what the encoder wrote gives the same frames, stamp and values (NaN too)."""
    cdr = pytest.importorskip('tf_demo.msgs.cdr')
    transforms = [
        ('world', 'frame_1', (0.0, 0.0, 1.0), (0.0, 0.0, 0.0, 1.0)),
        ('frame_1', 'frame_2', (1.0, 0.0, math.nan), (0.0, 0.0, 0.6, 0.8)),
    ]
    data = TfMessageEncoder('x/').encode(transforms, 42, 7)
    decoded = cdr.decode_tf_message_transforms(data)
    assert [(p, c, s) for p, c, s, _, _ in decoded] == [
        ('x/world', 'x/frame_1', 42 * SECOND + 7),
        ('x/frame_1', 'x/frame_2', 42 * SECOND + 7),
    ]
    assert decoded[1][4] == (0.0, 0.0, 0.6, 0.8)
    assert math.isnan(decoded[1][3][2])
