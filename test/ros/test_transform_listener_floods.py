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
Issue 10 point 8: a flood of bad /tf samples gives a bounded number of log lines.

A real peer process sends thousands of rounds of invalid transforms and of undecodable bytes to a
real ``tf_echo`` (whose listener decodes the serialised bytes itself in both worlds); its log
shows each kind's first line verbatim, then throttled counts per writer, and it still echoes the
valid transform sent afterwards.
"""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path
import re
import signal
import sys
import time
from typing import Any

from conftest import ChildProcess
from conftest import executable_command
from conftest import WORLD
import pytest

PEER = Path(__file__).resolve().parent / 'tf_flood_peer.py'
ROUNDS = 3000
#: Lines a flood may log: each kind's first on each topic, plus one count per kind and period.
#: A generous bound (the run takes seconds; the flood had ROUNDS * 6 bad samples and more).
MAX_LOG_LINES = 60
#: A TFMessage whose sequence claims 2**31 transforms in 12 bytes (as the peer sends).
GARBAGE = b'\x00\x01\x00\x00\x00\x00\x00\x80' + bytes(8)
BAD_LINE = re.compile(r'malformed|Ignoring transform|more rejected transforms|Failure to set')

pytestmark = pytest.mark.dds


def test_a_flood_of_bad_samples_logs_a_bounded_number_of_lines(world_env: dict[str, str]) -> None:
    """Thousands of bad samples: each kind logged once, then counted; tf_echo keeps working."""
    garbage = ['--garbage']
    echo = ChildProcess(executable_command('tf_echo', 'world', 'good', '5'), world_env)
    peer = ChildProcess([sys.executable, str(PEER), '--count', str(ROUNDS), *garbage], world_env)
    try:
        peer.wait_for_line('flooded', timeout=120)
        echo.wait_for_line('- Translation: [7.000, 0.000, 0.000]', timeout=60)
        counted = echo.wait_for_line('more rejected transforms', timeout=60, anywhere=True)
        assert re.search(
            r'\d+ more rejected transforms \(TF_\w+\) from .* in the last \d+\.\d s; '
            r'the latest: TF_\w+',
            counted,
        )
        if garbage:
            line = echo.wait_for_line('more malformed samples from ', 60, anywhere=True)
            # The standalone world names the writer by its GUID; rclpy's message info has none.
            writer = (
                r'writer ([0-9a-f]{2}\.){15}[0-9a-f]{2}' if WORLD == 'dds' else "a writer on '/tf'"
            )
            assert re.search(f'from {writer} in the last', line), line
        peer.process.send_signal(signal.SIGINT)
        assert peer.finish() == 0
        echo.process.send_signal(signal.SIGINT)
        echo.finish()
    finally:
        peer.stop()
        echo.stop()
    bad_lines = [line for line in echo.stderr if BAD_LINE.search(line)]
    assert bad_lines, echo.stderr
    assert len(bad_lines) <= MAX_LOG_LINES, '\n'.join(bad_lines)
    for first in (
        'TF_NAN_INPUT: Ignoring transform for child_frame_id "nan_q" from authority '
        '"default_authority" because of a nan value in the transform',
        'TF_NO_FRAME_ID: Ignoring transform with child_frame_id "no_parent"  from authority '
        '"default_authority" because frame_id not set',
        'TF_SELF_TRANSFORM: Ignoring transform from authority "default_authority" with '
        'frame_id and  child_frame_id "loop" because they are the same',
    ):
        assert any(first in line for line in bad_lines), (first, bad_lines)
    if garbage:
        assert any(
            'Dropping a malformed TFMessage: cannot decode tf2_msgs/msg/TFMessage: field '
            'transforms at byte 8: sequence length 2147483648 exceeds' in line
            for line in bad_lines
        ), bad_lines


@pytest.mark.standalone
@pytest.mark.parametrize('with_info', [False, True], ids=['message', 'message_and_info'])
def test_a_subscription_logs_a_flood_of_undecodable_samples_once(
    ros: None, capfd: pytest.CaptureFixture[str], with_info: bool
) -> None:
    """2,000 undecodable samples from one writer: one error line (then counts); data flows."""
    from tf_demo import transport
    from tf_demo.transport.executors import SingleThreadedExecutor
    from tf_demo.transport.messages import tf2_msgs
    from tf_demo.transport.qos import QoSProfile

    node = transport.create_node('robust')
    received: list[Any] = []
    callback = (lambda msg, _info: received.append(msg)) if with_info else received.append
    node.create_subscription(tf2_msgs.TFMessage, '/flood', callback, QoSProfile(depth=3000))
    publisher = transport.create_node('garbage').create_publisher(
        tf2_msgs.TFMessage, '/flood', QoSProfile(depth=3000)
    )
    executor = SingleThreadedExecutor()
    executor.add_node(node)
    try:
        assert spin_until(executor, lambda: publisher.get_subscription_count() >= 1)
        for _ in range(2000):
            publisher.publish(GARBAGE)
        publisher.publish(tf2_msgs.TFMessage(transforms=[make_good()]))
        assert spin_until(executor, lambda: len(received) == 1)
    finally:
        executor.shutdown()
    assert received[0].transforms[0].child_frame_id == 'good'
    lines = [line for line in capfd.readouterr().err.splitlines() if 'malformed' in line]
    firsts = [line for line in lines if ' more malformed samples from writer ' not in line]
    assert len(firsts) == 1, lines
    assert (
        "Dropped a malformed tf2_msgs/msg/TFMessage message on '/flood': cannot decode"
        in (firsts[0])
    )
    assert len(lines) <= MAX_LOG_LINES, lines


def make_good() -> Any:
    """Return a valid ``world`` -> ``good`` transform."""
    from tf_demo.nodes.helpers import make_transform_stamped

    return make_transform_stamped('world', 'good', 1, (7.0, 0.0, 0.0), (0.0, 0.0, 0.0, 1.0))


def spin_until(executor: Any, done: Callable[[], bool], timeout_s: float = 60.0) -> bool:
    """Spin until ``done()`` (bounded: a guard against hangs, not a timing assertion)."""
    deadline = time.monotonic() + timeout_s
    while not done() and time.monotonic() < deadline:
        executor.spin_once(timeout_sec=0.05)
    return done()


def test_rejected_transforms_are_throttled_per_source_and_kind(
    ros: None, capfd: pytest.CaptureFixture[str]
) -> None:
    """Direct inserts and each named writer get their own first line; the rest are counted."""
    from tf_demo.nodes.helpers import make_transform_stamped
    from tf_demo.ros import Buffer

    buffer = Buffer()
    nan = make_transform_stamped('a', 'b', 1, (float('nan'), 0.0, 0.0), (0.0, 0.0, 0.0, 1.0))
    for _ in range(500):
        buffer.set_transform(nan, 'me')
    buffer.set_log_source(bytes(range(16)))
    for _ in range(500):
        buffer.set_transform(nan, 'me')
    buffer.set_log_source(None)
    buffer.log_pending_rejections()
    lines = [line for line in capfd.readouterr().err.splitlines() if 'TF_NAN_INPUT' in line]
    assert len(lines) == 4, lines
    assert (
        'TF_NAN_INPUT: Ignoring transform for child_frame_id "b" from authority "me"' in (lines[0])
    )
    assert '499 more rejected transforms (TF_NAN_INPUT) from direct set_transform calls' in (
        '\n'.join(lines)
    )
    assert (
        '499 more rejected transforms (TF_NAN_INPUT) from writer 00.01.02.03.04.05.06.07.08.09'
        in '\n'.join(lines)
    )
