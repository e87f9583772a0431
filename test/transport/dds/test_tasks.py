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

"""Tasks: async callbacks and create_task's coroutines stepped by the executor."""

from __future__ import annotations

from conftest import STANDALONE_ONLY
import pytest

pytest.importorskip('cyclonedds', reason=STANDALONE_ONLY)

from dds_helpers import spin_until
from tf_demo.msgs import std_msgs
from tf_demo.transport import dds_backend


class Gate:
    """A minimal awaitable that yields until opened (rclpy Future's await protocol)."""

    def __init__(self) -> None:
        self.opened = False

    def __await__(self):
        while not self.opened:
            yield
        return 'open'


@pytest.mark.dds
def test_async_callbacks_run_as_tasks_until_their_await_completes(dds_world):
    """An async timer callback awaiting a gate resumes once a subscription callback opens it."""
    node = dds_backend.DdsNode('awaiter')
    gate = Gate()
    outcomes: list[str] = []

    async def on_timer() -> None:
        timer.cancel()
        outcomes.append(await gate)

    timer = node.create_timer(0.01, on_timer)
    node.create_subscription(
        std_msgs.String, 'open', lambda _msg: setattr(gate, 'opened', True), 1
    )
    publisher = node.create_publisher(std_msgs.String, 'open', 1)
    executor = dds_backend.SingleThreadedExecutor()
    executor.add_node(node)
    for _ in range(10):
        executor.spin_once(timeout_sec=0.02)
    assert outcomes == []
    publisher.publish(std_msgs.String(data='now'))
    assert spin_until(executor, lambda: outcomes == ['open'])


@pytest.mark.dds
def test_create_task_result_and_exceptions_propagate(dds_world):
    """create_task runs a coroutine to its result; an async callback's exception leaves spin."""
    node = dds_backend.DdsNode('tasks')
    executor = dds_backend.SingleThreadedExecutor()
    executor.add_node(node)

    async def answer() -> int:
        return 42

    task = executor.create_task(answer)
    executor.spin_until_future_complete(task, timeout_sec=5)
    assert task.done()
    assert task.result() == 42

    async def broken(_msg: object) -> None:
        raise ArithmeticError('callback failed')

    node.create_subscription(std_msgs.String, 'boom', broken, 1)
    node.create_publisher(std_msgs.String, 'boom', 1).publish(std_msgs.String(data='x'))
    with pytest.raises(ArithmeticError, match='callback failed'):
        spin_until(executor, lambda: False, timeout=5)
