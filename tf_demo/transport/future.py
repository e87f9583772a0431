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
A thread-safe future with ``rclpy.task.Future``'s API: the buffer's waits, service calls.

It can be awaited from an rclpy or tf_demo executor task (``__await__`` yields until done, as
rclpy's does), passed to ``spin_until_future_complete`` (which only needs ``done()`` and
``add_done_callback``), or waited on from a plain thread with :meth:`Future.wait`.
"""

from __future__ import annotations

from collections.abc import Callable
from collections.abc import Generator
import threading
from typing import cast
from typing import Generic
from typing import TypeVar

T = TypeVar('T')


class Future(Generic[T]):
    """
    The result of work that completes later: a value, an exception, or cancellation.

    Done callbacks run in the thread that completes the future (or at once, when added to a
    future that is already done).
    """

    def __init__(self) -> None:
        """Create a pending future."""
        self._lock = threading.Lock()
        self._event = threading.Event()
        self._result: T | None = None
        self._exception: BaseException | None = None
        self._cancelled = False
        self._callbacks: list[Callable[[Future[T]], object]] = []

    def done(self) -> bool:
        """Return whether a result or an exception was set, or the future was cancelled."""
        return self._event.is_set()

    def cancelled(self) -> bool:
        """Return whether the future was cancelled."""
        return self._cancelled

    def cancel(self) -> None:
        """Cancel the future if it is still pending; waiters then stop waiting for it."""
        self._complete(cancelled=True)

    def result(self) -> T:
        """
        Return the result, or raise the exception that was set.

        :return: the result; ``None`` while pending or after cancellation, as rclpy does.
        """
        if self._exception is not None:
            raise self._exception
        return cast('T', self._result)

    def exception(self) -> BaseException | None:
        """Return the exception that was set, if any."""
        return self._exception

    def set_result(self, result: T) -> None:
        """Complete the future with a value (ignored if it is already done)."""
        self._complete(result=result)

    def set_exception(self, exception: BaseException) -> None:
        """Complete the future with an exception (ignored if it is already done)."""
        self._complete(exception=exception)

    def add_done_callback(self, callback: Callable[[Future[T]], object]) -> None:
        """Call ``callback(future)`` when the future is done (at once if it already is)."""
        with self._lock:
            if not self._event.is_set():
                self._callbacks.append(callback)
                return
        callback(self)

    def wait(self, timeout_sec: float | None = None) -> bool:
        """
        Block the calling thread until the future is done (wall-clock ``timeout_sec``).

        :return: whether the future is done.
        """
        return self._event.wait(timeout_sec)

    def __await__(self) -> Generator[None, None, T]:
        """Yield to the executor until done, then return the result (or raise)."""
        while not self._event.is_set():
            yield None
        return self.result()

    def _complete(
        self,
        *,
        result: T | None = None,
        exception: BaseException | None = None,
        cancelled: bool = False,
    ) -> None:
        with self._lock:
            if self._event.is_set():
                return
            self._result = result
            self._exception = exception
            self._cancelled = cancelled
            callbacks, self._callbacks = self._callbacks, []
            self._event.set()
        for callback in callbacks:
            callback(self)
