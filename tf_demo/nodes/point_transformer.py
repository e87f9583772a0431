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
``point_transformer``: express a point 1 m ahead of base_link in map, each period, and log it.

Parameters: ``source_frame`` (``base_link``), ``target_frame`` (``map``), ``point``
([1.0, 0.0, 0.0]) and ``period`` (1.0 s). The point is stamped 0 (latest available transform)
and transformed with :meth:`tf_demo.ros.Buffer.transform`.
"""

from __future__ import annotations

import sys
from typing import TYPE_CHECKING

from tf_demo.core.exceptions import TransformException
from tf_demo.nodes.helpers import as_frame
from tf_demo.nodes.helpers import as_period_s
from tf_demo.nodes.helpers import as_vector3
from tf_demo.nodes.helpers import declare_checked
from tf_demo.ros.buffer import Buffer
from tf_demo.ros.transform_listener import TransformListener
from tf_demo.transport import run_node
from tf_demo.transport.node import Node

if TYPE_CHECKING:
    from tf_demo.msgs.geometry_msgs import PointStamped

NODE_NAME = 'point_transformer'


def format_point(source: str, target: str, point_in: PointStamped, point_out: PointStamped) -> str:
    """Log line: the point in the source frame and in the target frame."""
    a, b = point_in.point, point_out.point
    return (
        f'Point ({a.x:.3f}, {a.y:.3f}, {a.z:.3f}) in {source} is '
        f'({b.x:.3f}, {b.y:.3f}, {b.z:.3f}) in {target}'
    )


class PointTransformer(Node):
    """Transforms one point into another frame on a timer."""

    def __init__(self) -> None:
        """Read the parameters, subscribe to TF and start the timer."""
        super().__init__(NODE_NAME)
        from tf_demo.transport.messages import geometry_msgs

        self.source_frame = declare_checked(self, 'source_frame', 'base_link', as_frame)
        self.target_frame = declare_checked(self, 'target_frame', 'map', as_frame)
        x, y, z = declare_checked(self, 'point', [1.0, 0.0, 0.0], as_vector3)
        period = declare_checked(self, 'period', 1.0, as_period_s)
        self.point = geometry_msgs.PointStamped()
        self.point.header.frame_id = self.source_frame
        self.point.point.x, self.point.point.y, self.point.point.z = x, y, z
        self.tf_buffer = Buffer(node=self)
        self.tf_listener = TransformListener(self.tf_buffer, self)
        self.timer = self.create_timer(period, self.on_timer)

    def on_timer(self) -> None:
        """Transform the point with the latest transform and log the result."""
        try:
            out = self.tf_buffer.transform(self.point, self.target_frame)
        except TransformException as error:
            self.get_logger().warning(
                f'Could not transform {self.source_frame} to {self.target_frame}: {error}'
            )
            return
        self.get_logger().info(format_point(self.source_frame, self.target_frame, self.point, out))


def main(args: list[str] | None = None) -> int:
    """Run the node until Ctrl-C; exit 1 with a one-line error on bad parameters."""
    return run_node(PointTransformer, args)


if __name__ == '__main__':
    sys.exit(main())
