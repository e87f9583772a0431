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


"""Buffer's waits (tf_demo.ros.buffer_waits): blocking and awaitable, on real (sim) clocks."""

from __future__ import annotations

from collections.abc import Callable
from concurrent.futures import ThreadPoolExecutor
import threading

import pytest
from test_buffer import S
from test_buffer import sim_clock
from test_buffer import transform_msg
from tf_demo.core.exceptions import LookupException
from tf_demo.core.exceptions import TimeoutException
from tf_demo.ros import Buffer
from tf_demo.transport.clock import Duration
from tf_demo.transport.clock import Time

HANG_GUARD_S = 10.0


def in_thread(target: Callable[[], object]) -> tuple[threading.Thread, dict[str, object]]:
    """Run ``target()`` in a thread; its result or exception lands in the returned dict."""
    box: dict[str, object] = {}

    def run() -> None:
        try:
            box['result'] = target()
        except Exception as error:
            box['error'] = error

    thread = threading.Thread(target=run, daemon=True)
    thread.start()
    return thread, box


def test_blocking_wait_is_resolved_by_data_inserted_after_it_started() -> None:
    """A wait with a long timeout returns True once another thread inserts the transform."""
    buffer = Buffer()
    started = threading.Event()

    def wait() -> object:
        started.set()
        return buffer.can_transform('a', 'b', 0, Duration(seconds=HANG_GUARD_S * 3))

    thread, box = in_thread(wait)
    assert started.wait(HANG_GUARD_S)
    assert not buffer.can_transform('a', 'b', 0)
    buffer.set_transform(transform_msg('a', 'b', S), 'x')
    thread.join(HANG_GUARD_S)
    assert box == {'result': True}


def test_blocking_timeout_is_measured_on_the_sim_clock() -> None:
    """With a paused sim clock the wait keeps waiting; once /clock passes the timeout it fails."""
    clock = sim_clock(100.0)
    buffer = Buffer(clock=clock)
    thread, box = in_thread(lambda: buffer.lookup_transform('a', 'b', 0, Duration(seconds=2)))
    clock.set_ros_time_override(Time(seconds=101.0))
    thread.join(0.3)
    assert thread.is_alive(), 'the wait ended before 2 s of sim time passed'
    clock.set_ros_time_override(Time(seconds=102.5))
    thread.join(HANG_GUARD_S)
    assert not thread.is_alive()
    assert isinstance(box.get('error'), LookupException)


def test_wait_in_the_only_feeder_thread_returns_at_once() -> None:
    """A thread that delivers /tf itself cannot receive data while it waits: no deadlock."""
    clock = sim_clock(5.0)
    buffer = Buffer(clock=clock)

    def feeder_waits() -> object:
        buffer.note_feeder_thread()
        return buffer.can_transform('a', 'b', 0, Duration(seconds=1000))

    thread, box = in_thread(feeder_waits)
    thread.join(HANG_GUARD_S)
    assert box == {'result': False}


def test_dedicated_thread_makes_the_feeder_wait_block_again() -> None:
    """With set_using_dedicated_thread(True) the same wait blocks until data arrives."""
    buffer = Buffer()
    buffer.set_using_dedicated_thread(True)
    started = threading.Event()

    def feeder_waits() -> object:
        buffer.note_feeder_thread()
        started.set()
        return buffer.can_transform('a', 'b', 0, Duration(seconds=HANG_GUARD_S * 3))

    thread, box = in_thread(feeder_waits)
    assert started.wait(HANG_GUARD_S)
    buffer.set_transform(transform_msg('a', 'b', S), 'x')
    thread.join(HANG_GUARD_S)
    assert box == {'result': True}


def test_async_wait_resolves_to_the_transform_when_data_arrives() -> None:
    """wait_for_transform_async's future resolves to the TransformStamped after an insert."""
    buffer = Buffer()
    future = buffer.wait_for_transform_async('a', 'b', 0)
    assert not future.done()
    buffer.set_transform(transform_msg('a', 'b', S, (4.0, 0.0, 0.0)), 'x')
    assert future.done()
    assert future.result().transform.translation.x == 4.0


def test_async_lookup_coroutine_driven_by_hand() -> None:
    """lookup_transform_async (upstream's test pattern): send(None), insert, StopIteration."""
    buffer = Buffer()
    coro = buffer.lookup_transform_async('a', 'b', Time(seconds=3))
    coro.send(None)
    buffer.set_transform(transform_msg('a', 'b', 3 * S, (0.0, 5.0, 0.0)), 'x')
    with pytest.raises(StopIteration) as stop:
        coro.send(None)
    assert stop.value.value.transform.translation.y == 5.0


def test_async_timeout_raises_timeout_exception_on_sim_time() -> None:
    """An awaitable wait with a timeout fails with TimeoutException once sim time passes it."""
    clock = sim_clock(50.0)
    buffer = Buffer(clock=clock)
    future = buffer.wait_for_transform_async('a', 'b', 0, timeout=Duration(seconds=1))
    clock.set_ros_time_override(Time(seconds=50.5))
    assert not future.wait(0.3)
    clock.set_ros_time_override(Time(seconds=51.5))
    assert future.wait(HANG_GUARD_S)
    assert isinstance(future.exception(), TimeoutException)
    with pytest.raises(TimeoutException, match=r'from \[b\] to \[a\]'):
        future.result()


def test_async_wall_clock_timeout() -> None:
    """Without a node the system clock measures the async timeout."""
    buffer = Buffer()
    future = buffer.wait_for_transform_async('a', 'b', 0, timeout=Duration(seconds=0.2))
    assert future.wait(HANG_GUARD_S)
    assert isinstance(future.exception(), TimeoutException)


def test_async_full_wait_resolves() -> None:
    """wait_for_transform_full_async resolves once both times are available."""
    buffer = Buffer()
    buffer.set_transform(transform_msg('odom', 'base', 1 * S, (1.0, 0.0, 0.0)), 'x')
    future = buffer.wait_for_transform_full_async('base', 2 * S, 'base', 1 * S, 'odom')
    assert not future.done()
    buffer.set_transform(transform_msg('odom', 'base', 2 * S, (3.0, 0.0, 0.0)), 'x')
    assert future.result().transform.translation.x == pytest.approx(-2.0)


def test_thread_pool_workers_keep_blocking_waits() -> None:
    """In a MultiThreadedExecutor worker another worker may deliver: the wait blocks for data."""
    buffer = Buffer()
    started = threading.Event()

    def worker_waits() -> bool:
        buffer.note_feeder_thread()
        started.set()
        return bool(buffer.can_transform('a', 'b', 0, Duration(seconds=HANG_GUARD_S * 3)))

    with ThreadPoolExecutor(max_workers=1) as pool:
        future = pool.submit(worker_waits)
        assert started.wait(HANG_GUARD_S)
        buffer.set_transform(transform_msg('a', 'b', S), 'x')
        assert future.result(timeout=HANG_GUARD_S) is True
