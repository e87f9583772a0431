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
``StaticTransformBroadcaster``: latched transforms on ``/tf_static``.

``/tf_static`` is KEEP_LAST 1 and TRANSIENT_LOCAL, so only the last message of a publisher is
delivered to late joiners. The broadcaster therefore keeps every transform it was given, one per
child frame, and republishes the whole set on each call. A transform for a child frame that was
already sent **replaces** the earlier one in place, as tf2's C++ broadcaster does (Jazzy's Python
one ignores it, ros2/geometry2#705).
"""

from __future__ import annotations

from collections.abc import Iterable
import copy
from typing import TYPE_CHECKING

from tf_demo.ros.transform_broadcaster import as_transform_list

if TYPE_CHECKING:
    from tf_demo.msgs.geometry_msgs import TransformStamped
    from tf_demo.transport.node import Node
    from tf_demo.transport.qos import QoSProfile

DEFAULT_STATIC_TF_TOPIC = '/tf_static'


def merge_static_transforms(
    current: dict[str, TransformStamped], new: list[TransformStamped]
) -> dict[str, TransformStamped]:
    """
    Return the set after adding ``new``: same child frame replaces in place, others append.

    :param current: child frame id -> transform, in publication order (not modified).
    :param new: transforms to add.
    """
    merged = dict(current)
    for transform in new:
        merged[transform.child_frame_id] = transform
    return merged


class StaticTransformBroadcaster:
    """Publishes the accumulated static transforms on ``/tf_static`` (depth 1, latched)."""

    def __init__(
        self,
        node: Node,
        qos: QoSProfile | int | None = None,
        *,
        topic: str = DEFAULT_STATIC_TF_TOPIC,
    ) -> None:
        """
        Create the latched publisher.

        :param node: the node to publish from.
        :param qos: QoS profile or depth; default tf2's ``StaticBroadcasterQoS`` (KEEP_LAST 1,
            RELIABLE, TRANSIENT_LOCAL).
        :param topic: the topic (tf2 rolling's ``tf_static_topic``).
        """
        from tf_demo.transport.messages import tf2_msgs

        if qos is None:
            from tf_demo.transport.qos import StaticBroadcasterQoS

            qos = StaticBroadcasterQoS()
        self._message_type = tf2_msgs.TFMessage
        self.pub_tf = node.create_publisher(self._message_type, topic, qos)
        self._by_child: dict[str, TransformStamped] = {}

    @property
    def transforms(self) -> list[TransformStamped]:
        """The transforms that the next publication contains, in order."""
        return list(self._by_child.values())

    def send_transform(self, transform: TransformStamped | Iterable[TransformStamped]) -> None:
        """Add (or replace by child frame) the given transform(s) and republish the whole set."""
        new = [copy.deepcopy(t) for t in as_transform_list(transform)]
        self._by_child = merge_static_transforms(self._by_child, new)
        self.pub_tf.publish(self._message_type(transforms=self.transforms))

    sendTransform = send_transform  # noqa: N815 - tf2_ros's name
