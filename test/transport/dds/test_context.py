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

"""The process context: init, ok, shutdown and try_shutdown as rclpy's Context."""

from __future__ import annotations

from conftest import STANDALONE_ONLY
import pytest

pytest.importorskip('cyclonedds', reason=STANDALONE_ONLY)

from dds_helpers import spin_until
from tf_demo.msgs import std_msgs
from tf_demo.transport import dds_backend


def test_node_before_init_is_refused(dds_env):
    """Creating a node before init() (or after shutdown) raises a RuntimeError saying so."""
    dds_backend.init()
    dds_backend.shutdown()
    with pytest.raises(RuntimeError, match=r'call tf_demo\.transport\.init\(\) before'):
        dds_backend.DdsNode('early')


@pytest.mark.dds
def test_executor_keeps_working_after_shutdown_and_init_again(dds_env):
    """An executor made before shutdown() delivers messages again after a new init()."""
    dds_backend.init()
    executor = dds_backend.SingleThreadedExecutor()
    dds_backend.shutdown()
    dds_backend.init()
    try:
        node = dds_backend.DdsNode('reborn')
        received: list[object] = []
        node.create_subscription(std_msgs.String, 'echo', received.append, 10)
        node.create_publisher(std_msgs.String, 'echo', 10).publish(std_msgs.String(data='hi'))
        executor.add_node(node)
        assert spin_until(executor, lambda: len(received) == 1)
    finally:
        dds_backend.shutdown()


def test_second_shutdown_raises_like_rclpy_and_try_shutdown_is_quiet(dds_env):
    """shutdown() twice raises RuntimeError (rclpy's Context); try_shutdown() never does."""
    dds_backend.init(args=['prog'])
    dds_backend.shutdown()
    with pytest.raises(RuntimeError, match='already called'):
        dds_backend.shutdown()
    dds_backend.try_shutdown()
    dds_backend.init()
    dds_backend.try_shutdown()
    assert not dds_backend.ok()
