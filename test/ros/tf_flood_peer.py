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
A test peer that floods ``/tf`` and ``/tf_static`` with bad samples, until SIGINT/SIGTERM.

Once a subscriber matched, it sends ``--count`` rounds at once, each: a TFMessage of invalid
transforms (NaN quaternion, empty frame_id, frame its own parent) on both topics and, with
``--garbage``, undecodable CDR bytes on ``/tf`` (published as serialised bytes, which both
worlds' publishers take). It prints ``flooded <rounds>``, then sends one such round and a valid
``world`` -> ``good`` transform (x = 7) every 0.1 s.
"""

from __future__ import annotations

import argparse
import signal
import struct
import sys
import time
from typing import Any

from tf_demo import transport
from tf_demo.nodes.helpers import make_transform_stamped
from tf_demo.transport.messages import tf2_msgs
from tf_demo.transport.qos import DurabilityPolicy
from tf_demo.transport.qos import QoSProfile
from tf_demo.transport.qos import ReliabilityPolicy

NAN = float('nan')
#: A TFMessage whose sequence claims 2**31 transforms in 12 bytes.
GARBAGE = b'\x00\x01\x00\x00' + struct.pack('<I', 2**31) + bytes(8)
#: Rounds between two short pauses of the flood (lets the listener's reader keep up).
ROUNDS_PER_PAUSE = 50


def _say(text: str) -> None:
    sys.stdout.write(text + '\n')
    sys.stdout.flush()


def _bad(stamp_ns: int) -> Any:
    return tf2_msgs.TFMessage(
        transforms=[
            make_transform_stamped('world', 'nan_q', stamp_ns, (0, 0, 0), (NAN, 0, 0, 1)),
            make_transform_stamped('', 'no_parent', stamp_ns, (0, 0, 0), (0, 0, 0, 1)),
            make_transform_stamped('loop', 'loop', stamp_ns, (0, 0, 0), (0, 0, 0, 1)),
        ]
    )


def main() -> int:
    """Run the flood; see the module docstring."""
    parser = argparse.ArgumentParser()
    parser.add_argument('--count', type=int, default=3000)
    parser.add_argument('--garbage', action='store_true')
    args = parser.parse_args()
    stop: list[int] = []
    signal.signal(signal.SIGTERM, lambda *_: stop.append(1))
    signal.signal(signal.SIGINT, lambda *_: stop.append(1))
    transport.init(args=['tf_flood_peer'])
    node = transport.create_node('tf_flood_peer')
    reliable = ReliabilityPolicy.RELIABLE
    tf = node.create_publisher(
        tf2_msgs.TFMessage, '/tf', QoSProfile(depth=100, reliability=reliable)
    )
    tf_static = node.create_publisher(
        tf2_msgs.TFMessage,
        '/tf_static',
        QoSProfile(depth=1, reliability=reliable, durability=DurabilityPolicy.TRANSIENT_LOCAL),
    )
    while not stop and min(tf.get_subscription_count(), tf_static.get_subscription_count()) < 1:
        time.sleep(0.01)

    def one_round() -> None:
        bad = _bad(time.time_ns())
        tf.publish(bad)
        tf_static.publish(bad)
        if args.garbage:
            tf.publish(GARBAGE)

    for index in range(args.count):
        if stop:
            break
        one_round()
        if index % ROUNDS_PER_PAUSE == ROUNDS_PER_PAUSE - 1:
            time.sleep(0.01)
    _say(f'flooded {args.count}')
    while not stop:
        try:
            one_round()
            tf.publish(
                tf2_msgs.TFMessage(
                    transforms=[
                        make_transform_stamped(
                            'world', 'good', time.time_ns(), (7, 0, 0), (0, 0, 0, 1)
                        )
                    ]
                )
            )
        except Exception:
            # Under rclpy, Ctrl-C shuts the context down from rclpy's signal handler, so a
            # publish can fail before Python has even run this script's handler.
            if stop or not transport.ok():
                break
            raise
        time.sleep(0.1)
    node.destroy_node()
    transport.try_shutdown()
    return 0


if __name__ == '__main__':
    sys.exit(main())
