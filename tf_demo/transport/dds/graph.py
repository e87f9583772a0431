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

"""The graph writer: publishes this process' nodes and endpoints on ``ros_discovery_info``."""

from __future__ import annotations

from collections.abc import Iterable
import threading
from typing import Protocol

from tf_demo.msgs import cdr
from tf_demo.msgs import rmw_dds_common
from tf_demo.transport.dds import wire as dds_wire
from tf_demo.transport.dds.endpoints import _FLUSH_TIMEOUT_NS


class GraphNode(Protocol):
    """What the graph writer reads of a node: its names and the GUIDs of its endpoints."""

    def get_name(self) -> str: ...

    def get_namespace(self) -> str: ...

    def _reader_gids(self) -> list[bytes]: ...

    def _writer_gids(self) -> list[bytes]: ...


class _Graph:
    """Publishes this process' nodes and their endpoints on ``ros_discovery_info``."""

    def __init__(self, participant: dds_wire.DdsParticipant) -> None:
        self._messages = rmw_dds_common
        self._participant = participant
        info_type = rmw_dds_common.ParticipantEntitiesInfo
        self._writer = participant.create_writer(
            dds_wire.DISCOVERY_INFO_TOPIC,
            dds_wire.DISCOVERY_INFO_TYPE,
            dds_wire.EndpointQos(reliable=True, transient_local=True, depth=1),
            f'typehash={info_type.__typehash__};'.encode(),
        )
        self._lock = threading.Lock()

    def publish(self, nodes: Iterable[GraphNode]) -> None:
        messages = self._messages
        entries = [
            messages.NodeEntitiesInfo(
                node_namespace=node.get_namespace(),
                node_name=node.get_name(),
                reader_gid_seq=[messages.Gid(data=list(gid)) for gid in node._reader_gids()],
                writer_gid_seq=[messages.Gid(data=list(gid)) for gid in node._writer_gids()],
            )
            for node in nodes
        ]
        info = messages.ParticipantEntitiesInfo(
            gid=messages.Gid(data=list(self._participant.guid)), node_entities_info_seq=entries
        )
        with self._lock:
            self._writer.write(cdr.serialize(info))

    def close(self) -> None:
        self._writer.close(flush_timeout_ns=_FLUSH_TIMEOUT_NS // 4)
