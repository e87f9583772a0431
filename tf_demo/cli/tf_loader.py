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
``tf_loader FILE [--check]``: validate a tf snapshot and republish it as static transforms.

The whole file is validated first (:func:`tf_demo.cli._snapshot.read_snapshot`: schema version,
types, finite numbers, unit quaternions, no self-parent, duplicate child or loop, size limits);
a bad file is refused with a message naming the line and the problem, exit code 1, and nothing
is published. A valid file is published in one latched ``/tf_static`` message (stamped now) and
the tool keeps serving it to late listeners until stopped. ``--check`` only validates.
"""

from __future__ import annotations

import argparse
import sys

from tf_demo.cli._live import print_error
from tf_demo.cli._live import run_tool
from tf_demo.cli._snapshot import read_snapshot
from tf_demo.cli._snapshot import Snapshot
from tf_demo.cli._snapshot import SnapshotError
from tf_demo.transport.ros_args import split_ros_args

TOOL = 'tf_loader'


def build_parser() -> argparse.ArgumentParser:
    """Return tf_loader's argument parser."""
    parser = argparse.ArgumentParser(
        prog=TOOL, description='Validate a tf snapshot and republish it as static transforms.'
    )
    parser.add_argument('file', help='snapshot written by tf_saver')
    parser.add_argument('--check', action='store_true', help='only validate the file')
    return parser


def _publish(snapshot: Snapshot, source: str) -> int:
    from tf_demo import transport
    from tf_demo.msgs.convert import fill_transform_stamped
    from tf_demo.ros import StaticTransformBroadcaster
    from tf_demo.transport.messages import geometry_msgs

    node = transport.create_node(TOOL)
    try:
        stamp_ns = node.get_clock().now().nanoseconds
        messages = []
        for entry in snapshot.transforms:
            message = geometry_msgs.TransformStamped()
            fill_transform_stamped(
                message, entry.parent, entry.child, stamp_ns, entry.translation, entry.rotation
            )
            messages.append(message)
        broadcaster = StaticTransformBroadcaster(node)
        if messages:
            broadcaster.send_transform(messages)
        node.get_logger().info(
            f'Publishing {len(messages)} static transforms from {source} until stopped'
        )
        transport.spin(node)
        return 0
    finally:
        node.destroy_node()


def main(args: list[str] | None = None) -> int:
    """Run tf_loader with ``args`` (default: ``sys.argv[1:]``)."""
    tool_args, ros_args = split_ros_args(sys.argv[1:] if args is None else args)
    options = build_parser().parse_args(tool_args)
    try:
        snapshot = read_snapshot(options.file)
    except SnapshotError as error:
        print_error(TOOL, str(error))
        return 1
    if options.check:
        print(f'{options.file}: valid, {len(snapshot.transforms)} transforms', flush=True)
        return 0
    return run_tool(TOOL, ros_args, lambda: _publish(snapshot, options.file))


if __name__ == '__main__':
    sys.exit(main())
