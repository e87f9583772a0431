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
``dynamic_tf_pub``: odom -> base_link moving on a circle, published on ``/tf`` at 20 Hz.

With ``t`` the seconds of the stamp used: x = r·cos(t), y = r·sin(t), z = 0 and rotation
(0, 0, sin(t/2), cos(t/2)) (a yaw of ``t``). Parameters: ``radius`` (1.0; may be set while
running, e.g. ``ros2 param set /dynamic_tf_pub radius 2.0``), ``rate`` (20.0 Hz), ``parent_frame``
(``odom``), ``child_frame`` (``base_link``).
"""

from __future__ import annotations

import math
import sys
from typing import TYPE_CHECKING

from tf_demo.core.math3d import Quat
from tf_demo.core.math3d import Vec3
from tf_demo.nodes.helpers import as_float
from tf_demo.nodes.helpers import as_frame
from tf_demo.nodes.helpers import as_rate_hz
from tf_demo.nodes.helpers import declare_checked
from tf_demo.nodes.helpers import make_transform_stamped
from tf_demo.nodes.helpers import now_ns
from tf_demo.nodes.helpers import require_distinct_frames
from tf_demo.ros.transform_broadcaster import TransformBroadcaster
from tf_demo.transport import NodeConfigError
from tf_demo.transport import run_node
from tf_demo.transport.node import Node

if TYPE_CHECKING:
    from tf_demo.transport.parameters import Parameter
    from tf_demo.transport.parameters import SetParametersResult

NODE_NAME = 'dynamic_tf_pub'


def circle_transform(radius: float, stamp_ns: int) -> tuple[Vec3, Quat]:
    """Return odom_T_base_link at a stamp: position on the circle and yaw ``t``."""
    t = stamp_ns / 1e9
    return (
        (radius * math.cos(t), radius * math.sin(t), 0.0),
        (0.0, 0.0, math.sin(t / 2.0), math.cos(t / 2.0)),
    )


class DynamicTfPublisher(Node):
    """Publishes the moving odom -> base_link transform on a timer."""

    def __init__(self) -> None:
        """Read the parameters and start the timer."""
        super().__init__(NODE_NAME)
        self.radius = declare_checked(self, 'radius', 1.0, as_float)
        self.rate = declare_checked(self, 'rate', 20.0, as_rate_hz)
        self.parent_frame = declare_checked(self, 'parent_frame', 'odom', as_frame)
        self.child_frame = declare_checked(self, 'child_frame', 'base_link', as_frame)
        require_distinct_frames(self.parent_frame, self.child_frame)
        self.broadcaster = TransformBroadcaster(self)
        self.timer = self.create_timer(1.0 / self.rate, self.publish_once)
        self.add_on_set_parameters_callback(self._check_radius)
        self.add_post_set_parameters_callback(self._take_radius)
        self.get_logger().info(
            f'Publishing {self.parent_frame} -> {self.child_frame} on a circle of radius '
            f'{self.radius:g} m at {self.rate:g} Hz'
        )

    def _check_radius(self, parameters: list[Parameter]) -> SetParametersResult:
        """Accept a new ``radius`` only when it is a finite number (as at start-up)."""
        from tf_demo.transport.parameters import SetParametersResult

        for parameter in parameters:
            if parameter.name == 'radius':
                try:
                    as_float('radius', parameter.value)
                except NodeConfigError as error:
                    return SetParametersResult(successful=False, reason=str(error))
        return SetParametersResult(successful=True)

    def _take_radius(self, parameters: list[Parameter]) -> None:
        """Use a ``radius`` that was set from the next transform on."""
        for parameter in parameters:
            if parameter.name == 'radius':
                self.radius = as_float('radius', parameter.value)

    def publish_once(self) -> None:
        """Publish the transform for the current time."""
        stamp_ns = now_ns(self)
        translation, rotation = circle_transform(self.radius, stamp_ns)
        self.broadcaster.send_transform(
            make_transform_stamped(
                self.parent_frame, self.child_frame, stamp_ns, translation, rotation
            )
        )


def main(args: list[str] | None = None) -> int:
    """Run the node until Ctrl-C; exit 1 with a one-line error on bad parameters."""
    return run_node(DynamicTfPublisher, args)


if __name__ == '__main__':
    sys.exit(main())
