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

"""``TransformBroadcaster``: publishes dynamic transforms on ``/tf``, one message per call."""

from __future__ import annotations

from collections.abc import Iterable
from typing import cast
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from tf_demo.msgs.geometry_msgs import TransformStamped
    from tf_demo.transport.node import Node
    from tf_demo.transport.qos import QoSProfile

DEFAULT_TF_TOPIC = '/tf'


def as_transform_list(transform: object) -> list[TransformStamped]:
    """
    Return ``[transform]`` for one ``TransformStamped``, or the items of an iterable of them.

    Either world's messages pass (checked by their fields, as tf2_ros checks them).

    :raises TypeError: for anything that is neither.
    """
    if hasattr(transform, 'child_frame_id') and hasattr(transform, 'transform'):
        return [cast('TransformStamped', transform)]
    if isinstance(transform, Iterable) and not isinstance(transform, (str, bytes)):
        items = list(transform)
        for item in items:
            if not hasattr(item, 'child_frame_id'):
                msg = f'expected TransformStamped messages, got {type(item).__name__}'
                raise TypeError(msg)
        return cast('list[TransformStamped]', items)
    msg = f'expected a TransformStamped or a list of them, got {type(transform).__name__}'
    raise TypeError(msg)


class TransformBroadcaster:
    """Publishes ``TransformStamped`` messages on ``/tf`` (KEEP_LAST 100, RELIABLE, VOLATILE)."""

    def __init__(
        self, node: Node, qos: QoSProfile | int | None = None, *, topic: str = DEFAULT_TF_TOPIC
    ) -> None:
        """
        Create the publisher.

        :param node: the node to publish from (rclpy or tf_demo).
        :param qos: QoS profile or depth; default tf2's ``DynamicBroadcasterQoS``.
        :param topic: the topic (tf2 rolling's ``tf_topic``).
        """
        from tf_demo.transport.messages import tf2_msgs

        if qos is None:
            from tf_demo.transport.qos import DynamicBroadcasterQoS

            qos = DynamicBroadcasterQoS()
        self._message_type = tf2_msgs.TFMessage
        self.pub_tf = node.create_publisher(self._message_type, topic, qos)

    def send_transform(self, transform: TransformStamped | Iterable[TransformStamped]) -> None:
        """Publish one ``TFMessage`` with the given transform or transforms."""
        self.pub_tf.publish(self._message_type(transforms=as_transform_list(transform)))

    sendTransform = send_transform  # noqa: N815 - tf2_ros's name
