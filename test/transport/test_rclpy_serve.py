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
SubscriptionServer: an internal node's subscriptions served by a thread of their own.

Under rclpy the thread runs ``rclpy_serve.serve_subscriptions`` (rcl's wait set, no executor);
standalone a private executor. The same checks in both worlds: every message arrives, in order,
in the server's thread, raw bytes with their info; stopping ends the thread and the node.
"""

from __future__ import annotations

import threading
import time

import pytest
from tf_demo import transport
from tf_demo.transport.backend import backend_name
from tf_demo.transport.messages import std_msgs
from tf_demo.transport.qos import QoSProfile

MESSAGES = 300


@pytest.mark.usefixtures('ros')
def test_every_message_arrives_in_order_in_the_servers_thread() -> None:
    publisher_node = transport.create_node('serve_publisher')
    inputs = transport.create_internal_node('serve_inputs')
    received: list[tuple[bytes, str, bool]] = []
    done = threading.Event()

    def on_raw(data: bytes, info: object) -> None:
        received.append((data, threading.current_thread().name, info is not None))
        if len(received) == MESSAGES:
            done.set()

    profile = QoSProfile(depth=MESSAGES)
    subscription = inputs.create_subscription(
        std_msgs.String, '/served', on_raw, profile, raw=True
    )
    server = transport.SubscriptionServer(inputs, [subscription], 'served_inputs', 0.05)
    try:
        publisher = publisher_node.create_publisher(std_msgs.String, '/served', profile)
        deadline = time.monotonic() + 30
        while publisher.get_subscription_count() == 0 and time.monotonic() < deadline:
            time.sleep(0.05)
        for index in range(MESSAGES):
            publisher.publish(std_msgs.String(data=f'message {index:04d}'))
        assert done.wait(30), f'{len(received)} of {MESSAGES} arrived ({backend_name()} world)'
    finally:
        server.stop()
        publisher_node.destroy_node()
    texts = [data[8:].rstrip(b'\0').decode() for data, _, _ in received]
    assert texts == [f'message {index:04d}' for index in range(MESSAGES)]
    assert {thread for _, thread, _ in received} == {'served_inputs'}
    assert all(has_info for _, _, has_info in received)
    assert not server.thread.is_alive()
    assert server.thread not in transport._serving_threads


@pytest.mark.usefixtures('ros')
def test_stop_ends_the_thread_within_its_period_and_twice_is_harmless() -> None:
    inputs = transport.create_internal_node('serve_idle')
    subscription = inputs.create_subscription(
        std_msgs.String, '/nobody', lambda data, info: None, 10, raw=True
    )
    server = transport.SubscriptionServer(inputs, [subscription], 'idle_inputs', 0.05)
    assert server.thread.is_alive()
    server.stop()
    server.stop()
    assert not server.thread.is_alive()
