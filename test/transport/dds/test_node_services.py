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

"""A standalone node's service methods: create, list and destroy servers and clients as rclpy."""

from __future__ import annotations

from conftest import PARAMETER_SERVICES
from conftest import STANDALONE_ONLY
import pytest

pytest.importorskip('cyclonedds', reason=STANDALONE_ONLY)

from tf_demo.msgs import rcl_interfaces
from tf_demo.transport import dds_backend

pytestmark = [pytest.mark.standalone, pytest.mark.dds]


def test_servers_and_clients_are_listed_named_and_destroyed(dds_world: None) -> None:
    """Names resolve in the node's namespace; the parameter services are listed as in rclpy."""
    node = dds_backend.DdsNode('owner', namespace='/robot')
    assert sorted(s.srv_name for s in node.services) == [
        f'/robot/owner/{suffix}' for suffix in PARAMETER_SERVICES
    ]
    service = node.create_service(
        rcl_interfaces.GetParameters, 'lookup', lambda _request, response: response
    )
    client = node.create_client(rcl_interfaces.GetParameters, '~/ask')
    assert (service.srv_name, client.srv_name) == ('/robot/lookup', '/robot/owner/ask')
    assert service in node.services
    assert node.clients == [client]
    assert node.destroy_service(service)
    assert node.destroy_client(client)
    assert service not in node.services
    assert node.clients == []
    assert not node.destroy_client(client)  # already gone


def test_a_node_without_parameter_services_has_none(dds_world: None) -> None:
    """start_parameter_services=False leaves the service list empty (rclpy's option)."""
    node = dds_backend.DdsNode('quiet', start_parameter_services=False)
    assert node.services == []
    node.destroy_node()
    with pytest.raises(RuntimeError, match="node '/quiet' was destroyed"):
        node.create_client(rcl_interfaces.GetParameters, 'late')
