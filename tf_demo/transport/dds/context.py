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
The process context of the standalone world: init, ok, shutdown, the live nodes and executors.

The state exists once per process (``_context``); :func:`_graph_changed` republishes the
context's live nodes on ``ros_discovery_info`` whenever one of them changes.
"""

from __future__ import annotations

from collections.abc import Sequence
import threading
from typing import Protocol
import weakref

from tf_demo.transport.dds import wire as dds_wire
from tf_demo.transport.dds.graph import _Graph
from tf_demo.transport.dds.graph import GraphNode
from tf_demo.transport.dds.logging import get_logger


class _LiveNode(GraphNode, Protocol):
    """What the context asks of a live node: its graph entry, creation order and destruction."""

    _destroyed: bool
    _creation_index: int

    def destroy_node(self) -> None: ...


class _Wakeable(Protocol):
    """What the context asks of an executor at shutdown."""

    def wake(self) -> None: ...


class _Context:
    """The process-wide init/shutdown state, global ``--ros-args`` and live nodes."""

    def __init__(self) -> None:
        self.lock = threading.RLock()
        self.initialized = False
        self.shut_down = False
        self.args: list[str] = []
        self.nodes: weakref.WeakSet[_LiveNode] = weakref.WeakSet()
        self.executors: weakref.WeakSet[_Wakeable] = weakref.WeakSet()
        self.graph: _Graph | None = None

    def ok(self) -> bool:
        return self.initialized and not self.shut_down


_context = _Context()


def init(*, args: Sequence[str] | None = None, context: object = None) -> None:
    """Initialise the standalone world (rclpy ``init``); ``args`` may hold ``--ros-args``."""
    del context
    with _context.lock:
        _context.initialized = True
        _context.shut_down = False
        _context.args = list(args) if args is not None else []


def ok(*, context: object = None) -> bool:
    """Return whether :func:`init` was called and :func:`shutdown` was not."""
    del context
    return _context.ok()


def shutdown(*, context: object = None) -> None:
    """
    Stop every executor, flush every writer and release the DDS participant.

    :raises RuntimeError: before :func:`init` or a second time (as rclpy's ``Context.shutdown``;
        :func:`try_shutdown` is the quiet form).
    """
    del context
    with _context.lock:
        if not _context.initialized:
            msg = 'Context must be initialized before it can be shutdown'
            raise RuntimeError(msg)
        if _context.shut_down:
            msg = 'failed to shutdown: rcl_shutdown already called on the given context'
            raise RuntimeError(msg)
        _context.shut_down = True
    _release_everything()


def try_shutdown(*, context: object = None) -> None:
    """Shut down unless not initialised or already shut down (rclpy ``try_shutdown``)."""
    del context
    with _context.lock:
        if not _context.ok():
            return
        _context.shut_down = True
    _release_everything()


def _release_everything() -> None:
    """Wake every executor, destroy every node and close the graph writer and participant."""
    with _context.lock:
        executors = list(_context.executors)
        nodes = list(_context.nodes)
    for executor in executors:
        executor.wake()
    for node in nodes:
        node.destroy_node()
    with _context.lock:
        if _context.graph is not None:
            _context.graph.close()
            _context.graph = None
    dds_wire.close_participant()


def _participant() -> dds_wire.DdsParticipant:
    return dds_wire.get_participant(warn=_warn_process)


def _warn_process(text: str) -> None:
    get_logger('tf_demo.dds').warning(text)


def _graph_changed() -> None:
    with _context.lock:
        if _context.shut_down:
            return
        if _context.graph is None:
            _context.graph = _Graph(_participant())
        graph = _context.graph
        nodes = [node for node in _context.nodes if not node._destroyed]
        nodes.sort(key=lambda node: node._creation_index)
    graph.publish(nodes)
