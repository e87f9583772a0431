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
Waiting for transforms: blocking and awaitable waits, on a clock, for :class:`~tf_demo.ros.Buffer`.

Event-driven: a blocking wait sleeps on a :class:`threading.Condition` that new data (the core's
insert callback) and clock ticks (the clock's jump callback) notify; there is no polling. An
awaitable wait is a future that new data resolves and a watcher thread fails when its deadline
passes. Deadlines are read on the buffer's clock, so they follow sim time.

A blocking wait returns at once when data cannot arrive while it waits: the waiting thread is the
only one that ever delivered data, it is no thread-pool worker (rclpy's
``MultiThreadedExecutor``), and no dedicated thread fills the buffer (see the module docstring of
:mod:`tf_demo.ros.buffer`).
"""

from __future__ import annotations

from collections.abc import Callable
import threading
from typing import Generic
from typing import TypeVar

from tf_demo.core.exceptions import TimeoutException
from tf_demo.transport.future import Future

__all__ = ['DEDICATED_THREAD_WARNING', 'BufferWaits']

R = TypeVar('R')

POOL_THREAD_PREFIX = 'ThreadPoolExecutor'
"""Name prefix of ``concurrent.futures`` worker threads (rclpy's MultiThreadedExecutor)."""
MAX_WAIT_SLICE_S = 1.0
"""Longest single condition wait; bounds how late a deadline on a silent clock is noticed."""

DEDICATED_THREAD_WARNING = (
    'Do not call canTransform or lookupTransform with a timeout unless you are using another '
    'thread for populating data. Without a dedicated thread it will always timeout.  If you '
    'have a separate thread servicing tf messages, call setUsingDedicatedThread(true) on your '
    'Buffer instance.'
)


class _AsyncWait(Generic[R]):
    """One pending asynchronous wait: its readiness check, its lookup and its deadline."""

    __slots__ = ('deadline_ns', 'future', 'lookup', 'ready', 'timeout_text')

    def __init__(
        self, ready: Callable[[], bool], lookup: Callable[[], R], timeout_text: str
    ) -> None:
        self.timeout_text = timeout_text
        self.ready = ready
        self.lookup = lookup
        self.deadline_ns: int | None = None
        """When the wait fails on the clock (ns); None waits forever."""
        self.future: Future[R] = Future()

    def resolve(self) -> None:
        """Finish the future with the lookup's result or exception."""
        try:
            result = self.lookup()
        except Exception as error:
            self.future.set_exception(error)
        else:
            self.future.set_result(result)

    def expired(self, now_ns: int | None) -> bool:
        """Whether the deadline passed at ``now_ns`` (None: not a deadline check)."""
        return now_ns is not None and self.deadline_ns is not None and now_ns >= self.deadline_ns


class BufferWaits(Generic[R]):
    """
    The waits of one buffer, whose lookups give ``R``.

    :param now_ns: the buffer's clock, in integer nanoseconds.
    :param warn: logs the dedicated-thread warning (once).
    """

    def __init__(self, now_ns: Callable[[], int], warn: Callable[[str], object]) -> None:
        self._now_ns = now_ns
        self._warn = warn
        self._condition = threading.Condition()
        self._blocked_waits = 0
        """Threads inside :meth:`wait_until`'s condition wait (changed under ``_condition``)."""
        self._async_waits: list[_AsyncWait[R]] = []
        self._watcher: threading.Thread | None = None
        self._dedicated_thread = False
        self._feeder_threads: set[int] = set()
        self._warned_no_dedicated_thread = False

    def wake(self) -> None:
        """Wake every blocking wait (new data or a clock tick), to check again."""
        with self._condition:
            self._condition.notify_all()

    def on_new_data(self) -> None:
        """Wake blocking waits (if any) and resolve asynchronous ones (the insert callback)."""
        # A waiter registers under the lock before it checks its condition, so one that
        # registers after this read sees the inserted data itself: no wake-up is lost.
        if self._blocked_waits:
            self.wake()
        if self._async_waits:
            self._service(now_ns=None)

    def note_feeder_thread(self) -> None:
        """Record that the calling thread delivers transforms."""
        ident = threading.get_ident()
        if ident not in self._feeder_threads:
            with self._condition:
                self._feeder_threads.add(ident)

    def set_using_dedicated_thread(self, value: bool) -> None:
        """Declare that a thread other than the callers' fills the buffer."""
        self._dedicated_thread = value

    def _data_can_arrive_while_waiting(self) -> bool:
        if self._dedicated_thread:
            return True
        current = threading.current_thread()
        if current.name.startswith(POOL_THREAD_PREFIX):
            return True  # a multi-threaded executor: another worker can deliver meanwhile
        with self._condition:
            feeders = set(self._feeder_threads)
        return feeders != {current.ident}

    def wait_until(self, ready: Callable[[], bool], timeout_ns: int) -> None:
        """Block until ``ready()`` or until ``timeout_ns`` passed on the clock."""
        if timeout_ns <= 0 or ready():
            return
        if not self._data_can_arrive_while_waiting():
            if not self._warned_no_dedicated_thread:
                self._warned_no_dedicated_thread = True
                self._warn(DEDICATED_THREAD_WARNING)
            return
        deadline_ns = self._now_ns() + timeout_ns
        with self._condition:
            self._blocked_waits += 1
            try:
                while not ready():
                    remaining_ns = deadline_ns - self._now_ns()
                    if remaining_ns <= 0:
                        return
                    self._condition.wait(min(remaining_ns / 1e9, MAX_WAIT_SLICE_S))
            finally:
                self._blocked_waits -= 1

    def wait_async(
        self,
        ready: Callable[[], bool],
        lookup: Callable[[], R],
        timeout_ns: int | None,
        timeout_text: str,
    ) -> Future[R]:
        """
        Return a future of ``lookup()``, done once ``ready()``; None waits forever.

        When ``timeout_ns`` passes on the clock first, the future fails with
        :class:`~tf_demo.core.exceptions.TimeoutException` (``timeout_text``).
        """
        wait = _AsyncWait(ready, lookup, timeout_text)
        if ready():
            wait.resolve()
            return wait.future
        if timeout_ns is not None:
            wait.deadline_ns = self._now_ns() + timeout_ns
        wait.future.add_done_callback(lambda _: self._forget(wait))
        with self._condition:
            self._async_waits.append(wait)
            if wait.deadline_ns is not None:
                self._ensure_watcher()
        # Data may have arrived between the first check and the registration.
        self._service(now_ns=None)
        return wait.future

    def _forget(self, wait: _AsyncWait[R]) -> None:
        with self._condition:
            if wait in self._async_waits:
                self._async_waits.remove(wait)

    def _service(self, now_ns: int | None) -> None:
        """Resolve ready waits; fail expired ones when ``now_ns`` is given."""
        with self._condition:
            pending = list(self._async_waits)
        for wait in pending:
            if wait.future.done():
                continue
            try:
                is_ready = wait.ready()
            except Exception as error:
                wait.future.set_exception(error)
                continue
            if is_ready:
                wait.resolve()
            elif wait.expired(now_ns):
                wait.future.set_exception(TimeoutException(wait.timeout_text))

    def _ensure_watcher(self) -> None:
        """Start the deadline watcher thread if it is not running (caller holds the lock)."""
        if self._watcher is not None and self._watcher.is_alive():
            return
        self._watcher = threading.Thread(
            target=self._watch_deadlines, name='tf_demo_buffer_deadlines', daemon=True
        )
        self._watcher.start()

    def _watch_deadlines(self) -> None:
        """Fail asynchronous waits whose deadline passed on the clock."""
        while True:
            now_ns = self._now_ns()
            self._service(now_ns)
            with self._condition:
                deadlines = [
                    w.deadline_ns
                    for w in self._async_waits
                    if w.deadline_ns is not None and not w.future.done()
                ]
                if not deadlines:
                    self._watcher = None
                    return
                remaining_ns = min(deadlines) - self._now_ns()
                if remaining_ns > 0:
                    self._condition.wait(min(remaining_ns / 1e9, MAX_WAIT_SLICE_S))
