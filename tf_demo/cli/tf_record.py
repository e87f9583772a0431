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
``tf_record -o PATH [--duration S] [--topics ...] [--storage S]``: record TF to a rosbag2.

Records ``/tf`` and ``/tf_static`` (and, when asked, ``/joint_states``, ``/robot_description``,
``/clock``) from the live network, in either world, into a new rosbag2 that ROS 2's tools open:
MCAP by default, the topics' type names, ``cdr`` and the QoS their publishers offer (read from
the graph when the first message arrives, as rosbag2 does) in the metadata. Messages are
written as received (serialised, untouched) with the node clock's time; a topic whose
publishers were found but sent nothing is listed with no messages. ``/tf_static`` and
``/robot_description`` are subscribed latched, so what was published before the recording
started is in it. Ctrl-C or ``--duration`` closes the bag cleanly (exit 0).
Needs the ``bag`` extra. ``--ros-args`` is accepted.
"""

from __future__ import annotations

import argparse
import math
import sys
import time
from typing import TYPE_CHECKING

from tf_demo.cli._live import add_namespace_option
from tf_demo.cli._live import tool_main
from tf_demo.cli._live import ToolError

if TYPE_CHECKING:
    from tf_demo.msgs._message import Message
    from tf_demo.transport.node import Node
    from tf_demo.transport.qos import QoSProfile

TOOL = 'tf_record'
DEFAULT_TOPICS = ['/tf', '/tf_static']
SPIN_SLICE_S = 0.1
FLUSH_PERIOD_S = 1.0
"""How often the bag is committed to disk while recording (SQLite3)."""


def build_parser() -> argparse.ArgumentParser:
    """Return tf_record's command line."""
    from tf_demo.bag.writer import STORAGES
    from tf_demo.bag.writer import TOPIC_TYPES

    parser = argparse.ArgumentParser(prog=TOOL, description=__doc__.strip().splitlines()[0])
    parser.add_argument('-o', '--output', required=True, help='the new bag (a directory)')
    parser.add_argument('--duration', type=float, default=None, help='seconds, then stop')
    parser.add_argument(
        '--topics', nargs='+', default=DEFAULT_TOPICS, choices=sorted(TOPIC_TYPES),
        metavar='TOPIC', help=f'default: /tf /tf_static; any of {sorted(TOPIC_TYPES)}',
    )  # fmt: skip
    parser.add_argument('--storage', choices=STORAGES, default='mcap', help='rosbag2 storage')
    add_namespace_option(parser)
    return parser


def options_error(options: argparse.Namespace) -> str | None:
    """Return what is wrong with the options, or None."""
    duration = options.duration
    if duration is not None and not (math.isfinite(duration) and duration > 0):
        return f'--duration must be a positive number of seconds, got {duration}'
    return None


def _subscription_of(topic: str) -> tuple[type[Message], QoSProfile | int]:
    """Return the message type and QoS to subscribe to ``topic`` with."""
    from tf_demo.transport.messages import rosgraph_msgs
    from tf_demo.transport.messages import sensor_msgs
    from tf_demo.transport.messages import std_msgs
    from tf_demo.transport.messages import tf2_msgs
    from tf_demo.transport.qos import DurabilityPolicy
    from tf_demo.transport.qos import DynamicListenerQoS
    from tf_demo.transport.qos import QoSProfile
    from tf_demo.transport.qos import ReliabilityPolicy
    from tf_demo.transport.qos import StaticListenerQoS

    if topic == '/tf':
        return tf2_msgs.TFMessage, DynamicListenerQoS()
    if topic == '/tf_static':
        return tf2_msgs.TFMessage, StaticListenerQoS()
    if topic == '/robot_description':
        latched = QoSProfile(depth=1, durability=DurabilityPolicy.TRANSIENT_LOCAL)
        return std_msgs.String, latched
    if topic == '/clock':  # best effort takes both kinds of /clock publisher
        return rosgraph_msgs.Clock, QoSProfile(depth=10, reliability=ReliabilityPolicy.BEST_EFFORT)
    return sensor_msgs.JointState, 10


def _offered_qos(node: Node, topic: str) -> list[QoSProfile]:
    """Return the QoS profiles the publishers of ``topic`` offer (rosbag2 records them)."""
    try:
        return [info.qos_profile for info in node.get_publishers_info_by_topic(topic)]
    except Exception:  # a graph query that fails costs the metadata, not the recording
        return []


def _record(options: argparse.Namespace) -> int:
    from tf_demo import transport
    from tf_demo.bag import BagError
    from tf_demo.bag import TfBagWriter

    try:
        topics = list(dict.fromkeys(options.topics))  # each once, in the order given
        bag = TfBagWriter(options.output, topics, options.storage)
    except BagError as error:
        raise ToolError(str(error)) from None
    node = transport.create_node(TOOL)
    clock = node.get_clock()
    offered: dict[str, list[QoSProfile]] = {}  # each topic's publishers' QoS, once they are found
    try:
        for topic in topics:
            msg_type, qos = _subscription_of(topic)

            def on_data(data: bytes, topic: str = topic) -> None:
                if topic not in offered:
                    offered[topic] = _offered_qos(node, topic)
                bag.write(topic, clock.now().nanoseconds, bytes(data), offered[topic])

            node.create_subscription(msg_type, topic, on_data, qos, raw=True)
        print(f'tf_record: recording {" ".join(topics)} to {bag.path}', flush=True)
        deadline = None if options.duration is None else time.monotonic() + options.duration
        next_flush = time.monotonic() + FLUSH_PERIOD_S
        while transport.ok() and (deadline is None or time.monotonic() < deadline):
            transport.spin_once(node, timeout_sec=SPIN_SLICE_S)
            if time.monotonic() >= next_flush:  # a crash loses at most this much
                bag.flush()
                next_flush = time.monotonic() + FLUSH_PERIOD_S
                for topic in topics:  # as rosbag2 meets a topic's publishers before their data
                    if topic not in offered and (found := _offered_qos(node, topic)):
                        offered[topic] = found
    finally:
        for topic, profiles in offered.items():
            bag.add_topic(topic, profiles)  # listed even if nothing arrived (a no-op otherwise)
        node.destroy_node()
        bag.close()
        print(f'tf_record: {bag.count} messages in {bag.path}', flush=True)
    return 0


def main(args: list[str] | None = None) -> int:
    """Run tf_record with ``args`` (default: ``sys.argv[1:]``)."""
    return tool_main(TOOL, args, build_parser(), options_error, _record)


if __name__ == '__main__':
    sys.exit(main())
