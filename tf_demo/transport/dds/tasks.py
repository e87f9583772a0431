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

"""Tasks: coroutines (or plain callables) that a DDS executor steps (rclpy ``Task`` subset)."""

from __future__ import annotations

from collections.abc import Callable
from collections.abc import Coroutine
from collections.abc import Sequence
import inspect
from typing import TypeAlias

__all__ = ['DdsTask', 'TaskHandler']

TaskHandler: TypeAlias = 'Coroutine[object, object, object] | Callable[..., object]'
"""What a task runs: a coroutine, or a callable (an ``async def`` function, or a plain one)."""


class DdsTask:
    """
    A coroutine (or plain callable) run by a DDS executor: rclpy's ``Task`` subset.

    The executor steps the coroutine with ``send(None)`` when it starts and again on every
    spin until it returns; awaiting a future that yields until done (rclpy's and
    ``tf_demo.ros.Future``'s protocol) therefore works.
    """

    def __init__(self, handler: TaskHandler, args: Sequence[object] = ()) -> None:
        self._handler = handler
        self._function = handler if callable(handler) else None
        self._args = tuple(args)
        self._coroutine: Coroutine[object, object, object] | None = (
            handler if inspect.iscoroutine(handler) else None
        )
        self._done = False
        self._cancelled = False
        self._result: object = None
        self._exception: BaseException | None = None
        self._done_callbacks: list[Callable[[DdsTask], object]] = []
        self._executing = False

    def executing(self) -> bool:
        """Return whether a step of the task is running (or queued in a thread pool)."""
        return self._executing

    def done(self) -> bool:
        """Return whether the task finished (returned, raised or was cancelled)."""
        return self._done

    def cancelled(self) -> bool:
        """Return whether the task was cancelled."""
        return self._cancelled

    def cancel(self) -> None:
        """Stop stepping the task."""
        if not self._done:
            self._cancelled = True
            if self._coroutine is not None:
                self._coroutine.close()
            self._finish()

    def result(self) -> object:
        """Return the task's result; re-raise its exception if it failed."""
        if self._exception is not None:
            raise self._exception
        return self._result

    def exception(self) -> BaseException | None:
        """Return the exception the task raised, if any."""
        return self._exception

    def add_done_callback(self, callback: Callable[[DdsTask], object]) -> None:
        """Call ``callback(task)`` when the task finishes (at once if it already has)."""
        if self._done:
            callback(self)
        else:
            self._done_callbacks.append(callback)

    def step(self) -> None:
        """Run the task until its next suspension point (or to the end)."""
        if self._done:
            return
        try:
            if self._coroutine is None:
                if self._function is None:
                    msg = f"'{type(self._handler).__name__}' object is not callable"
                    raise TypeError(msg)
                outcome = self._function(*self._args)
                if not inspect.iscoroutine(outcome):
                    self._result = outcome
                    self._finish()
                    return
                self._coroutine = outcome
            self._coroutine.send(None)
        except StopIteration as stop:
            self._result = stop.value
            self._finish()
        except Exception as error:  # kept for result(); the executor re-raises it
            self._exception = error
            self._finish()

    def _finish(self) -> None:
        self._done = True
        callbacks, self._done_callbacks = self._done_callbacks, []
        for callback in callbacks:
            callback(self)
