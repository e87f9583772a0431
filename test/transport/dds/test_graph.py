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

"""The graph writer: ros_discovery_info follows this process' nodes and endpoints."""

from __future__ import annotations

import time

from conftest import STANDALONE_ONLY
import pytest

pytest.importorskip('cyclonedds', reason=STANDALONE_ONLY)

from tf_demo.msgs import std_msgs
from tf_demo.transport import dds_backend


@pytest.mark.dds
def test_ros_discovery_info_follows_entity_and_node_changes(dds_world):
    """ros_discovery_info is republished when a publisher or a node goes away."""
    from tf_demo.msgs import cdr
    from tf_demo.msgs import rmw_dds_common
    from tf_demo.transport.dds import wire as dds_wire

    participant = dds_wire.get_participant()
    reader = participant.create_reader(
        dds_wire.DISCOVERY_INFO_TOPIC,
        dds_wire.DISCOVERY_INFO_TYPE,
        dds_wire.EndpointQos(reliable=True, transient_local=True, keep_all=True),
        b'',
    )
    latest: list[rmw_dds_common.ParticipantEntitiesInfo] = []

    def nodes_now() -> dict[str, tuple[int, int]]:
        deadline = time.monotonic() + 5
        while time.monotonic() < deadline:
            payloads = reader.take()
            if payloads:
                latest.append(
                    cdr.deserialize(rmw_dds_common.ParticipantEntitiesInfo, payloads[-1])
                )
                break
            time.sleep(0.01)
        return {
            n.node_name: (len(n.reader_gid_seq), len(n.writer_gid_seq))
            for n in latest[-1].node_entities_info_seq
        }

    # Every node has rclpy's built-ins: the six parameter services (request readers, reply
    # writers) and the /parameter_events and /rosout writers.
    builtin_readers, builtin_writers = 6, 8
    keeper = dds_backend.DdsNode('keeper')
    node = dds_backend.DdsNode('changing')
    publisher = node.create_publisher(std_msgs.String, 'chatter', 10)
    assert nodes_now() == {
        'keeper': (builtin_readers, builtin_writers),
        'changing': (builtin_readers, builtin_writers + 1),
    }
    assert bytes(latest[-1].gid.data) == participant.guid
    node.destroy_publisher(publisher)
    assert nodes_now() == {
        'keeper': (builtin_readers, builtin_writers),
        'changing': (builtin_readers, builtin_writers),
    }
    node.destroy_node()
    assert nodes_now() == {'keeper': (builtin_readers, builtin_writers)}
    del keeper
