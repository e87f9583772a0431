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
Writing TF recordings: a rosbag2 that ROS 2's own tools open (MCAP by default, or SQLite3).

Messages arrive serialised (CDR, as received) and are written with their receive times; each
topic's connection carries its type name, ``cdr`` and the QoS its publishers offer as tf2 and
ROS 2 define them for these topics (``/tf_static`` and ``/robot_description`` latched). Every
message is written as it arrives, so a crash leaves what was written readable as far as the
storage allows (SQLite3 commits each message; MCAP needs its summary, written on close).
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

from tf_demo.bag.reader import BagError
from tf_demo.bag.reader import ClosesOnExit

#: What each recordable topic holds, and whether its publishers latch it.
TOPIC_TYPES = {
    '/tf': ('tf2_msgs/msg/TFMessage', False, 100),
    '/tf_static': ('tf2_msgs/msg/TFMessage', True, 1),
    '/joint_states': ('sensor_msgs/msg/JointState', False, 10),
    '/robot_description': ('std_msgs/msg/String', True, 1),
    '/clock': ('rosgraph_msgs/msg/Clock', False, 10),
}
STORAGES = ('mcap', 'sqlite3')


def _offered_qos(latched: bool, depth: int) -> Any:
    """Return the rosbags QoS of a reliable publisher (transient local when ``latched``)."""
    from rosbags.interfaces import Qos
    from rosbags.interfaces import QosDurability
    from rosbags.interfaces import QosHistory
    from rosbags.interfaces import QosLiveliness
    from rosbags.interfaces import QosReliability
    from rosbags.interfaces import QosTime

    infinite = QosTime(0x7FFFFFFF, 0xFFFFFFFF)
    durability = QosDurability.TRANSIENT_LOCAL if latched else QosDurability.VOLATILE
    return Qos(
        QosHistory.KEEP_LAST, depth, QosReliability.RELIABLE, durability, infinite,
        infinite, QosLiveliness.AUTOMATIC, infinite, False,
    )  # fmt: skip


class TfBagWriter(ClosesOnExit):
    """A new rosbag2 at ``path`` for ``topics`` (a context manager; :meth:`write` each message)."""

    def __init__(self, path: str | Path, topics: list[str], storage: str = 'mcap') -> None:
        try:
            from rosbags.rosbag2 import StoragePlugin
            from rosbags.rosbag2 import Writer
            from rosbags.typesys import get_typestore
            from rosbags.typesys import Stores
        except ImportError as error:
            msg = f"writing bags needs the 'bag' extra (pip install 'tf_demo[bag]'): {error}"
            raise BagError(msg) from None
        unknown = [topic for topic in topics if topic not in TOPIC_TYPES]
        if unknown or storage not in STORAGES:
            what = f'topics {unknown} (known: {sorted(TOPIC_TYPES)})' if unknown else storage
            raise BagError(f'{path}: cannot record {what}')
        self.path = Path(path)
        if self.path.exists():
            raise BagError(f'{self.path}: already exists (rosbag2 writes a new directory)')
        plugin = StoragePlugin.MCAP if storage == 'mcap' else StoragePlugin.SQLITE3
        store = get_typestore(Stores.ROS2_JAZZY)
        try:
            self._writer = Writer(self.path, version=9, storage_plugin=plugin)
            self._writer.open()
            self._connections = {}
            for topic in topics:
                msgtype, latched, depth = TOPIC_TYPES[topic]
                self._connections[topic] = self._writer.add_connection(
                    topic, msgtype, typestore=store, serialization_format='cdr',
                    offered_qos_profiles=[_offered_qos(latched, depth)],
                )  # fmt: skip
        except Exception as error:  # rosbags' WriterError, OSError ...
            raise BagError(f'{self.path}: cannot write a bag here: {error}') from None
        self.count = 0

    def write(self, topic: str, receive_ns: int, data: bytes) -> None:
        """Write one serialised message of ``topic`` received at ``receive_ns``."""
        self._writer.write(self._connections[topic], receive_ns, data)
        self.count += 1

    def close(self) -> None:
        """Finish the bag (its metadata and, for MCAP, the summary)."""
        self._writer.close()
