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
The multi-threaded executor behaves as rclpy Jazzy's, in both worlds.

Written against the node API only (``tf_demo.transport``), so the same assertions run on the
standalone backend and on real rclpy: ``MultiThreadedExecutor`` runs callbacks in a pool and
honours reentrant and mutually exclusive groups, an exception raised in a pool thread comes out
of ``spin_once``, and the TF2 guide's blocking lookup in a reentrant timer works. Waits are on
events and barriers with generous timeouts, never on durations.
"""

from __future__ import annotations

from collections.abc import Callable
import threading
import time
from typing import Any

from conftest import executor_with
import pytest
from tf_demo import transport
from tf_demo.core.exceptions import TransformException
from tf_demo.nodes.helpers import make_transform_stamped
from tf_demo.ros import Buffer
from tf_demo.ros import StaticTransformBroadcaster
from tf_demo.ros import TransformListener
from tf_demo.transport.callback_groups import MutuallyExclusiveCallbackGroup
from tf_demo.transport.callback_groups import ReentrantCallbackGroup
from tf_demo.transport.clock import Duration
from tf_demo.transport.clock import Time
from tf_demo.transport.executors import MultiThreadedExecutor
from tf_demo.transport.messages import std_msgs

pytestmark = pytest.mark.dds

DEADLINE_S = 30.0
"""Upper bound for anything to happen (discovery, scheduling on a loaded machine)."""
EVENT_TIMEOUT_S = 10.0
"""How long a callback waits for a partner (barrier, event) before giving up."""


def spin_until(executor: Any, done: Callable[[], bool], timeout_s: float = DEADLINE_S) -> bool:
    """Spin ``executor`` in this thread until ``done()`` or the (generous) deadline."""
    deadline = time.monotonic() + timeout_s
    while not done() and time.monotonic() < deadline:
        executor.spin_once(timeout_sec=0.1)
    return done()


def multi_threaded(executors: list[Any], *nodes: Any, num_threads: int = 2) -> Any:
    return executor_with(executors, MultiThreadedExecutor(num_threads=num_threads), *nodes)


def test_multi_threaded_reentrant_group_runs_two_callbacks_at_once(
    executors: list[Any],
) -> None:
    """Two timers of a reentrant group both pass a two-party barrier: they run concurrently."""
    node = transport.create_node('reentrant_node')
    group = ReentrantCallbackGroup()
    barrier = threading.Barrier(2)
    outcomes: dict[str, bool] = {}
    timers: dict[str, Any] = {}
    spinning_thread = threading.get_ident()
    callback_threads: set[int] = set()

    def make_callback(name: str) -> Callable[[], None]:
        def on_timer() -> None:
            timers[name].cancel()  # once each: a second run of the same timer cannot pair up
            callback_threads.add(threading.get_ident())
            try:
                barrier.wait(timeout=EVENT_TIMEOUT_S)
            except threading.BrokenBarrierError:
                outcomes[name] = False
            else:
                outcomes[name] = True

        return on_timer

    for name in ('first', 'second'):
        timers[name] = node.create_timer(0.05, make_callback(name), callback_group=group)
    executor = multi_threaded(executors, node)
    assert spin_until(executor, lambda: len(outcomes) == 2)
    assert outcomes == {'first': True, 'second': True}
    assert spinning_thread not in callback_threads
    assert len(callback_threads) == 2


@pytest.mark.parametrize('group_kind', ['explicit', 'node_default'])
def test_multi_threaded_mutually_exclusive_group_never_overlaps(
    executors: list[Any], group_kind: str
) -> None:
    """Two always-due timers of one mutually exclusive group both run, never at the same time."""
    node = transport.create_node('exclusive_node')
    group = MutuallyExclusiveCallbackGroup() if group_kind == 'explicit' else None
    runs_each = 2
    lock = threading.Lock()
    state = {'active': 0, 'most_active': 0}
    runs = {'first': 0, 'second': 0}
    timers: dict[str, Any] = {}

    def make_callback(name: str) -> Callable[[], None]:
        def on_timer() -> None:
            with lock:
                state['active'] += 1
                state['most_active'] = max(state['most_active'], state['active'])
                runs[name] += 1
                if runs[name] >= runs_each:
                    timers[name].cancel()
            time.sleep(0.2)  # ample room for the other timer to start, were it allowed to
            with lock:
                state['active'] -= 1

        return on_timer

    for name in ('first', 'second'):
        timers[name] = node.create_timer(0.05, make_callback(name), callback_group=group)
    expected_group = node.default_callback_group if group is None else group
    assert all(expected_group.has_entity(timer) for timer in timers.values())
    executor = multi_threaded(executors, node)

    def both_done() -> bool:
        with lock:
            return min(runs.values()) >= runs_each and state['active'] == 0

    assert spin_until(executor, both_done), f'runs: {runs}'
    assert state['most_active'] == 1


def test_multi_threaded_groups_do_not_hold_each_other_back(executors: list[Any]) -> None:
    """A timer blocked in the node's default group; a subscription in another group runs."""
    node = transport.create_node('two_groups_node')
    message_seen = threading.Event()
    waits: list[bool] = []

    def on_timer() -> None:
        timer.cancel()
        waits.append(message_seen.wait(timeout=EVENT_TIMEOUT_S))

    timer = node.create_timer(0.05, on_timer)
    node.create_subscription(
        std_msgs.String,
        'other_group',
        lambda _msg: message_seen.set(),
        10,
        callback_group=MutuallyExclusiveCallbackGroup(),
    )
    talker = transport.create_node('other_group_talker')
    publisher = talker.create_publisher(std_msgs.String, 'other_group', 10)
    executor = multi_threaded(executors, node)
    assert spin_until(executor, lambda: bool(timer.is_canceled()))
    deadline = time.monotonic() + DEADLINE_S
    while not waits and time.monotonic() < deadline:
        if publisher.get_subscription_count() > 0:
            publisher.publish(std_msgs.String(data='wake up'))
        executor.spin_once(timeout_sec=0.1)
    assert waits == [True], 'the subscription did not run while the timer callback waited'


def test_multi_threaded_callback_exception_comes_out_of_spin_once(executors: list[Any]) -> None:
    """An exception raised by a callback in a pool thread is raised by spin_once."""

    class CallbackFailedError(Exception):
        pass

    node = transport.create_node('failing_node')
    threads: list[int] = []

    def on_timer() -> None:
        threads.append(threading.get_ident())
        msg = 'raised in a pool thread'
        raise CallbackFailedError(msg)

    node.create_timer(0.05, on_timer)
    executor = multi_threaded(executors, node)
    with pytest.raises(CallbackFailedError, match='raised in a pool thread'):
        spin_until(executor, lambda: False)
    assert threads
    assert threading.get_ident() not in threads


def test_tf2_guide_blocking_lookup_in_a_reentrant_timer_of_a_multi_threaded_executor(
    executors: list[Any],
) -> None:
    """The guide's listener: a reentrant timer blocks in lookup_transform(timeout=1 s)."""
    node = transport.create_node('frame_listener')
    buffer = Buffer()
    listener = TransformListener(buffer, node)
    attempted = threading.Event()
    found: list[Any] = []

    def on_timer() -> None:
        attempted.set()
        try:
            transform = buffer.lookup_transform(
                'world', 'turtle1', Time(), timeout=Duration(seconds=1)
            )
        except TransformException:
            return
        found.append(transform)

    node.create_timer(0.5, on_timer, callback_group=ReentrantCallbackGroup())
    broadcaster_node = transport.create_node('turtle_static_broadcaster')
    broadcaster = StaticTransformBroadcaster(broadcaster_node)
    executor = multi_threaded(executors, node, num_threads=4)
    try:
        assert spin_until(executor, attempted.is_set)
        broadcaster.send_transform(
            make_transform_stamped('world', 'turtle1', 0, (1.0, 2.0, 0.0), (0.0, 0.0, 0.0, 1.0))
        )
        assert spin_until(executor, lambda: bool(found))
    finally:
        listener.unregister()
    translation = found[0].transform.translation
    assert (translation.x, translation.y, translation.z) == (1.0, 2.0, 0.0)
    assert (found[0].header.frame_id, found[0].child_frame_id) == ('world', 'turtle1')


@pytest.mark.standalone
def test_multi_threaded_shutdown_waits_for_running_callbacks(executors: list[Any]) -> None:
    """shutdown(timeout_sec) reports a callback still running, then waits for it to end.

    Standalone only: rclpy Jazzy's ``Executor.shutdown`` never waits for callbacks (its
    ``_work_tracker`` wait is unreachable) and its MultiThreadedExecutor never joins the pool;
    later rclpy releases do both.
    """
    node = transport.create_node('shutdown_node')
    started = threading.Event()
    release = threading.Event()
    finished = threading.Event()

    def on_timer() -> None:
        timer.cancel()
        started.set()
        release.wait(timeout=EVENT_TIMEOUT_S)
        finished.set()

    timer = node.create_timer(0.05, on_timer)
    executor = MultiThreadedExecutor(num_threads=2)
    executor.add_node(node)
    assert spin_until(executor, started.is_set)
    assert executor.shutdown(timeout_sec=0) is False
    assert not finished.is_set()
    release.set()
    assert executor.shutdown(timeout_sec=EVENT_TIMEOUT_S) is True
    assert finished.is_set()
    assert executor.get_nodes() == []
