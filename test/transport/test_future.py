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

"""The thread-safe Future (``rclpy.task.Future``'s API), the same object in both worlds."""

from __future__ import annotations

import threading

import pytest
from tf_demo.transport.future import Future


def test_a_value_completes_the_future_once_and_reaches_every_callback() -> None:
    """Callbacks added before completion run then, later ones at once; a second value is lost."""
    future: Future[int] = Future()
    seen: list[tuple[str, int]] = []
    future.add_done_callback(lambda done: seen.append(('before', done.result())))
    assert not future.done()
    assert future.result() is None
    future.set_result(7)
    future.set_result(8)
    future.add_done_callback(lambda done: seen.append(('after', done.result())))
    assert future.done()
    assert not future.cancelled()
    assert future.result() == 7
    assert seen == [('before', 7), ('after', 7)]


def test_an_exception_is_raised_by_result() -> None:
    """set_exception completes the future; result() raises it and exception() returns it."""
    future: Future[int] = Future()
    error = ArithmeticError('no answer')
    future.set_exception(error)
    assert future.done()
    assert future.exception() is error
    with pytest.raises(ArithmeticError, match='no answer'):
        future.result()


def test_cancel_completes_a_pending_future_without_a_result() -> None:
    """A cancelled future is done with no result; cancelling a done future changes nothing."""
    pending: Future[str] = Future()
    pending.cancel()
    assert pending.done()
    assert pending.cancelled()
    assert pending.result() is None  # rclpy's: no result after cancellation
    finished: Future[str] = Future()
    finished.set_result('kept')
    finished.cancel()
    assert (finished.cancelled(), finished.result()) == (False, 'kept')


def test_a_thread_waits_for_the_value_another_thread_sets() -> None:
    """wait() returns True once another thread completes the future (an Event, no polling)."""
    future: Future[str] = Future()
    setter = threading.Thread(target=future.set_result, args=('from a thread',))
    setter.start()
    assert future.wait(timeout_sec=30)
    setter.join()
    assert future.result() == 'from a thread'


def test_awaiting_yields_until_done_then_returns_the_result() -> None:
    """``await future`` yields to the executor while pending, then gives the result."""
    future: Future[int] = Future()

    async def waiter() -> int:
        return await future

    coroutine = waiter()
    assert coroutine.send(None) is None  # pending: yields to the executor
    future.set_result(42)
    with pytest.raises(StopIteration) as stopped:
        coroutine.send(None)
    assert stopped.value.value == 42
