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
What every part of a standalone node shares: its identity, names, clock, logger, entity lists.

:class:`NodeBase` is the base of the node's parts (:class:`~.node_endpoints.NodeEndpointsMixin`,
:class:`~.node_services.NodeServicesMixin`); :class:`~.node.DdsNode` sets its attributes.
"""

from __future__ import annotations

from collections.abc import Callable
import threading
from typing import Protocol
from typing import TypeVar

from tf_demo.transport.dds import wire as dds_wire
from tf_demo.transport.dds.callback_groups import CallbackGroup
from tf_demo.transport.dds.clock import Clock
from tf_demo.transport.dds.clock import ROSClock
from tf_demo.transport.dds.context import _context
from tf_demo.transport.dds.context import _graph_changed
from tf_demo.transport.dds.logging import Logger
from tf_demo.transport.dds.names import expand_topic_name

__all__ = ['NodeBase']

_EntityT = TypeVar('_EntityT')


class _ReaderEntity(Protocol):
    """A subscription, service or client: served from a read condition, closed when destroyed."""

    def _close(self) -> None: ...


_ReaderEntityT = TypeVar('_ReaderEntityT', bound=_ReaderEntity)


class NodeBase:
    """
    The identity, names and shared state of a standalone node (set by ``DdsNode.__init__``).

    The parts of the node create their entities under :attr:`_lock`, after
    :meth:`_check_alive`, with topic names from :meth:`resolve_topic_name`, and call
    :meth:`_wake_executors` when the executors must wait on something new.
    """

    _node_name: str
    _namespace: str
    _remap: Callable[[str, str, str], str]
    _destroyed: bool
    _lock: threading.RLock
    _logger: Logger
    _clock: ROSClock
    _participant: dds_wire.DdsParticipant
    _default_callback_group: CallbackGroup

    # -- identity --------------------------------------------------------------------------

    def get_name(self) -> str:
        """Return the node's name."""
        return self._node_name

    def get_namespace(self) -> str:
        """Return the node's absolute namespace."""
        return self._namespace

    def get_fully_qualified_name(self) -> str:
        """Return ``/namespace/name``."""
        return self._namespace.rstrip('/') + '/' + self._node_name

    @property
    def context(self) -> object:
        """The process context (kept for rclpy compatibility)."""
        return _context

    def get_logger(self) -> Logger:
        """Return the node's logger."""
        return self._logger

    def get_clock(self) -> Clock:
        """Return the node's ROS clock (``/clock`` when ``use_sim_time`` is true)."""
        return self._clock

    @property
    def default_callback_group(self) -> CallbackGroup:
        """The mutually exclusive group of entities created without a ``callback_group``."""
        return self._default_callback_group

    # -- names -----------------------------------------------------------------------------

    def resolve_topic_name(self, topic: str, *, only_expand: bool = False) -> str:
        """Expand ``topic`` as rcl does and apply the ``-r`` remapping rules."""
        expanded = expand_topic_name(topic, self._node_name, self._namespace)
        if only_expand:
            return expanded
        remapped = str(self._remap(expanded, self._node_name, self._namespace))
        if remapped != expanded:
            remapped = expand_topic_name(remapped, self._node_name, self._namespace)
        return remapped

    # -- entities --------------------------------------------------------------------------

    def _check_alive(self) -> None:
        if self._destroyed:
            msg = f'node {self.get_fully_qualified_name()!r} was destroyed'
            raise RuntimeError(msg)

    def _detach(self, entities: list[_EntityT], entity: _EntityT) -> bool:
        """Remove ``entity`` from the node's list; False when it is not (or no longer) there."""
        with self._lock:
            if entity not in entities:
                return False
            entities.remove(entity)
        return True

    def _add_reader_entity(
        self, entities: list[_ReaderEntityT], entity: _ReaderEntityT, group: CallbackGroup
    ) -> None:
        """Register a new subscription, service or client with its group, executors and graph."""
        group.add_entity(entity)
        with self._lock:
            entities.append(entity)
        self._wake_executors()
        _graph_changed()

    def _destroy_reader_entity(
        self, entities: list[_ReaderEntityT], entity: _ReaderEntityT
    ) -> bool:
        """Destroy a subscription, service or client of the node; False when it is not one."""
        if not self._detach(entities, entity):
            return False
        self._wake_executors()
        entity._close()
        _graph_changed()
        return True

    def _wake_executors(self) -> None:
        """Interrupt the waits of the executors that spin the node (``DdsNode`` knows them)."""
        raise NotImplementedError
