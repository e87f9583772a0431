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
Bags for tests: rosbag2 recordings of known TF written with rosbags' own writer.

Independent of :mod:`tf_demo.bag` (which reads them): the container is rosbags', the payloads
this package's CDR encoder (byte-identical to rclpy's, checked against golden bytes).
"""

from __future__ import annotations

from collections.abc import Sequence
import math
from pathlib import Path

from tf_demo.msgs.cdr import serialize
from tf_demo.msgs.geometry_msgs import TransformStamped
from tf_demo.msgs.tf2_msgs import TFMessage

SECOND = 1_000_000_000
#: Storage plugins by the name rosbag2 gives them.
STORAGES = ('mcap', 'sqlite3')


def transform(
    parent: str, child: str, stamp_ns: int, xyz: Sequence[float], yaw: float = 0.0
) -> TransformStamped:
    """Return a TransformStamped: ``xyz`` and a rotation of ``yaw`` about z."""
    message = TransformStamped()
    message.header.stamp.sec, message.header.stamp.nanosec = divmod(stamp_ns, SECOND)
    message.header.frame_id = parent
    message.child_frame_id = child
    translation = message.transform.translation
    translation.x, translation.y, translation.z = (float(v) for v in xyz)
    message.transform.rotation.z = math.sin(yaw / 2)
    message.transform.rotation.w = math.cos(yaw / 2)
    return message


def tf_bytes(*transforms: TransformStamped) -> bytes:
    """Return a serialised TFMessage holding ``transforms``."""
    message = TFMessage()
    message.transforms = list(transforms)
    return serialize(message)


def write_bag(
    path: Path,
    storage: str,
    messages: Sequence[tuple[str, int, bytes]],
    msgtype: str = 'tf2_msgs/msg/TFMessage',
) -> Path:
    """Write ``(topic, bag_time_ns, cdr)`` messages into a new rosbag2 at ``path``."""
    from rosbags.rosbag2 import StoragePlugin
    from rosbags.rosbag2 import Writer
    from rosbags.typesys import get_typestore
    from rosbags.typesys import Stores

    plugin = StoragePlugin.MCAP if storage == 'mcap' else StoragePlugin.SQLITE3
    store = get_typestore(Stores.ROS2_JAZZY)
    with Writer(path, version=9, storage_plugin=plugin) as writer:
        connections = {}
        for topic, bag_time, data in messages:
            if topic not in connections:
                connections[topic] = writer.add_connection(topic, msgtype, typestore=store)
            writer.write(connections[topic], bag_time, data)
    return path
