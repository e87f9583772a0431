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
``tf_monitor [framea frameb]``: tf2_monitor's periodic report of delays and publishing rates.

As tf2_ros' tf2_monitor (Jazzy): without arguments it watches all frames, with two it first waits
for the chain from ``framea`` to ``frameb`` and reports its net delay too; other argument counts
log ``TF_Monitor: usage: tf2_monitor framea frameb`` and exit with 255 (upstream's -1). Every 0.5
s it looks the chain up; after 21 ticks it prints ``RESULTS``, the per-frame delays (now − stamp
of every received transform, the last 1000 per frame) and the per-broadcaster rate, then starts
again. Additions: ``--interval SECONDS`` (time between reports, default 10.5) and ``--limit N``
(exit 0 after N reports).
"""

from __future__ import annotations

import argparse
from collections import deque
import math
import sys
import time
from typing import TYPE_CHECKING

from tf_demo import transport
from tf_demo.cli._args import count_argument
from tf_demo.cli._args import namespace_ros_args
from tf_demo.cli._live import add_namespace_option
from tf_demo.cli._live import finish_after_damage
from tf_demo.cli._live import log_unnamed
from tf_demo.cli._live import print_error
from tf_demo.cli._live import run_tool
from tf_demo.cli._live import TfRecorder
from tf_demo.cli._observations import add_observation
from tf_demo.cli._observations import Observation
from tf_demo.cli._observations import observations_from_bag
from tf_demo.cli._observations import quiet_log
from tf_demo.cli.formatting import format_echo_waiting
from tf_demo.cli.formatting import format_monitor_broadcasters
from tf_demo.cli.formatting import format_monitor_frames
from tf_demo.cli.formatting import format_monitor_header
from tf_demo.core.buffer_core import BufferCore
from tf_demo.core.exceptions import TransformException
from tf_demo.transport.ros_args import split_ros_args

if TYPE_CHECKING:
    from tf_demo.transport.node import Node

TOOL = 'tf2_monitor'
NO_AUTHORITY = '<no authority available>'
HISTORY = 1000
TICK_S = 0.5
TICKS_PER_REPORT = 21


class DelayStats:
    """Per-frame and per-broadcaster delay and arrival histories, as tf2_monitor keeps them."""

    def __init__(self) -> None:
        self.frame_delays: dict[str, deque[float]] = {}
        self.frame_authority: dict[str, str] = {}
        self.authority_delays: dict[str, deque[float]] = {}
        self.authority_arrivals: dict[str, deque[float]] = {}

    def add(self, observation: Observation, now_s: float) -> None:
        """Record one message received at ``now_s``."""
        authority = NO_AUTHORITY
        total = 0.0
        for t in observation.transforms:
            offset = now_s - t.stamp_ns / 1e9
            total += offset
            self.frame_authority[t.child] = authority
            self.frame_delays.setdefault(t.child, deque(maxlen=HISTORY)).append(offset)
        average = total / max(1, len(observation.transforms))
        self.authority_delays.setdefault(authority, deque(maxlen=HISTORY)).append(average)
        self.authority_arrivals.setdefault(authority, deque(maxlen=HISTORY)).append(now_s)


def _print_report(
    frames: list[str], chain: list[str] | None, avg_diff: float, max_diff: float, stats: DelayStats
) -> None:
    """Print one report: RESULTS and frames on stdout, the broadcaster title on stderr."""
    framea, frameb = frames if frames else (None, None)
    sys.stdout.write(format_monitor_header(framea, frameb, chain, avg_diff, max_diff))
    sys.stdout.write(format_monitor_frames(stats.frame_delays, stats.frame_authority, chain))
    sys.stdout.flush()
    sys.stderr.write('\nAll Broadcasters:\n')
    sys.stderr.flush()
    sys.stdout.write(format_monitor_broadcasters(stats.authority_delays, stats.authority_arrivals))
    sys.stdout.flush()


def _spin_for(node: Node, seconds: float) -> None:
    deadline = time.monotonic() + seconds
    while transport.ok():
        remaining = deadline - time.monotonic()
        if remaining <= 0:
            return
        transport.spin_once(node, timeout_sec=remaining)


def _monitor(options: argparse.Namespace) -> int:
    node = transport.create_node('tf2_monitor_main')
    clock = node.get_clock()
    stats = DelayStats()
    core = BufferCore(log=quiet_log)

    def on_message(observation: Observation) -> None:
        stats.add(observation, observation.receive_ns / 1e9)
        add_observation(core, observation)

    try:
        TfRecorder(node, on_message=on_message)
        chain: list[str] | None = None
        if options.frames:
            framea, frameb = options.frames
            last_log = -1.0
            while transport.ok():
                reason = core.transform_error(framea, frameb, 0)
                if not reason:
                    break
                if time.monotonic() - last_log >= 1.0:
                    last_log = time.monotonic()
                    node.get_logger().info(format_echo_waiting(framea, frameb, reason))
                _spin_for(node, TICK_S)
            try:
                chain = core.chain(frameb, 0, framea, 0, frameb)
            except TransformException as error:
                node.get_logger().warning(f'Transform Exception {error}')
                chain = []
            print(f'Gathering data on {framea} -> {frameb} for 10 seconds...', flush=True)
        else:
            print('Gathering data on all frames for 10 seconds...', flush=True)
        avg_diff = max_diff = 0.0
        reports = 0
        ticks_per_report = max(1, round(options.interval / TICK_S))
        counter = 0
        while transport.ok():
            counter += 1
            if options.frames:
                try:
                    found = core.lookup_transform(options.frames[0], options.frames[1], 0)
                except TransformException as error:
                    node.get_logger().warning(f'Transform Exception {error}')
                else:
                    diff = clock.now().nanoseconds / 1e9 - found.stamp_ns / 1e9
                    avg_diff = 0.01 * diff + 0.99 * avg_diff
                    max_diff = max(max_diff, diff)
            _spin_for(node, TICK_S)
            if counter >= ticks_per_report:
                counter = 0
                _print_report(options.frames, chain, avg_diff, max_diff, stats)
                reports += 1
                if options.limit is not None and reports >= options.limit:
                    return 0
        return 0
    finally:
        node.destroy_node()


def _monitor_bag(options: argparse.Namespace) -> int:
    """
    tf2_monitor over a rosbag2 recording: the same reports, at the same intervals of bag time.

    Messages count as received at their bag times, so rates and delays are the recording's; a
    report is printed every ``--interval`` seconds of bag time and one at the end.
    """
    bag = observations_from_bag(options.bag)
    observations, start_ns, end_ns = bag.observations, bag.start_ns, bag.end_ns
    stats = DelayStats()
    core = BufferCore(end_ns - start_ns + 10**10, log=quiet_log)
    frames: list[str] = options.frames
    chain: list[str] | None = None
    avg_diff = max_diff = 0.0
    tick_ns = round(TICK_S * 1e9)
    report_ns = round(options.interval * 1e9)
    print(
        f'Gathering data on {frames[0]} -> {frames[1]} for 10 seconds...'
        if frames
        else 'Gathering data on all frames for 10 seconds...',
        flush=True,
    )
    reports = 0
    next_tick, next_report = start_ns + tick_ns, start_ns + report_ns

    def tick(now_ns: int) -> None:
        nonlocal avg_diff, max_diff, chain
        if not frames:
            return
        try:
            found = core.lookup_transform(frames[0], frames[1], 0)
        except TransformException:
            return
        if chain is None:
            chain = core.chain(frames[1], 0, frames[0], 0, frames[1])
        diff = now_ns / 1e9 - found.stamp_ns / 1e9
        avg_diff = 0.01 * diff + 0.99 * avg_diff
        max_diff = max(max_diff, diff)

    for observation in [*observations, None]:
        receive_ns = observation.receive_ns if observation is not None else end_ns + 1
        while next_tick <= receive_ns:
            tick(next_tick)
            if next_tick >= next_report:
                _print_report(frames, chain, avg_diff, max_diff, stats)
                reports += 1
                next_report += report_ns
                if options.limit is not None and reports >= options.limit:
                    return finish_after_damage('tf_monitor', 0, bag.damage)
            next_tick += tick_ns
        if observation is not None:
            stats.add(observation, receive_ns / 1e9)
            add_observation(core, observation)
    if next_report - report_ns < end_ns or reports == 0:  # what came after the last report
        _print_report(frames, chain, avg_diff, max_diff, stats)
    return finish_after_damage('tf_monitor', 0, bag.damage)


def build_parser() -> argparse.ArgumentParser:
    """Return tf_monitor's argument parser (upstream's two frames plus the additions)."""
    parser = argparse.ArgumentParser(prog='tf_monitor', add_help=True)
    parser.add_argument('frames', nargs='*')
    parser.add_argument('--interval', type=float, default=TICK_S * TICKS_PER_REPORT)
    parser.add_argument('--limit', type=count_argument, default=None)
    parser.add_argument(
        '--bag', metavar='PATH', help='report on a rosbag2 recording instead of listening'
    )
    add_namespace_option(parser)
    return parser


def options_error(options: argparse.Namespace) -> str | None:
    """Return why parsed ``options`` cannot run (besides the frame count), else None."""
    if not (options.interval > 0 and math.isfinite(options.interval)):
        return f'--interval must be a finite number > 0, got {options.interval}'
    return None


def main(args: list[str] | None = None) -> int:
    """Run tf_monitor with ``args`` (default: ``sys.argv[1:]``)."""
    tool_args, ros_args = split_ros_args(sys.argv[1:] if args is None else args)
    options = build_parser().parse_args(tool_args)
    if len(options.frames) not in (0, 2):
        log_unnamed('INFO', 'TF_Monitor: usage: tf2_monitor framea frameb')
        return 255
    problem = options_error(options)
    if problem is None and options.namespace is not None:
        try:
            ros_args = [*ros_args, *namespace_ros_args(options.namespace)]
        except ValueError as error:
            problem = str(error)
    if problem is not None:
        print_error('tf_monitor', problem)
        return 2
    if options.bag is not None:
        from tf_demo.bag import BagError

        try:
            return _monitor_bag(options)
        except BagError as error:
            print_error('tf_monitor', str(error))
            return 1
    return run_tool(TOOL, ros_args, lambda: _monitor(options))


if __name__ == '__main__':
    sys.exit(main())
