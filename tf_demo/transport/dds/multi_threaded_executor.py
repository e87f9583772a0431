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

"""rclpy's ``MultiThreadedExecutor`` over the waitset executor: callbacks run in a thread pool."""

from __future__ import annotations

from collections import deque
from collections.abc import Callable
from concurrent.futures import ThreadPoolExecutor
import os
import threading
import warnings

from tf_demo.transport.dds.executors import DdsExecutor

__all__ = ['MultiThreadedExecutor']


def _default_thread_count() -> int:
    """Return rclpy's default pool size: the CPUs this process may use, else the count, or 2."""
    if hasattr(os, 'sched_getaffinity'):
        return len(os.sched_getaffinity(0)) or 2
    return os.cpu_count() or 2


class MultiThreadedExecutor(DdsExecutor):
    """
    rclpy's ``MultiThreadedExecutor``: callbacks run in a pool of ``num_threads`` threads.

    The spinning thread waits and hands entities out; a pool thread then asks the entity's
    callback group for permission (a mutually exclusive group runs one callback at a time, a
    reentrant one any number, even several of the same entity), takes the data, runs the
    callback and wakes the waitset, so an entity its group held back is considered again. An
    exception raised by a callback is re-raised in the spinning thread by the next
    :meth:`spin_once`. :meth:`shutdown` waits for running callbacks, then stops the pool.

    :param num_threads: pool size; None: the CPUs this process may use (as rclpy).
    """

    _pooled = True

    def __init__(self, num_threads: int | None = None, *, context: object = None) -> None:
        if num_threads is None:
            num_threads = _default_thread_count()
        self._pool = ThreadPoolExecutor(num_threads)  # worker names: 'ThreadPoolExecutor-...'
        super().__init__(context=context)
        if num_threads == 1:
            warnings.warn(
                'MultiThreadedExecutor is used with a single thread.\n'
                'Use the SingleThreadedExecutor instead.',
                stacklevel=2,
            )
        self._errors: deque[BaseException] = deque()
        self._work = threading.Condition()
        self._outstanding = 0
        """Jobs submitted to the pool and not finished."""
        self._job_thread = threading.local()

    def _execute(self, job: Callable[[], None]) -> None:
        """Run ``job`` in the pool."""
        with self._work:
            self._outstanding += 1
        try:
            self._pool.submit(self._run_job, job)
        except RuntimeError:  # the pool was stopped by a concurrent shutdown()
            self._job_finished()
            if not self._shutdown:
                raise

    def _run_job(self, job: Callable[[], None]) -> None:
        self._job_thread.active = True
        try:
            job()
        except BaseException as error:  # re-raised in the spinning thread by spin_once
            self._errors.append(error)
        finally:
            self._job_thread.active = False
            self._job_finished()
            self.wake()

    def _job_finished(self) -> None:
        with self._work:
            self._outstanding -= 1
            self._work.notify_all()

    def _raise_pending_error(self) -> None:
        """Re-raise the oldest exception a pooled callback raised."""
        try:
            error = self._errors.popleft()
        except IndexError:
            return
        raise error

    def _wait_for_callbacks(self, timeout_sec: float | None) -> bool:
        """Wait for the pool's jobs (not the calling one, from a callback) and stop the pool."""
        own = 1 if getattr(self._job_thread, 'active', False) else 0
        limit = None if timeout_sec is None or timeout_sec < 0 else timeout_sec
        with self._work:
            if not self._work.wait_for(lambda: self._outstanding <= own, limit):
                return False
        self._pool.shutdown(wait=not own)
        return True
