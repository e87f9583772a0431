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
Executors schedule as rclpy's: what one wait found ready is served before the next wait.

The first test is written against the node API only, so it runs in both worlds (on real rclpy
in the rclpy world); the standalone one (marked) spins several DdsNodes with one executor.
"""

from __future__ import annotations

import time
from typing import Any

from conftest import executor_with
from conftest import HAVE_CYCLONEDDS
import pytest
from tf_demo import transport
from tf_demo.msgs import tf2_msgs
from tf_demo.transport.executors import SingleThreadedExecutor
from tf_demo.transport.messages import std_msgs

if HAVE_CYCLONEDDS:  # for the standalone test only
    from dds_helpers import one_transform
    from dds_helpers import spin_until
    from tf_demo.transport import dds_backend

pytestmark = pytest.mark.dds

DEADLINE_S = 30.0
"""Upper bound for anything to happen (discovery, scheduling on a loaded machine)."""


def single_threaded(executors: list[Any], *nodes: Any) -> Any:
    return executor_with(executors, SingleThreadedExecutor(), *nodes)


def test_single_threaded_timer_blocking_past_its_period_does_not_starve_a_subscription(
    executors: list[Any],
) -> None:
    """A timer overdue whenever it returns still leaves room for the subscription's messages."""
    node = transport.create_node('slow_timer_node')
    timer_runs: list[float] = []

    def on_timer() -> None:
        timer_runs.append(time.monotonic())
        time.sleep(0.3)  # three periods: the timer is overdue again when it returns

    node.create_timer(0.1, on_timer)
    received: list[Any] = []
    node.create_subscription(std_msgs.String, 'starved', received.append, 10)
    talker = transport.create_node('starved_talker')
    publisher = talker.create_publisher(std_msgs.String, 'starved', 10)
    executor = single_threaded(executors, node)
    sent = 0
    deadline = time.monotonic() + DEADLINE_S
    while len(received) < 3 and time.monotonic() < deadline:
        # Publish only once the timer is overrunning, so every wait finds it overdue.
        if timer_runs and publisher.get_subscription_count() > 0:
            publisher.publish(std_msgs.String(data=str(sent)))
            sent += 1
        executor.spin_once(timeout_sec=0.1)
    assert len(received) >= 3, f'{sent} sent, {len(timer_runs)} timer runs, too few received'
    assert len(timer_runs) >= 2, 'the timer must keep running as well'
    assert all(isinstance(msg, std_msgs.String) for msg in received)


@pytest.mark.standalone
def test_one_executor_runs_callbacks_of_several_nodes(dds_world):
    """A publisher node and a subscriber node spun by one executor exchange messages in order."""
    talker = dds_backend.DdsNode('talker')
    listener = dds_backend.DdsNode('listener')
    received: list[float] = []
    listener.create_subscription(
        tf2_msgs.TFMessage,
        '/tf',
        lambda m: received.append(m.transforms[0].transform.translation.x),
        100,
    )
    publisher = talker.create_publisher(tf2_msgs.TFMessage, '/tf', 100)
    executor = dds_backend.SingleThreadedExecutor()
    executor.add_node(talker)
    executor.add_node(listener)
    sent = iter(range(20))
    talker.create_timer(0.005, lambda: publisher.publish(one_transform(float(next(sent, 19)))))
    assert spin_until(executor, lambda: len(received) >= 20)
    assert received[:20] == [float(i) for i in range(20)]
    executor.shutdown()
