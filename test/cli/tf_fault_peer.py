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
A test peer that publishes a tf scenario given as JSON (faults included), until SIGINT/SIGTERM.

Each entry: ``{"parent", "child", "t": [x, y, z], "q": [x, y, z, w], "static": bool,
"group": name, "rate": Hz, "stamp_offset": seconds, "zero_stamp": bool,
"values": [[x, y, z], ...], "volatile": bool, "best_effort": bool}``. Static entries of one
``group`` share a latched broadcaster (a separate node per group, so two groups are two
publishers); dynamic entries are sent at ``rate`` with stamp now + ``stamp_offset`` and cycle
through ``values`` when given. ``volatile``/``best_effort`` break tf2's QoS on purpose. Prints
``ready`` once everything was sent the first time.
"""

from __future__ import annotations

from collections.abc import Sequence
import json
import signal
import sys
import time
from typing import TypedDict

from tf_demo import transport
from tf_demo.msgs.convert import fill_transform_stamped
from tf_demo.ros import StaticTransformBroadcaster
from tf_demo.ros import TransformBroadcaster
from tf_demo.transport.messages import geometry_msgs
from tf_demo.transport.node import Node
from tf_demo.transport.qos import DurabilityPolicy
from tf_demo.transport.qos import QoSProfile
from tf_demo.transport.qos import ReliabilityPolicy


class Entry(TypedDict, total=False):
    """One transform of the scenario (the keys of the module docstring)."""

    parent: str
    child: str
    t: list[float]
    q: list[float]
    static: bool
    group: str
    rate: float
    stamp_offset: float
    zero_stamp: bool
    values: list[list[float]]
    volatile: bool
    best_effort: bool


def main() -> None:
    spec: list[Entry] = json.loads(sys.argv[1])
    stop: list[int] = []
    signal.signal(signal.SIGTERM, lambda *_: stop.append(1))
    signal.signal(signal.SIGINT, lambda *_: stop.append(1))
    transport.init(args=['tf_fault_peer'])
    nodes: dict[str, Node] = {}
    static_broadcasters: dict[str, StaticTransformBroadcaster] = {}
    dynamic_broadcasters: dict[str, TransformBroadcaster] = {}

    def node_for(group: str) -> Node:
        if group not in nodes:
            nodes[group] = transport.create_node(f'tf_fault_peer_{group}')
        return nodes[group]

    def message(
        entry: Entry, stamp_ns: int, translation: Sequence[float]
    ) -> geometry_msgs.TransformStamped:
        msg = geometry_msgs.TransformStamped()
        rotation = tuple(entry.get('q', (0.0, 0.0, 0.0, 1.0)))
        fill_transform_stamped(
            msg, entry['parent'], entry['child'], stamp_ns, tuple(translation), rotation
        )
        return msg

    dynamic: list[Entry] = []
    for entry in spec:
        group = entry.get('group', 'main')
        if entry.get('static', False):
            if group not in static_broadcasters:
                qos = None
                if entry.get('volatile'):
                    qos = QoSProfile(depth=1, durability=DurabilityPolicy.VOLATILE)
                static_broadcasters[group] = StaticTransformBroadcaster(node_for(group), qos)
            now = node_for(group).get_clock().now().nanoseconds
            static_broadcasters[group].send_transform(
                message(entry, now, entry.get('t', [0, 0, 0]))
            )
        else:
            if group not in dynamic_broadcasters:
                qos = None
                if entry.get('best_effort'):
                    qos = QoSProfile(depth=10, reliability=ReliabilityPolicy.BEST_EFFORT)
                dynamic_broadcasters[group] = TransformBroadcaster(node_for(group), qos)
            dynamic.append(entry)
    print('ready', flush=True)
    next_due = [0.0] * len(dynamic)
    counts = [0] * len(dynamic)
    while not stop:
        now_wall = time.monotonic()
        for index, entry in enumerate(dynamic):
            if now_wall < next_due[index]:
                continue
            next_due[index] = now_wall + 1.0 / entry.get('rate', 20.0)
            group = entry.get('group', 'main')
            now = nodes[group].get_clock().now().nanoseconds
            stamp = 0 if entry.get('zero_stamp') else now + int(entry.get('stamp_offset', 0) * 1e9)
            values: Sequence[Sequence[float]] = entry.get('values') or [entry.get('t', [0, 0, 0])]
            translation = values[counts[index] % len(values)]
            counts[index] += 1
            dynamic_broadcasters[group].send_transform(message(entry, stamp, translation))
        time.sleep(0.005)
    for node in nodes.values():
        node.destroy_node()
    transport.shutdown()


if __name__ == '__main__':
    main()
