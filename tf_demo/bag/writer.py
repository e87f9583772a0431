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
topic's connection, made when its first message arrives (as rosbag2 makes it when it meets the
topic's publishers), carries its type name, ``cdr`` and the QoS profiles its publishers offer
(given by the caller from the graph; tf2's and ROS 2's for these topics when none is known:
``/tf_static`` and ``/robot_description`` latched). Every message is written as it arrives;
:meth:`TfBagWriter.flush` puts what was written on disk (rosbags commits SQLite3 and writes
MCAP chunks only on close or every MiB), so a crash loses only what came after the last flush:
a crashed ``.db3`` opens as it is; a crashed ``.mcap`` lacks its summary and is read by MCAP's
streaming readers (``mcap recover``).
"""

from __future__ import annotations

from collections.abc import Sequence
from enum import Enum
from pathlib import Path
from typing import Protocol
from typing import TYPE_CHECKING
from typing import TypeVar

from tf_demo.bag.reader import BagError
from tf_demo.bag.reader import ClosesOnExit
from tf_demo.core.extras import extra_hint

if TYPE_CHECKING:
    from rosbags.interfaces import Connection
    from rosbags.interfaces import Qos
    from rosbags.interfaces import QosTime

_PolicyT = TypeVar('_PolicyT', bound=Enum)


class QosLike(Protocol):
    """What :func:`rosbags_qos` reads of a ``QoSProfile`` (rclpy's or this package's)."""

    @property
    def history(self) -> object: ...
    @property
    def depth(self) -> int: ...
    @property
    def reliability(self) -> object: ...
    @property
    def durability(self) -> object: ...


#: What each recordable topic holds, and whether its publishers latch it.
TOPIC_TYPES = {
    '/tf': ('tf2_msgs/msg/TFMessage', False, 100),
    '/tf_static': ('tf2_msgs/msg/TFMessage', True, 1),
    '/joint_states': ('sensor_msgs/msg/JointState', False, 10),
    '/robot_description': ('std_msgs/msg/String', True, 1),
    '/clock': ('rosgraph_msgs/msg/Clock', False, 10),
}
STORAGES = ('mcap', 'sqlite3')


#: ``RMW_DURATION_INFINITE`` as rosbag2 writes it (seconds, nanoseconds).
_INFINITE = (9223372036, 854775807)


def _offered_qos(latched: bool, depth: int) -> Qos:
    """Return the rosbags QoS of a reliable publisher (transient local when ``latched``)."""
    from rosbags.interfaces import Qos
    from rosbags.interfaces import QosDurability
    from rosbags.interfaces import QosHistory
    from rosbags.interfaces import QosLiveliness
    from rosbags.interfaces import QosReliability
    from rosbags.interfaces import QosTime

    infinite = QosTime(*_INFINITE)
    durability = QosDurability.TRANSIENT_LOCAL if latched else QosDurability.VOLATILE
    return Qos(
        QosHistory.KEEP_LAST, depth, QosReliability.RELIABLE, durability, infinite,
        infinite, QosLiveliness.AUTOMATIC, infinite, False,
    )  # fmt: skip


def rosbags_qos(profile: QosLike) -> Qos:
    """
    Return a ROS ``QoSProfile`` (rclpy's or this package's) as rosbags' ``Qos`` for metadata.

    Policies go by their names; a duration by its nanoseconds (zero or more than
    ``RMW_DURATION_INFINITE``: infinite, as rosbag2 writes it).
    """
    from rosbags.interfaces import Qos
    from rosbags.interfaces import QosDurability
    from rosbags.interfaces import QosHistory
    from rosbags.interfaces import QosLiveliness
    from rosbags.interfaces import QosReliability
    from rosbags.interfaces import QosTime

    def policy(kind: type[_PolicyT], value: object) -> _PolicyT:
        name = str(getattr(value, 'name', value)).upper()
        found: _PolicyT = getattr(kind, name, kind['SYSTEM_DEFAULT'])
        return found

    def duration(value: object) -> QosTime:
        nanoseconds = int(getattr(value, 'nanoseconds', 0) or 0)
        infinite = nanoseconds <= 0 or nanoseconds >= _INFINITE[0] * 10**9 + _INFINITE[1]
        return QosTime(*(_INFINITE if infinite else divmod(nanoseconds, 1_000_000_000)))

    return Qos(
        policy(QosHistory, profile.history),
        int(profile.depth),
        policy(QosReliability, profile.reliability),
        policy(QosDurability, profile.durability),
        duration(getattr(profile, 'deadline', None)),
        duration(getattr(profile, 'lifespan', None)),
        policy(QosLiveliness, getattr(profile, 'liveliness', 'AUTOMATIC')),
        duration(getattr(profile, 'liveliness_lease_duration', None)),
        bool(getattr(profile, 'avoid_ros_namespace_conventions', False)),
    )


class TfBagWriter(ClosesOnExit):
    """A new rosbag2 at ``path`` for ``topics`` (a context manager; :meth:`write` each message)."""

    def __init__(self, path: str | Path, topics: list[str], storage: str = 'mcap') -> None:
        try:
            from rosbags.rosbag2 import StoragePlugin
            from rosbags.rosbag2 import Writer
            from rosbags.typesys import get_typestore
            from rosbags.typesys import Stores
        except ImportError as error:
            msg = f"writing bags needs the 'bag' extra ({extra_hint('bag')}): {error}"
            raise BagError(msg) from None
        unknown = [topic for topic in topics if topic not in TOPIC_TYPES]
        if unknown or storage not in STORAGES:
            what = f'topics {unknown} (known: {sorted(TOPIC_TYPES)})' if unknown else storage
            raise BagError(f'{path}: cannot record {what}')
        self.path = Path(path)
        if self.path.exists():
            raise BagError(f'{self.path}: already exists (rosbag2 writes a new directory)')
        plugin = StoragePlugin.MCAP if storage == 'mcap' else StoragePlugin.SQLITE3
        self._store = get_typestore(Stores.ROS2_JAZZY)
        self.topics = list(topics)
        try:
            self._writer = Writer(self.path, version=9, storage_plugin=plugin)
            self._writer.open()
        except Exception as error:  # rosbags' WriterError, OSError ...
            raise BagError(f'{self.path}: cannot write a bag here: {error}') from None
        self._connections: dict[str, Connection] = {}
        self.count = 0

    def write(
        self, topic: str, receive_ns: int, data: bytes, offered_qos: Sequence[QosLike] = ()
    ) -> None:
        """
        Write one serialised message of ``topic`` received at ``receive_ns``.

        ``offered_qos``: the ``QoSProfile`` of each of the topic's publishers, used when this is
        the topic's first message (none: tf2's and ROS 2's profile for the topic).
        """
        connection = self._connections.get(topic) or self.add_topic(topic, offered_qos)
        self._writer.write(connection, receive_ns, data)
        self.count += 1

    def flush(self) -> None:
        """
        Put what was written so far on disk, to survive a crash.

        SQLite3: commit (rosbags keeps one transaction open until close). MCAP: close the
        pending chunk and flush the file (rosbags buffers up to 1 MiB of messages in memory);
        a crashed MCAP has no summary, and MCAP's streaming readers (``mcap recover``) read it.
        """
        storage = getattr(self._writer, 'storage', None)
        connection = getattr(storage, 'conn', None)
        if connection is not None:  # rosbags' Sqlite3Writer
            connection.commit()
        chunk = getattr(storage, 'chunk', None)
        if storage is not None and getattr(chunk, 'msgs', None):  # rosbags' McapWriter
            storage.close_chunk()
            storage.bio.flush()

    def add_topic(self, topic: str, offered_qos: Sequence[QosLike] = ()) -> Connection:
        """Add ``topic``'s connection now (once; see :meth:`write` for ``offered_qos``)."""
        connection = self._connections.get(topic)
        if connection is None:
            msgtype, latched, depth = TOPIC_TYPES[topic]
            profiles = [rosbags_qos(p) for p in offered_qos] or [_offered_qos(latched, depth)]
            connection = self._connections[topic] = self._writer.add_connection(
                topic, msgtype, typestore=self._store, serialization_format='cdr',
                offered_qos_profiles=profiles,
            )  # fmt: skip
        return connection

    def close(self) -> None:
        """Finish the bag (its metadata and, for MCAP, the summary)."""
        self._writer.close()
