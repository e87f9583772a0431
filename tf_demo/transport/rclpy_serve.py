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
The rclpy world's loop for :class:`~tf_demo.transport.SubscriptionServer`: rcl's wait set.

Imported only where rclpy is (the rclpy backend itself stays a pure pass-through to rclpy).
"""

from __future__ import annotations

from collections.abc import Sequence
import contextlib
import threading
from typing import Any

import rclpy.node
import rclpy.subscription
from tf_demo.transport.rclpy_backend import _rclpy_impl

#: How many samples one subscription may deliver per wake before the others get their turn.
SERVE_BURST = 100


def serve_subscriptions(
    node: rclpy.node.Node,
    subscriptions: Sequence[rclpy.subscription.Subscription[Any]],
    stop: threading.Event,
    period_s: float,
) -> None:
    """
    Run the callbacks of ``subscriptions`` (``node``'s only entities) until ``stop`` or shutdown.

    The private listener thread's loop: rcl's wait set on the subscriptions directly, each
    ready one drained (up to :data:`SERVE_BURST` samples) in this thread. rclpy's executor
    would do the same work for a node of subscriptions only, at about 3.5 times the CPU per
    sample (it rebuilds its entity lists, tasks and futures on every ``spin_once``:
    ``bench/bench_ros_world.py`` measures both). ``stop`` is checked every ``period_s``.
    """
    context = node.context
    timeout_ns = int(period_s * 1e9)
    with_info = rclpy.subscription.Subscription.CallbackType.WithMessageInfo
    while not stop.is_set() and context.ok():
        with contextlib.ExitStack() as held:
            handles = [sub.handle for sub in subscriptions]
            for handle in handles:  # in use: a destroy waits for the end of this round
                held.enter_context(handle)
            held.enter_context(context.handle)
            wait_set = _rclpy_impl.WaitSet(len(handles), 0, 0, 0, 0, 0, context.handle)
            wait_set.clear_entities()
            for handle in handles:
                wait_set.add_subscription(handle)
            wait_set.wait(timeout_ns)
            ready = wait_set.get_ready_entities('subscription')
            for sub, handle in zip(subscriptions, handles, strict=True):
                if handle.pointer not in ready:
                    continue
                for _ in range(SERVE_BURST):
                    taken = handle.take_message(sub.msg_type, sub.raw)
                    if taken is None:
                        break
                    if sub._callback_type is with_info:  # rclpy's own dispatch rule
                        sub.callback(*taken)
                    else:
                        sub.callback(taken[0])
