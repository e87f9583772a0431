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
``/rosout`` for standalone nodes, as rcl_logging_rosout publishes it.

Each node created with ``enable_rosout=True`` (the default) gets a ``rcl_interfaces/msg/Log``
writer on ``/rosout`` with rcl's rosout QoS (reliable, transient local, keep last 1000, lifespan
10 s), registered under its logger's name. Every message a logger emits
(:func:`tf_demo.transport.dds.logging.add_log_sink`) whose logger name is registered, or whose
logger is a child (``get_child``) of a registered one, is published with rcl's fields: stamp,
level (10..50), logger name, text, file, function and line.
"""

from __future__ import annotations

import threading

from tf_demo.msgs import builtin_interfaces
from tf_demo.msgs import cdr
from tf_demo.msgs import rcl_interfaces
from tf_demo.transport.dds import wire as dds_wire
from tf_demo.transport.dds.logging import add_log_sink
from tf_demo.transport.dds.logging import LogRecord
from tf_demo.transport.dds.logging import remove_log_sink
from tf_demo.transport.dds.qos import qos_profile_rosout_default

__all__ = ['RosoutPublisher', 'log_message']

_lock = threading.Lock()
#: Logger name -> the rosout publishers registered under it (rcl's logger map).
_publishers: dict[str, list[RosoutPublisher]] = {}


def log_message(record: LogRecord) -> rcl_interfaces.Log:
    """Return the ``rcl_interfaces/msg/Log`` rcl publishes for ``record``."""
    sec, nanosec = divmod(record.stamp_ns, 1_000_000_000)
    return rcl_interfaces.Log(
        stamp=builtin_interfaces.Time(sec=sec, nanosec=nanosec),
        level=int(record.severity),
        name=record.name,
        msg=record.message,
        file=record.file_name,
        function=record.function_name,
        line=record.line_number,
    )


def _publisher_for(record: LogRecord) -> RosoutPublisher | None:
    with _lock:
        found = _publishers.get(record.name)
        if found:
            return found[-1]
        if record.name != record.logger.name:
            return None  # name= override: rcl looks that name up only
        logger = record.logger.parent
        while logger is not None:
            found = _publishers.get(logger.name)
            if found:
                return found[-1]
            logger = logger.parent
    return None


def _sink(record: LogRecord) -> None:
    publisher = _publisher_for(record)
    if publisher is not None:
        publisher.publish(record)


class RosoutPublisher:
    """The ``/rosout`` writer of one node, registered under the node's logger name."""

    def __init__(self, participant: dds_wire.DdsParticipant, logger_name: str) -> None:
        self.logger_name = logger_name
        message_type = rcl_interfaces.Log
        self.writer = participant.create_writer(
            dds_wire.dds_topic_name('/rosout'),
            message_type.__dds_typename__,
            dds_wire.endpoint_qos_from_profile(qos_profile_rosout_default),
            f'typehash={message_type.__typehash__};'.encode(),
        )
        with _lock:
            first = not _publishers
            _publishers.setdefault(logger_name, []).append(self)
        if first:
            add_log_sink(_sink)

    def publish(self, record: LogRecord) -> None:
        """Publish one log record."""
        if self.writer.handle > 0:
            self.writer.write(cdr.serialize(log_message(record)))

    def close(self) -> None:
        """Unregister and delete the writer (waiting briefly for acknowledgements)."""
        with _lock:
            entries = _publishers.get(self.logger_name, [])
            if self in entries:
                entries.remove(self)
            if not entries:
                _publishers.pop(self.logger_name, None)
            last = not _publishers
        if last:
            remove_log_sink(_sink)
        self.writer.close(flush_timeout_ns=100_000_000)
