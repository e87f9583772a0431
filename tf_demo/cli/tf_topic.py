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
``tf_topic echo|hz TOPIC``: ``ros2 topic echo`` and ``ros2 topic hz`` for the TF topics.

``TOPIC`` is any topic of type ``tf2_msgs/msg/TFMessage`` or ``sensor_msgs/msg/JointState``:
``/tf``, ``/robot1/tf_static``, ``joint_states``... A name whose last part is ``tf``,
``tf_static`` or ``joint_states`` has that part's type; any other name takes its type (and
whether it is latched) from the graph, as ``ros2 topic echo`` does: from the publishers seen
within a few seconds, and a topic of another type, or with none, is refused (exit 1). ``echo``
prints each message as ``ros2 topic echo`` does (the message as block YAML, then ``---``);
``--once`` stops after the first. A ``tf_static`` topic (or a latched one) is read with tf2's
static listener QoS, so the latched transforms of publishers that started earlier arrive too.
``hz`` prints ``ros2 topic hz``'s lines once a second (average rate, min, max, standard
deviation of the intervals over the last ``--window`` messages). Exit codes: 0 (stopped or
``--once``), 1 for a topic of another type or none found, 2 for bad arguments. ``--ros-args``
is accepted.
"""

from __future__ import annotations

import argparse
from collections import deque
from collections.abc import Callable
from collections.abc import Sequence
from dataclasses import dataclass
from dataclasses import field
import math
import sys
import time
from typing import Any

from tf_demo.cli._live import tool_main
from tf_demo.cli._live import ToolError
from tf_demo.cli.formatting import format_message_yaml

TOOL = 'tf_topic'
TF_MESSAGE = 'tf2_msgs/msg/TFMessage'
JOINT_STATE = 'sensor_msgs/msg/JointState'
#: A topic's type by the last part of its name: ``(type, latched)``.
KNOWN_NAMES = {
    'tf': (TF_MESSAGE, False),
    'tf_static': (TF_MESSAGE, True),
    'joint_states': (JOINT_STATE, False),
}
#: How long an unknown name waits for a publisher that tells its type.
TYPE_DISCOVERY_S = 3.0
DEFAULT_WINDOW = 10_000
HZ_PERIOD_S = 1.0


@dataclass
class HzStats:
    """``ros2 topic hz``'s arithmetic: intervals between receptions (ns), printed once a second."""

    window: int = DEFAULT_WINDOW
    intervals: deque[int] = field(default_factory=deque)
    last_ns: int = -1
    printed_ns: int = 0

    def add(self, now_ns: int) -> None:
        """Record a message received at ``now_ns`` (a clock going back starts again)."""
        if 0 <= self.last_ns <= now_ns:
            self.intervals.append(now_ns - self.last_ns)
            if len(self.intervals) > self.window:
                self.intervals.popleft()
        else:
            self.intervals.clear()
        self.last_ns = now_ns

    def report(self) -> str | None:
        """Return the lines to print now, or None (no data yet, or less than a second since)."""
        if not self.intervals:
            return None
        if self.printed_ns == 0:
            self.printed_ns = self.last_ns
            return None
        if self.last_ns < self.printed_ns + 1_000_000_000:
            return None
        count = len(self.intervals)
        mean = sum(self.intervals) / count
        rate = 1.0 / mean if mean > 0 else 0.0
        deviation = math.sqrt(sum((x - mean) ** 2 for x in self.intervals) / count)
        self.printed_ns = self.last_ns
        return (
            f'average rate: {rate * 1e9:.3f}\n\tmin: {min(self.intervals) * 1e-9:.3f}s '
            f'max: {max(self.intervals) * 1e-9:.3f}s std dev: {deviation * 1e-9:.5f}s '
            f'window: {count}'
        )


def build_parser() -> argparse.ArgumentParser:
    """Return tf_topic's command line."""
    parser = argparse.ArgumentParser(prog=TOOL, description=__doc__.strip().splitlines()[0])
    verbs = parser.add_subparsers(dest='verb', required=True)
    echo = verbs.add_parser('echo', help='print the messages of a TF topic')
    topic_help = 'a TFMessage or JointState topic (/tf, /tf_static, /robot1/tf, /joint_states...)'
    echo.add_argument('topic', help=topic_help)
    echo.add_argument('--once', action='store_true', help='print the first message and exit')
    hz = verbs.add_parser('hz', help='print the average publishing rate of a TF topic')
    hz.add_argument('topic', help=topic_help)
    hz.add_argument('--window', '-w', type=int, default=DEFAULT_WINDOW, help='messages averaged')
    return parser


def options_error(options: argparse.Namespace) -> str | None:
    """Return what is wrong with the options, or None."""
    if options.verb == 'hz' and options.window < 1:
        return f'--window must be at least 1, got {options.window}'
    return None


def kind_by_name(topic: str) -> tuple[str, bool] | None:
    """Return ``(type, latched)`` of ``topic`` by the last part of its name, or None."""
    return KNOWN_NAMES.get(topic.rstrip('/').rsplit('/', 1)[-1])


def kind_from_publishers(topic: str, publishers: Sequence[Any]) -> tuple[str, bool]:
    """
    Return ``(type, latched)`` of ``topic`` from its publishers' endpoint infos (rclpy's).

    :raises ToolError: when they publish another type (or several types).
    """
    types = sorted({str(info.topic_type) for info in publishers})
    if types not in ([TF_MESSAGE], [JOINT_STATE]):
        msg = (
            f"topic '{topic}' has type {' and '.join(types)}: tf_topic reads {TF_MESSAGE} and "
            f'{JOINT_STATE} topics (ros2 topic echo reads the others)'
        )
        raise ToolError(msg)
    latched = any(
        getattr(getattr(info.qos_profile, 'durability', None), 'name', '') == 'TRANSIENT_LOCAL'
        for info in publishers
    )
    return types[0], latched


def _topic_kind(node: Any, topic: str) -> tuple[str, bool]:
    """Return ``(type, latched)`` of ``topic``: by its name, else from the graph (waiting)."""
    from tf_demo import transport

    known = kind_by_name(topic)
    if known is not None:
        return known
    deadline = time.monotonic() + TYPE_DISCOVERY_S
    while transport.ok():
        publishers = node.get_publishers_info_by_topic(topic)
        if publishers:
            return kind_from_publishers(topic, publishers)
        if time.monotonic() > deadline:
            break
        transport.spin_once(node, timeout_sec=0.1)
    msg = (
        f"no publisher on '{topic}' within {TYPE_DISCOVERY_S:g} s to tell its type (a name "
        'ending in tf, tf_static or joint_states needs none)'
    )
    raise ToolError(msg)


def _subscribe(
    node: Any, topic: str, kind: tuple[str, bool], callback: Callable[[Any], None]
) -> None:
    from tf_demo.transport.messages import sensor_msgs
    from tf_demo.transport.messages import tf2_msgs
    from tf_demo.transport.qos import DynamicListenerQoS
    from tf_demo.transport.qos import StaticListenerQoS

    message_type, latched = kind
    if message_type == JOINT_STATE:
        node.create_subscription(sensor_msgs.JointState, topic, callback, 10)
    else:
        qos = StaticListenerQoS() if latched else DynamicListenerQoS()
        node.create_subscription(tf2_msgs.TFMessage, topic, callback, qos)


def _run(options: argparse.Namespace) -> int:
    from tf_demo import transport

    node = transport.create_node(TOOL)
    done = False
    stats = HzStats(options.window) if options.verb == 'hz' else None
    clock = node.get_clock()

    def on_message(message: Any) -> None:
        nonlocal done
        if stats is not None:
            stats.add(clock.now().nanoseconds)
            return
        if done:
            return
        sys.stdout.write(format_message_yaml(message) + '---\n')
        sys.stdout.flush()
        done = options.once

    def on_second() -> None:
        lines = stats.report() if stats is not None else None
        if lines is not None:
            print(lines, flush=True)

    try:
        _subscribe(node, options.topic, _topic_kind(node, options.topic), on_message)
        if stats is not None:
            node.create_timer(HZ_PERIOD_S, on_second)
        while transport.ok() and not done:
            transport.spin_once(node, timeout_sec=0.1)
    finally:
        node.destroy_node()
    return 0


def main(args: list[str] | None = None) -> int:
    """Run tf_topic with ``args`` (default: ``sys.argv[1:]``)."""
    return tool_main(TOOL, args, build_parser(), options_error, _run)


if __name__ == '__main__':
    sys.exit(main())
