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

Executors are waitset based and schedule as rclpy's: the spinning thread waits on the read
conditions of the subscriptions its nodes may run now, a guard condition and the earliest timer
deadline; everything that wait found ready (node by node: timers, then subscriptions) is handed
out, one entity per ``spin_once``, before the next wait, so an always-overdue timer cannot starve
a subscription. :class:`SingleThreadedExecutor` runs callbacks in the spinning thread,
:class:`MultiThreadedExecutor` in a thread pool, honouring callback groups. Each process also
publishes its nodes on ``ros_discovery_info`` so that ``ros2 node list`` shows them.
"""

from __future__ import annotations

from collections import deque
from collections.abc import Callable
from collections.abc import Iterable
from collections.abc import Sequence
from concurrent.futures import ThreadPoolExecutor
import contextlib
import functools
import inspect
import itertools
import os
import re
import threading
import time
from typing import Any
from typing import cast
from typing import Protocol
from typing import TypeAlias
import warnings
import weakref

from tf_demo.transport import dds_wire
from tf_demo.transport.clock import Clock
from tf_demo.transport.clock import Duration
from tf_demo.transport.clock import ROSClock
from tf_demo.transport.clock import TimeSource
from tf_demo.transport.dds_services import NodeServicesMixin
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
    """
    A subscription (rclpy ``Subscription`` subset); its callback runs in the executor.

    ``callback_group`` is the group it was created in (the node's default group unless given).
    """

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
        callback_group: CallbackGroup | None = None,
    ) -> None:
        self._node_ref = weakref.ref(node)
        self.msg_type = msg_type
        self.topic_name = topic
        self.callback = callback
        self.callback_group: CallbackGroup = (
            MutuallyExclusiveCallbackGroup() if callback_group is None else callback_group
        )
        self.qos_profile = qos_profile
        self.raw = raw
        self._reader = reader
        from tf_demo.msgs import cdr
        from tf_demo.msgs.log_throttle import PerWriterThrottle

        self._deserialize = cdr.deserialize
        self._decode_error = cdr.CdrError
        self._malformed = PerWriterThrottle('malformed samples')

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
            if self.raw:
                return [(payload, None) for payload in self._reader.take(_TAKE_BATCH)]
            samples = self._reader.take_with_info(_TAKE_BATCH)
            decoded = (self._decode(payload, writer) for payload, _, writer in samples)
            return [(m, None) for m in decoded if m is not None]
        received_ns = time.time_ns()
        items: list[tuple[Any, dict[str, Any] | None]] = []
        for payload, source_ns, publication_handle in self._reader.take_with_info(_TAKE_BATCH):
            message = payload if self.raw else self._decode(payload, publication_handle)
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

    def _decode(self, payload: bytes, publication_handle: int) -> Any:
        """Decode one sample; a malformed one is dropped, logged throttled per writer."""
        try:
            return self._deserialize(self.msg_type, payload)
        except (self._decode_error, ValueError) as error:
            node = self._node_ref()
            if node is not None:
                line = self._malformed.line(
                    self._reader.publisher_gid(publication_handle),
                    f'Dropped a malformed {self.msg_type.__msgtype__} message on '
                    f"'{self.topic_name}': {error}",
                )
                if line is not None:
                    node.get_logger().error(line)
            return None

    def destroy(self) -> bool:
        """Destroy this subscription (same as ``node.destroy_subscription(self)``)."""
        node = self._node_ref()
        return node.destroy_subscription(self) if node is not None else False

    def _close(self) -> None:
        self._reader.close()


class DdsTimer:
    """
    A periodic timer (rclpy ``Timer`` subset) on the node's clock.

    ``callback_group`` is the group it was created in (the node's default group unless given).
    Its state is guarded by a lock: a pool thread marks it called while the spinning thread
    asks whether it is ready.
    """

    def __init__(
        self,
        callback: Callable[[], Any],
        period_ns: int,
        clock: Clock,
        *,
        autostart: bool = True,
        callback_group: CallbackGroup | None = None,
    ) -> None:
        self.callback = callback
        self.timer_period_ns = period_ns
        self.clock = clock
        self.callback_group: CallbackGroup = (
            MutuallyExclusiveCallbackGroup() if callback_group is None else callback_group
        )
        self._lock = threading.RLock()
        self._canceled = not autostart
        self._next_call_ns = int(clock.now().nanoseconds) + period_ns
        self._last_call_ns: int | None = None
        self._wake: Callable[[], None] | None = None

    def _now_ns(self) -> int:
        now = int(self.clock.now().nanoseconds)
        with self._lock:
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
        with self._lock:
            self._canceled = False
            self._next_call_ns = self._now_ns() + self.timer_period_ns
        if self._wake is not None:
            self._wake()

    def is_ready(self) -> bool:
        """Return whether the timer is due."""
        with self._lock:
            return not self._canceled and self._now_ns() >= self._next_call_ns

    def time_until_next_call(self) -> int | None:
        """Return nanoseconds until the next call (None when canceled)."""
        with self._lock:
            if self._canceled:
                return None
            return max(0, self._next_call_ns - self._now_ns())

    def time_since_last_call(self) -> int:
        """Return nanoseconds since the last call (or since creation)."""
        with self._lock:
            last = self._last_call_ns
            reference = last if last is not None else self._next_call_ns - self.timer_period_ns
            return self._now_ns() - reference

    def _mark_called(self) -> None:
        with self._lock:
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
    rclpy's callback group: decides when the callbacks of its entities may run.

    Entities (subscriptions, timers) are added with :meth:`add_entity` when they are created;
    an executor asks :meth:`can_execute` before handing an entity out, takes permission with
    :meth:`beginning_execution` and returns it with :meth:`ending_execution`. Subclasses
    implement those three, as in rclpy.
    """

    def __init__(self) -> None:
        self.entities: set[weakref.ref[Any]] = set()

    def add_entity(self, entity: Any) -> None:
        """Add ``entity`` (a subscription or timer) to the group."""
        self.entities.add(weakref.ref(entity))

    def has_entity(self, entity: Any) -> bool:
        """Return whether ``entity`` was added to the group."""
        return weakref.ref(entity) in self.entities

    def can_execute(self, entity: Any) -> bool:
        """Return whether a callback of ``entity`` may start now."""
        raise NotImplementedError

    def beginning_execution(self, entity: Any) -> bool:
        """Ask to start a callback of ``entity``; True obliges to call :meth:`ending_execution`."""
        raise NotImplementedError

    def ending_execution(self, entity: Any) -> None:
        """Tell the group that a callback of ``entity`` finished."""
        raise NotImplementedError


class ReentrantCallbackGroup(CallbackGroup):
    """Callbacks of the group may run concurrently, even the same entity's."""

    def can_execute(self, entity: Any) -> bool:
        """Return True: the group never holds a callback back."""
        del entity
        return True

    def beginning_execution(self, entity: Any) -> bool:
        """Return True: permission is always given."""
        del entity
        return True

    def ending_execution(self, entity: Any) -> None:
        """Nothing to release."""
        del entity


class MutuallyExclusiveCallbackGroup(CallbackGroup):
    """At most one callback of the group runs at a time (a node's default group is one)."""

    def __init__(self) -> None:
        super().__init__()
        self._active_entity: Any = None
        self._lock = threading.Lock()

    def _check_member(self, entity: Any) -> None:
        if not self.has_entity(entity):
            msg = f'{entity!r} is not an entity of this callback group'
            raise AssertionError(msg)

    def can_execute(self, entity: Any) -> bool:
        """Return whether no callback of the group is running."""
        with self._lock:
            self._check_member(entity)
            return self._active_entity is None

    def beginning_execution(self, entity: Any) -> bool:
        """Take the group for ``entity`` unless a callback of the group is running."""
        with self._lock:
            self._check_member(entity)
            if self._active_entity is None:
                self._active_entity = entity
                return True
        return False

    def ending_execution(self, entity: Any) -> None:
        """Release the group taken for ``entity``."""
        with self._lock:
            if self._active_entity is not entity:
                msg = f'{entity!r} is not the entity running in this callback group'
                raise AssertionError(msg)
            self._active_entity = None


# --------------------------------------------------------------------------------------------
# Node
# --------------------------------------------------------------------------------------------

_creation_counter = itertools.count()


class DdsNode(NodeServicesMixin):
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
        from tf_demo.transport.dds_parameter_services import NodeInterfaces
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
        self._services: list[Any] = []
        self._clients: list[Any] = []
        self._executors: weakref.WeakSet[DdsExecutor] = weakref.WeakSet()
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
        self, namespace: str, parameters: Sequence[Sequence[Any]], ignore_override: bool = False
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
        self._executing = False

    def executing(self) -> bool:
        """Return whether a step of the task is running (or queued in a thread pool)."""
        return self._executing

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


class _ReaderEntity(Protocol):
    """
    What the executor needs of an entity served from a read condition.

    Subscriptions, and service servers and clients (``dds_services``), which the executors
    serve alike: wait on ``read_condition``, ``take_messages()``, then ``callback`` per item.
    """

    callback_group: CallbackGroup

    @property
    def read_condition(self) -> int: ...

    @property
    def callback(self) -> Callable[..., Any]: ...

    def take_messages(self) -> list[tuple[Any, dict[str, Any] | None]]: ...


_Entity: TypeAlias = 'DdsTimer | _ReaderEntity'
_Call: TypeAlias = 'tuple[Callable[..., Any], tuple[Any, ...]]'


def _reader_entities(node: DdsNode) -> list[_ReaderEntity]:
    """Return the node's read-condition entities: subscriptions, clients, services (rclpy)."""
    return [
        *node.subscriptions,
        *getattr(node, 'clients', ()),
        *getattr(node, 'services', ()),
    ]


class ExternalShutdownException(Exception):  # noqa: N818 - rclpy's name
    """The context was shut down (rclpy's ``rclpy.executors.ExternalShutdownException``)."""


class DdsExecutor:
    """
    Runs the callbacks of any number of nodes, scheduled as rclpy's ``Executor`` does.

    A wait is on a Cyclone waitset holding the read condition of every subscription that may
    run now (not handed out already, and its callback group allows it), a guard condition (woken
    when entities change, on shutdown and when a pooled callback ends) and a timeout at the
    earliest deadline of such a timer. What the wait found ready is queued node by node, timers
    first, then subscriptions; :meth:`spin_once` hands out one queued entity per call and waits
    again only once the queue is empty (rclpy's persisted generator), so every entity that was
    ready is served before a timer that is overdue again runs a second time. A subscription
    handed out takes up to 256 waiting samples and runs its callback on each. Where callbacks
    run is the subclass' choice (:meth:`_execute`); ``async def`` callbacks become tasks that
    later spins resume.
    """

    _pooled = False
    """Whether callbacks run in other threads (which then wake the waitset)."""

    def __init__(self, *, context: object = None) -> None:
        del context
        self._nodes: list[DdsNode] = []
        self._lock = threading.RLock()
        self._waitset_participant = _participant()
        self._waitset = dds_wire.WaitSet(self._waitset_participant)
        self._attached: dict[int, _ReaderEntity] = {}
        self._shutdown = False
        self._tasks: list[DdsTask] = []
        self._tasks_lock = threading.Lock()
        self._ready: deque[tuple[DdsNode, _Entity]] = deque()
        """Entities found ready by the last wait and not handed out yet."""
        self._handed_out: set[_Entity] = set()
        """Entities handed out whose data is not taken yet: not waited on (rclpy's flag)."""
        self._handed_out_lock = threading.Lock()
        with _context.lock:
            _context.executors.add(self)

    def __enter__(self) -> DdsExecutor:
        return self

    def __exit__(self, *exc_info: object) -> None:
        self.shutdown()

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

    def can_execute(self, entity: _Entity) -> bool:
        """Return whether ``entity`` may be waited on and handed out now (rclpy's rule)."""
        with self._handed_out_lock:
            if entity in self._handed_out:
                return False
        return bool(entity.callback_group.can_execute(entity))

    # -- waiting ---------------------------------------------------------------------------

    def _refresh_conditions(self) -> dict[int, _ReaderEntity]:
        participant = _participant()
        if participant is not self._waitset_participant:
            # The world was shut down and initialised again: the old waitset died with the old
            # participant.
            self._waitset_participant = participant
            self._waitset = dds_wire.WaitSet(participant)
            self._attached = {}
        wanted: dict[int, _ReaderEntity] = {}
        for node in self.get_nodes():
            for entity in _reader_entities(node):
                if self.can_execute(entity):
                    wanted[entity.read_condition] = entity
        for condition in set(self._attached) - set(wanted):
            self._waitset.detach(condition)
        for condition in set(wanted) - set(self._attached):
            self._waitset.attach(condition)
        self._attached = wanted
        return wanted

    def _wait_timeout_ns(self, timeout_sec: float | None) -> int:
        limit = _IDLE_WAIT_NS if timeout_sec is None else int(timeout_sec * 1e9)
        for node in self.get_nodes():
            for timer in node.timers:
                if not self.can_execute(timer):
                    continue
                remaining = timer.time_until_next_call()
                if remaining is None:
                    continue
                if isinstance(timer.clock, ROSClock) and timer.clock.ros_time_is_active:
                    remaining = min(remaining, _SIM_TIME_MAX_WAIT_NS)
                limit = min(limit, remaining)
        return max(0, limit)

    def _collect_ready(self, triggered: list[int], conditions: dict[int, _ReaderEntity]) -> None:
        """Queue what the wait found ready: node by node, due timers, then subscriptions (...)."""
        with_data = {id(conditions[c]) for c in triggered if c in conditions}
        for node in self.get_nodes():
            if node._destroyed:
                continue
            self._ready.extend(
                (node, timer)
                for timer in node.timers
                if timer.is_ready() and self.can_execute(timer)
            )
            self._ready.extend(
                (node, entity)
                for entity in _reader_entities(node)
                if id(entity) in with_data and self.can_execute(entity)
            )

    # -- handing out and running -----------------------------------------------------------

    def _dispatch_next(self) -> bool:
        """Hand out the next queued entity its group lets run; False when none is left."""
        while True:
            try:
                node, entity = self._ready.popleft()
            except IndexError:
                return False
            with self._lock:
                present = node in self._nodes
            if not present or node._destroyed or not self.can_execute(entity):
                # Considered again by the next wait (its data or deadline is still there).
                continue
            with self._handed_out_lock:
                self._handed_out.add(entity)
            self._execute(functools.partial(self._serve, node, entity))
            return True

    def _execute(self, job: Callable[[], None]) -> None:
        """Run ``job`` (a handed-out entity or a task step): here, in the spinning thread."""
        job()

    def _serve(self, node: DdsNode, entity: _Entity) -> None:
        """With the group's permission take the entity's data and run its callback(s)."""
        group = entity.callback_group
        if self._shutdown or not group.beginning_execution(entity):
            # Not now: the entity is waited on again and runs once its group is free.
            self._taken(entity)
            return
        try:
            try:
                calls = self._take(node, entity)
            finally:
                self._taken(entity)
            for callback, args in calls:
                self._run_callback(callback, *args)
        finally:
            group.ending_execution(entity)

    def _taken(self, entity: _Entity) -> None:
        """Let the entity be waited on again: its data is taken (or left for later)."""
        with self._handed_out_lock:
            self._handed_out.discard(entity)
        if self._pooled:
            self.wake()

    def _take(self, node: DdsNode, entity: _Entity) -> list[_Call]:
        """Mark a timer called, or take a reader entity's samples; the calls to make."""
        if node._destroyed:
            return []
        if isinstance(entity, DdsTimer):
            if entity not in node._timers or entity.is_canceled():
                return []
            entity._mark_called()
            return [(entity.callback, ())]
        if entity not in _reader_entities(node):
            return []
        try:
            items = entity.take_messages()
        except dds_wire.DdsWireError:
            if entity in _reader_entities(node):
                raise
            return []  # destroyed while its samples were being taken
        callback = entity.callback
        return [(callback, (msg,) if info is None else (msg, info)) for msg, info in items]

    def _run_callback(self, callback: Callable[..., Any], *args: Any) -> None:
        # As in rclpy, an exception raised by user code propagates out of spin(), and an
        # ``async def`` callback becomes a task that is resumed on later spins.
        outcome = callback(*args)
        if inspect.iscoroutine(outcome):
            task = DdsTask(outcome)
            task.step()
            if not task.done():
                with self._tasks_lock:
                    self._tasks.append(task)
                return
            error = task.exception()
            if error is not None:
                raise error

    def _raise_pending_error(self) -> None:
        """Re-raise an exception a callback raised in another thread (none here)."""

    # -- tasks -----------------------------------------------------------------------------

    def create_task(self, callback: Any, *args: Any) -> DdsTask:
        """Run a coroutine (or ``callback(*args)``) in this executor; returns its task."""
        task = DdsTask(callback, args)
        with self._tasks_lock:
            self._tasks.append(task)
        self.wake()
        return task

    def _step_task(self, task: DdsTask) -> None:
        try:
            task.step()
        finally:
            task._executing = False
        if not task.done():
            return
        with self._tasks_lock:
            if task in self._tasks:
                self._tasks.remove(task)
        error = task.exception()
        if error is not None:
            raise error

    def _resume_tasks(self) -> bool:
        """Step every pending task not already being stepped; return whether any finished."""
        with self._tasks_lock:
            pending = list(self._tasks)
        finished = False
        for task in pending:
            with self._tasks_lock:
                if task._executing:
                    continue
                task._executing = True
            self._execute(functools.partial(self._step_task, task))
            finished = task.done() or finished
        return finished

    # -- spinning --------------------------------------------------------------------------

    def spin_once(self, timeout_sec: float | None = None) -> None:
        """
        Hand out one ready entity, waiting up to ``timeout_sec`` (None or negative: no limit).

        Entities found ready by the last wait are handed out first, one per call; a new wait
        happens only when none is left. A handed-out subscription drains up to 256 samples.
        Returns also when a task finished, or at the timeout.
        """
        if not _context.ok() or self._shutdown:
            return
        self._raise_pending_error()
        deadline = (
            None if timeout_sec is None or timeout_sec < 0 else time.monotonic() + timeout_sec
        )
        while True:
            if self._dispatch_next():
                self._raise_pending_error()
                return
            if self._resume_tasks():
                return
            conditions = self._refresh_conditions()
            remaining = None if deadline is None else max(0.0, deadline - time.monotonic())
            wait_ns = self._wait_timeout_ns(remaining)
            if self._tasks:
                # A pending task may be waiting for something another thread completes.
                wait_ns = min(wait_ns, _TASK_POLL_NS)
            triggered = self._waitset.wait(wait_ns)
            if not _context.ok() or self._shutdown:
                return
            self._raise_pending_error()
            self._collect_ready(triggered, conditions)
            if not self._ready and deadline is not None and time.monotonic() >= deadline:
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
        """
        Stop spinning, wait for running callbacks and drop the nodes.

        :param timeout_sec: longest wait for running callbacks (None or negative: no limit).
        :return: False when callbacks were still running at the timeout (nodes are kept).
        """
        self._shutdown = True
        self.wake()
        if not self._wait_for_callbacks(timeout_sec):
            return False
        for node in self.get_nodes():
            self.remove_node(node)
        self._ready.clear()
        return True

    def _wait_for_callbacks(self, timeout_sec: float | None) -> bool:
        """Wait for callbacks running in other threads (none here)."""
        del timeout_sec
        return True


class SingleThreadedExecutor(DdsExecutor):
    """rclpy's ``SingleThreadedExecutor``: every callback runs in the spinning thread."""


def _default_thread_count() -> int:
    """Return rclpy's default pool size: the CPUs this process may use, else the count, or 2."""
    if hasattr(os, 'sched_getaffinity'):
        return len(os.sched_getaffinity(0)) or 2
    return os.cpu_count() or 2


class MultiThreadedExecutor(DdsExecutor):
    """
    rclpy's ``MultiThreadedExecutor``: callbacks run in a pool of ``num_threads`` threads.

    The spinning thread waits and hands entities out; a pool thread then asks the entity's
    callback group for permission (a mutually exclusive group runs one callback at a time, a
    reentrant one any number, even several of the same entity), takes the data, runs the
    callback and wakes the waitset, so an entity its group held back is considered again. An
    exception raised by a callback is re-raised in the spinning thread by the next
    :meth:`spin_once`. :meth:`shutdown` waits for running callbacks, then stops the pool.

    :param num_threads: pool size; None: the CPUs this process may use (as rclpy).
    """

    _pooled = True

    def __init__(self, num_threads: int | None = None, *, context: object = None) -> None:
        if num_threads is None:
            num_threads = _default_thread_count()
        self._pool = ThreadPoolExecutor(num_threads)  # worker names: 'ThreadPoolExecutor-...'
        super().__init__(context=context)
        if num_threads == 1:
            warnings.warn(
                'MultiThreadedExecutor is used with a single thread.\n'
                'Use the SingleThreadedExecutor instead.',
                stacklevel=2,
            )
        self._errors: deque[BaseException] = deque()
        self._work = threading.Condition()
        self._outstanding = 0
        """Jobs submitted to the pool and not finished."""
        self._job_thread = threading.local()

    def _execute(self, job: Callable[[], None]) -> None:
        """Run ``job`` in the pool."""
        with self._work:
            self._outstanding += 1
        try:
            self._pool.submit(self._run_job, job)
        except RuntimeError:  # the pool was stopped by a concurrent shutdown()
            self._job_finished()
            if not self._shutdown:
                raise

    def _run_job(self, job: Callable[[], None]) -> None:
        self._job_thread.active = True
        try:
            job()
        except BaseException as error:  # re-raised in the spinning thread by spin_once
            self._errors.append(error)
        finally:
            self._job_thread.active = False
            self._job_finished()
            self.wake()

    def _job_finished(self) -> None:
        with self._work:
            self._outstanding -= 1
            self._work.notify_all()

    def _raise_pending_error(self) -> None:
        """Re-raise the oldest exception a pooled callback raised."""
        try:
            error = self._errors.popleft()
        except IndexError:
            return
        raise error

    def _wait_for_callbacks(self, timeout_sec: float | None) -> bool:
        """Wait for the pool's jobs (not the calling one, from a callback) and stop the pool."""
        own = 1 if getattr(self._job_thread, 'active', False) else 0
        limit = None if timeout_sec is None or timeout_sec < 0 else timeout_sec
        with self._work:
            if not self._work.wait_for(lambda: self._outstanding <= own, limit):
                return False
        self._pool.shutdown(wait=not own)
        return True


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
