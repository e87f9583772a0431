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
The standalone world's node: the subset of ``rclpy.node.Node`` the package uses, over DDS.

:class:`DdsNode` has rclpy's method names and signatures for publishers, subscriptions, timers,
clock, parameters (the node-API's :class:`~tf_demo.transport.parameters.ParameterStore`), logger
and graph counts. Names are expanded and validated as rcl does (relative names get the node's
namespace, ``~`` is the node's fully qualified name) and remapped by ``--ros-args -r``.

Executors are waitset based: one thread waits on the read conditions of every subscription of
its nodes, a guard condition, and the earliest timer deadline, then runs the callbacks in that
same thread. Each process also publishes its nodes on ``ros_discovery_info`` so that
``ros2 node list`` shows them.
"""

from __future__ import annotations

from collections.abc import Callable
from collections.abc import Iterable
from collections.abc import Sequence
import contextlib
import inspect
import itertools
import re
import threading
import time
from typing import Any
from typing import cast
import weakref

from tf_demo.transport import dds_wire
from tf_demo.transport.clock import Clock
from tf_demo.transport.clock import Duration
from tf_demo.transport.clock import ROSClock
from tf_demo.transport.clock import TimeSource
from tf_demo.transport.qos import QoSProfile

__all__ = [
    'CallbackGroup',
    'DdsExecutor',
    'DdsNode',
    'DdsPublisher',
    'DdsSubscription',
    'DdsTask',
    'DdsTimer',
    'InvalidNameError',
    'MultiThreadedExecutor',
    'MutuallyExclusiveCallbackGroup',
    'Node',
    'ReentrantCallbackGroup',
    'SingleThreadedExecutor',
    'create_node',
    'expand_topic_name',
    'init',
    'ok',
    'shutdown',
    'spin',
    'spin_once',
    'spin_until_future_complete',
    'try_shutdown',
    'validate_namespace',
    'validate_node_name',
]

_FLUSH_TIMEOUT_NS = 1_000_000_000
_DDS_INFINITY = 2**63 - 1
_WAIT_FOREVER = Duration(seconds=-1)
_TAKE_BATCH = 256


# --------------------------------------------------------------------------------------------
# Names (pure, rcl's rules)
# --------------------------------------------------------------------------------------------


class InvalidNameError(ValueError):
    """A node name, namespace or topic name breaks ROS 2's naming rules; says where and why."""

    def __init__(self, kind: str, name: str, reason: str, index: int) -> None:
        pointer = ' ' * (index + 3) + '^'
        super().__init__(f"Invalid {kind}: {reason}:\n  '{name}'\n{pointer}")
        self.name = name
        self.reason = reason
        self.index = index


_NODE_NAME_RE = re.compile(r'[A-Za-z0-9_]*')
_TOKEN_CHARS_RE = re.compile(r'[A-Za-z0-9_/~{}]')


def validate_node_name(name: str) -> None:
    """Check a node name as ``rmw_validate_node_name``; raise :class:`InvalidNameError`."""
    if not name:
        raise InvalidNameError('node name', name, 'node name must not be empty', 0)
    match = _NODE_NAME_RE.match(name)
    end = match.end() if match else 0
    if end != len(name):
        raise InvalidNameError(
            'node name',
            name,
            'node name must not contain characters other than alphanumerics or "_"',
            end,
        )
    if name[0].isdigit():
        raise InvalidNameError('node name', name, 'node name must not start with a number', 0)
    if len(name) > 255:
        raise InvalidNameError('node name', name, 'node name length must not exceed 255', 255)


def validate_namespace(namespace: str) -> None:
    """Check an absolute namespace as ``rmw_validate_namespace``."""
    kind = 'namespace'
    if not namespace:
        raise InvalidNameError(kind, namespace, 'namespace must not be empty', 0)
    if not namespace.startswith('/'):
        raise InvalidNameError(kind, namespace, 'namespace must be absolute', 0)
    if namespace == '/':
        return
    if namespace.endswith('/'):
        raise InvalidNameError(kind, namespace, "namespace must not end with '/'", len(namespace))
    _validate_tokens(kind, namespace)


def _validate_tokens(kind: str, name: str, extra_chars: str = '') -> None:
    allowed = '_/' + extra_chars
    for index, char in enumerate(name):
        if not (char.isascii() and (char.isalnum() or char in allowed)):
            raise InvalidNameError(
                kind,
                name,
                f'{kind} must not contain characters other than alphanumerics, "_" or "/"',
                index,
            )
    if '//' in name:
        raise InvalidNameError(kind, name, "must not contain repeated '/'", name.index('//'))
    position = 0
    for token in name.split('/'):
        if token and token[0].isdigit():
            raise InvalidNameError(kind, name, 'a token must not start with a number', position)
        position += len(token) + 1


def expand_topic_name(topic: str, node_name: str, namespace: str) -> str:
    """
    Expand and validate a topic name as rcl and rmw do (``rcl_expand_topic_name``).

    ``~`` is the node's fully qualified name, relative names are put in the namespace, and
    ``{node}``/``{ns}``/``{namespace}`` substitutions are replaced.

    :raises InvalidNameError: naming the offending character.
    """
    kind = 'topic name'
    if not topic:
        raise InvalidNameError(kind, topic, 'topic name must not be empty', 0)
    for index, char in enumerate(topic):
        if not (char.isascii() and _TOKEN_CHARS_RE.match(char)):
            raise InvalidNameError(
                kind,
                topic,
                'topic name must not contain characters other than alphanumerics, '
                '"_", "~", "{", "}" or "/"',
                index,
            )
    if '~' in topic[1:]:
        raise InvalidNameError(
            kind, topic, "'~' must only be the first character", topic.index('~', 1)
        )
    if topic.startswith('~') and len(topic) > 1 and topic[1] != '/':
        raise InvalidNameError(kind, topic, "'~' must be followed by '/'", 1)
    if topic.endswith('/'):
        raise InvalidNameError(kind, topic, "topic name must not end with '/'", len(topic) - 1)
    _validate_tokens(kind, topic, '~{}')
    node_fqn = namespace.rstrip('/') + '/' + node_name
    expanded = topic
    for key, value in (('{node}', node_name), ('{ns}', namespace), ('{namespace}', namespace)):
        expanded = expanded.replace(key, value)
    if '{' in expanded or '}' in expanded:
        index = max(expanded.find('{'), expanded.find('}'))
        raise InvalidNameError(kind, topic, 'unknown substitution', index)
    if expanded.startswith('~'):
        expanded = node_fqn + expanded[1:]
    elif not expanded.startswith('/'):
        expanded = namespace.rstrip('/') + '/' + expanded
    if expanded.endswith('/') and expanded != '/':
        raise InvalidNameError(kind, expanded, "topic name must not end with '/'", len(expanded))
    _validate_tokens(kind, expanded)
    return expanded


# --------------------------------------------------------------------------------------------
# Process context
# --------------------------------------------------------------------------------------------


class _Context:
    """The process-wide init/shutdown state, global ``--ros-args`` and live nodes."""

    def __init__(self) -> None:
        self.lock = threading.RLock()
        self.initialized = False
        self.shut_down = False
        self.args: list[str] = []
        self.nodes: weakref.WeakSet[DdsNode] = weakref.WeakSet()
        self.executors: weakref.WeakSet[DdsExecutor] = weakref.WeakSet()
        self.graph: _Graph | None = None

    def ok(self) -> bool:
        return self.initialized and not self.shut_down


_context = _Context()


def init(*, args: Sequence[str] | None = None, context: object = None) -> None:
    """Initialise the standalone world (rclpy ``init``); ``args`` may hold ``--ros-args``."""
    del context
    with _context.lock:
        _context.initialized = True
        _context.shut_down = False
        _context.args = list(args) if args is not None else []


def ok(*, context: object = None) -> bool:
    """Return whether :func:`init` was called and :func:`shutdown` was not."""
    del context
    return _context.ok()


def shutdown(*, context: object = None) -> None:
    """
    Stop every executor, flush every writer and release the DDS participant.

    :raises RuntimeError: before :func:`init` or a second time (as rclpy's ``Context.shutdown``;
        :func:`try_shutdown` is the quiet form).
    """
    del context
    with _context.lock:
        if not _context.initialized:
            msg = 'Context must be initialized before it can be shutdown'
            raise RuntimeError(msg)
        if _context.shut_down:
            msg = 'failed to shutdown: rcl_shutdown already called on the given context'
            raise RuntimeError(msg)
        _context.shut_down = True
    _release_everything()


def try_shutdown(*, context: object = None) -> None:
    """Shut down unless not initialised or already shut down (rclpy ``try_shutdown``)."""
    del context
    with _context.lock:
        if not _context.ok():
            return
        _context.shut_down = True
    _release_everything()


def _release_everything() -> None:
    """Wake every executor, destroy every node and close the graph writer and participant."""
    with _context.lock:
        executors = list(_context.executors)
        nodes = list(_context.nodes)
    for executor in executors:
        executor.wake()
    for node in nodes:
        node.destroy_node()
    with _context.lock:
        if _context.graph is not None:
            _context.graph.close()
            _context.graph = None
    dds_wire.close_participant()


def _participant() -> dds_wire.DdsParticipant:
    return dds_wire.get_participant(warn=_warn_process)


def _warn_process(text: str) -> None:
    from tf_demo.transport.logging import get_logger

    get_logger('tf_demo.dds').warning(text)


# --------------------------------------------------------------------------------------------
# Graph (ros_discovery_info)
# --------------------------------------------------------------------------------------------


class _Graph:
    """Publishes this process' nodes and their endpoints on ``ros_discovery_info``."""

    def __init__(self, participant: dds_wire.DdsParticipant) -> None:
        from tf_demo.msgs import rmw_dds_common

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

    def publish(self, nodes: Iterable[DdsNode]) -> None:
        from tf_demo.msgs import cdr

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


def _graph_changed() -> None:
    with _context.lock:
        if _context.shut_down:
            return
        if _context.graph is None:
            _context.graph = _Graph(_participant())
        graph = _context.graph
        nodes = [node for node in _context.nodes if not node._destroyed]
        nodes.sort(key=lambda node: node._creation_index)
    graph.publish(nodes)


# --------------------------------------------------------------------------------------------
# Entities
# --------------------------------------------------------------------------------------------


def _as_profile(qos_or_depth: Any) -> Any:
    if isinstance(qos_or_depth, bool):
        msg = f'qos_profile must be a QoSProfile or a history depth, got {qos_or_depth!r}'
        raise TypeError(msg)
    if isinstance(qos_or_depth, int):
        if qos_or_depth < 0:
            msg = f'history depth must be >= 0, got {qos_or_depth}'
            raise ValueError(msg)
        return QoSProfile(depth=qos_or_depth)
    if all(hasattr(qos_or_depth, attr) for attr in ('reliability', 'durability', 'depth')):
        return qos_or_depth
    msg = f'qos_profile must be a QoSProfile or a history depth, got {qos_or_depth!r}'
    raise TypeError(msg)


def _message_type_info(msg_type: Any) -> tuple[str, str]:
    type_name = getattr(msg_type, '__dds_typename__', None)
    type_hash = getattr(msg_type, '__typehash__', None)
    if not isinstance(type_name, str) or not isinstance(type_hash, str):
        msg = (
            f'{msg_type!r} is not a message class of tf_demo.msgs '
            '(it has no __dds_typename__/__typehash__)'
        )
        raise TypeError(msg)
    return type_name, type_hash


class DdsPublisher:
    """A publisher (rclpy ``Publisher`` subset): ``publish``, ``topic_name``, counts."""

    def __init__(
        self, node: DdsNode, msg_type: Any, topic: str, qos_profile: Any, writer: Any
    ) -> None:
        self._node_ref = weakref.ref(node)
        self.msg_type = msg_type
        self.topic_name = topic
        self.qos_profile = qos_profile
        self._writer = writer
        from tf_demo.msgs import cdr

        self._serialize = cdr.serialize

    @property
    def topic(self) -> str:
        """The fully qualified topic name."""
        return self.topic_name

    def publish(self, msg: Any) -> None:
        """Serialize ``msg`` (an instance of the publisher's type, or CDR ``bytes``); send it."""
        if isinstance(msg, self.msg_type):
            payload = self._serialize(msg)
        elif isinstance(msg, bytes):
            payload = msg
        else:
            msg_text = (
                f'Expected {self.msg_type.__name__}, got {type(msg).__name__} '
                f'on topic {self.topic_name!r}'
            )
            raise TypeError(msg_text)
        self._writer.write(payload)

    def get_subscription_count(self) -> int:
        """Return the number of matched subscriptions."""
        return int(self._writer.matched_count())

    def wait_for_all_acked(self, timeout: Duration = _WAIT_FOREVER) -> bool:
        """Block until every reliable subscription acknowledged everything (negative: no limit)."""
        timeout_ns = timeout.nanoseconds
        return bool(self._writer.wait_for_acks(timeout_ns if timeout_ns >= 0 else _DDS_INFINITY))

    def destroy(self) -> bool:
        """Destroy this publisher (same as ``node.destroy_publisher(self)``)."""
        node = self._node_ref()
        return node.destroy_publisher(self) if node is not None else False

    def _close(self) -> None:
        self._writer.close(flush_timeout_ns=_FLUSH_TIMEOUT_NS)


_SEQUENCE_NUMBER_UNSUPPORTED = 2**64 - 1
"""``RMW_MESSAGE_INFO_SEQUENCE_NUMBER_UNSUPPORTED``: Cyclone does not report sequence numbers."""


def _takes_message_info(callback: Callable[..., Any]) -> bool:
    """
    Whether ``callback`` gets ``(msg, message_info)``, by rclpy's rule.

    A callback that binds one argument gets the message only; else one that binds two gets the
    message info too.

    :raises RuntimeError: when it binds neither (rclpy's text).
    """
    for arity in (1, 2):
        try:
            inspect.signature(callback).bind(*(object(),) * arity)
        except TypeError:
            continue
        return arity == 2
    msg = (
        'Subscription.__init__(): callback should be either be callable with one argument'
        '(to get only the message) or two (to get message and message info)'
    )
    raise RuntimeError(msg)


class DdsSubscription:
    """A subscription (rclpy ``Subscription`` subset); its callback runs in the executor."""

    def __init__(
        self,
        node: DdsNode,
        msg_type: Any,
        topic: str,
        callback: Callable[[Any], Any],
        *,
        qos_profile: Any,
        reader: Any,
        raw: bool,
    ) -> None:
        self._node_ref = weakref.ref(node)
        self.msg_type = msg_type
        self.topic_name = topic
        self.callback = callback
        self.qos_profile = qos_profile
        self.raw = raw
        self._reader = reader
        from tf_demo.msgs import cdr

        self._deserialize = cdr.deserialize
        self._decode_error = cdr.CdrError

    @property
    def callback(self) -> Callable[..., Any]:
        """The user callback; setting it re-applies rclpy's one-or-two-argument rule."""
        return self._callback

    @callback.setter
    def callback(self, value: Callable[..., Any]) -> None:
        self.wants_message_info = _takes_message_info(value)
        self._callback = value

    @property
    def topic(self) -> str:
        """The fully qualified topic name."""
        return self.topic_name

    @property
    def read_condition(self) -> int:
        """The DDS read condition that triggers when samples are waiting."""
        return int(self._reader.read_condition)

    def get_publisher_count(self) -> int:
        """Return the number of matched publishers."""
        return int(self._reader.matched_count())

    def take_messages(self) -> list[tuple[Any, dict[str, Any] | None]]:
        """
        Take waiting samples and decode them; malformed ones are logged and dropped.

        Each item is ``(message, message_info)``; ``message_info`` (rclpy's ``MessageInfo``
        keys plus ``publisher_gid``, the writer's 16-byte GUID) is built only for callbacks that
        take two arguments.
        """
        if not self.wants_message_info:
            payloads = self._reader.take(_TAKE_BATCH)
            if self.raw:
                return [(payload, None) for payload in payloads]
            return [(m, None) for m in (self._decode(p) for p in payloads) if m is not None]
        received_ns = time.time_ns()
        items: list[tuple[Any, dict[str, Any] | None]] = []
        for payload, source_ns, publication_handle in self._reader.take_with_info(_TAKE_BATCH):
            message = payload if self.raw else self._decode(payload)
            if message is None:
                continue
            info = {
                'source_timestamp': source_ns,
                'received_timestamp': received_ns,
                'publication_sequence_number': _SEQUENCE_NUMBER_UNSUPPORTED,
                'reception_sequence_number': _SEQUENCE_NUMBER_UNSUPPORTED,
                'publisher_gid': self._reader.publisher_gid(publication_handle),
            }
            items.append((message, info))
        return items

    def _decode(self, payload: bytes) -> Any:
        try:
            return self._deserialize(self.msg_type, payload)
        except (self._decode_error, ValueError) as error:
            node = self._node_ref()
            if node is not None:
                node.get_logger().error(
                    f'Dropped a malformed {self.msg_type.__msgtype__} message on '
                    f"'{self.topic_name}': {error}"
                )
            return None

    def destroy(self) -> bool:
        """Destroy this subscription (same as ``node.destroy_subscription(self)``)."""
        node = self._node_ref()
        return node.destroy_subscription(self) if node is not None else False

    def _close(self) -> None:
        self._reader.close()


class DdsTimer:
    """A periodic timer (rclpy ``Timer`` subset) on the node's clock."""

    def __init__(
        self, callback: Callable[[], Any], period_ns: int, clock: Clock, *, autostart: bool = True
    ) -> None:
        self.callback = callback
        self.timer_period_ns = period_ns
        self.clock = clock
        self._canceled = not autostart
        self._next_call_ns = int(clock.now().nanoseconds) + period_ns
        self._last_call_ns: int | None = None
        self._wake: Callable[[], None] | None = None

    def _now_ns(self) -> int:
        now = int(self.clock.now().nanoseconds)
        if now < self._next_call_ns - self.timer_period_ns:
            # The clock jumped backwards (e.g. a bag replayed on /clock from the start):
            # restart the period from the new time instead of waiting for the old deadline.
            self._next_call_ns = now + self.timer_period_ns
        return now

    def cancel(self) -> None:
        """Stop calling the callback until :meth:`reset`."""
        self._canceled = True

    def is_canceled(self) -> bool:
        """Return whether the timer is canceled."""
        return self._canceled

    def reset(self) -> None:
        """Restart the period from now (and un-cancel)."""
        self._canceled = False
        self._next_call_ns = self._now_ns() + self.timer_period_ns
        if self._wake is not None:
            self._wake()

    def is_ready(self) -> bool:
        """Return whether the timer is due."""
        return not self._canceled and self._now_ns() >= self._next_call_ns

    def time_until_next_call(self) -> int | None:
        """Return nanoseconds until the next call (None when canceled)."""
        if self._canceled:
            return None
        return max(0, self._next_call_ns - self._now_ns())

    def time_since_last_call(self) -> int:
        """Return nanoseconds since the last call (or since creation)."""
        last = self._last_call_ns
        reference = last if last is not None else self._next_call_ns - self.timer_period_ns
        return self._now_ns() - reference

    def _mark_called(self) -> None:
        now = self._now_ns()
        self._last_call_ns = now
        self._next_call_ns += self.timer_period_ns
        if self.timer_period_ns == 0:
            self._next_call_ns = now
        elif self._next_call_ns <= now:
            # Fell behind (or the clock jumped): skip missed periods, as rcl does.
            missed = (now - self._next_call_ns) // self.timer_period_ns + 1
            self._next_call_ns += missed * self.timer_period_ns

    def destroy(self) -> None:
        """Cancel the timer for good."""
        self._canceled = True


def _refuse_unsupported(event_callbacks: object, qos_overriding_options: object) -> None:
    """Raise rather than silently ignore rclpy options that change an endpoint's behaviour."""
    for name, value in (
        ('event_callbacks', event_callbacks),
        ('qos_overriding_options', qos_overriding_options),
    ):
        if value is not None:
            msg = f'{name} is not supported by the standalone (DDS) backend; pass None'
            raise NotImplementedError(msg)


class CallbackGroup:
    """
    rclpy's callback group, accepted for compatibility.

    The DDS executors run every callback in the spinning thread, one at a time, which satisfies
    both group kinds.
    """


class MutuallyExclusiveCallbackGroup(CallbackGroup):
    """Callbacks of the group never run concurrently (always true here)."""


class ReentrantCallbackGroup(CallbackGroup):
    """Callbacks of the group may run concurrently (they run one at a time here)."""


# --------------------------------------------------------------------------------------------
# Node
# --------------------------------------------------------------------------------------------

_creation_counter = itertools.count()


class DdsNode:
    """
    A standalone node with the ``rclpy.node.Node`` subset that tf_demo uses.

    :param node_name: the node's name (``__node:=`` in ``--ros-args`` overrides it).
    :param namespace: absolute or relative namespace (``__ns:=`` overrides it).
    :param cli_args: this node's own ``--ros-args`` (in addition to those given to :func:`init`).
    :param use_global_arguments: whether the arguments given to :func:`init` apply.
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
        parameter_overrides: Sequence[Any] | None = None,
        allow_undeclared_parameters: bool = False,
        automatically_declare_parameters_from_overrides: bool = False,
        enable_logger_service: bool = False,
    ) -> None:
        del context, enable_rosout, start_parameter_services, enable_logger_service
        from tf_demo.transport import ros_args
        from tf_demo.transport.logging import get_logger
        from tf_demo.transport.parameters import ParameterStore

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
        self._executors: weakref.WeakSet[DdsExecutor] = weakref.WeakSet()
        self._clock = ROSClock()
        self._participant = _participant()
        with _context.lock:
            _context.nodes.add(self)
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

    # -- parameters ------------------------------------------------------------------------

    def declare_parameter(
        self,
        name: str,
        value: Any = None,
        descriptor: Any = None,
        ignore_override: bool = False,
    ) -> Any:
        """Declare one parameter (rclpy semantics; overrides from ``--ros-args`` apply)."""
        return self._parameters.declare_parameter(name, value, descriptor, ignore_override)

    def declare_parameters(
        self, namespace: str, parameters: Sequence[tuple[Any, ...]], ignore_override: bool = False
    ) -> list[Any]:
        """Declare several parameters: tuples of ``(name[, value[, descriptor]])``."""
        return self._parameters.declare_parameters(namespace, parameters, ignore_override)

    def undeclare_parameter(self, name: str) -> None:
        """Undeclare a parameter."""
        self._parameters.undeclare_parameter(name)

    def has_parameter(self, name: str) -> bool:
        """Return whether ``name`` is declared."""
        return self._parameters.has_parameter(name)

    def get_parameter(self, name: str) -> Any:
        """Return the ``Parameter`` named ``name``."""
        return self._parameters.get_parameter(name)

    def get_parameters(self, names: Iterable[str]) -> list[Any]:
        """Return several parameters."""
        return self._parameters.get_parameters(names)

    def get_parameter_or(self, name: str, alternative_value: Any = None) -> Any:
        """Return the parameter, or ``alternative_value`` when it is not declared."""
        return self._parameters.get_parameter_or(name, alternative_value)

    def get_parameters_by_prefix(self, prefix: str) -> dict[str, Any]:
        """Return the parameters under ``prefix.`` keyed by the rest of their names."""
        return self._parameters.get_parameters_by_prefix(prefix)

    def describe_parameter(self, name: str) -> Any:
        """Return the descriptor of a parameter."""
        return self._parameters.describe_parameter(name)

    def set_parameters(self, parameter_list: Sequence[Any]) -> list[Any]:
        """Set parameters one by one; returns one ``SetParametersResult`` each."""
        return self._parameters.set_parameters(parameter_list)

    def set_parameters_atomically(self, parameter_list: Sequence[Any]) -> Any:
        """Set parameters all or nothing."""
        return self._parameters.set_parameters_atomically(parameter_list)

    def add_on_set_parameters_callback(self, callback: Callable[[list[Any]], Any]) -> None:
        """Register a callback that may reject parameter changes."""
        self._parameters.add_on_set_parameters_callback(callback)

    def remove_on_set_parameters_callback(self, callback: Callable[[list[Any]], Any]) -> None:
        """Remove a callback registered with :meth:`add_on_set_parameters_callback`."""
        self._parameters.remove_on_set_parameters_callback(callback)

    def add_pre_set_parameters_callback(self, callback: Callable[[list[Any]], Any]) -> None:
        """Register a callback that may modify a parameter list before it is set."""
        self._parameters.add_pre_set_parameters_callback(callback)

    def remove_pre_set_parameters_callback(self, callback: Callable[[list[Any]], Any]) -> None:
        """Remove a callback registered with :meth:`add_pre_set_parameters_callback`."""
        self._parameters.remove_pre_set_parameters_callback(callback)

    def add_post_set_parameters_callback(self, callback: Callable[[list[Any]], Any]) -> None:
        """Register a callback told about parameters after they were set."""
        self._parameters.add_post_set_parameters_callback(callback)

    def remove_post_set_parameters_callback(self, callback: Callable[[list[Any]], Any]) -> None:
        """Remove a callback registered with :meth:`add_post_set_parameters_callback`."""
        self._parameters.remove_post_set_parameters_callback(callback)

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
        callback_group: object = None,
        event_callbacks: object = None,
        qos_overriding_options: object = None,
        raw: bool = False,
    ) -> DdsSubscription:
        """
        Create a subscription; ``callback(msg)`` runs in the executor that spins the node.

        ``callback(msg, message_info)`` when it binds two arguments but not one (rclpy's rule).

        :raises RuntimeError: for a callback that binds neither one nor two arguments.
        :raises NotImplementedError: for ``event_callbacks`` or ``qos_overriding_options``.
        """
        del callback_group
        _refuse_unsupported(event_callbacks, qos_overriding_options)
        _takes_message_info(callback)
        reader, full_topic, profile = self._open_endpoint(
            msg_type, topic, qos_profile, publisher=False
        )
        subscription = DdsSubscription(
            self, msg_type, full_topic, callback, qos_profile=profile, reader=reader, raw=raw
        )
        with self._lock:
            self._subscriptions.append(subscription)
        self._wake_executors()
        _graph_changed()
        return subscription

    def create_timer(
        self,
        timer_period_sec: float,
        callback: Callable[[], Any],
        callback_group: object = None,
        clock: Clock | None = None,
        autostart: bool = True,
    ) -> DdsTimer:
        """
        Create a timer calling ``callback()`` every ``timer_period_sec`` seconds.

        The period is truncated to whole nanoseconds, as rclpy does; with ``autostart=False``
        the timer starts canceled until :meth:`DdsTimer.reset`.
        """
        del callback_group
        self._check_alive()
        period_ns = int(float(timer_period_sec) * 1e9)
        if period_ns < 0:
            msg = f'timer period must be non-negative, got {timer_period_sec!r}'
            raise ValueError(msg)
        timer = DdsTimer(callback, period_ns, clock or self._clock, autostart=autostart)
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
        for executor in list(self._executors):
            executor.remove_node(self)
        for publisher in publishers:
            publisher._close()
        for subscription in subscriptions:
            subscription._close()
        for timer in timers:
            timer.destroy()
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
        return [s._reader.guid for s in self._subscriptions]

    def _writer_gids(self) -> list[bytes]:
        return [p._writer.guid for p in self._publishers]

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


# --------------------------------------------------------------------------------------------
# Executors
# --------------------------------------------------------------------------------------------


class DdsTask:
    """
    A coroutine (or plain callable) run by a DDS executor: rclpy's ``Task`` subset.

    The executor steps the coroutine with ``send(None)`` when it starts and again on every
    spin until it returns; awaiting a future that yields until done (rclpy's and
    ``tf_demo.ros.Future``'s protocol) therefore works.
    """

    def __init__(self, handler: Any, args: Sequence[Any] = ()) -> None:
        self._handler = handler
        self._args = tuple(args)
        self._coroutine: Any = handler if inspect.iscoroutine(handler) else None
        self._done = False
        self._cancelled = False
        self._result: Any = None
        self._exception: BaseException | None = None
        self._done_callbacks: list[Callable[[DdsTask], Any]] = []

    def done(self) -> bool:
        """Return whether the task finished (returned, raised or was cancelled)."""
        return self._done

    def cancelled(self) -> bool:
        """Return whether the task was cancelled."""
        return self._cancelled

    def cancel(self) -> None:
        """Stop stepping the task."""
        if not self._done:
            self._cancelled = True
            if self._coroutine is not None:
                self._coroutine.close()
            self._finish()

    def result(self) -> Any:
        """Return the task's result; re-raise its exception if it failed."""
        if self._exception is not None:
            raise self._exception
        return self._result

    def exception(self) -> BaseException | None:
        """Return the exception the task raised, if any."""
        return self._exception

    def add_done_callback(self, callback: Callable[[DdsTask], Any]) -> None:
        """Call ``callback(task)`` when the task finishes (at once if it already has)."""
        if self._done:
            callback(self)
        else:
            self._done_callbacks.append(callback)

    def step(self) -> None:
        """Run the task until its next suspension point (or to the end)."""
        if self._done:
            return
        try:
            if self._coroutine is None:
                outcome = self._handler(*self._args)
                if not inspect.iscoroutine(outcome):
                    self._result = outcome
                    self._finish()
                    return
                self._coroutine = outcome
            self._coroutine.send(None)
        except StopIteration as stop:
            self._result = stop.value
            self._finish()
        except Exception as error:  # kept for result(); the executor re-raises it
            self._exception = error
            self._finish()

    def _finish(self) -> None:
        self._done = True
        callbacks, self._done_callbacks = self._done_callbacks, []
        for callback in callbacks:
            callback(self)


_IDLE_WAIT_NS = 200_000_000
_TASK_POLL_NS = 5_000_000
_SIM_TIME_MAX_WAIT_NS = 10_000_000


class DdsExecutor:
    """
    Runs the callbacks of any number of nodes in the thread that spins it.

    Each :meth:`spin_once` waits on a Cyclone waitset holding the read condition of every
    subscription, a guard condition (woken when entities change or on shutdown) and a timeout
    at the earliest timer deadline; then it runs due timers and the callbacks of every
    subscription with data, in that thread.
    """

    def __init__(self, *, context: object = None) -> None:
        del context
        self._nodes: list[DdsNode] = []
        self._lock = threading.RLock()
        self._waitset_participant = _participant()
        self._waitset = dds_wire.WaitSet(self._waitset_participant)
        self._attached: dict[int, DdsSubscription] = {}
        self._shutdown = False
        self._tasks: list[DdsTask] = []
        self._tasks_lock = threading.Lock()
        with _context.lock:
            _context.executors.add(self)

    def add_node(self, node: DdsNode) -> bool:
        """Add ``node``; returns False when it was already added."""
        with self._lock:
            if node in self._nodes:
                return False
            self._nodes.append(node)
        node._executors.add(self)
        self.wake()
        return True

    def remove_node(self, node: DdsNode) -> None:
        """Remove ``node``."""
        with self._lock:
            if node in self._nodes:
                self._nodes.remove(node)
        node._executors.discard(self)
        self.wake()

    def get_nodes(self) -> list[DdsNode]:
        """Return the nodes of this executor."""
        with self._lock:
            return list(self._nodes)

    def wake(self) -> None:
        """Interrupt a wait so that entity changes or shutdown are seen at once."""
        self._waitset.wake()

    def _refresh_conditions(self) -> dict[int, DdsSubscription]:
        participant = _participant()
        if participant is not self._waitset_participant:
            # The world was shut down and initialised again: the old waitset died with the old
            # participant.
            self._waitset_participant = participant
            self._waitset = dds_wire.WaitSet(participant)
            self._attached = {}
        wanted: dict[int, DdsSubscription] = {}
        for node in self.get_nodes():
            for subscription in node.subscriptions:
                wanted[subscription.read_condition] = subscription
        for condition in set(self._attached) - set(wanted):
            self._waitset.detach(condition)
        for condition in set(wanted) - set(self._attached):
            self._waitset.attach(condition)
        self._attached = wanted
        return wanted

    def _timers(self) -> list[tuple[DdsNode, DdsTimer]]:
        return [(node, timer) for node in self.get_nodes() for timer in node.timers]

    def _wait_timeout_ns(self, timeout_sec: float | None) -> int:
        limit = _IDLE_WAIT_NS if timeout_sec is None or timeout_sec < 0 else int(timeout_sec * 1e9)
        for _node, timer in self._timers():
            remaining = timer.time_until_next_call()
            if remaining is None:
                continue
            if isinstance(timer.clock, ROSClock) and timer.clock.ros_time_is_active:
                remaining = min(remaining, _SIM_TIME_MAX_WAIT_NS)
            limit = min(limit, remaining)
        return max(0, limit)

    def _run_ready_timers(self) -> bool:
        ran = False
        for node, timer in self._timers():
            if node._destroyed or not timer.is_ready():
                continue
            timer._mark_called()
            ran = True
            self._run_callback(timer.callback)
        return ran

    def _run_callback(self, callback: Callable[..., Any], *args: Any) -> None:
        # As in rclpy, an exception raised by user code propagates out of spin(), and an
        # ``async def`` callback becomes a task that is resumed on later spins.
        outcome = callback(*args)
        if inspect.iscoroutine(outcome):
            task = DdsTask(outcome)
            with self._tasks_lock:
                self._tasks.append(task)
            self._step_task(task)

    def create_task(self, callback: Any, *args: Any) -> DdsTask:
        """Run a coroutine (or ``callback(*args)``) in this executor; returns its task."""
        task = DdsTask(callback, args)
        with self._tasks_lock:
            self._tasks.append(task)
        self.wake()
        return task

    def _step_task(self, task: DdsTask) -> bool:
        task.step()
        if not task.done():
            return False
        with self._tasks_lock:
            if task in self._tasks:
                self._tasks.remove(task)
        error = task.exception()
        if error is not None:
            raise error
        return True

    def _resume_tasks(self) -> bool:
        """Step every pending task once; return whether any finished."""
        with self._tasks_lock:
            pending = list(self._tasks)
        finished = False
        for task in pending:
            finished = self._step_task(task) or finished
        return finished

    def spin_once(self, timeout_sec: float | None = None) -> None:
        """
        Wait up to ``timeout_sec`` (None: until something happens) and run what is ready.

        Unlike rclpy, which runs one callback per call, every due timer and every waiting
        sample (up to 256 per subscription) is handled, so a busy topic is drained in one call.
        """
        if not _context.ok() or self._shutdown:
            return
        deadline = None if timeout_sec is None else time.monotonic() + max(0.0, timeout_sec)
        while True:
            conditions = self._refresh_conditions()
            tasks_finished = self._resume_tasks()
            if self._run_ready_timers() or tasks_finished:
                return
            remaining = None if deadline is None else deadline - time.monotonic()
            wait_ns = self._wait_timeout_ns(remaining)
            if self._tasks:
                # A pending task may be waiting for something another thread completes.
                wait_ns = min(wait_ns, _TASK_POLL_NS)
            triggered = self._waitset.wait(wait_ns)
            if not _context.ok() or self._shutdown:
                return
            ran = self._run_ready_timers()
            for condition in triggered:
                subscription = conditions.get(condition)
                if subscription is None:
                    continue
                node = subscription._node_ref()
                if node is None or node._destroyed:
                    continue
                for message, info in subscription.take_messages():
                    if info is None:
                        self._run_callback(subscription.callback, message)
                    else:
                        self._run_callback(subscription.callback, message, info)
                ran = True
            if ran or (deadline is not None and time.monotonic() >= deadline):
                return

    def spin(self) -> None:
        """Run callbacks until :func:`shutdown` (or :meth:`shutdown` of this executor)."""
        while _context.ok() and not self._shutdown:
            self.spin_once(None)

    def spin_until_future_complete(self, future: Any, timeout_sec: float | None = None) -> None:
        """Spin until ``future.done()`` or the timeout."""
        end = None if timeout_sec is None else time.monotonic() + timeout_sec
        while _context.ok() and not self._shutdown and not future.done():
            remaining = None if end is None else end - time.monotonic()
            if remaining is not None and remaining <= 0:
                return
            self.spin_once(0.1 if remaining is None else min(0.1, remaining))

    def shutdown(self, timeout_sec: float | None = None) -> bool:
        """Stop spinning and release the waitset."""
        del timeout_sec
        self._shutdown = True
        self.wake()
        for node in self.get_nodes():
            self.remove_node(node)
        return True


class SingleThreadedExecutor(DdsExecutor):
    """rclpy's ``SingleThreadedExecutor``: every callback runs in the spinning thread."""


class MultiThreadedExecutor(DdsExecutor):
    """
    Accepts rclpy's ``MultiThreadedExecutor`` arguments; callbacks still run one at a time.

    Serialising callbacks is a valid schedule for rclpy's default mutually exclusive callback
    groups, which is all tf_demo uses.
    """

    def __init__(self, num_threads: int | None = None, *, context: object = None) -> None:
        del num_threads
        super().__init__(context=context)


_default_executors: dict[int, DdsExecutor] = {}


def _executor_for(node: DdsNode, executor: DdsExecutor | None) -> DdsExecutor:
    if executor is not None:
        executor.add_node(node)
        return executor
    default = _default_executors.get(threading.get_ident())
    if default is None or default._shutdown:
        default = SingleThreadedExecutor()
        _default_executors[threading.get_ident()] = default
    default.add_node(node)
    return default


def spin_once(
    node: DdsNode, *, executor: DdsExecutor | None = None, timeout_sec: float | None = None
) -> None:
    """Run at most one round of ready callbacks of ``node`` (rclpy ``spin_once``)."""
    chosen = _executor_for(node, executor)
    try:
        chosen.spin_once(timeout_sec)
    finally:
        chosen.remove_node(node)


def spin_until_future_complete(
    node: DdsNode,
    future: Any,
    executor: DdsExecutor | None = None,
    timeout_sec: float | None = None,
) -> None:
    """Run the callbacks of ``node`` until ``future.done()`` or the timeout."""
    chosen = _executor_for(node, executor)
    try:
        chosen.spin_until_future_complete(future, timeout_sec)
    finally:
        chosen.remove_node(node)


def spin(node: DdsNode, executor: DdsExecutor | None = None) -> None:
    """Run the callbacks of ``node`` until shutdown (rclpy ``spin``)."""
    chosen = _executor_for(node, executor)
    try:
        while _context.ok() and not node._destroyed and not chosen._shutdown:
            chosen.spin_once(None)
    finally:
        chosen.remove_node(node)
