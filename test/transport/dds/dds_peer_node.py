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
A small DdsNode program the transport tests run as a separate process.

``pub``: publish TFMessages (one transform; child frame ``<frame>``, translation x = sequence
number) from a timer, after ``--wait-subs`` subscriptions matched; then hold for ``--hold`` s.
With ``--burst`` all messages are published at once and the process shuts down immediately.
``sub``: print ``msg <child> <x> <parent> <y> <z> <qx> <qy> <qz> <qw>`` per received transform
and ``done <n>`` at the end (after ``--count`` transforms or ``--timeout`` s). Both print
``ready`` once set up.
"""

from __future__ import annotations

import argparse
import sys
import time

from tf_demo.msgs import geometry_msgs
from tf_demo.msgs import tf2_msgs
from tf_demo.transport import dds_backend
from tf_demo.transport.clock import Duration
from tf_demo.transport.qos import DurabilityPolicy
from tf_demo.transport.qos import HistoryPolicy
from tf_demo.transport.qos import QoSProfile
from tf_demo.transport.qos import ReliabilityPolicy


def _profile(args: argparse.Namespace) -> QoSProfile:
    return QoSProfile(
        history=HistoryPolicy.KEEP_ALL if args.keep_all else HistoryPolicy.KEEP_LAST,
        depth=args.depth,
        reliability=ReliabilityPolicy[args.reliability.upper()],
        durability=DurabilityPolicy[args.durability.upper()],
    )


def _say(text: str) -> None:
    sys.stdout.write(text + '\n')
    sys.stdout.flush()


def _message(frame: str, index: int) -> tf2_msgs.TFMessage:
    transform = geometry_msgs.TransformStamped()
    transform.header.frame_id = 'world'
    transform.child_frame_id = frame
    transform.transform.translation.x = float(index)
    transform.transform.rotation.w = 1.0
    return tf2_msgs.TFMessage(transforms=[transform])


def _publish(node: dds_backend.DdsNode, args: argparse.Namespace) -> int:
    publisher = node.create_publisher(tf2_msgs.TFMessage, args.topic, _profile(args))
    deadline = time.monotonic() + args.timeout
    while publisher.get_subscription_count() < args.wait_subs:
        if time.monotonic() > deadline:
            _say('no subscription')
            return 1
        time.sleep(0.01)
    _say('ready')
    sent = 0
    if args.burst:
        # Publish everything at once and shut down at once: only the shutdown flush can
        # get the tail of the burst to the subscribers.
        for index in range(args.count):
            publisher.publish(_message(args.frame, index))
        _say(f'sent {args.count}')
        return 0

    def tick() -> None:
        nonlocal sent
        if sent >= args.count:
            return
        publisher.publish(_message(args.frame, sent))
        sent += 1

    node.create_timer(1.0 / args.rate, tick)
    end = None
    while dds_backend.ok():
        dds_backend.spin_once(node, timeout_sec=0.05)
        if sent >= args.count and end is None:
            publisher.wait_for_all_acked(Duration(seconds=5.0))
            end = time.monotonic() + args.hold
            _say(f'sent {sent}')
        if end is not None and time.monotonic() >= end:
            break
    return 0


def _subscribe(node: dds_backend.DdsNode, args: argparse.Namespace) -> int:
    received = 0

    def on_message(msg: tf2_msgs.TFMessage) -> None:
        nonlocal received
        for transform in msg.transforms:
            received += 1
            translation = transform.transform.translation
            rotation = transform.transform.rotation
            _say(
                f'msg {transform.child_frame_id} {translation.x:g} {transform.header.frame_id} '
                f'{translation.y:g} {translation.z:g} '
                f'{rotation.x:g} {rotation.y:g} {rotation.z:g} {rotation.w:g}'
            )

    node.create_subscription(tf2_msgs.TFMessage, args.topic, on_message, _profile(args))
    _say('ready')
    deadline = time.monotonic() + args.timeout
    while dds_backend.ok() and received < args.count and time.monotonic() < deadline:
        dds_backend.spin_once(node, timeout_sec=0.05)
    _say(f'done {received}')
    return 0


def main() -> int:
    parser = argparse.ArgumentParser()
    parser.add_argument('mode', choices=['pub', 'sub'])
    parser.add_argument('--name', default='peer')
    parser.add_argument('--topic', default='/tf')
    parser.add_argument('--frame', default='child')
    parser.add_argument('--count', type=int, default=1)
    parser.add_argument('--rate', type=float, default=100.0)
    parser.add_argument('--depth', type=int, default=100)
    parser.add_argument('--keep-all', action='store_true')
    parser.add_argument('--reliability', default='reliable')
    parser.add_argument('--durability', default='volatile')
    parser.add_argument('--wait-subs', type=int, default=0)
    parser.add_argument('--hold', type=float, default=0.0)
    parser.add_argument('--burst', action='store_true')
    parser.add_argument('--timeout', type=float, default=20.0)
    args = parser.parse_args()
    dds_backend.init()
    node = dds_backend.DdsNode(args.name)
    try:
        return _publish(node, args) if args.mode == 'pub' else _subscribe(node, args)
    finally:
        dds_backend.shutdown()


if __name__ == '__main__':
    sys.exit(main())
