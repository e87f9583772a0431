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

"""rclpy's module-level spin functions for a standalone node: spin_once, spin_until_*, spin."""

from __future__ import annotations

from conftest import STANDALONE_ONLY
import pytest

pytest.importorskip('cyclonedds', reason=STANDALONE_ONLY)

from tf_demo.transport import dds_backend
from tf_demo.transport.future import Future

pytestmark = [pytest.mark.standalone, pytest.mark.dds]


def test_spin_once_runs_one_ready_callback_per_call(dds_world: None) -> None:
    """Each call serves one ready entity of the node; the node can be spun again afterwards."""
    node = dds_backend.DdsNode('once', start_parameter_services=False)
    ticks: list[int] = []
    node.create_timer(0, lambda: ticks.append(len(ticks)))
    dds_backend.spin_once(node, timeout_sec=30)
    assert ticks == [0]
    dds_backend.spin_once(node, timeout_sec=30)
    assert ticks == [0, 1]


def test_spin_until_future_complete_returns_once_a_callback_completes_it(dds_world: None) -> None:
    """The node's callbacks run until the future is done (here a timer sets it)."""
    node = dds_backend.DdsNode('until', start_parameter_services=False)
    future: Future[str] = Future()
    node.create_timer(0.01, lambda: future.set_result('done'))
    dds_backend.spin_until_future_complete(node, future, timeout_sec=30)
    assert future.result() == 'done'


def test_spin_returns_when_the_node_is_destroyed(dds_world: None) -> None:
    """spin serves the node until it is destroyed (here by its own timer)."""
    node = dds_backend.DdsNode('spun', start_parameter_services=False)
    ticks: list[int] = []

    def tick() -> None:
        ticks.append(1)
        if len(ticks) == 3:
            node.destroy_node()

    node.create_timer(0, tick)
    dds_backend.spin(node)
    assert ticks == [1, 1, 1]
