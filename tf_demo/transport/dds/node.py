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

from collections.abc import Callable
from collections.abc import Sequence
import contextlib
import itertools
import threading
from typing import Any
from typing import cast
from typing import Protocol
import weakref

from tf_demo.transport.dds import wire as dds_wire
from tf_demo.transport.dds.callback_groups import CallbackGroup
from tf_demo.transport.dds.callback_groups import MutuallyExclusiveCallbackGroup
from tf_demo.transport.dds.clock import Clock
from tf_demo.transport.dds.clock import ROSClock
from tf_demo.transport.dds.context import _context
from tf_demo.transport.dds.context import _graph_changed
from tf_demo.transport.dds.context import _participant
from tf_demo.transport.dds.endpoints import _as_profile
from tf_demo.transport.dds.endpoints import _message_type_info
from tf_demo.transport.dds.endpoints import _refuse_unsupported
from tf_demo.transport.dds.endpoints import _takes_message_info
from tf_demo.transport.dds.endpoints import DdsPublisher
from tf_demo.transport.dds.endpoints import DdsSubscription
from tf_demo.transport.dds.names import expand_topic_name
from tf_demo.transport.dds.names import validate_namespace
from tf_demo.transport.dds.names import validate_node_name
from tf_demo.transport.dds.node_parameters import NodeParametersMixin
from tf_demo.transport.dds.node_services import NodeServicesMixin
from tf_demo.transport.dds.time_source import TimeSource
from tf_demo.transport.dds.timers import DdsTimer


class _NodeExecutor(Protocol):
    """What a node asks of the executors that spin it."""

    def wake(self) -> None: ...

    def remove_node(self, node: DdsNode) -> None: ...


_creation_counter = itertools.count()


class DdsNode(NodeParametersMixin, NodeServicesMixin):
    """
    A standalone node with the ``rclpy.node.Node`` subset that tf_demo uses.

    Like an rclpy node it publishes ``/parameter_events`` and (``enable_rosout``) its log lines
    on ``/rosout``, offers the parameter services (``start_parameter_services``) and has
    rclpy's service and client methods (``dds_services.NodeServicesMixin``).

    :param node_name: the node's name (``__node:=`` in ``--ros-args`` overrides it).
    :param namespace: absolute or relative namespace (``__ns:=`` overrides it).
    :param cli_args: this node's own ``--ros-args`` (in addition to those given to :func:`init`).
    :param use_global_arguments: whether the arguments given to :func:`init` apply.
    :param parameter_overrides: ``Parameter`` objects that replace declared defaults.
    """

    supports_raw_subscriptions = True
    """
    Capability: ``create_subscription(..., raw=True)`` hands callbacks the CDR bytes.

    Readers of serialized samples (the tf listener's fast path) check this class attribute
    (default False where absent, as on rclpy's ``Node``) instead of the class' module.
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
        parameter_overrides: Sequence[Any] | None = None,
        allow_undeclared_parameters: bool = False,
        automatically_declare_parameters_from_overrides: bool = False,
        enable_logger_service: bool = False,
    ) -> None:
        del context, enable_logger_service
        from tf_demo.transport import ros_args
        from tf_demo.transport.dds.logging import get_logger
        from tf_demo.transport.dds.parameter_services import NodeInterfaces
        from tf_demo.transport.dds.parameter_store import ParameterStore

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
        self._publishers: list[DdsPublisher] = []
        self._subscriptions: list[DdsSubscription] = []
        self._timers: list[DdsTimer] = []
        self._services: list[Any] = []
        self._clients: list[Any] = []
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
        self._time_source = TimeSource(node=cast('Any', self))
        self._time_source.attach_clock(self._clock)
        _graph_changed()

    # -- identity --------------------------------------------------------------------------

    def get_name(self) -> str:
        """Return the node's name."""
        return self._node_name

    def get_namespace(self) -> str:
        """Return the node's absolute namespace."""
        return self._namespace

    def get_fully_qualified_name(self) -> str:
        """Return ``/namespace/name``."""
        return self._namespace.rstrip('/') + '/' + self._node_name

    @property
    def context(self) -> object:
        """The process context (kept for rclpy compatibility)."""
        return _context

    def get_logger(self) -> Any:
        """Return the node's logger."""
        return self._logger

    def get_clock(self) -> Clock:
        """Return the node's ROS clock (``/clock`` when ``use_sim_time`` is true)."""
        return self._clock

    @property
    def default_callback_group(self) -> CallbackGroup:
        """The mutually exclusive group of entities created without a ``callback_group``."""
        return self._default_callback_group

    # -- names -----------------------------------------------------------------------------

    def resolve_topic_name(self, topic: str, *, only_expand: bool = False) -> str:
        """Expand ``topic`` as rcl does and apply the ``-r`` remapping rules."""
        expanded = expand_topic_name(topic, self._node_name, self._namespace)
        if only_expand:
            return expanded
        remapped = str(self._remap(expanded, self._node_name, self._namespace))
        if remapped != expanded:
            remapped = expand_topic_name(remapped, self._node_name, self._namespace)
        return remapped

    # -- entities --------------------------------------------------------------------------

    def _check_alive(self) -> None:
        if self._destroyed:
            msg = f'node {self.get_fully_qualified_name()!r} was destroyed'
            raise RuntimeError(msg)

    def _incompatible_qos_reporter(self, topic: str, *, publisher: bool) -> Callable[[str], None]:
        # rclpy's default event handlers print the topic as the caller spelled it.
        logger = self._logger
        if publisher:
            text = (
                f"New subscription discovered on topic '{topic}', requesting incompatible QoS. "
                'No messages will be sent to it. Last incompatible policy: {policy}'
            )
        else:
            text = (
                f"New publisher discovered on topic '{topic}', offering incompatible QoS. "
                'No messages will be received from it. Last incompatible policy: {policy}'
            )

        def report(policy: str) -> None:
            logger.warning(text.format(policy=policy))

        return report

    def _open_endpoint(
        self, msg_type: Any, topic: str, qos_profile: Any, *, publisher: bool
    ) -> tuple[Any, str, Any]:
        """Create the DDS writer (``publisher``) or reader; return it, the topic and profile."""
        self._check_alive()
        type_name, type_hash = _message_type_info(msg_type)
        profile = _as_profile(qos_profile)
        full_topic = self.resolve_topic_name(topic)
        participant = self._participant
        create = participant.create_writer if publisher else participant.create_reader
        endpoint = create(
            dds_wire.dds_topic_name(full_topic),
            type_name,
            dds_wire.endpoint_qos_from_profile(profile),
            f'typehash={type_hash};'.encode(),
            self._incompatible_qos_reporter(topic, publisher=publisher),
        )
        return endpoint, full_topic, profile

    def create_publisher(
        self,
        msg_type: Any,
        topic: str,
        qos_profile: Any,
        *,
        callback_group: object = None,
        event_callbacks: object = None,
        qos_overriding_options: object = None,
        publisher_class: type[DdsPublisher] = DdsPublisher,
    ) -> DdsPublisher:
        """
        Create a publisher of ``msg_type`` on ``topic`` with a QoSProfile or history depth.

        :raises NotImplementedError: for ``event_callbacks`` or ``qos_overriding_options``
            (incompatible QoS is logged as rclpy's default handler does).
        """
        del callback_group
        _refuse_unsupported(event_callbacks, qos_overriding_options)
        writer, full_topic, profile = self._open_endpoint(
            msg_type, topic, qos_profile, publisher=True
        )
        publisher = publisher_class(self, msg_type, full_topic, profile, writer)
        with self._lock:
            self._publishers.append(publisher)
        _graph_changed()
        return publisher

    def create_subscription(
        self,
        msg_type: Any,
        topic: str,
        callback: Callable[[Any], Any],
        qos_profile: Any,
        *,
        callback_group: CallbackGroup | None = None,
        event_callbacks: object = None,
        qos_overriding_options: object = None,
        raw: bool = False,
    ) -> DdsSubscription:
        """
        Create a subscription; ``callback(msg)`` runs in the executor that spins the node.

        ``callback(msg, message_info)`` when it binds two arguments but not one (rclpy's rule).
        The subscription joins ``callback_group`` (default: :attr:`default_callback_group`).

        :raises RuntimeError: for a callback that binds neither one nor two arguments.
        :raises NotImplementedError: for ``event_callbacks`` or ``qos_overriding_options``.
        """
        group = callback_group or self._default_callback_group
        _refuse_unsupported(event_callbacks, qos_overriding_options)
        _takes_message_info(callback)
        reader, full_topic, profile = self._open_endpoint(
            msg_type, topic, qos_profile, publisher=False
        )
        subscription = DdsSubscription(
            self,
            msg_type,
            full_topic,
            callback,
            qos_profile=profile,
            reader=reader,
            raw=raw,
            callback_group=group,
        )
        group.add_entity(subscription)
        with self._lock:
            self._subscriptions.append(subscription)
        self._wake_executors()
        _graph_changed()
        return subscription

    def create_timer(
        self,
        timer_period_sec: float,
        callback: Callable[[], Any],
        callback_group: CallbackGroup | None = None,
        clock: Clock | None = None,
        autostart: bool = True,
    ) -> DdsTimer:
        """
        Create a timer calling ``callback()`` every ``timer_period_sec`` seconds.

        The period is truncated to whole nanoseconds, as rclpy does; with ``autostart=False``
        the timer starts canceled until :meth:`DdsTimer.reset`. The timer joins
        ``callback_group`` (default: :attr:`default_callback_group`).
        """
        self._check_alive()
        period_ns = int(float(timer_period_sec) * 1e9)
        if period_ns < 0:
            msg = f'timer period must be non-negative, got {timer_period_sec!r}'
            raise ValueError(msg)
        group = self._default_callback_group if callback_group is None else callback_group
        timer = DdsTimer(
            callback,
            period_ns,
            clock or self._clock,
            autostart=autostart,
            callback_group=group,
        )
        group.add_entity(timer)
        timer._wake = self._wake_executors
        with self._lock:
            self._timers.append(timer)
        self._wake_executors()
        return timer

    def create_rate(self, frequency: float, clock: Clock | None = None) -> Any:
        """Rates are not supported by the standalone backend (use a timer)."""
        del frequency, clock
        msg = 'create_rate is not supported by the DDS backend; use create_timer'
        raise NotImplementedError(msg)

    def destroy_publisher(self, publisher: DdsPublisher) -> bool:
        """Destroy ``publisher`` (waits briefly for reliable readers to acknowledge)."""
        if not self._detach(self._publishers, publisher):
            return False
        publisher._close()
        _graph_changed()
        return True

    def destroy_subscription(self, subscription: DdsSubscription) -> bool:
        """Destroy ``subscription``."""
        if not self._detach(self._subscriptions, subscription):
            return False
        self._wake_executors()
        subscription._close()
        _graph_changed()
        return True

    def destroy_timer(self, timer: DdsTimer) -> bool:
        """Destroy ``timer``."""
        if not self._detach(self._timers, timer):
            return False
        timer.destroy()
        return True

    def _detach(self, entities: list[Any], entity: object) -> bool:
        """Remove ``entity`` from the node's list; False when it is not (or no longer) there."""
        with self._lock:
            if entity not in entities:
                return False
            entities.remove(entity)
        return True

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

    def count_subscribers(self, topic_name: str) -> int:
        """Return the number of subscriptions on ``topic_name`` in the whole domain."""
        full_topic = self.resolve_topic_name(topic_name)
        return self._participant.count_endpoints(
            dds_wire.dds_topic_name(full_topic), publications=False
        )

    @property
    def publishers(self) -> list[DdsPublisher]:
        """The node's publishers."""
        return list(self._publishers)

    @property
    def subscriptions(self) -> list[DdsSubscription]:
        """The node's subscriptions."""
        return list(self._subscriptions)

    @property
    def timers(self) -> list[DdsTimer]:
        """The node's timers."""
        return list(self._timers)

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
