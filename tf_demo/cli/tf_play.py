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
``tf_play PATH [-r RATE] [--clock [HZ]] [-l] [--start-offset S] [-d S]``: play a bag's TF back.

As ``ros2 bag play`` for the TF topics of a rosbag2 recording, in either world: every ``/tf``
message is published again as recorded (its bytes, its stamps) at its bag time, scaled by
``--rate``. ``/tf_static`` is latched, as tf2's static broadcaster latches it: every static
transform is published at the start (they hold at all times) and kept for late subscribers; one
that changes during the recording is sent again when it changes. ``--clock`` publishes the
playback time on ``/clock`` (40 Hz, or HZ), so that nodes with ``use_sim_time`` follow the
recording. ``--loop`` starts again at the end. The bag is streamed: memory stays bounded
however long it is. Needs the ``bag`` extra. ``--ros-args`` is accepted.
"""

from __future__ import annotations

import argparse
from collections.abc import Iterable
from collections.abc import Iterator
from dataclasses import dataclass
import math
import sys
import time
from typing import TYPE_CHECKING

from tf_demo.cli._live import tool_main
from tf_demo.cli._live import ToolError
from tf_demo.msgs.cdr import TransformTuple

if TYPE_CHECKING:
    from tf_demo.bag.reader import BagRecord
    from tf_demo.bag.reader import TfBag
    from tf_demo.transport.node import Node

TOOL = 'tf_play'
DEFAULT_CLOCK_HZ = 40.0
#: The longest sleep between two checks for Ctrl-C.
WAIT_SLICE_S = 0.1

StaticKey = tuple[str, int, tuple[float, ...], tuple[float, ...]]


def build_parser() -> argparse.ArgumentParser:
    """Return tf_play's command line (``ros2 bag play``'s names for the same options)."""
    parser = argparse.ArgumentParser(prog=TOOL, description=__doc__.strip().splitlines()[0])
    parser.add_argument('bag', metavar='PATH', help='the rosbag2 (directory, .mcap or .db3)')
    parser.add_argument('-r', '--rate', type=float, default=1.0, help='playback speed factor')
    parser.add_argument(
        '--clock', type=float, nargs='?', const=DEFAULT_CLOCK_HZ, default=None, metavar='HZ',
        help=f'publish the playback time on /clock (default {DEFAULT_CLOCK_HZ:g} Hz)',
    )  # fmt: skip
    parser.add_argument('-l', '--loop', action='store_true', help='play again at the end')
    parser.add_argument(
        '--start-offset', type=float, default=0.0, metavar='S', help='skip the first S seconds'
    )
    parser.add_argument(
        '-d', '--delay', type=float, default=0.0, metavar='S', help='wait S seconds first'
    )
    parser.add_argument('--tf-topic', default='/tf', help='recorded topic of dynamic transforms')
    parser.add_argument(
        '--tf-static-topic', default='/tf_static', help='recorded topic of static transforms'
    )
    return parser


def options_error(options: argparse.Namespace) -> str | None:
    """Return what is wrong with the options, or None."""
    if not (math.isfinite(options.rate) and options.rate > 0):
        return f'--rate must be a positive number, got {options.rate}'
    if options.clock is not None and not (math.isfinite(options.clock) and options.clock > 0):
        return f'--clock must be a positive number of Hz, got {options.clock}'
    for name in ('start_offset', 'delay'):
        value = getattr(options, name)
        if not (math.isfinite(value) and value >= 0):
            return f'--{name.replace("_", "-")} must be zero or more seconds, got {value}'
    return None


@dataclass(frozen=True)
class Timeline:
    """Where playback stands: bag time ``first_ns`` was played at ``started`` (monotonic s)."""

    first_ns: int
    started: float
    rate: float

    def due(self, bag_time_ns: int) -> float:
        """Return the monotonic time at which ``bag_time_ns`` is played."""
        return self.started + (bag_time_ns - self.first_ns) / 1e9 / self.rate

    def bag_time(self, now: float) -> int:
        """Return the bag time being played at monotonic time ``now``."""
        return self.first_ns + round((now - self.started) * self.rate * 1e9)


def static_key(transform: TransformTuple) -> tuple[str, StaticKey]:
    """Return a static transform's child and what it says (a change is worth sending again)."""
    parent, child, stamp_ns, translation, rotation = transform
    return child, (parent, stamp_ns, tuple(translation), tuple(rotation))


def first_statics(records: Iterable[BagRecord]) -> dict[str, TransformTuple]:
    """Return each child's first recorded static transform (they hold from the bag's start)."""
    found: dict[str, TransformTuple] = {}
    for record in records:
        for transform in record.transforms:
            found.setdefault(transform[1], transform)
    return found


class Player:
    """The publishers and the clock of one playback (see the module docstring)."""

    def __init__(self, node: Node, options: argparse.Namespace) -> None:
        from tf_demo.ros import StaticTransformBroadcaster
        from tf_demo.transport.messages import rosgraph_msgs
        from tf_demo.transport.messages import tf2_msgs
        from tf_demo.transport.qos import DynamicBroadcasterQoS
        from tf_demo.transport.qos import QoSProfile
        from tf_demo.transport.qos import ReliabilityPolicy

        self.options = options
        self.tf = node.create_publisher(tf2_msgs.TFMessage, '/tf', DynamicBroadcasterQoS())
        self.statics = StaticTransformBroadcaster(node)
        self.sent_statics: dict[str, StaticKey] = {}
        self.clock = None
        self.clock_message = rosgraph_msgs.Clock
        if options.clock is not None:  # rclcpp's ClockQoS, as rosbag2's player
            qos = QoSProfile(depth=1, reliability=ReliabilityPolicy.BEST_EFFORT)
            self.clock = node.create_publisher(rosgraph_msgs.Clock, '/clock', qos)
        self.next_tick = 0.0
        self.published = 0

    def send_statics(self, transforms: Iterable[TransformTuple]) -> None:
        """Send the static transforms that are new or changed (the broadcaster latches all)."""
        from tf_demo.nodes.helpers import make_transform_stamped

        changed = []
        for transform in transforms:
            child, key = static_key(transform)
            if self.sent_statics.get(child) != key:
                self.sent_statics[child] = key
                changed.append(make_transform_stamped(*transform))
        if changed:
            self.statics.send_transform(changed)

    def wait_until(self, deadline: float, timeline: Timeline | None) -> bool:
        """
        Sleep until ``deadline``, ticking /clock with ``timeline``'s bag time (if any).

        :returns: False when the process is stopping.
        """
        from tf_demo import transport

        while transport.ok():
            now = time.monotonic()
            ticking = self.clock is not None and timeline is not None
            if timeline is not None and ticking and now >= self.next_tick:
                self.tick(timeline.bag_time(now))
                self.next_tick = now + 1.0 / self.options.clock
            if now >= deadline:
                return True
            wake = min(deadline, self.next_tick) if ticking else deadline
            time.sleep(min(WAIT_SLICE_S, max(0.0, wake - now)))
        return False

    def tick(self, bag_time_ns: int) -> None:
        """Publish ``bag_time_ns`` on /clock."""
        if self.clock is None:
            return
        message = self.clock_message()
        message.clock.sec, message.clock.nanosec = divmod(bag_time_ns, 1_000_000_000)
        self.clock.publish(message)


def play_once(player: Player, bag: TfBag) -> bool:
    """Play the bag through once; False when stopped early."""
    options = player.options
    first_ns = bag.start_ns + round(options.start_offset * 1e9)
    timeline = Timeline(first_ns, time.monotonic(), options.rate)
    for record in _records(bag):
        if record.is_static:
            player.send_statics(record.transforms)
            continue
        if record.bag_time_ns < first_ns:
            continue
        if not player.wait_until(timeline.due(record.bag_time_ns), timeline):
            return False
        player.tf.publish(record.data)
        player.published += 1
    return True


def _records(bag: TfBag) -> Iterator[BagRecord]:
    """Yield the bag's records; a damaged bag ends playback with its one-line error."""
    from tf_demo.bag import BagError

    try:
        yield from bag.records()
    except BagError as error:
        raise ToolError(str(error)) from None


def _play(options: argparse.Namespace) -> int:
    from tf_demo import transport
    from tf_demo.bag import BagError
    from tf_demo.bag import open_tf_bag

    try:
        bag = open_tf_bag(options.bag, options.tf_topic, options.tf_static_topic)
    except BagError as error:
        raise ToolError(str(error)) from None
    node = transport.create_node(TOOL)
    try:
        with bag:
            try:
                statics = first_statics(bag.records(statics_only=True))
            except BagError:
                statics = {}  # the main pass stops at the damage and says where
            player = Player(node, options)
            player.send_statics(statics.values())
            span_s = (bag.end_ns - bag.start_ns) / 1e9
            print(
                f'{TOOL}: playing {bag.path} ({span_s:.3f} s; {", ".join(bag.topics)}) '
                f'at rate {options.rate:g}' + (' on a loop' if options.loop else ''),
                flush=True,
            )
            if not player.wait_until(time.monotonic() + options.delay, None):
                return 0
            while play_once(player, bag) and options.loop:
                pass
            print(f'{TOOL}: done, {player.published} /tf messages published', flush=True)
    finally:
        node.destroy_node()
    return 0


def main(args: list[str] | None = None) -> int:
    """Run tf_play with ``args`` (default: ``sys.argv[1:]``)."""
    return tool_main(TOOL, args, build_parser(), options_error, _play)


if __name__ == '__main__':
    sys.exit(main())
