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

"""TransformListener and the broadcasters over real DDS on loopback (in-process and spawned)."""

from __future__ import annotations

from collections.abc import Callable
import subprocess
import sys
import threading
import time
from typing import Any

import pytest
from tf_demo import transport
from tf_demo.core.exceptions import LookupException
from tf_demo.core.exceptions import TimeoutException
from tf_demo.nodes.helpers import make_transform_stamped
from tf_demo.ros import Buffer
from tf_demo.ros import StaticTransformBroadcaster
from tf_demo.ros import TransformBroadcaster
from tf_demo.ros import TransformListener
from tf_demo.transport.clock import Duration
from tf_demo.transport.executors import SingleThreadedExecutor
from tf_demo.transport.messages import rosgraph_msgs
from tf_demo.transport.messages import tf2_msgs
from tf_demo.transport.parameters import Parameter
from tf_demo.transport.qos import StaticListenerQoS

pytestmark = pytest.mark.dds

S = 1_000_000_000
DISCOVERY_TIMEOUT_S = 20.0


def wait_for(condition: Callable[[], bool], timeout_s: float = DISCOVERY_TIMEOUT_S) -> bool:
    """Bounded wait for something that arrives over the network (not a timing assertion)."""
    deadline = time.monotonic() + timeout_s
    while time.monotonic() < deadline:
        if condition():
            return True
        time.sleep(0.02)
    return condition()


class Spinner:
    """Spins some nodes in a background executor thread for the duration of a test."""

    def __init__(self, *nodes: Any) -> None:
        self.executor = SingleThreadedExecutor()
        for node in nodes:
            self.executor.add_node(node)
        self._stop = threading.Event()
        self.thread = threading.Thread(target=self._run, daemon=True)
        self.thread.start()

    def _run(self) -> None:
        while not self._stop.is_set():
            self.executor.spin_once(timeout_sec=0.05)

    def stop(self) -> None:
        self._stop.set()
        self.thread.join(5.0)


def translation(msg: Any) -> tuple[float, float, float]:
    t = msg.transform.translation
    return (t.x, t.y, t.z)


def test_static_broadcaster_replaces_by_child_and_late_listener_gets_the_set(ros: None) -> None:
    """Resending a child replaces it (C++ semantics); a late listener receives the whole set."""
    publisher = transport.create_node('static_pub')
    broadcaster = StaticTransformBroadcaster(publisher)
    broadcaster.send_transform(make_transform_stamped('a', 'b', 0, (1.0, 2.0, 3.0), (0, 0, 0, 1)))
    broadcaster.send_transform(
        [
            make_transform_stamped('a', 'c', 0, (7.0, 8.0, 9.0), (0, 0, 0, 1)),
            make_transform_stamped('a', 'b', 0, (4.0, 5.0, 6.0), (0, 0, 0, 1)),
        ]
    )
    assert [t.child_frame_id for t in broadcaster.transforms] == ['b', 'c']
    late = transport.create_node('late_listener')
    received: list[Any] = []
    late.create_subscription(
        tf2_msgs.TFMessage, '/tf_static', received.append, StaticListenerQoS()
    )
    buffer = Buffer(node=late)
    listener = TransformListener(buffer, late, spin_thread=True)
    spinner = Spinner(late)
    try:
        assert buffer.can_transform('a', 'c', 0, Duration(seconds=DISCOVERY_TIMEOUT_S))
        assert translation(buffer.lookup_transform('a', 'b', 0)) == (4.0, 5.0, 6.0)
        assert wait_for(lambda: len(received) >= 1)
        assert [t.child_frame_id for t in received[-1].transforms] == ['b', 'c']
    finally:
        spinner.stop()
        listener.unregister()


def test_listener_skips_garbage_transforms_and_keeps_the_rest(ros: None) -> None:
    """A NaN and an empty child in one TFMessage are dropped; the good transforms are used."""
    listener_node = transport.create_node('listener')
    buffer = Buffer(node=listener_node)
    listener = TransformListener(buffer, listener_node, spin_thread=True)
    publisher = transport.create_node('garbage_pub')
    broadcaster = TransformBroadcaster(publisher)
    # Feeding our Buffer, the listener decodes bytes straight into the core in both worlds.
    assert listener.raw_decoding
    try:
        assert wait_for(lambda: publisher.count_subscribers('/tf') >= 1)
        now = time.time_ns()
        broadcaster.send_transform(
            [
                make_transform_stamped('a', 'good1', now, (1.0, 0.0, 0.0), (0, 0, 0, 1)),
                make_transform_stamped('a', 'nan', now, (float('nan'), 0.0, 0.0), (0, 0, 0, 1)),
                make_transform_stamped('a', '', now, (0.0, 0.0, 0.0), (0, 0, 0, 1)),
                make_transform_stamped('a', 'good2', now, (2.0, 0.0, 0.0), (0, 0, 0, 1)),
            ]
        )
        assert buffer.can_transform('a', 'good2', 0, Duration(seconds=DISCOVERY_TIMEOUT_S))
        assert translation(buffer.lookup_transform('a', 'good1', 0)) == (1.0, 0.0, 0.0)
        with pytest.raises(LookupException):
            buffer.lookup_transform('a', 'nan', 0)
    finally:
        listener.unregister()


def test_spin_thread_listener_does_not_spin_the_users_node(ros: None) -> None:
    """With spin_thread=True the user's own timer is not run by the listener's thread."""
    user_node = transport.create_node('user')
    fired: list[int] = []
    user_node.create_timer(0.01, lambda: fired.append(1))
    buffer = Buffer(node=user_node)
    listener = TransformListener(buffer, user_node, spin_thread=True)
    publisher = transport.create_node('pub')
    StaticTransformBroadcaster(publisher).send_transform(
        make_transform_stamped('a', 'b', 0, (1.0, 0.0, 0.0), (0, 0, 0, 1))
    )
    try:
        assert buffer.can_transform('a', 'b', 0, Duration(seconds=DISCOVERY_TIMEOUT_S))
        assert fired == []
    finally:
        listener.unregister()


#: A process that leaves a spin-thread listener running when its interpreter exits.
LISTENER_LEFT_RUNNING = """
from tf_demo import transport
from tf_demo.ros import Buffer, TransformListener

transport.init(['left_running'])
node = transport.create_node('left_running')
listener = TransformListener(Buffer(node=node), node, spin_thread=True)
print('listening', flush=True)
"""


@pytest.mark.parametrize('shutdown_first', [False, True], ids=['running', 'shut_down'])
def test_a_listener_never_unregistered_does_not_abort_the_exit(
    world_env: dict[str, str], shutdown_first: bool
) -> None:
    """
    A program that exits with its spin-thread listener still running exits 0.

    Under rclpy the private thread, still blocked in the middleware when Python finalised, was
    killed inside pybind11 and the process aborted (``terminate called without an active
    exception``, exit -6): a tool interrupted between creating its listener and its ``try``.
    """
    code = LISTENER_LEFT_RUNNING + ('transport.shutdown()\n' if shutdown_first else '')
    result = subprocess.run(
        [sys.executable, '-c', code],
        env=world_env,
        capture_output=True,
        text=True,
        timeout=120,
        check=False,
    )
    assert (result.returncode, result.stdout) == (0, 'listening\n'), result.stderr
    assert 'terminate called' not in result.stderr


def test_wait_started_before_the_publisher_process_resolves(spawn: Any, ros: None) -> None:
    """An async wait begun before frame_broadcaster starts resolves once its /tf arrives."""
    node = transport.create_node('waiter')
    buffer = Buffer(node=node)
    listener = TransformListener(buffer, node, spin_thread=True)
    future = buffer.wait_for_transform_async(
        'base_link', 'camera_link', 0, timeout=Duration(seconds=60)
    )
    assert not future.done()
    spawn.start('frame_broadcaster')
    try:
        assert future.wait(60.0)
        assert translation(future.result()) == pytest.approx((0.1, 0.2, 0.3))
    finally:
        listener.unregister()


def sim_time_world(user_name: str, clock_name: str) -> tuple[Any, Any, Callable[[float], None]]:
    """Return a use_sim_time node, a /clock publishing node and ``publish_clock(seconds)``."""
    sim_node = transport.create_node(
        user_name, parameter_overrides=[Parameter('use_sim_time', value=True)]
    )
    clock_node = transport.create_node(clock_name)
    clock_pub = clock_node.create_publisher(rosgraph_msgs.Clock, '/clock', 10)

    def publish_clock(seconds: float) -> None:
        msg = rosgraph_msgs.Clock()
        msg.clock.sec, msg.clock.nanosec = int(seconds), round(seconds % 1 * 1e9)
        clock_pub.publish(msg)

    return sim_node, clock_node, publish_clock


def test_timeout_on_sim_time_over_dds(ros: None) -> None:
    """With use_sim_time the wait ends when /clock passes the timeout, not on wall time."""
    sim_node, clock_node, publish_clock = sim_time_world('sim_user', 'clock_pub')
    spinner = Spinner(sim_node)
    buffer = Buffer(node=sim_node)

    try:
        assert wait_for(lambda: clock_node.count_subscribers('/clock') >= 1)

        def clock_reached(seconds: float) -> bool:
            publish_clock(seconds)
            return bool(sim_node.get_clock().now().nanoseconds == seconds * S)

        assert wait_for(lambda: clock_reached(1000.0))
        box: dict[str, Any] = {}

        def blocking_wait() -> None:
            box['result'] = buffer.can_transform('a', 'b', 0, Duration(seconds=3))

        waiter = threading.Thread(target=blocking_wait, daemon=True)
        waiter.start()
        publish_clock(1001.0)
        waiter.join(1.0)
        assert waiter.is_alive(), 'timed out before 3 s of sim time'

        def waiter_finished_at(seconds: float) -> bool:
            publish_clock(seconds)
            return not waiter.is_alive()

        assert wait_for(lambda: waiter_finished_at(1004.0))
        assert box == {'result': False}
    finally:
        spinner.stop()


def test_message_callbacks_skip_garbage_and_malformed_bytes(ros: None) -> None:
    """tf2_ros's callback(msg) path and the raw path survive NaN transforms and junk bytes."""
    node = transport.create_node('direct')
    buffer = Buffer(node=node)
    listener = TransformListener(buffer, node)
    message = tf2_msgs.TFMessage(
        transforms=[
            make_transform_stamped('a', 'nan', S, (0.0, float('nan'), 0.0), (0, 0, 0, 1)),
            make_transform_stamped('a', 'ok', S, (1.0, 0.0, 0.0), (0, 0, 0, 1)),
        ]
    )
    listener.callback(message)
    listener.static_callback(message)
    # The bytes path, with a standalone world's message info and with an rclpy one (no GUID).
    listener._raw_callback(b'\x00\x01\x00\x00\xff\xff', {'publisher_gid': bytes(16)})
    listener._raw_callback(b'\x00\x01\x00\x00\xff\xff', {'source_timestamp': 0})
    assert buffer.can_transform('a', 'ok', S)
    assert not buffer.can_transform('a', 'nan', S)
    listener.unregister()


def test_clock_jumping_back_over_dds_clears_the_buffer(ros: None) -> None:
    """A bag loop: /clock going back 10 s clears dynamic transforms, static ones stay."""
    sim_node, _clock_node, publish_clock = sim_time_world('bag_user', 'bag_clock')
    spinner = Spinner(sim_node)
    buffer = Buffer(node=sim_node)

    def clock_at(seconds: int) -> bool:
        publish_clock(seconds)
        return bool(sim_node.get_clock().now().nanoseconds == seconds * S)

    try:
        assert wait_for(lambda: clock_at(500))
        buffer.set_transform(
            make_transform_stamped('a', 'd', 499 * S, (1, 0, 0), (0, 0, 0, 1)), 'x'
        )
        buffer.set_transform_static(
            make_transform_stamped('a', 's', 0, (2, 0, 0), (0, 0, 0, 1)), 'x'
        )
        assert buffer.can_transform('a', 'd', 499 * S)
        assert wait_for(lambda: clock_at(490))
        assert not buffer.can_transform('a', 'd', 499 * S)
        assert buffer.can_transform('a', 's', 0)
    finally:
        spinner.stop()


def test_blocking_wait_in_a_single_threaded_executor_callback_does_not_deadlock(
    ros: None,
) -> None:
    """A timer that waits 1000 s for a missing frame, in the thread delivering /tf, returns."""
    publisher = transport.create_node('steady_pub')
    broadcaster = TransformBroadcaster(publisher)
    publisher.create_timer(
        0.05,
        lambda: broadcaster.send_transform(
            make_transform_stamped('a', 'b', time.time_ns(), (1, 0, 0), (0, 0, 0, 1))
        ),
    )
    publisher_spinner = Spinner(publisher)
    node = transport.create_node('single_threaded_user')
    buffer = Buffer(node=node)
    listener = TransformListener(buffer, node)
    outcome: list[bool] = []

    def on_timer() -> None:
        if outcome or not buffer.can_transform('a', 'b', 0):
            return
        answer = buffer.can_transform('a', 'missing', 0, Duration(seconds=1000))
        outcome.append(bool(answer))

    node.create_timer(0.05, on_timer)
    executor = SingleThreadedExecutor()
    executor.add_node(node)

    def spin_until_answered() -> None:
        deadline = time.monotonic() + DISCOVERY_TIMEOUT_S * 2
        while not outcome and time.monotonic() < deadline:
            executor.spin_once(timeout_sec=0.05)

    user_thread = threading.Thread(target=spin_until_answered, daemon=True)
    user_thread.start()
    try:
        user_thread.join(DISCOVERY_TIMEOUT_S * 3)
        assert not user_thread.is_alive(), 'the executor thread is stuck in the wait'
        assert outcome == [False]
    finally:
        publisher_spinner.stop()
        listener.unregister()


def test_awaited_lookup_in_a_single_threaded_executor_resolves_and_times_out(
    ros: None,
) -> None:
    """An async timer awaits a transform its own executor delivers; a missing one times out."""
    node = transport.create_node('async_user')
    buffer = Buffer(node=node)
    listener = TransformListener(buffer, node)
    results: dict[str, Any] = {}

    async def on_timer() -> None:
        if results.get('started'):
            return
        results['started'] = True
        results['found'] = await buffer.lookup_transform_async(
            'a', 'b', 0, timeout=Duration(seconds=DISCOVERY_TIMEOUT_S)
        )
        try:
            await buffer.lookup_transform_async('a', 'missing', 0, timeout=Duration(seconds=0.5))
        except TimeoutException as error:
            results['timeout'] = error

    node.create_timer(0.05, on_timer)
    executor = SingleThreadedExecutor()
    executor.add_node(node)
    publisher = transport.create_node('late_pub')
    broadcaster = StaticTransformBroadcaster(publisher)
    deadline = time.monotonic() + DISCOVERY_TIMEOUT_S * 2
    try:
        while 'started' not in results and time.monotonic() < deadline:
            executor.spin_once(timeout_sec=0.05)
        broadcaster.send_transform(make_transform_stamped('a', 'b', 0, (3, 0, 0), (0, 0, 0, 1)))
        while 'timeout' not in results and time.monotonic() < deadline:
            executor.spin_once(timeout_sec=0.05)
        assert translation(results['found']) == (3.0, 0.0, 0.0)
        assert isinstance(results['timeout'], TimeoutException)
    finally:
        listener.unregister()


def test_the_exit_hook_skips_a_spin_thread_stopped_before_it_started() -> None:
    """A Ctrl-C between registering the private thread and starting it: exit stays quiet."""
    never_started = threading.Thread(target=lambda: None, daemon=True)
    stop = threading.Event()
    transport._serving_threads[never_started] = stop
    transport._stop_serving_threads_at_exit()  # raised RuntimeError: cannot join ...
    assert stop.is_set()
    assert never_started not in transport._serving_threads
