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
Start-up: from ``exec`` of ``static_tf_pub`` to its first /tf_static sample at a running listener.

A listener process of the same world subscribes to ``/tf_static`` (tf2's static listener QoS)
and prints the CLOCK_MONOTONIC time at which each new writer's first sample arrives; this process
reads the clock just before it starts ``static_tf_pub``, ``--runs`` times (default 10), and
prints the median and spread. The standalone world runs the virtual environment's console
script (target median <= 0.5 s); inside a sourced Jazzy (``--world rclpy``) the executable
``ros2 run tf_demo static_tf_pub`` would exec, and ``ros2 run`` itself as a second row.

Run: ``.venv/bin/python bench/bench_startup.py`` (standalone) or, inside a sourced Jazzy with
the overlay built, ``python bench/bench_startup.py --world rclpy``.
"""

from __future__ import annotations

import argparse
import os
from pathlib import Path
import shutil
import signal
import statistics
import subprocess
import sys
import time

sys.path.insert(0, str(Path(__file__).resolve().parent.parent))

from _flow import build_line

TIMEOUT_S = 30.0


def run_listener() -> None:
    """Print ``<monotonic ns> <stamp ns>`` for each /tf_static sample of a new stamp."""
    from tf_demo import transport
    from tf_demo.transport.messages import tf2_msgs
    from tf_demo.transport.qos import StaticListenerQoS

    transport.init(['bench_startup_listener'])
    node = transport.create_node('bench_startup_listener')
    seen: set[tuple[int, int]] = set()

    def on_sample(message: object) -> None:
        arrived = time.monotonic_ns()
        for transform in getattr(message, 'transforms', []):
            stamp = (transform.header.stamp.sec, transform.header.stamp.nanosec)
            if stamp not in seen:
                seen.add(stamp)
                print(arrived, stamp[0] * 1_000_000_000 + stamp[1], flush=True)
                return

    node.create_subscription(tf2_msgs.TFMessage, '/tf_static', on_sample, StaticListenerQoS())
    print('ready', flush=True)
    try:
        transport.spin(node)
    except (KeyboardInterrupt, Exception):  # stopped by the benchmark (SIGTERM, shutdown)
        return


def publisher_command(world: str, via_ros2_run: bool) -> list[str]:
    if world == 'dds':
        script = Path(sys.executable).parent / 'static_tf_pub'
        return [str(script)]
    if via_ros2_run:
        return ['ros2', 'run', 'tf_demo', 'static_tf_pub']
    prefix = subprocess.run(
        ['ros2', 'pkg', 'prefix', 'tf_demo'], capture_output=True, text=True, check=True
    ).stdout.strip()
    return [str(Path(prefix) / 'lib' / 'tf_demo' / 'static_tf_pub')]


def measure(env: dict[str, str], command: list[str], runs: int) -> list[float]:
    listener = subprocess.Popen(
        [sys.executable, __file__, '--role', 'listener'],
        env=env, stdout=subprocess.PIPE, text=True,
    )  # fmt: skip
    assert listener.stdout is not None
    assert listener.stdout.readline().strip() == 'ready'
    seconds: list[float] = []
    try:
        for _ in range(runs):
            wall_start = time.time_ns()
            start = time.monotonic_ns()
            publisher = subprocess.Popen(
                command,
                env=env,
                stdout=subprocess.DEVNULL,
                stderr=subprocess.DEVNULL,
                start_new_session=True,  # `ros2 run` has a child: stop the whole group
            )
            while True:  # the first sample stamped by this run's publisher (not an earlier one's)
                line = listener.stdout.readline().split()
                if not line:
                    sys.exit('the listener stopped before a sample arrived')
                if int(line[1]) >= wall_start:
                    break
            seconds.append((int(line[0]) - start) / 1e9)
            os.killpg(publisher.pid, signal.SIGTERM)
            publisher.wait(timeout=TIMEOUT_S)
            time.sleep(0.3)  # let the writer's disappearance reach the listener
    finally:
        listener.kill()  # a measuring tool: no clean shutdown needed
        listener.wait(timeout=TIMEOUT_S)
    return seconds


def report(what: str, seconds: list[float], target: float | None) -> None:
    median = statistics.median(seconds)
    verdict = (
        ''
        if target is None
        else f' (target <= {target} s) ' + ('ok' if median <= target else 'MISSED')
    )
    print(
        f'{what}: median {median:.3f} s, min {min(seconds):.3f} s, max {max(seconds):.3f} s '
        f'over {len(seconds)} runs{verdict}'
    )


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[1])
    parser.add_argument('--role', choices=('main', 'listener'), default='main')
    parser.add_argument('--world', choices=('dds', 'rclpy'), default='dds')
    parser.add_argument('--runs', type=int, default=10)
    args = parser.parse_args()
    if args.role == 'listener':
        run_listener()
        return
    env = dict(os.environ, TF_DEMO_BACKEND=args.world)
    env.setdefault('ROS_DOMAIN_ID', '229')
    env['ROS_AUTOMATIC_DISCOVERY_RANGE'] = 'LOCALHOST'
    if args.world == 'rclpy' and shutil.which('ros2') is None:
        sys.exit('--world rclpy runs inside a sourced ROS 2 Jazzy with the overlay built')
    print(f'tf_demo build: {build_line()}')
    print(f'start-up of static_tf_pub, {args.world} world (domain {env["ROS_DOMAIN_ID"]})')
    command = publisher_command(args.world, via_ros2_run=False)
    target = 0.5 if args.world == 'dds' else None
    report(
        f'exec {Path(command[0]).name} -> first /tf_static sample',
        measure(env, command, args.runs),
        target,
    )
    if args.world == 'rclpy':
        command = publisher_command(args.world, via_ros2_run=True)
        report(
            'ros2 run tf_demo static_tf_pub -> first sample',
            measure(env, command, args.runs),
            None,
        )


if __name__ == '__main__':
    main()
