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

"""Waitset executors scheduled as rclpy's: ``DdsExecutor`` and ``SingleThreadedExecutor``."""

from __future__ import annotations

from collections import deque
from collections.abc import Callable
from collections.abc import Sequence
import functools
import inspect
import threading
import time
from typing import Protocol
from typing import TypeAlias

from tf_demo.transport.dds import wire as dds_wire
from tf_demo.transport.dds.callback_groups import CallbackGroup
from tf_demo.transport.dds.clock import ROSClock
from tf_demo.transport.dds.context import _context
from tf_demo.transport.dds.context import _participant
from tf_demo.transport.dds.endpoints import MessageInfo
from tf_demo.transport.dds.node import DdsNode
from tf_demo.transport.dds.tasks import DdsTask
from tf_demo.transport.dds.tasks import TaskHandler
from tf_demo.transport.dds.timers import DdsTimer

__all__ = ['Executor', 'ExternalShutdownException', 'SingleThreadedExecutor']

_IDLE_WAIT_NS = 200_000_000
_TASK_POLL_NS = 5_000_000
_SIM_TIME_MAX_WAIT_NS = 10_000_000


class _ReaderEntity(Protocol):
    """
    What the executor needs of an entity served from a read condition.

    Subscriptions, and service servers and clients (``dds_services``), which the executors
    serve alike: wait on ``read_condition``, ``take_messages()``, then ``callback`` per item.
    """

    callback_group: CallbackGroup

    @property
    def read_condition(self) -> int: ...

    @property
    def callback(self) -> Callable[..., object]: ...

    def take_messages(self) -> Sequence[tuple[object, MessageInfo | None]]: ...


_Entity: TypeAlias = 'DdsTimer | _ReaderEntity'
_Call: TypeAlias = 'tuple[Callable[..., object], tuple[object, ...]]'


class Completable(Protocol):
    """What ``spin_until_future_complete`` waits for: a future or a task."""

    def done(self) -> bool: ...


def _reader_entities(node: DdsNode) -> list[_ReaderEntity]:
    """Return the node's read-condition entities: subscriptions, clients, services (rclpy)."""
    return [
        *node.subscriptions,
        *getattr(node, 'clients', ()),
        *getattr(node, 'services', ()),
    ]


class ExternalShutdownException(Exception):  # noqa: N818 - rclpy's name
    """The context was shut down (rclpy's ``rclpy.executors.ExternalShutdownException``)."""


class DdsExecutor:
    """
    Runs the callbacks of any number of nodes, scheduled as rclpy's ``Executor`` does.

    A wait is on a Cyclone waitset holding the read condition of every subscription that may
    run now (not handed out already, and its callback group allows it), a guard condition (woken
    when entities change, on shutdown and when a pooled callback ends) and a timeout at the
    earliest deadline of such a timer. What the wait found ready is queued node by node, timers
    first, then subscriptions; :meth:`spin_once` hands out one queued entity per call and waits
    again only once the queue is empty (rclpy's persisted generator), so every entity that was
    ready is served before a timer that is overdue again runs a second time. A subscription
    handed out takes up to 256 waiting samples and runs its callback on each. Where callbacks
    run is the subclass' choice (:meth:`_execute`); ``async def`` callbacks become tasks that
    later spins resume.
    """

    _pooled = False
    """Whether callbacks run in other threads (which then wake the waitset)."""

    def __init__(self, *, context: object = None) -> None:
        del context
        self._nodes: list[DdsNode] = []
        self._lock = threading.RLock()
        self._waitset_participant = _participant()
        self._waitset = dds_wire.WaitSet(self._waitset_participant)
        self._attached: dict[int, _ReaderEntity] = {}
        self._shutdown = False
        self._tasks: list[DdsTask] = []
        self._tasks_lock = threading.Lock()
        self._ready: deque[tuple[DdsNode, _Entity]] = deque()
        """Entities found ready by the last wait and not handed out yet."""
        self._handed_out: set[_Entity] = set()
        """Entities handed out whose data is not taken yet: not waited on (rclpy's flag)."""
        self._handed_out_lock = threading.Lock()
        with _context.lock:
            _context.executors.add(self)

    def __enter__(self) -> DdsExecutor:
        return self

    def __exit__(self, *exc_info: object) -> None:
        self.shutdown()

    def add_node(self, node: DdsNode) -> bool:
        """Add ``node``; returns False when it was already added."""
        with self._lock:
            if node in self._nodes:
                return False
            self._nodes.append(node)
        node._executors.add(self)
        self.wake()
        return True

    def remove_node(self, node: DdsNode) -> None:
        """Remove ``node``."""
        with self._lock:
            if node in self._nodes:
                self._nodes.remove(node)
        node._executors.discard(self)
        self.wake()

    def get_nodes(self) -> list[DdsNode]:
        """Return the nodes of this executor."""
        with self._lock:
            return list(self._nodes)

    def wake(self) -> None:
        """Interrupt a wait so that entity changes or shutdown are seen at once."""
        self._waitset.wake()

    def can_execute(self, entity: _Entity) -> bool:
        """Return whether ``entity`` may be waited on and handed out now (rclpy's rule)."""
        with self._handed_out_lock:
            if entity in self._handed_out:
                return False
        return bool(entity.callback_group.can_execute(entity))

    # -- waiting ---------------------------------------------------------------------------

    def _refresh_conditions(self) -> dict[int, _ReaderEntity]:
        participant = _participant()
        if participant is not self._waitset_participant:
            # The world was shut down and initialised again: the old waitset died with the old
            # participant.
            self._waitset_participant = participant
            self._waitset = dds_wire.WaitSet(participant)
            self._attached = {}
        wanted: dict[int, _ReaderEntity] = {}
        for node in self.get_nodes():
            for entity in _reader_entities(node):
                if self.can_execute(entity):
                    wanted[entity.read_condition] = entity
        for condition in set(self._attached) - set(wanted):
            self._waitset.detach(condition)
        for condition in set(wanted) - set(self._attached):
            self._waitset.attach(condition)
        self._attached = wanted
        return wanted

    def _wait_timeout_ns(self, timeout_sec: float | None) -> int:
        limit = _IDLE_WAIT_NS if timeout_sec is None else int(timeout_sec * 1e9)
        for node in self.get_nodes():
            for timer in node.timers:
                if not self.can_execute(timer):
                    continue
                remaining = timer.time_until_next_call()
                if remaining is None:
                    continue
                if isinstance(timer.clock, ROSClock) and timer.clock.ros_time_is_active:
                    remaining = min(remaining, _SIM_TIME_MAX_WAIT_NS)
                limit = min(limit, remaining)
        return max(0, limit)

    def _collect_ready(self, triggered: list[int], conditions: dict[int, _ReaderEntity]) -> None:
        """Queue what the wait found ready: node by node, due timers, then subscriptions (...)."""
        with_data = {id(conditions[c]) for c in triggered if c in conditions}
        for node in self.get_nodes():
            if node._destroyed:
                continue
            self._ready.extend(
                (node, timer)
                for timer in node.timers
                if timer.is_ready() and self.can_execute(timer)
            )
            self._ready.extend(
                (node, entity)
                for entity in _reader_entities(node)
                if id(entity) in with_data and self.can_execute(entity)
            )

    # -- handing out and running -----------------------------------------------------------

    def _dispatch_next(self) -> bool:
        """Hand out the next queued entity its group lets run; False when none is left."""
        while True:
            try:
                node, entity = self._ready.popleft()
            except IndexError:
                return False
            with self._lock:
                present = node in self._nodes
            if not present or node._destroyed or not self.can_execute(entity):
                # Considered again by the next wait (its data or deadline is still there).
                continue
            with self._handed_out_lock:
                self._handed_out.add(entity)
            self._execute(functools.partial(self._serve, node, entity))
            return True

    def _execute(self, job: Callable[[], None]) -> None:
        """Run ``job`` (a handed-out entity or a task step): here, in the spinning thread."""
        job()

    def _serve(self, node: DdsNode, entity: _Entity) -> None:
        """With the group's permission take the entity's data and run its callback(s)."""
        group = entity.callback_group
        if self._shutdown or not group.beginning_execution(entity):
            # Not now: the entity is waited on again and runs once its group is free.
            self._taken(entity)
            return
        try:
            try:
                calls = self._take(node, entity)
            finally:
                self._taken(entity)
            for callback, args in calls:
                self._run_callback(callback, *args)
        finally:
            group.ending_execution(entity)

    def _taken(self, entity: _Entity) -> None:
        """Let the entity be waited on again: its data is taken (or left for later)."""
        with self._handed_out_lock:
            self._handed_out.discard(entity)
        if self._pooled:
            self.wake()

    def _take(self, node: DdsNode, entity: _Entity) -> list[_Call]:
        """Mark a timer called, or take a reader entity's samples; the calls to make."""
        if node._destroyed:
            return []
        if isinstance(entity, DdsTimer):
            if entity not in node._timers or entity.is_canceled():
                return []
            entity._mark_called()
            return [(entity.callback, ())]
        if entity not in _reader_entities(node):
            return []
        try:
            items = entity.take_messages()
        except dds_wire.DdsWireError:
            if entity in _reader_entities(node):
                raise
            return []  # destroyed while its samples were being taken
        callback = entity.callback
        return [(callback, (msg,) if info is None else (msg, info)) for msg, info in items]

    def _run_callback(self, callback: Callable[..., object], *args: object) -> None:
        # As in rclpy, an exception raised by user code propagates out of spin(), and an
        # ``async def`` callback becomes a task that is resumed on later spins.
        outcome = callback(*args)
        if inspect.iscoroutine(outcome):
            task = DdsTask(outcome)
            task.step()
            if not task.done():
                with self._tasks_lock:
                    self._tasks.append(task)
                return
            error = task.exception()
            if error is not None:
                raise error

    def _raise_pending_error(self) -> None:
        """Re-raise an exception a callback raised in another thread (none here)."""

    # -- tasks -----------------------------------------------------------------------------

    def create_task(self, callback: TaskHandler, *args: object) -> DdsTask:
        """Run a coroutine (or ``callback(*args)``) in this executor; returns its task."""
        task = DdsTask(callback, args)
        with self._tasks_lock:
            self._tasks.append(task)
        self.wake()
        return task

    def _step_task(self, task: DdsTask) -> None:
        try:
            task.step()
        finally:
            task._executing = False
        if not task.done():
            return
        with self._tasks_lock:
            if task in self._tasks:
                self._tasks.remove(task)
        error = task.exception()
        if error is not None:
            raise error

    def _resume_tasks(self) -> bool:
        """Step every pending task not already being stepped; return whether any finished."""
        with self._tasks_lock:
            pending = list(self._tasks)
        finished = False
        for task in pending:
            with self._tasks_lock:
                if task._executing:
                    continue
                task._executing = True
            self._execute(functools.partial(self._step_task, task))
            finished = task.done() or finished
        return finished

    # -- spinning --------------------------------------------------------------------------

    def spin_once(self, timeout_sec: float | None = None) -> None:
        """
        Hand out one ready entity, waiting up to ``timeout_sec`` (None or negative: no limit).

        Entities found ready by the last wait are handed out first, one per call; a new wait
        happens only when none is left. A handed-out subscription drains up to 256 samples.
        Returns also when a task finished, or at the timeout.
        """
        if not _context.ok() or self._shutdown:
            return
        self._raise_pending_error()
        deadline = (
            None if timeout_sec is None or timeout_sec < 0 else time.monotonic() + timeout_sec
        )
        while True:
            if self._dispatch_next():
                self._raise_pending_error()
                return
            if self._resume_tasks():
                return
            conditions = self._refresh_conditions()
            remaining = None if deadline is None else max(0.0, deadline - time.monotonic())
            wait_ns = self._wait_timeout_ns(remaining)
            if self._tasks:
                # A pending task may be waiting for something another thread completes.
                wait_ns = min(wait_ns, _TASK_POLL_NS)
            triggered = self._waitset.wait(wait_ns)
            if not _context.ok() or self._shutdown:
                return
            self._raise_pending_error()
            self._collect_ready(triggered, conditions)
            if not self._ready and deadline is not None and time.monotonic() >= deadline:
                return

    def spin(self) -> None:
        """Run callbacks until :func:`~tf_demo.transport.shutdown` (or :meth:`shutdown`)."""
        while _context.ok() and not self._shutdown:
            self.spin_once(None)

    def spin_until_future_complete(
        self, future: Completable, timeout_sec: float | None = None
    ) -> None:
        """Spin until ``future.done()`` or the timeout."""
        end = None if timeout_sec is None else time.monotonic() + timeout_sec
        while _context.ok() and not self._shutdown and not future.done():
            remaining = None if end is None else end - time.monotonic()
            if remaining is not None and remaining <= 0:
                return
            self.spin_once(0.1 if remaining is None else min(0.1, remaining))

    def shutdown(self, timeout_sec: float | None = None) -> bool:
        """
        Stop spinning, wait for running callbacks and drop the nodes.

        :param timeout_sec: longest wait for running callbacks (None or negative: no limit).
        :return: False when callbacks were still running at the timeout (nodes are kept).
        """
        self._shutdown = True
        self.wake()
        if not self._wait_for_callbacks(timeout_sec):
            return False
        for node in self.get_nodes():
            self.remove_node(node)
        self._ready.clear()
        return True

    def _wait_for_callbacks(self, timeout_sec: float | None) -> bool:
        """Wait for callbacks running in other threads (none here)."""
        del timeout_sec
        return True


class SingleThreadedExecutor(DdsExecutor):
    """rclpy's ``SingleThreadedExecutor``: every callback runs in the spinning thread."""


Executor = DdsExecutor
"""rclpy's name for the executors' base class."""
