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

"""The standalone executor: one SingleThreadedExecutor spins several nodes over real DDS."""

from __future__ import annotations

from conftest import STANDALONE_ONLY
import pytest

pytest.importorskip('cyclonedds', reason=STANDALONE_ONLY)

from dds_helpers import one_transform
from dds_helpers import spin_until
from tf_demo.msgs import tf2_msgs
from tf_demo.transport import dds_backend


@pytest.mark.dds
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
