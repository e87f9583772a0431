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
Benchmark of tf_relay: N robots x 30 frames at 50 Hz through one relay process.

This process publishes each robot's TFMessage (30 transforms) on ``/robot<i>/tf`` at 50 Hz and
listens both there and on the relayed ``/tf``: the added latency of a message is the time it
arrives on ``/tf`` minus the time it arrives on ``/robot<i>/tf``, both read from this process'
monotonic clock, so neither the stamps nor the publisher's own delays count. Printed: the relay's
CPU (from ``/proc``, % of one core), the median and p99 added latency, and the messages lost.
Nothing is asserted (issue 24, item 6: a benchmark, never a timed test).

Run: ``.venv/bin/python bench/bench_relay.py [--robots 10] [--seconds 10]`` (the standalone
world), or with ROS 2 sourced and tf_demo installed in the workspace (the rclpy world; the relay
is ``tf_relay`` of this interpreter's tf_demo). Uses ``ROS_DOMAIN_ID`` if set (else 232) with
loopback-only discovery.
"""

from __future__ import annotations

import argparse
import os
from pathlib import Path
import struct
import subprocess
import sys
import threading
import time

from _flow import build_line

FRAMES = 30
RATE_HZ = 50.0
TICKS_PER_S = os.sysconf('SC_CLK_TCK')
#: The stamp of a message (header of the first transform): sec, nanosec after the count.
_STAMP = struct.Struct('<iI')


def percentile(values: list[float], fraction: float) -> float:
    ordered = sorted(values)
    return (
        ordered[min(len(ordered) - 1, int(fraction * len(ordered)))] if ordered else float('nan')
    )


def process_cpu_s(pid: int) -> float:
    """CPU time (user + system) of process ``pid`` so far, from /proc."""
    fields = Path(f'/proc/{pid}/stat').read_text(encoding='ascii').rsplit(')', 1)[1].split()
    return (int(fields[11]) + int(fields[12])) / TICKS_PER_S


def robot_frames(
    robot: int,
) -> list[tuple[str, str, tuple[float, float, float], tuple[float, ...]]]:
    """A robot's 30 transforms: odom -> base_link, then a chain of links (unprefixed names)."""
    names = ['odom', 'base_link', *[f'link_{k}' for k in range(FRAMES - 1)]]
    return [
        (names[k], names[k + 1], (0.1 * robot, 0.01 * k, 0.0), (0.0, 0.0, 0.0, 1.0))
        for k in range(FRAMES)
    ]


def relay_command(robots: int) -> list[str]:
    code = 'import sys; from tf_demo.nodes.tf_relay import main; sys.exit(main())'
    return [sys.executable, '-c', code, *[f'/robot{r}' for r in range(robots)]]


def run(robots: int, seconds: float) -> None:
    from tf_demo import transport
    from tf_demo.msgs.cdr import TfMessageEncoder
    from tf_demo.transport.messages import tf2_msgs
    from tf_demo.transport.qos import DynamicBroadcasterQoS
    from tf_demo.transport.qos import DynamicListenerQoS

    os.environ.setdefault('ROS_DOMAIN_ID', '232')
    os.environ['ROS_AUTOMATIC_DISCOVERY_RANGE'] = 'LOCALHOST'
    relay = subprocess.Popen(relay_command(robots), stderr=subprocess.PIPE, text=True)
    transport.init(['bench_relay'])
    node = transport.create_node('bench_relay')
    direct: dict[bytes, int] = {}  # stamp bytes -> arrival on /robot<i>/tf (monotonic ns)
    added_ns: list[int] = []
    lock = threading.Lock()

    def on_direct(data: bytes) -> None:
        now = time.monotonic_ns()
        with lock:
            direct[data[8:16]] = now

    def on_relayed(data: bytes) -> None:
        now = time.monotonic_ns()
        with lock:
            first = direct.pop(data[8:16], None)
            if first is not None:
                added_ns.append(now - first)
            else:
                late.append(data[8:16])

    late: list[bytes] = []  # relayed before its direct copy arrived (counted, then matched)
    # The receiving side as the relay's own: an internal node served by its own thread (rcl's
    # wait set under rclpy), so both copies of a message wait the same, short, way.
    inputs = transport.create_internal_node('bench_relay_inputs')
    subs = [
        inputs.create_subscription(
            tf2_msgs.TFMessage, f'/robot{r}/tf', on_direct, DynamicListenerQoS(), raw=True
        )
        for r in range(robots)
    ]
    subs.append(
        inputs.create_subscription(
            tf2_msgs.TFMessage, '/tf', on_relayed, DynamicListenerQoS(), raw=True
        )
    )
    pubs = [
        node.create_publisher(tf2_msgs.TFMessage, f'/robot{r}/tf', DynamicBroadcasterQoS())
        for r in range(robots)
    ]
    encoders = [TfMessageEncoder() for _ in range(robots)]
    frames = [robot_frames(r) for r in range(robots)]
    server = transport.SubscriptionServer(inputs, subs, 'bench_relay_inputs')
    sent = 0

    def publish(slot: int) -> None:
        """Publish robot ``slot % robots``: the robots take turns, out of phase."""
        nonlocal sent
        r = slot % robots
        base = time.time_ns() // 1000 * 1000  # robot r's stamps end in r ns: unique per message
        sec, nanosec = divmod(base + r, 1_000_000_000)
        pubs[r].publish(encoders[r].encode(frames[r], sec, nanosec))  # type: ignore[arg-type]
        sent += 1

    slot_s = 1 / (RATE_HZ * robots)
    try:
        # Warm up until every robot's messages come back relayed (discovery, first layouts).
        deadline = time.monotonic() + 60
        slot = 0
        while time.monotonic() < deadline:
            publish(slot)
            slot += 1
            time.sleep(slot_s)
            with lock:
                if len(added_ns) >= 5 * robots:
                    break
        else:
            print('the relay never relayed: is tf_demo importable by the relay process?')
            return
        time.sleep(0.5)
        with lock:
            added_ns.clear()
            direct.clear()
            late.clear()
        sent = 0
        cpu_start = process_cpu_s(relay.pid)
        wall_start = next_slot = time.monotonic()
        while time.monotonic() - wall_start < seconds:
            publish(slot)
            slot += 1
            next_slot += slot_s
            time.sleep(max(0.0, next_slot - time.monotonic()))
        wall = time.monotonic() - wall_start
        cpu = process_cpu_s(relay.pid) - cpu_start
        time.sleep(1.0)  # the last messages arrive
        with lock:
            received = len(added_ns) + len(late)
            values_us = [value / 1000 for value in added_ns]
    finally:
        server.stop()
        relay.send_signal(2)
        relay.communicate(timeout=15)
        node.destroy_node()
        transport.shutdown()
    print(
        f'tf_relay, {robots} robots x {FRAMES} frames at {RATE_HZ:g} Hz '
        f'({robots * RATE_HZ:g} msg/s, {robots * FRAMES * RATE_HZ:g} transforms/s, robots out of '
        f'phase) for {wall:.1f} s:'
    )
    print(f'  relay CPU {100 * cpu / wall:.1f} % of one core')
    print(
        f'  added latency: median {percentile(values_us, 0.5):.0f} us, '
        f'p99 {percentile(values_us, 0.99):.0f} us (target median <= 1000 us; '
        f'{len(late)} relayed before their direct copy, not timed)'
    )
    print(f'  lost: {sent - received} of {sent}')


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[1])
    parser.add_argument('--robots', type=int, default=10, help='robots (default 10)')
    parser.add_argument('--seconds', type=float, default=10.0, help='measured time (default 10)')
    options = parser.parse_args()
    if options.robots < 1 or options.seconds <= 0:
        parser.error('--robots must be at least 1 and --seconds positive')
    print(build_line())
    run(options.robots, options.seconds)


if __name__ == '__main__':
    main()
