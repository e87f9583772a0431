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
A standalone node's publishers, subscriptions and timers (rclpy's ``create_*``/``destroy_*``).

Names are expanded and remapped by the node (:meth:`~.node_base.NodeBase.resolve_topic_name`);
the DDS endpoints come from the process' participant, their QoS from rmw_cyclonedds' mapping.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Literal
from typing import NoReturn
from typing import overload
from typing import TypeAlias
from typing import TypeVar

from tf_demo.msgs._message import Message
from tf_demo.transport.dds import wire as dds_wire
from tf_demo.transport.dds.callback_groups import CallbackGroup
from tf_demo.transport.dds.clock import Clock
from tf_demo.transport.dds.context import _graph_changed
from tf_demo.transport.dds.endpoints import _as_profile
from tf_demo.transport.dds.endpoints import _message_type_info
from tf_demo.transport.dds.endpoints import _refuse_unsupported
from tf_demo.transport.dds.endpoints import _takes_message_info
from tf_demo.transport.dds.endpoints import AnyPublisher
from tf_demo.transport.dds.endpoints import DdsPublisher
from tf_demo.transport.dds.endpoints import DdsSubscription
from tf_demo.transport.dds.endpoints import incompatible_qos_reporter
from tf_demo.transport.dds.endpoints import MsgT
from tf_demo.transport.dds.endpoints import SubscriptionCallback
from tf_demo.transport.dds.node_base import NodeBase
from tf_demo.transport.dds.qos import QoSProfile
from tf_demo.transport.dds.timers import DdsTimer

__all__ = ['NodeEndpointsMixin']

_EndpointT = TypeVar('_EndpointT', dds_wire.RawWriter, dds_wire.RawReader)
_CreateEndpoint: TypeAlias = (
    'Callable[[str, str, dds_wire.EndpointQos, bytes, Callable[[str], None]], _EndpointT]'
)
"""The participant's ``create_writer`` or ``create_reader``."""


class NodeEndpointsMixin(NodeBase):
    """The ``rclpy.node.Node`` publisher, subscription and timer methods of ``DdsNode``."""

    _publishers: list[AnyPublisher]
    _subscriptions: list[DdsSubscription]
    _timers: list[DdsTimer]

    def _open_endpoint(
        self,
        create: _CreateEndpoint[_EndpointT],
        msg_type: type[Message],
        topic: str,
        qos_profile: QoSProfile | int,
        *,
        publisher: bool,
    ) -> tuple[_EndpointT, str, QoSProfile]:
        """Create the DDS writer (``publisher``) or reader; return it, the topic and profile."""
        self._check_alive()
        type_name, type_hash = _message_type_info(msg_type)
        profile = _as_profile(qos_profile)
        full_topic = self.resolve_topic_name(topic)
        endpoint = create(
            dds_wire.dds_topic_name(full_topic),
            type_name,
            dds_wire.endpoint_qos_from_profile(profile),
            f'typehash={type_hash};'.encode(),
            incompatible_qos_reporter(self._logger, topic, publisher=publisher),
        )
        return endpoint, full_topic, profile

    def create_publisher(
        self,
        msg_type: type[MsgT],
        topic: str,
        qos_profile: QoSProfile | int,
        *,
        callback_group: object = None,
        event_callbacks: object = None,
        qos_overriding_options: object = None,
        publisher_class: type[DdsPublisher[MsgT]] = DdsPublisher,
    ) -> DdsPublisher[MsgT]:
        """
        Create a publisher of ``msg_type`` on ``topic`` with a QoSProfile or history depth.

        :raises NotImplementedError: for ``event_callbacks`` or ``qos_overriding_options``
            (incompatible QoS is logged as rclpy's default handler does).
        """
        del callback_group
        _refuse_unsupported(event_callbacks, qos_overriding_options)
        writer, full_topic, profile = self._open_endpoint(
            self._participant.create_writer, msg_type, topic, qos_profile, publisher=True
        )
        publisher = publisher_class(self, msg_type, full_topic, profile, writer)
        with self._lock:
            self._publishers.append(publisher)
        _graph_changed()
        return publisher

    @overload
    def create_subscription(
        self,
        msg_type: type[MsgT],
        topic: str,
        callback: SubscriptionCallback[MsgT],
        qos_profile: QoSProfile | int,
        *,
        callback_group: CallbackGroup | None = None,
        event_callbacks: object = None,
        qos_overriding_options: object = None,
        raw: Literal[False] = False,
    ) -> DdsSubscription: ...

    @overload
    def create_subscription(
        self,
        msg_type: type[Message],
        topic: str,
        callback: SubscriptionCallback[bytes],
        qos_profile: QoSProfile | int,
        *,
        callback_group: CallbackGroup | None = None,
        event_callbacks: object = None,
        qos_overriding_options: object = None,
        raw: bool,
    ) -> DdsSubscription: ...

    def create_subscription(
        self,
        msg_type: type[Message],
        topic: str,
        callback: Callable[..., object],
        qos_profile: QoSProfile | int,
        *,
        callback_group: CallbackGroup | None = None,
        event_callbacks: object = None,
        qos_overriding_options: object = None,
        raw: bool = False,
    ) -> DdsSubscription:
        """
        Create a subscription; ``callback(msg)`` runs in the executor that spins the node.

        ``callback(msg, message_info)`` when it binds two arguments but not one (rclpy's rule).
        With ``raw=True`` the callback gets the CDR ``bytes`` instead of the message.
        The subscription joins ``callback_group`` (default: :attr:`default_callback_group`).

        :raises RuntimeError: for a callback that binds neither one nor two arguments.
        :raises NotImplementedError: for ``event_callbacks`` or ``qos_overriding_options``.
        """
        group = callback_group or self._default_callback_group
        _refuse_unsupported(event_callbacks, qos_overriding_options)
        _takes_message_info(callback)
        reader, full_topic, profile = self._open_endpoint(
            self._participant.create_reader, msg_type, topic, qos_profile, publisher=False
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
        self._add_reader_entity(self._subscriptions, subscription, group)
        return subscription

    def create_timer(
        self,
        timer_period_sec: float,
        callback: Callable[[], object],
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

    def create_rate(self, frequency: float, clock: Clock | None = None) -> NoReturn:
        """Rates are not supported by the standalone backend (use a timer)."""
        del frequency, clock
        msg = 'create_rate is not supported by the DDS backend; use create_timer'
        raise NotImplementedError(msg)

    def destroy_publisher(self, publisher: DdsPublisher[MsgT]) -> bool:
        """Destroy ``publisher`` (waits briefly for reliable readers to acknowledge)."""
        if not self._detach(self._publishers, publisher):
            return False
        publisher._close()
        _graph_changed()
        return True

    def destroy_subscription(self, subscription: DdsSubscription) -> bool:
        """Destroy ``subscription``."""
        return self._destroy_reader_entity(self._subscriptions, subscription)

    def destroy_timer(self, timer: DdsTimer) -> bool:
        """Destroy ``timer``."""
        if not self._detach(self._timers, timer):
            return False
        timer.destroy()
        return True

    @property
    def publishers(self) -> list[AnyPublisher]:
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
