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

"""rclpy's service and client methods for the standalone node (``create_service``, ...)."""

from __future__ import annotations

from collections.abc import Callable

from tf_demo.transport.dds.callback_groups import CallbackGroup
from tf_demo.transport.dds.node_base import NodeBase
from tf_demo.transport.dds.qos import qos_profile_services_default
from tf_demo.transport.dds.qos import QoSProfile
from tf_demo.transport.dds.services import AnyClient
from tf_demo.transport.dds.services import AnyService
from tf_demo.transport.dds.services import DdsClient
from tf_demo.transport.dds.services import DdsService
from tf_demo.transport.dds.services import RequestT
from tf_demo.transport.dds.services import ResponseT
from tf_demo.transport.dds.services import ServiceType

__all__ = ['NodeServicesMixin']


class NodeServicesMixin(NodeBase):
    """rclpy's service and client methods of :class:`~tf_demo.transport.dds.node.DdsNode`."""

    _services: list[AnyService]
    _clients: list[AnyClient]

    def create_service(
        self,
        srv_type: ServiceType[RequestT, ResponseT],
        srv_name: str,
        callback: Callable[[RequestT, ResponseT], ResponseT],
        *,
        qos_profile: QoSProfile = qos_profile_services_default,
        callback_group: CallbackGroup | None = None,
    ) -> DdsService[RequestT, ResponseT]:
        """
        Create a service server; ``callback(request, response)`` returns the response.

        It is answered by the executor that spins the node, in ``callback_group`` (default:
        the node's default group); QoS default: ``qos_profile_services_default``.
        """
        self._check_alive()
        group = callback_group or self._default_callback_group
        name = self.resolve_topic_name(srv_name)
        service = DdsService(
            self,
            srv_type,
            name,
            callback,
            qos_profile,
            group,
        )
        self._add_reader_entity(self._services, service, group)
        return service

    def create_client(
        self,
        srv_type: ServiceType[RequestT, ResponseT],
        srv_name: str,
        *,
        qos_profile: QoSProfile = qos_profile_services_default,
        callback_group: CallbackGroup | None = None,
    ) -> DdsClient[RequestT, ResponseT]:
        """Create a service client (replies are taken by the executor that spins the node)."""
        self._check_alive()
        group = callback_group or self._default_callback_group
        name = self.resolve_topic_name(srv_name)
        client = DdsClient(self, srv_type, name, qos_profile, group)
        self._add_reader_entity(self._clients, client, group)
        return client

    def destroy_service(self, service: DdsService[RequestT, ResponseT]) -> bool:
        """Destroy ``service``."""
        return self._destroy_reader_entity(self._services, service)

    def destroy_client(self, client: DdsClient[RequestT, ResponseT]) -> bool:
        """Destroy ``client`` (its pending futures are cancelled)."""
        return self._destroy_reader_entity(self._clients, client)

    @property
    def services(self) -> list[AnyService]:
        """The node's service servers (the parameter services included, as in rclpy)."""
        return list(self._services)

    @property
    def clients(self) -> list[AnyClient]:
        """The node's service clients."""
        return list(self._clients)

    def _service_reader_gids(self) -> list[bytes]:
        """Request readers of servers, reply readers of clients (rmw's graph entries)."""
        return [entity.reader_gid for entity in [*self._services, *self._clients]]

    def _service_writer_gids(self) -> list[bytes]:
        """Reply writers of servers, request writers of clients."""
        return [entity.writer_gid for entity in [*self._services, *self._clients]]
