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

"""
The standalone node: the subset of ``rclpy.node.Node`` the package uses, over DDS.

Names are expanded and validated as rcl does (relative names get the node's namespace, ``~``
is the node's fully qualified name) and remapped by ``--ros-args -r``.
"""

from __future__ import annotations

from collections.abc import Sequence
import contextlib
from dataclasses import dataclass
import itertools
import threading
from typing import Any
from typing import Protocol
import weakref

from tf_demo.transport import ros_args
from tf_demo.transport.dds import wire as dds_wire
from tf_demo.transport.dds.callback_groups import CallbackGroup
from tf_demo.transport.dds.callback_groups import MutuallyExclusiveCallbackGroup
from tf_demo.transport.dds.clock import ROSClock
from tf_demo.transport.dds.context import _context
from tf_demo.transport.dds.context import _graph_changed
from tf_demo.transport.dds.context import _participant
from tf_demo.transport.dds.endpoints import AnyPublisher
from tf_demo.transport.dds.endpoints import DdsSubscription
from tf_demo.transport.dds.logging import get_logger
from tf_demo.transport.dds.names import validate_namespace
from tf_demo.transport.dds.names import validate_node_name
from tf_demo.transport.dds.node_endpoints import NodeEndpointsMixin
from tf_demo.transport.dds.node_parameters import NodeParametersMixin
from tf_demo.transport.dds.node_services import NodeServicesMixin
from tf_demo.transport.dds.parameter_services import NodeInterfaces
from tf_demo.transport.dds.parameter_store import ParameterStore
from tf_demo.transport.dds.parameters import Parameter
from tf_demo.transport.dds.qos import QoSProfile
from tf_demo.transport.dds.services import AnyClient
from tf_demo.transport.dds.services import AnyService
from tf_demo.transport.dds.time_source import TimeSource
from tf_demo.transport.dds.timers import DdsTimer

__all__ = ['Node']


@dataclass(frozen=True)
class TopicEndpointInfo:
    """One endpoint on a topic, as rclpy's ``TopicEndpointInfo`` (``get_*_info_by_topic``)."""

    node_name: str
    node_namespace: str
    topic_type: str
    endpoint_type: str
    endpoint_gid: bytes
    qos_profile: QoSProfile


#: What rmw reports for an endpoint whose node it cannot name (``rmw`` graph cache).
UNKNOWN_NODE = ('_NODE_NAME_UNKNOWN_', '_NODE_NAMESPACE_UNKNOWN_')


class _NodeExecutor(Protocol):
    """What a node asks of the executors that spin it."""

    def wake(self) -> None: ...

    def remove_node(self, node: DdsNode) -> None: ...


_creation_counter = itertools.count()


class DdsNode(NodeParametersMixin, NodeServicesMixin, NodeEndpointsMixin):
    """
    A standalone node with the ``rclpy.node.Node`` subset that tf_demo uses.

    Like an rclpy node it publishes ``/parameter_events`` and (``enable_rosout``) its log lines
    on ``/rosout``, offers the parameter services (``start_parameter_services``) and has
    rclpy's parameter, service and client, publisher, subscription and timer methods (the
    mixins of ``node_parameters``, ``node_services`` and ``node_endpoints``).

    :param node_name: the node's name (``__node:=`` in ``--ros-args`` overrides it).
    :param namespace: absolute or relative namespace (``__ns:=`` overrides it).
    :param cli_args: this node's own ``--ros-args`` (in addition to those given to
        :func:`~tf_demo.transport.init`).
    :param use_global_arguments: whether the arguments given to :func:`~tf_demo.transport.init`
        apply.
    :param parameter_overrides: ``Parameter`` objects that replace declared defaults.
    """

    def __init__(
        self,
        node_name: str,
        *,
        context: object = None,
        cli_args: Sequence[str] | None = None,
        namespace: str | None = None,
        use_global_arguments: bool = True,
        enable_rosout: bool = True,
        start_parameter_services: bool = True,
        parameter_overrides: Sequence[Parameter] | None = None,
        allow_undeclared_parameters: bool = False,
        automatically_declare_parameters_from_overrides: bool = False,
        enable_logger_service: bool = False,
    ) -> None:
        del context, enable_logger_service
        if not _context.ok():
            msg = (
                'the standalone world is not initialised (or was shut down): call '
                'tf_demo.transport.init() before creating a node'
            )
            raise RuntimeError(msg)
        self._destroyed = False
        self._creation_index = next(_creation_counter)
        arguments: list[str] = []
        if use_global_arguments:
            arguments.extend(_context.args)
        arguments.extend(cli_args or [])
        resolved = ros_args.resolve_node_arguments(arguments, node_name, namespace or '')
        self._node_name = str(resolved.node_name)
        namespace_text = str(resolved.namespace or '/')
        if not namespace_text.startswith('/'):
            namespace_text = '/' + namespace_text
        validate_node_name(self._node_name)
        validate_namespace(namespace_text)
        self._namespace = namespace_text
        self._remap = resolved.remap_topic
        overrides = dict(resolved.parameter_overrides)
        for parameter in parameter_overrides or ():
            overrides[parameter.name] = parameter
        self._parameters = ParameterStore(
            overrides,
            allow_undeclared_parameters=allow_undeclared_parameters,
            automatically_declare_parameters_from_overrides=(
                automatically_declare_parameters_from_overrides
            ),
        )
        logger_name = self.get_fully_qualified_name().lstrip('/').replace('/', '.')
        self._logger = get_logger(logger_name)
        if resolved.log_level is not None:
            self._logger.set_level(resolved.log_level)
        self._lock = threading.RLock()
        self._publishers: list[AnyPublisher] = []
        self._subscriptions: list[DdsSubscription] = []
        self._timers: list[DdsTimer] = []
        self._services: list[AnyService] = []
        self._clients: list[AnyClient] = []
        self._executors: weakref.WeakSet[_NodeExecutor] = weakref.WeakSet()
        self._default_callback_group: CallbackGroup = MutuallyExclusiveCallbackGroup()
        self._clock = ROSClock()
        self._participant = _participant()
        with _context.lock:
            _context.nodes.add(self)
        self._interfaces: NodeInterfaces | None = None
        self._interfaces = NodeInterfaces(
            self, enable_rosout=enable_rosout, start_parameter_services=start_parameter_services
        )
        self._time_source = TimeSource(node=self)
        self._time_source.attach_clock(self._clock)
        _graph_changed()

    def destroy_node(self) -> None:
        """Destroy every entity of the node (publishers are flushed first)."""
        if self._destroyed:
            return
        with contextlib.suppress(Exception):
            self._time_source.detach_node()
        with self._lock:
            self._destroyed = True
            publishers, self._publishers = self._publishers, []
            subscriptions, self._subscriptions = self._subscriptions, []
            timers, self._timers = self._timers, []
            services, self._services = self._services, []
            clients, self._clients = self._clients, []
        for executor in list(self._executors):
            executor.remove_node(self)
        for publisher in publishers:
            publisher._close()
        for subscription in subscriptions:
            subscription._close()
        for timer in timers:
            timer.destroy()
        for entity in [*services, *clients]:
            entity._close()
        self._parameters.event_sink = None
        if self._interfaces is not None:
            self._interfaces.close()
        with _context.lock:
            _context.nodes.discard(self)
        _graph_changed()

    # -- graph -----------------------------------------------------------------------------

    def count_publishers(self, topic_name: str) -> int:
        """Return the number of publishers on ``topic_name`` in the whole domain."""
        full_topic = self.resolve_topic_name(topic_name)
        return self._participant.count_endpoints(
            dds_wire.dds_topic_name(full_topic), publications=True
        )

    def get_publishers_info_by_topic(
        self, topic_name: str, no_mangle: bool = False
    ) -> list[TopicEndpointInfo]:
        """
        Return every publisher on ``topic_name`` in the domain with the QoS it offers.

        As rclpy's; the publishing node's name is rmw's ``_NODE_NAME_UNKNOWN_`` here (this
        backend does not map endpoints to the nodes of other processes).
        """
        full_topic = topic_name if no_mangle else self.resolve_topic_name(topic_name)
        dds_topic = full_topic if no_mangle else dds_wire.dds_topic_name(full_topic)
        return [
            TopicEndpointInfo(
                *UNKNOWN_NODE,
                dds_wire.ros_type_name(sample.type_name),
                'PUBLISHER',
                bytes(sample.key.bytes),
                dds_wire.profile_from_cyclone(sample.qos),
            )
            for sample in self._participant.endpoints(dds_topic, publications=True)
        ]

    def count_subscribers(self, topic_name: str) -> int:
        """Return the number of subscriptions on ``topic_name`` in the whole domain."""
        full_topic = self.resolve_topic_name(topic_name)
        return self._participant.count_endpoints(
            dds_wire.dds_topic_name(full_topic), publications=False
        )

    def _reader_gids(self) -> list[bytes]:
        return [s._reader.guid for s in self._subscriptions] + self._service_reader_gids()

    def _writer_gids(self) -> list[bytes]:
        interfaces = getattr(self, '_interfaces', None)
        return [
            *(p._writer.guid for p in self._publishers),
            *self._service_writer_gids(),
            *(interfaces.writer_gids() if interfaces is not None else ()),
        ]

    def _wake_executors(self) -> None:
        for executor in list(self._executors):
            executor.wake()

    def __enter__(self) -> DdsNode:
        return self

    def __exit__(self, *exc_info: object) -> None:
        self.destroy_node()


Node = DdsNode


def create_node(node_name: str, **kwargs: Any) -> DdsNode:
    """Create a :class:`DdsNode` (rclpy ``create_node``)."""
    return DdsNode(node_name, **kwargs)
