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

"""Publishers and subscriptions (rclpy ``Publisher``/``Subscription`` subsets) over DDS."""

from __future__ import annotations

from collections.abc import Callable
import inspect
import time
from typing import Any
from typing import Generic
from typing import Protocol
from typing import TypeAlias
from typing import TypedDict
from typing import TypeVar
import weakref

from tf_demo.msgs import cdr
from tf_demo.msgs._message import Message
from tf_demo.msgs.log_throttle import PerWriterThrottle
from tf_demo.transport.dds.callback_groups import CallbackGroup
from tf_demo.transport.dds.callback_groups import MutuallyExclusiveCallbackGroup
from tf_demo.transport.dds.logging import Logger
from tf_demo.transport.dds.qos import QoSProfile
from tf_demo.transport.dds.raw_endpoints import RawReader
from tf_demo.transport.dds.raw_endpoints import RawWriter
from tf_demo.transport.dds.time import Duration

__all__ = [
    'AnyPublisher',
    'DdsPublisher',
    'DdsSubscription',
    'MessageInfo',
    'MsgT',
    'SubscriptionCallback',
    'incompatible_qos_reporter',
]

MsgT = TypeVar('MsgT', bound=Message)
"""The message class of a publisher or subscription."""


class MessageInfo(TypedDict):
    """
    What a two-argument subscription callback gets beside the message (rclpy's keys).

    ``publisher_gid`` (the writer's 16-byte GUID) is the standalone world's addition.
    """

    source_timestamp: int
    received_timestamp: int
    publication_sequence_number: int
    reception_sequence_number: int
    publisher_gid: bytes


_PayloadT = TypeVar('_PayloadT')
SubscriptionCallback: TypeAlias = (
    'Callable[[_PayloadT], object] | Callable[[_PayloadT, MessageInfo], object]'
)
"""A subscription callback: ``callback(msg)`` or ``callback(msg, message_info)`` (rclpy's)."""


class _EndpointOwner(Protocol):
    """What a publisher or subscription asks of the node that created it."""

    def get_logger(self) -> Logger: ...

    def destroy_publisher(self, publisher: DdsPublisher[MsgT]) -> bool: ...

    def destroy_subscription(self, subscription: DdsSubscription) -> bool: ...


_FLUSH_TIMEOUT_NS = 1_000_000_000
_DDS_INFINITY = 2**63 - 1
_WAIT_FOREVER = Duration(seconds=-1)
_TAKE_BATCH = 256


def _as_profile(qos_or_depth: QoSProfile | int) -> QoSProfile:
    """
    Return the profile of ``qos_or_depth`` (an int is a KEEP_LAST depth).

    An object with rclpy's profile attributes passes as a profile (a user's rclpy profile).
    """
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


def _message_type_info(msg_type: type[Message]) -> tuple[str, str]:
    type_name = getattr(msg_type, '__dds_typename__', None)
    type_hash = getattr(msg_type, '__typehash__', None)
    if not isinstance(type_name, str) or not isinstance(type_hash, str):
        msg = (
            f'{msg_type!r} is not a message class of tf_demo.msgs '
            '(it has no __dds_typename__/__typehash__)'
        )
        raise TypeError(msg)
    return type_name, type_hash


class DdsPublisher(Generic[MsgT]):
    """A publisher (rclpy ``Publisher`` subset): ``publish``, ``topic_name``, counts."""

    def __init__(
        self,
        node: _EndpointOwner,
        msg_type: type[MsgT],
        topic: str,
        qos_profile: QoSProfile,
        writer: RawWriter,
    ) -> None:
        self._node_ref = weakref.ref(node)
        self.msg_type = msg_type
        self.topic_name = topic
        self.qos_profile = qos_profile
        self._writer = writer
        self._serialize = cdr.serialize

    @property
    def topic(self) -> str:
        """The fully qualified topic name."""
        return self.topic_name

    def publish(self, msg: MsgT | bytes) -> None:
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


def _takes_message_info(callback: Callable[..., object]) -> bool:
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
        node: _EndpointOwner,
        msg_type: type[Message],
        topic: str,
        callback: Callable[..., object],
        *,
        qos_profile: QoSProfile,
        reader: RawReader,
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
        self._deserialize = cdr.deserialize
        self._decode_error = cdr.CdrError
        self._malformed = PerWriterThrottle('malformed samples')

    @property
    def callback(self) -> Callable[..., object]:
        """
        The user callback; setting it re-applies rclpy's one-or-two-argument rule.

        It takes the message (or its CDR ``bytes`` when ``raw``), and the
        :class:`MessageInfo` when ``wants_message_info``.
        """
        return self._callback

    @callback.setter
    def callback(self, value: Callable[..., object]) -> None:
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

    def take_messages(self) -> list[tuple[Message | bytes, MessageInfo | None]]:
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
        items: list[tuple[Message | bytes, MessageInfo | None]] = []
        for payload, source_ns, publication_handle in self._reader.take_with_info(_TAKE_BATCH):
            message = payload if self.raw else self._decode(payload, publication_handle)
            if message is None:
                continue
            info: MessageInfo = {
                'source_timestamp': source_ns,
                'received_timestamp': received_ns,
                'publication_sequence_number': _SEQUENCE_NUMBER_UNSUPPORTED,
                'reception_sequence_number': _SEQUENCE_NUMBER_UNSUPPORTED,
                'publisher_gid': self._reader.publisher_gid(publication_handle),
            }
            items.append((message, info))
        return items

    def _decode(self, payload: bytes, publication_handle: int) -> Message | None:
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


def incompatible_qos_reporter(
    logger: Logger, topic: str, *, publisher: bool
) -> Callable[[str], None]:
    """
    Return what logs an incompatible QoS peer of a publisher or subscription on ``topic``.

    rclpy's default event handlers' texts; the topic as the caller spelled it.
    """
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


AnyPublisher: TypeAlias = 'DdsPublisher[Any]'
"""A publisher of any message class (a node's list of them)."""


def _refuse_unsupported(event_callbacks: object, qos_overriding_options: object) -> None:
    """Raise rather than silently ignore rclpy options that change an endpoint's behaviour."""
    for name, value in (
        ('event_callbacks', event_callbacks),
        ('qos_overriding_options', qos_overriding_options),
    ):
        if value is not None:
            msg = f'{name} is not supported by the standalone (DDS) backend; pass None'
            raise NotImplementedError(msg)
