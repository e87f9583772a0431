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

"""rclpy's module-level ``spin``, ``spin_once`` and ``spin_until_future_complete``."""

from __future__ import annotations

from collections.abc import Sequence
import threading

from tf_demo.transport.dds.context import _context
from tf_demo.transport.dds.context import ok
from tf_demo.transport.dds.endpoints import DdsSubscription
from tf_demo.transport.dds.executors import Completable
from tf_demo.transport.dds.executors import DdsExecutor
from tf_demo.transport.dds.executors import SingleThreadedExecutor
from tf_demo.transport.dds.node import DdsNode

_default_executors: dict[int, DdsExecutor] = {}


def _executor_for(node: DdsNode, executor: DdsExecutor | None) -> DdsExecutor:
    if executor is not None:
        executor.add_node(node)
        return executor
    default = _default_executors.get(threading.get_ident())
    if default is None or default._shutdown:
        default = SingleThreadedExecutor()
        _default_executors[threading.get_ident()] = default
    default.add_node(node)
    return default


def spin_once(
    node: DdsNode, *, executor: DdsExecutor | None = None, timeout_sec: float | None = None
) -> None:
    """Run at most one round of ready callbacks of ``node`` (rclpy ``spin_once``)."""
    chosen = _executor_for(node, executor)
    try:
        chosen.spin_once(timeout_sec)
    finally:
        chosen.remove_node(node)


def spin_until_future_complete(
    node: DdsNode,
    future: Completable,
    executor: DdsExecutor | None = None,
    timeout_sec: float | None = None,
) -> None:
    """Run the callbacks of ``node`` until ``future.done()`` or the timeout."""
    chosen = _executor_for(node, executor)
    try:
        chosen.spin_until_future_complete(future, timeout_sec)
    finally:
        chosen.remove_node(node)


def spin(node: DdsNode, executor: DdsExecutor | None = None) -> None:
    """Run the callbacks of ``node`` until shutdown (rclpy ``spin``)."""
    chosen = _executor_for(node, executor)
    try:
        while _context.ok() and not node._destroyed and not chosen._shutdown:
            chosen.spin_once(None)
    finally:
        chosen.remove_node(node)


def serve_subscriptions(
    node: DdsNode, subscriptions: Sequence[DdsSubscription], stop: threading.Event, period_s: float
) -> None:
    """
    Run the callbacks of ``node`` (which holds ``subscriptions``) until ``stop`` or shutdown.

    The standalone executor already waits on the read conditions directly: a private
    :class:`SingleThreadedExecutor`, ``stop`` checked every ``period_s``.
    """
    del subscriptions  # the node's executor serves them all
    executor = SingleThreadedExecutor()
    executor.add_node(node)
    try:
        while not stop.is_set() and ok():
            executor.spin_once(timeout_sec=period_s)
    finally:
        executor.shutdown()
