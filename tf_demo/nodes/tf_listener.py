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
``tf_listener``: look up target_frame <- source_frame periodically and log the translation.

Parameters: ``target_frame`` (``odom``), ``source_frame`` (``camera_link``), ``period``
(1.0 s). When the lookup fails it warns ``Could not transform <target> to <source>: <reason>``,
as the course's listener does, and keeps going.
"""

from __future__ import annotations

import sys
from typing import TYPE_CHECKING

from tf_demo.core.exceptions import TransformException
from tf_demo.msgs.convert import transform_stamped_args
from tf_demo.nodes.helpers import as_frame
from tf_demo.nodes.helpers import as_period_s
from tf_demo.nodes.helpers import declare_checked
from tf_demo.ros.buffer import Buffer
from tf_demo.ros.transform_listener import TransformListener
from tf_demo.transport import run_node
from tf_demo.transport.clock import Time
from tf_demo.transport.node import Node

if TYPE_CHECKING:
    from tf_demo.msgs.convert import TransformStampedLike

NODE_NAME = 'tf_listener'


def format_translation(target: str, source: str, transform: TransformStampedLike) -> str:
    """Log line for a successful lookup: the pose of ``source`` in ``target``."""
    _, _, stamp_ns, (x, y, z), _ = transform_stamped_args(transform)
    return (
        f'Transform {target} <- {source} at {stamp_ns / 1e9:.6f}: '
        f'translation x={x:.3f}, y={y:.3f}, z={z:.3f}'
    )


def format_failure(target: str, source: str, reason: object) -> str:
    """Warning line for a failed lookup (the course's wording)."""
    return f'Could not transform {target} to {source}: {reason}'


class TfListenerNode(Node):
    """Periodically looks up one transform with a buffer filled by a listener."""

    def __init__(self) -> None:
        """Read the parameters, subscribe to TF and start the timer."""
        super().__init__(NODE_NAME)
        self.target_frame = declare_checked(self, 'target_frame', 'odom', as_frame)
        self.source_frame = declare_checked(self, 'source_frame', 'camera_link', as_frame)
        period = declare_checked(self, 'period', 1.0, as_period_s)
        self.tf_buffer = Buffer(node=self)
        self.tf_listener = TransformListener(self.tf_buffer, self)
        self.timer = self.create_timer(period, self.on_timer)

    def on_timer(self) -> None:
        """Look up the latest transform and log it, or warn why it is not available."""
        try:
            transform = self.tf_buffer.lookup_transform(
                self.target_frame, self.source_frame, Time()
            )
        except TransformException as error:
            self.get_logger().warning(format_failure(self.target_frame, self.source_frame, error))
            return
        self.get_logger().info(format_translation(self.target_frame, self.source_frame, transform))


def main(args: list[str] | None = None) -> int:
    """Run the node until Ctrl-C; exit 1 with a one-line error on bad parameters."""
    return run_node(TfListenerNode, args)


if __name__ == '__main__':
    sys.exit(main())
