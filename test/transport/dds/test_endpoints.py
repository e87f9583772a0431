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

"""Publishers and subscriptions over real DDS: bad payloads, wrong types, MessageInfo."""

from __future__ import annotations

import time

from conftest import STANDALONE_ONLY
import pytest

pytest.importorskip('cyclonedds', reason=STANDALONE_ONLY)

from dds_helpers import one_transform
from dds_helpers import spin_until
from tf_demo.msgs import std_msgs
from tf_demo.msgs import tf2_msgs
from tf_demo.transport import dds_backend
from tf_demo.transport.dds.endpoints import MessageInfo


@pytest.mark.dds
def test_malformed_payload_is_logged_and_the_subscription_keeps_working(dds_world, capfd):
    """Garbage bytes on a topic produce an error line naming the type; good messages still come."""
    node = dds_backend.DdsNode('robust')
    received: list[tf2_msgs.TFMessage] = []
    node.create_subscription(tf2_msgs.TFMessage, '/tf', received.append, 10)
    publisher = node.create_publisher(tf2_msgs.TFMessage, '/tf', 10)
    executor = dds_backend.SingleThreadedExecutor()
    executor.add_node(node)
    publisher.publish(b'\x00\x01\x00\x00\x05\x00\x00\x00')
    publisher.publish(one_transform(3.0))
    assert spin_until(executor, lambda: len(received) == 1)
    assert received[0].transforms[0].transform.translation.x == 3.0
    assert "Dropped a malformed tf2_msgs/msg/TFMessage message on '/tf'" in capfd.readouterr().err
    executor.shutdown()


@pytest.mark.dds
def test_publish_rejects_the_wrong_message_type(dds_world):
    """Publishing a String on a TFMessage publisher raises TypeError naming both types."""
    node = dds_backend.DdsNode('strict')
    publisher = node.create_publisher(tf2_msgs.TFMessage, '/tf', 10)
    with pytest.raises(TypeError, match='Expected TFMessage, got String'):
        publisher.publish(std_msgs.String(data='x'))  # type: ignore[arg-type]  # refused
    with pytest.raises(TypeError, match='QoSProfile or a history depth'):
        node.create_publisher(tf2_msgs.TFMessage, '/tf', 'reliable')  # type: ignore[arg-type]


@pytest.mark.dds
def test_two_argument_callbacks_get_message_info_with_the_publisher_gid(dds_world):
    """A (msg, info) callback gets rclpy's MessageInfo keys and the sending writer's GUID."""
    node = dds_backend.DdsNode('informed')
    infos: list[MessageInfo] = []
    node.create_subscription(tf2_msgs.TFMessage, '/tf', lambda _msg, info: infos.append(info), 10)
    first = node.create_publisher(tf2_msgs.TFMessage, '/tf', 10)
    second = dds_backend.DdsNode('other').create_publisher(tf2_msgs.TFMessage, '/tf', 10)
    executor = dds_backend.SingleThreadedExecutor()
    executor.add_node(node)
    before = time.time_ns()
    first.publish(one_transform(1.0))
    second.publish(one_transform(2.0))
    assert spin_until(executor, lambda: len(infos) == 2)
    assert {info['publisher_gid'] for info in infos} == {first._writer.guid, second._writer.guid}
    assert first._writer.guid != second._writer.guid
    for info in infos:
        assert before <= info['source_timestamp'] <= info['received_timestamp']
        assert set(info) >= {'publication_sequence_number', 'reception_sequence_number'}
