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
Reading TF out of a rosbag2: streamed in recording order, decoded straight into tuples.

A bag is a directory with ``metadata.yaml`` or a single ``.mcap`` / ``.db3`` file, as ROS 2
Jazzy's rosbag2 (MCAP by default) and Humble's (SQLite3) write them. Every problem is one
:class:`BagError` line naming the file and what is wrong: no such bag, not a bag, a damaged
container, no TF topic, a serialization other than ``cdr``, an undecodable message (with its bag
time). An ``.mcap`` whose recorder was killed (no summary) is read with MCAP's stream reader up to
where the writing stopped (:class:`UnfinishedMcap`). :meth:`TfBag.records` is a generator, so
a long bag is read in bounded memory.
"""

from __future__ import annotations

from collections.abc import Callable
from collections.abc import Iterator
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path
from types import TracebackType
from typing import cast
from typing import Protocol
from typing import TYPE_CHECKING
from typing import TypeVar

from tf_demo.core.buffer_core import BufferCore
from tf_demo.core.extras import extra_hint
from tf_demo.msgs.cdr import decode_tf_message_transforms
from tf_demo.msgs.cdr import TransformTuple

if TYPE_CHECKING:
    from mcap.records import Message as McapMessage

TF_TYPE = 'tf2_msgs/msg/TFMessage'
DEFAULT_TF_TOPIC = '/tf'
DEFAULT_STATIC_TOPIC = '/tf_static'
#: A loaded buffer keeps the whole recording (plus this much) unless told otherwise.
_CACHE_MARGIN_NS = 10_000_000_000


class BagError(ValueError):
    """A bag that cannot be read (the message names the file and the problem)."""


@dataclass(frozen=True)
class BagRecord:
    """One recorded TFMessage: when the bag received it, its transforms, which topic."""

    bag_time_ns: int
    transforms: list[TransformTuple]
    is_static: bool
    data: bytes = b''
    """The recorded CDR bytes (they decode to ``transforms``)."""


_Closing = TypeVar('_Closing', bound='ClosesOnExit')


class ClosesOnExit:
    """A context manager whose exit calls :meth:`close` (the bag reader's and writer's)."""

    def close(self) -> None:
        """Release the files."""
        raise NotImplementedError

    def __enter__(self: _Closing) -> _Closing:
        return self

    def __exit__(
        self,
        kind: type[BaseException] | None,
        value: BaseException | None,
        traceback: TracebackType | None,
    ) -> None:
        self.close()


class Connection(Protocol):
    """What :class:`TfBag` reads of a topic's connection (rosbags' ``Connection``, a channel)."""

    @property
    def id(self) -> int: ...
    @property
    def topic(self) -> str: ...
    @property
    def msgtype(self) -> str: ...
    @property
    def ext(self) -> object: ...


class BagReader(Protocol):
    """What :class:`TfBag` uses of a bag reader (rosbags' ``Reader``, :class:`UnfinishedMcap`)."""

    @property
    def start_time(self) -> int: ...
    @property
    def end_time(self) -> int: ...
    @property
    def connections(self) -> Sequence[Connection]: ...
    def messages(
        self, connections: list[Connection]
    ) -> Iterator[tuple[Connection, int, bytes]]: ...
    def close(self) -> None: ...


class TfBag(ClosesOnExit):
    """An open bag's TF connections (use :func:`open_tf_bag`; a context manager)."""

    def __init__(
        self, path: Path, reader: BagReader, connections: list[Connection], static_topic: str
    ) -> None:
        self.path = path
        self._reader = reader
        self._connections = connections
        self._static_topic = static_topic

    @property
    def start_ns(self) -> int:
        """The bag's first receive time."""
        return int(self._reader.start_time)

    @property
    def end_ns(self) -> int:
        """The bag's last receive time."""
        return max(int(self._reader.end_time) - 1, self.start_ns)  # rosbags: one past the last

    @property
    def topics(self) -> list[str]:
        """The TF topics found (their order in the bag)."""
        return [connection.topic for connection in self._connections]

    def records(self, *, statics_only: bool = False) -> Iterator[BagRecord]:
        """
        Yield every TF message (or only the static topic's) in recording order.

        :raises BagError: at the first damaged chunk or undecodable message, after yielding
            everything before it.
        """
        connections = self._connections
        if statics_only:
            connections = [c for c in connections if c.topic == self._static_topic]
            if not connections:
                return
        messages = self._reader.messages(connections=connections)
        bag_time = self.start_ns
        while True:
            try:
                connection, bag_time, data = next(messages)
            except StopIteration:
                return
            except Exception as error:  # rosbags' reader errors, zstd, sqlite, struct ...
                msg = f'{self.path}: damaged after bag time {_seconds(bag_time)} s: {error}'
                raise BagError(msg) from None
            try:
                transforms = decode_tf_message_transforms(data)
            except Exception as error:
                msg = (
                    f'{self.path}: message on {connection.topic} at bag time '
                    f'{_seconds(bag_time)} s is not a TFMessage: {error}'
                )
                raise BagError(msg) from None
            is_static = connection.topic == self._static_topic
            yield BagRecord(int(bag_time), transforms, is_static, bytes(data))

    def read(self, consume: Callable[[BagRecord], object]) -> tuple[int, BagError | None]:
        """
        Hand every record to ``consume`` up to the bag's end or its damage.

        :returns: the end of what was read (the bag's end, or the last record before the damage)
            and the damage (None when the whole bag was read).
        """
        last_ns = self.start_ns
        try:
            for record in self.records():
                consume(record)
                last_ns = record.bag_time_ns
        except BagError as damage:
            return last_ns, damage
        return self.end_ns, None

    def close(self) -> None:
        """Close the bag's files."""
        self._reader.close()


def open_tf_bag(
    path: str | Path, tf_topic: str = DEFAULT_TF_TOPIC, static_topic: str = DEFAULT_STATIC_TOPIC
) -> TfBag:
    """
    Open the bag at ``path`` for its ``tf_topic`` and ``static_topic`` messages.

    :raises BagError: naming ``path``: missing, not a rosbag2, no TF topic, or not ``cdr``.
    """
    try:
        from rosbags.rosbag2 import Reader
    except ImportError as error:
        msg = f"reading bags needs the 'bag' extra ({extra_hint('bag')}): {error}"
        raise BagError(msg) from None
    bag = Path(path)
    if not bag.exists():
        msg = f'{bag}: no such bag (a directory with metadata.yaml, or a .mcap or .db3 file)'
        raise BagError(msg)
    reader: BagReader
    try:
        rosbags_reader = Reader(bag)
        rosbags_reader.open()
        # Its messages() takes its own connections: the ones TfBag hands back to it.
        reader = cast('BagReader', rosbags_reader)
    except Exception as error:  # rosbags raises its own errors, and OSError, sqlite3 ...
        unfinished = _unfinished_mcap(bag)
        if unfinished is None:
            msg = f'{bag}: not a readable rosbag2: {error}'
            raise BagError(msg) from None
        reader = unfinished
    wanted = (tf_topic, static_topic)
    connections = [c for c in reader.connections if c.topic in wanted]
    problem = None
    if not connections:
        found = ', '.join(sorted({c.topic for c in reader.connections})) or 'none'
        problem = f'no {tf_topic} or {static_topic} topic in the bag (topics: {found})'
    for connection in connections:
        formats = getattr(connection.ext, 'serialization_format', 'cdr')
        if connection.msgtype != TF_TYPE:
            problem = f'{connection.topic} holds {connection.msgtype}, not {TF_TYPE}'
        elif formats != 'cdr':
            problem = f"{connection.topic} is serialized as '{formats}' (only 'cdr' is read)"
    if problem is not None:
        reader.close()
        raise BagError(f'{bag}: {problem}')
    return TfBag(bag, reader, connections, static_topic)


@dataclass(frozen=True)
class LoadedBag:
    """A bag read into a buffer: up to its end, or up to the damage that stopped the reading."""

    core: BufferCore
    start_ns: int
    end_ns: int
    """The bag's end, or the last message read before the damage."""
    damage: BagError | None
    """What stopped the reading early (None: the whole bag was read)."""


def load_bag(
    path: str | Path,
    cache_time_ns: int | None = None,
    tf_topic: str = DEFAULT_TF_TOPIC,
    static_topic: str = DEFAULT_STATIC_TOPIC,
) -> LoadedBag:
    """
    Read every transform of the bag into a new :class:`BufferCore`, keeping what precedes damage.

    Static transforms count from the bag's start whenever they were recorded (tf2 treats them as
    valid at all times). ``cache_time_ns`` defaults to the whole recording. Transforms tf2
    refuses (NaN, an empty frame id) are skipped, as a listener skips them. A damaged chunk or
    an undecodable message ends the reading: everything before it is kept and the error is
    :attr:`LoadedBag.damage`.

    :raises BagError: for a bag that cannot be opened (:func:`open_tf_bag`).
    """
    with open_tf_bag(path, tf_topic, static_topic) as bag:
        span = bag.end_ns - bag.start_ns + _CACHE_MARGIN_NS
        core = BufferCore(cache_time_ns if cache_time_ns is not None else span, log=_quiet)
        insert = core.set_transforms
        authority = f'bag {bag.path.name}'

        def insert_all(record: BagRecord) -> None:
            # One compiled call a message, as the listener inserts; a transform the core
            # refuses is logged (quietly) or returned as a failure, and the rest go in.
            insert(record.transforms, authority, record.is_static)

        end_ns, damage = bag.read(insert_all)
        return LoadedBag(core, bag.start_ns, end_ns, damage)


def load_buffer(
    path: str | Path,
    cache_time_ns: int | None = None,
    tf_topic: str = DEFAULT_TF_TOPIC,
    static_topic: str = DEFAULT_STATIC_TOPIC,
) -> BufferCore:
    """
    Return a :class:`BufferCore` holding every transform of the bag (see :func:`load_bag`).

    :raises BagError: as :func:`open_tf_bag`, and for a damaged bag (:func:`load_bag` keeps
        what came before the damage).
    """
    loaded = load_bag(path, cache_time_ns, tf_topic, static_topic)
    if loaded.damage is not None:
        raise loaded.damage
    return loaded.core


@dataclass(frozen=True)
class _McapChannel:
    """What :class:`TfBag` reads of a connection, for an MCAP channel."""

    id: int
    topic: str
    msgtype: str
    ext: object


class UnfinishedMcap:
    """
    An MCAP file without its summary (its recorder was killed), read with MCAP's stream reader.

    It offers what :class:`TfBag` uses of rosbags' reader. Everything up to the end of the last
    whole record is read; the messages then end with an error saying the file was not closed.
    """

    def __init__(self, path: Path) -> None:
        self.path = path
        self.connections: list[_McapChannel] = []
        times = [message.log_time for message in self._records(self.connections.append)]
        self.start_time = min(times, default=0)
        self.end_time = max(times, default=0) + 1  # rosbags: one past the last

    def _records(self, on_channel: Callable[[_McapChannel], object]) -> Iterator[McapMessage]:
        """Yield the file's messages (calling ``on_channel`` for each channel), to its cut."""
        from types import SimpleNamespace

        from mcap.records import Channel
        from mcap.records import Message
        from mcap.records import Schema
        from mcap.stream_reader import StreamReader

        schemas: dict[int, str] = {}
        with self.path.open('rb') as stream:
            records = StreamReader(stream, skip_magic=False).records
            while True:
                try:
                    record = next(records)
                except Exception:  # EndOfFile, a record cut short: where the writing stopped
                    return
                if isinstance(record, Schema):
                    schemas[record.id] = record.name
                elif isinstance(record, Channel):
                    ext = SimpleNamespace(serialization_format=record.message_encoding)
                    msgtype = schemas.get(record.schema_id, '')
                    on_channel(_McapChannel(record.id, record.topic, msgtype, ext))
                elif isinstance(record, Message):
                    yield record

    def messages(self, connections: list[Connection]) -> Iterator[tuple[Connection, int, bytes]]:
        """Yield ``(connection, log time, data)`` of ``connections``, then say it ends early."""
        wanted = {connection.id: connection for connection in connections}
        for message in self._records(lambda channel: None):
            connection = wanted.get(message.channel_id)
            if connection is not None:
                yield connection, message.log_time, message.data
        msg = 'the file ends without its summary (the recording was not closed)'
        raise ValueError(msg)

    def close(self) -> None:
        """Nothing is kept open between reads."""


def _unfinished_mcap(bag: Path) -> UnfinishedMcap | None:
    """Open ``bag`` (an ``.mcap``, or a directory holding one) as an unfinished MCAP, or None."""
    files = [bag] if bag.suffix == '.mcap' else sorted(bag.glob('*.mcap')) if bag.is_dir() else []
    if len(files) != 1 or (bag.is_dir() and (bag / 'metadata.yaml').exists()):
        return None
    try:
        with files[0].open('rb') as stream:
            if stream.read(8) != b'\x89MCAP0\r\n':
                return None
        opened = UnfinishedMcap(files[0])
    except Exception:  # no mcap package, unreadable: the caller reports rosbags' error
        return None
    return opened if opened.connections else None


def _seconds(stamp_ns: int) -> str:
    """Return a bag time as exact seconds (``sec.nanosec``)."""
    sec, nanosec = divmod(int(stamp_ns), 1_000_000_000)
    return f'{sec}.{nanosec:09d}'


def _quiet(level: int, text: str) -> None:
    """Drop the loaded buffer's log lines: a recording's old data is not news."""
    del level, text
