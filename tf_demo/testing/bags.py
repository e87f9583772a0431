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


#: Humble's offered QoS for a reliable volatile publisher: a YAML *string* of rmw's numbers.
_HUMBLE_QOS = (
    '- history: 3\n  depth: 0\n  reliability: 1\n  durability: 2\n'
    '  deadline:\n    sec: 9223372036\n    nsec: 854775807\n'
    '  lifespan:\n    sec: 9223372036\n    nsec: 854775807\n  liveliness: 1\n'
    '  liveliness_lease_duration:\n    sec: 9223372036\n    nsec: 854775807\n'
    '  avoid_ros_namespace_conventions: false'
)


def write_humble_bag(
    path: Path, messages: Sequence[tuple[str, int, bytes]], msgtype: str = 'tf2_msgs/msg/TFMessage'
) -> Path:
    """
    Write ``(topic, bag_time_ns, cdr)`` messages as ROS 2 Humble's rosbag2 writes SQLite3.

    Metadata version 5 (offered QoS as a YAML string of numbers, no type hashes, no
    ``ros_distro`` or ``custom_data``) and the database schema version 3 of Humble's
    ``sqlite_storage.cpp``: tables ``schema``, ``metadata``, ``topics`` (no type hash column)
    and ``messages``. rosbags writes only versions 8 and 9, so this is written by hand.
    """
    import sqlite3

    import yaml

    path.mkdir(parents=True)
    database = f'{path.name}_0.db3'
    topics = list(dict.fromkeys(topic for topic, _, _ in messages))
    with sqlite3.connect(path / database) as connection:
        connection.executescript(
            'CREATE TABLE schema(schema_version INTEGER PRIMARY KEY, ros_distro TEXT NOT NULL);'
            'CREATE TABLE metadata(id INTEGER PRIMARY KEY, metadata_version INTEGER NOT NULL,'
            ' metadata TEXT NOT NULL);'
            'CREATE TABLE topics(id INTEGER PRIMARY KEY, name TEXT NOT NULL, type TEXT NOT NULL,'
            ' serialization_format TEXT NOT NULL, offered_qos_profiles TEXT NOT NULL);'
            'CREATE TABLE messages(id INTEGER PRIMARY KEY, topic_id INTEGER NOT NULL,'
            ' timestamp INTEGER NOT NULL, data BLOB NOT NULL);'
            'CREATE INDEX timestamp_idx ON messages (timestamp ASC);'
            "INSERT INTO schema VALUES (3, 'humble');"
        )
        connection.executemany(
            'INSERT INTO topics VALUES (?, ?, ?, ?, ?)',
            [(i + 1, topic, msgtype, 'cdr', _HUMBLE_QOS) for i, topic in enumerate(topics)],
        )
        connection.executemany(
            'INSERT INTO messages (topic_id, timestamp, data) VALUES (?, ?, ?)',
            [(topics.index(topic) + 1, stamp, data) for topic, stamp, data in messages],
        )
    start = min(stamp for _, stamp, _ in messages)
    duration = max(stamp for _, stamp, _ in messages) - start
    counts = {topic: sum(1 for t, _, _ in messages if t == topic) for topic in topics}
    information = {
        'version': 5,
        'storage_identifier': 'sqlite3',
        'duration': {'nanoseconds': duration},
        'starting_time': {'nanoseconds_since_epoch': start},
        'message_count': len(messages),
        'topics_with_message_count': [
            {
                'topic_metadata': {
                    'name': topic,
                    'type': msgtype,
                    'serialization_format': 'cdr',
                    'offered_qos_profiles': _HUMBLE_QOS,
                },
                'message_count': counts[topic],
            }
            for topic in topics
        ],
        'compression_format': '',
        'compression_mode': '',
        'relative_file_paths': [database],
        'files': [
            {
                'path': database,
                'starting_time': {'nanoseconds_since_epoch': start},
                'duration': {'nanoseconds': duration},
                'message_count': len(messages),
            }
        ],
    }
    text = yaml.safe_dump({'rosbag2_bagfile_information': information}, sort_keys=False)
    (path / 'metadata.yaml').write_text(text, encoding='utf-8')
    return path
