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
from typing import Any
from typing import cast

from tf_demo.transport.dds.context import _graph_changed
from tf_demo.transport.dds.qos import qos_profile_services_default
from tf_demo.transport.dds.services import DdsClient
from tf_demo.transport.dds.services import DdsService

__all__ = ['NodeServicesMixin']


class NodeServicesMixin:
    """
    rclpy's service and client methods of :class:`~tf_demo.transport.dds.node.DdsNode`.

    The node provides ``_lock``, ``_services``, ``_clients``, ``_participant``,
    ``_default_callback_group``, ``resolve_topic_name``, ``get_logger``, ``_check_alive``,
    ``_wake_executors`` and ``_detach``.
    """

    _lock: Any
    _services: list[DdsService]
    _clients: list[DdsClient]
    _default_callback_group: Any

    def create_service(
        self,
        srv_type: Any,
        srv_name: str,
        callback: Callable[[Any, Any], Any],
        *,
        qos_profile: Any = qos_profile_services_default,
        callback_group: Any = None,
    ) -> DdsService:
        """
        Create a service server; ``callback(request, response)`` returns the response.

        It is answered by the executor that spins the node, in ``callback_group`` (default:
        the node's default group); QoS default: ``qos_profile_services_default``.
        """
        node = cast('Any', self)
        node._check_alive()
        group = callback_group or self._default_callback_group
        name = node.resolve_topic_name(srv_name)
        service = DdsService(
            node,
            srv_type,
            name,
            callback,
            qos_profile,
            group,
        )
        group.add_entity(service)
        with self._lock:
            self._services.append(service)
        node._wake_executors()
        _graph_changed()
        return service

    def create_client(
        self,
        srv_type: Any,
        srv_name: str,
        *,
        qos_profile: Any = qos_profile_services_default,
        callback_group: Any = None,
    ) -> DdsClient:
        """Create a service client (replies are taken by the executor that spins the node)."""
        node = cast('Any', self)
        node._check_alive()
        group = callback_group or self._default_callback_group
        name = node.resolve_topic_name(srv_name)
        client = DdsClient(node, srv_type, name, qos_profile, group)
        group.add_entity(client)
        with self._lock:
            self._clients.append(client)
        node._wake_executors()
        _graph_changed()
        return client

    def destroy_service(self, service: DdsService) -> bool:
        """Destroy ``service``."""
        node = cast('Any', self)
        if not node._detach(self._services, service):
            return False
        node._wake_executors()
        service._close()
        _graph_changed()
        return True

    def destroy_client(self, client: DdsClient) -> bool:
        """Destroy ``client`` (its pending futures are cancelled)."""
        node = cast('Any', self)
        if not node._detach(self._clients, client):
            return False
        node._wake_executors()
        client._close()
        _graph_changed()
        return True

    @property
    def services(self) -> list[DdsService]:
        """The node's service servers (the parameter services included, as in rclpy)."""
        return list(self._services)

    @property
    def clients(self) -> list[DdsClient]:
        """The node's service clients."""
        return list(self._clients)

    def _service_reader_gids(self) -> list[bytes]:
        """Request readers of servers, reply readers of clients (rmw's graph entries)."""
        return [entity.reader_gid for entity in [*self._services, *self._clients]]

    def _service_writer_gids(self) -> list[bytes]:
        """Reply writers of servers, request writers of clients."""
        return [entity.writer_gid for entity in [*self._services, *self._clients]]
