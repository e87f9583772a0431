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
``tf_echo source_frame target_frame [echo_rate]``: print a transform as tf2_echo does.

The output is the pose of ``target_frame`` expressed in ``source_frame`` (``lookupTransform(
source_frame, target_frame, latest)``), printed at ``echo_rate`` Hz (default 1) in tf2_echo's
exact block. While the transform is unavailable it logs ``Waiting for transform A ->  B: <why>``
at most once per second; a later failure prints tf2_echo's failure block with the frame list and
keeps going. Exit codes as upstream: 1 for a wrong argument count (usage on stdout), 2 for a rate
that is not a number, 3 for a number with trailing characters.

Additions, off by default: ``-p/--precision N`` (decimals), ``--limit N`` (exit 0 after N
blocks) and ``--json`` (one JSON object per line). ``--ros-args`` is accepted.

``--bag PATH`` echoes a rosbag2 recording instead of listening (the ``bag`` extra; no ROS): the
same blocks at bag times from the recording's start to its end, ``echo_rate`` blocks per second of
bag time, each the transform at that instant (interpolated as tf2 does); before the data arrives,
tf2_echo's failure block with tf2's error. ``--at T`` prints one block, at ``T`` seconds from
the bag's start (or at absolute time ``T`` when ``T`` is a time inside the recording).
"""

from __future__ import annotations

import sys
import time

from tf_demo.cli._args import EchoArgs
from tf_demo.cli._args import namespace_ros_args
from tf_demo.cli._args import parse_echo_args
from tf_demo.cli._live import finish_after_damage
from tf_demo.cli._live import run_tool
from tf_demo.cli.formatting import ECHO_EXTRAS_USAGE
from tf_demo.cli.formatting import ECHO_USAGE
from tf_demo.cli.formatting import format_echo_failure
from tf_demo.cli.formatting import format_echo_failure_json
from tf_demo.cli.formatting import format_echo_json
from tf_demo.cli.formatting import format_echo_transform
from tf_demo.cli.formatting import format_echo_waiting
from tf_demo.core.math3d import Quat
from tf_demo.core.math3d import Vec3
from tf_demo.msgs.convert import TransformStampedLike
from tf_demo.transport.ros_args import split_ros_args

TOOL = 'tf2_echo'
WAITING_LOG_PERIOD_S = 1.0


def _write(text: str) -> None:
    sys.stdout.write(text)
    sys.stdout.flush()


def _print_transform(options: EchoArgs, transform: TransformStampedLike) -> None:
    stamp = transform.header.stamp
    t = transform.transform.translation
    q = transform.transform.rotation
    translation = (float(t.x), float(t.y), float(t.z))
    rotation = (float(q.x), float(q.y), float(q.z), float(q.w))
    _print_block(options, int(stamp.sec), int(stamp.nanosec), translation, rotation)


def _print_block(
    options: EchoArgs, sec: int, nanosec: int, translation: Vec3, rotation: Quat
) -> None:
    """Print one transform as tf2_echo's block (or one JSON line with ``--json``)."""
    if options.json:
        _write(
            format_echo_json(
                options.source_frame, options.target_frame, sec, nanosec, translation, rotation
            )
        )
    else:
        _write(format_echo_transform(sec, nanosec, translation, rotation, options.precision))


def _echo(options: EchoArgs) -> int:
    from tf_demo import transport
    from tf_demo.core.exceptions import TransformException
    from tf_demo.ros import Buffer
    from tf_demo.ros import TransformListener
    from tf_demo.transport.clock import Time

    node = transport.create_node(TOOL)
    clock = node.get_clock()
    buffer = Buffer(node=node)
    listener = TransformListener(buffer, node, spin_thread=True)
    period = 1.0 / options.rate_hz
    try:
        last_log = -WAITING_LOG_PERIOD_S
        while transport.ok():
            ready, reason = buffer.can_transform_core(
                options.source_frame, options.target_frame, Time()
            )
            if ready:
                break
            if time.monotonic() - last_log >= WAITING_LOG_PERIOD_S:
                last_log = time.monotonic()
                node.get_logger().info(
                    format_echo_waiting(options.source_frame, options.target_frame, reason)
                )
            time.sleep(period)
        printed = 0
        while transport.ok():
            try:
                transform = buffer.lookup_transform(
                    options.source_frame, options.target_frame, Time()
                )
            except TransformException as error:
                now_s = clock.now().nanoseconds / 1e9
                if options.json:
                    _write(format_echo_failure_json(now_s, str(error), buffer.frame_ids()))
                else:
                    _write(format_echo_failure(now_s, str(error), buffer.all_frames_as_string()))
            else:
                _print_transform(options, transform)
                printed += 1
                if options.limit is not None and printed >= options.limit:
                    return 0
            time.sleep(period)
    finally:
        listener.unregister()
        node.destroy_node()
    return 0


def _bag_instants(options: EchoArgs, start_ns: int, end_ns: int) -> range:
    """Return the bag times to echo: ``--at`` (relative or absolute), else every 1/rate."""
    if options.at_s is not None:
        at_ns = round(options.at_s * 1e9)
        instant = at_ns if start_ns <= at_ns <= end_ns else start_ns + at_ns
        return range(instant, instant + 1)
    return range(start_ns, end_ns + 1, max(1, round(1e9 / options.rate_hz)))


def _echo_bag(options: EchoArgs) -> int:
    from tf_demo.bag import BagError
    from tf_demo.bag import load_bag
    from tf_demo.core.exceptions import TransformException

    assert options.bag is not None
    try:
        loaded = load_bag(options.bag)
    except BagError as error:
        print(f'{TOOL}: {error}', file=sys.stderr, flush=True)
        return 1
    core, start_ns, end_ns = loaded.core, loaded.start_ns, loaded.end_ns
    printed = 0
    for instant in _bag_instants(options, start_ns, end_ns):
        try:
            result = core.lookup_transform(options.source_frame, options.target_frame, instant)
        except TransformException as error:
            now_s = instant / 1e9
            if options.json:
                _write(format_echo_failure_json(now_s, str(error), core.frame_ids()))
            else:
                _write(format_echo_failure(now_s, str(error), core.all_frames_as_string()))
            continue
        sec, nanosec = divmod(result.stamp_ns, 1_000_000_000)
        _print_block(options, sec, nanosec, result.translation, result.rotation)
        printed += 1
        if options.limit is not None and printed >= options.limit:
            break
    return finish_after_damage(TOOL, 0, loaded.damage)


def main(args: list[str] | None = None) -> int:
    """Run tf_echo with ``args`` (default: ``sys.argv[1:]``)."""
    tool_args, ros_args = split_ros_args(sys.argv[1:] if args is None else args)
    options = parse_echo_args(tool_args)
    if options.show_usage:
        # A wrong count gets upstream's usage only (stderr stays empty, as tf2_echo's); --help
        # adds tf_demo's flags.
        _write(ECHO_USAGE + (ECHO_EXTRAS_USAGE if options.show_help else ''))
        return options.exit_code
    if options.error:
        print(options.error, file=sys.stderr, flush=True)
        return options.exit_code
    if options.bag is not None:
        return _echo_bag(options)
    if options.namespace is not None:
        try:
            ros_args = [*ros_args, *namespace_ros_args(options.namespace)]
        except ValueError as error:
            print(error, file=sys.stderr, flush=True)
            return 2
    return run_tool(TOOL, ros_args, lambda: _echo(options))


if __name__ == '__main__':
    sys.exit(main())
