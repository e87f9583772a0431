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
``tf_demo.ros.Buffer`` against the real ``tf2_ros.Buffer``, side by side in one process.

Both buffers take the same seeded scenarios (``strategies.build_scenario`` for Jazzy's core:
out-of-order, repeated, rejected and re-parented inserts, static overwrites, today's epoch
stamps) as rclpy ``TransformStamped`` messages, and answer the same questions through their
public API with rclpy ``Time`` objects: ``lookup_transform``, ``lookup_transform_full``,
``can_transform`` and ``can_transform_full`` with their debug texts.  Answers must agree: the
same frames and stamp, the transform within 1e-9 (q or -q), the same exception text and class
(ours raises tf2's extrapolation subclasses of ``ExtrapolationException``, which tf2_py folds
into that class).
"""

from __future__ import annotations

from typing import Any

import pytest
from tf_demo.testing import strategies

pytestmark = pytest.mark.rclpy_world

SCENARIOS = 3000
TOLERANCE = 1e-9

Answer = tuple[Any, ...] | None


def _ask(buffer: Any, op: list[Any]) -> Answer:
    """Apply one operation through the buffer's public API; encode what it answers."""
    from rclpy.time import Time
    from tf_demo.nodes.helpers import make_transform_stamped

    kind = op[0]

    def at(ns: int) -> Time:
        return Time(nanoseconds=ns)

    try:
        if kind == 'set':
            insert = buffer.set_transform_static if op[7] else buffer.set_transform
            insert(make_transform_stamped(*op[1:6]), op[6])
            return None
        if kind == 'clear':
            buffer.clear()
            return None
        if kind == 'can':
            return ('can', buffer.can_transform(op[1], op[2], at(op[3]), return_debug_tuple=True))
        if kind == 'can_full':
            full = (op[1], at(op[2]), op[3], at(op[4]), op[5])
            return ('can_full', buffer.can_transform_full(*full, return_debug_tuple=True))
        if kind == 'lookup':
            result = buffer.lookup_transform(op[1], op[2], at(op[3]))
        elif kind == 'lookup_full':
            result = buffer.lookup_transform_full(op[1], at(op[2]), op[3], at(op[4]), op[5])
        else:
            return None  # questions tf2_ros's Python buffer does not ask (chain, velocity...)
    except Exception as error:  # both sides' exceptions are the answers compared
        return ('exception', type(error).__name__, str(error))
    header, t, q = result.header, result.transform.translation, result.transform.rotation
    return (
        'transform',
        header.frame_id,
        result.child_frame_id,
        header.stamp.sec,
        header.stamp.nanosec,
        (t.x, t.y, t.z),
        (q.x, q.y, q.z, q.w),
    )


def _agree(ours: Answer, theirs: Answer) -> bool:
    """Whether two answers are the same (transforms to TOLERANCE, q or -q)."""
    if ours == theirs:
        return True
    if ours is None or theirs is None or ours[0] != theirs[0]:
        return False
    if ours[0] == 'exception':
        our_class, their_class = str(ours[1]), str(theirs[1])
        same_class = our_class == their_class or (
            their_class == 'ExtrapolationException' and our_class.endswith(their_class)
        )
        return same_class and str(ours[2]) == str(theirs[2])
    if ours[0] != 'transform' or ours[1:5] != theirs[1:5]:
        return False

    def close(a: tuple[float, ...], b: tuple[float, ...], sign: float = 1.0) -> bool:
        return all(abs(x - sign * y) <= TOLERANCE for x, y in zip(a, b, strict=True))

    return close(ours[5], theirs[5]) and (
        close(ours[6], theirs[6]) or close(ours[6], theirs[6], -1.0)
    )


def test_our_buffer_answers_as_tf2_ros_buffer_on_seeded_scenarios() -> None:
    """Three thousand scenarios, every question answered alike by both buffers."""
    from rclpy.duration import Duration
    import tf2_ros
    from tf_demo.ros import Buffer

    questions = 0
    disagreements: list[str] = []
    for seed in range(SCENARIOS):
        scenario = strategies.build_scenario(strategies.SeededChooser(seed), ros1=False)
        cache_time = Duration(nanoseconds=scenario['cache_time_ns'])
        theirs, ours = tf2_ros.Buffer(cache_time=cache_time), Buffer(cache_time=cache_time)
        for position, op in enumerate(scenario['ops']):
            their_answer, our_answer = _ask(theirs, op), _ask(ours, op)
            questions += their_answer is not None
            if not _agree(our_answer, their_answer):
                disagreements.append(
                    f'seed {seed} op {position} {op}: tf2_ros {their_answer}, ours {our_answer}'
                )
    assert not disagreements, f'{len(disagreements)} disagreements:\n' + '\n'.join(
        disagreements[:5]
    )
    assert questions > 5 * SCENARIOS
