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
``frame_broadcaster``: base_link -> camera_link (0.1, 0.2, 0.3) every 0.5 s, stamped now.

Unlike ``static_tf_pub`` this publishes on ``/tf`` (a dynamic transform re-sent periodically), as
the course's frame broadcaster does. Parameters: ``parent_frame``, ``child_frame``,
``translation``, ``rotation`` ([roll, pitch, yaw] or [x, y, z, w]) and ``period`` (0.5 s).
"""

from __future__ import annotations

import sys

from tf_demo.nodes.helpers import as_frame
from tf_demo.nodes.helpers import as_period_s
from tf_demo.nodes.helpers import as_vector3
from tf_demo.nodes.helpers import declare_checked
from tf_demo.nodes.helpers import make_transform_stamped
from tf_demo.nodes.helpers import now_ns
from tf_demo.nodes.helpers import require_distinct_frames
from tf_demo.nodes.helpers import rotation_from_values
from tf_demo.ros.transform_broadcaster import TransformBroadcaster
from tf_demo.transport import run_node
from tf_demo.transport.node import Node

NODE_NAME = 'frame_broadcaster'


class FrameBroadcaster(Node):
    """Re-sends one fixed transform with a fresh stamp on a timer."""

    def __init__(self) -> None:
        """Read the parameters and start the timer."""
        super().__init__(NODE_NAME)
        self.parent_frame = declare_checked(self, 'parent_frame', 'base_link', as_frame)
        self.child_frame = declare_checked(self, 'child_frame', 'camera_link', as_frame)
        require_distinct_frames(self.parent_frame, self.child_frame)
        self.translation = declare_checked(self, 'translation', [0.1, 0.2, 0.3], as_vector3)
        self.rotation = declare_checked(self, 'rotation', [0.0, 0.0, 0.0], rotation_from_values)
        period = declare_checked(self, 'period', 0.5, as_period_s)
        self.broadcaster = TransformBroadcaster(self)
        self.timer = self.create_timer(period, self.publish_once)

    def publish_once(self) -> None:
        """Publish the transform stamped now."""
        self.broadcaster.send_transform(
            make_transform_stamped(
                self.parent_frame,
                self.child_frame,
                now_ns(self),
                self.translation,
                self.rotation,
            )
        )


def main(args: list[str] | None = None) -> int:
    """Run the node until Ctrl-C; exit 1 with a one-line error on bad parameters."""
    return run_node(FrameBroadcaster, args)


if __name__ == '__main__':
    sys.exit(main())
