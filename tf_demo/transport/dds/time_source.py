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

"""``use_sim_time`` and ``/clock`` for a standalone node's ROS clocks (``rclpy.time_source``)."""

from __future__ import annotations

from collections.abc import Callable
from typing import Protocol
from typing import TYPE_CHECKING
import weakref

from tf_demo.msgs import rosgraph_msgs
from tf_demo.transport.dds.clock import ROSClock
from tf_demo.transport.dds.logging import Logger
from tf_demo.transport.dds.parameters import Parameter
from tf_demo.transport.dds.parameters import SetParametersResult
from tf_demo.transport.dds.qos import QoSProfile
from tf_demo.transport.dds.qos import ReliabilityPolicy
from tf_demo.transport.dds.time import Time

if TYPE_CHECKING:  # the ROS world imports this module without cyclonedds (endpoints need it)
    from tf_demo.transport.dds.endpoints import DdsSubscription

__all__ = ['CLOCK_TOPIC', 'USE_SIM_TIME_NAME', 'TimeSource']

CLOCK_TOPIC = '/clock'
USE_SIM_TIME_NAME = 'use_sim_time'


class _TimeSourceNode(Protocol):
    """What :class:`TimeSource` needs from a node (a subset of ``rclpy.node.Node``)."""

    def has_parameter(self, name: str) -> bool: ...

    def declare_parameter(self, name: str, value: object = None) -> Parameter: ...

    def get_parameter(self, name: str) -> Parameter: ...

    def add_on_set_parameters_callback(
        self, callback: Callable[[list[Parameter]], SetParametersResult]
    ) -> None: ...

    def create_subscription(
        self,
        msg_type: type[rosgraph_msgs.Clock],
        topic: str,
        callback: Callable[[rosgraph_msgs.Clock], None],
        qos_profile: QoSProfile,
    ) -> DdsSubscription: ...

    def destroy_subscription(self, subscription: DdsSubscription) -> bool: ...

    def get_logger(self) -> Logger: ...


class TimeSource:
    """
    Follows ``use_sim_time`` and ``/clock`` for the ROS clocks of a node (``rclpy.time_source``).

    When ``use_sim_time`` is true it subscribes to ``/clock`` (KEEP_LAST 1, BEST_EFFORT) and
    feeds every attached :class:`ROSClock`; when it turns false it unsubscribes and the clocks
    return to system time.
    """

    def __init__(self, *, node: _TimeSourceNode | None = None) -> None:
        self._node_ref: weakref.ReferenceType[_TimeSourceNode] | None = None
        self._clock_subscription: DdsSubscription | None = None
        self._clocks: weakref.WeakSet[ROSClock] = weakref.WeakSet()
        self._last_time_set: Time | None = None
        self._ros_time_is_active = False
        if node is not None:
            self.attach_node(node)

    @property
    def ros_time_is_active(self) -> bool:
        """Whether the attached clocks report ``/clock`` time."""
        return self._ros_time_is_active

    @ros_time_is_active.setter
    def ros_time_is_active(self, enabled: bool) -> None:
        if self._ros_time_is_active == enabled:
            return
        self._ros_time_is_active = enabled
        for clock in list(self._clocks):
            clock._set_ros_time_is_active(enabled)
        if enabled:
            self._subscribe_to_clock_topic()
        else:
            node = self._node()
            if self._clock_subscription is not None and node is not None:
                node.destroy_subscription(self._clock_subscription)
            self._clock_subscription = None

    def _node(self) -> _TimeSourceNode | None:
        return self._node_ref() if self._node_ref is not None else None

    def _subscribe_to_clock_topic(self) -> None:
        node = self._node()
        if self._clock_subscription is not None or node is None:
            return
        self._clock_subscription = node.create_subscription(
            rosgraph_msgs.Clock,
            CLOCK_TOPIC,
            self.clock_callback,
            QoSProfile(depth=1, reliability=ReliabilityPolicy.BEST_EFFORT),
        )

    def attach_node(self, node: _TimeSourceNode) -> None:
        """Declare ``use_sim_time`` on ``node`` (if needed) and follow its value."""
        self._node_ref = weakref.ref(node)
        if not node.has_parameter(USE_SIM_TIME_NAME):
            node.declare_parameter(USE_SIM_TIME_NAME, False)
        parameter = node.get_parameter(USE_SIM_TIME_NAME)
        if parameter.type_ == Parameter.Type.BOOL:
            self.ros_time_is_active = parameter.value
        elif parameter.type_ != Parameter.Type.NOT_SET:
            node.get_logger().error(
                f"Invalid type for parameter '{USE_SIM_TIME_NAME}' {parameter.type_!r} "
                'should be bool'
            )
        node.add_on_set_parameters_callback(self._on_parameter_event)

    def detach_node(self) -> None:
        """Stop following the node (unsubscribes from ``/clock``)."""
        node = self._node()
        if self._clock_subscription is not None and node is not None:
            node.destroy_subscription(self._clock_subscription)
        self._clock_subscription = None
        self._node_ref = None

    def attach_clock(self, clock: ROSClock) -> None:
        """Drive ``clock`` from this source."""
        if not isinstance(clock, ROSClock):
            msg = 'Only clocks with type ROS_TIME can be attached.'
            raise ValueError(msg)
        if self._last_time_set is not None:
            clock.set_ros_time_override(self._last_time_set)
        clock._set_ros_time_is_active(self._ros_time_is_active)
        self._clocks.add(clock)

    def clock_callback(self, msg: rosgraph_msgs.Clock) -> None:
        """Take the time of one ``rosgraph_msgs/msg/Clock`` message."""
        now = Time.from_msg(msg.clock)
        self._last_time_set = now
        for clock in list(self._clocks):
            clock.set_ros_time_override(now)

    def _on_parameter_event(self, parameters: list[Parameter]) -> SetParametersResult:

        for parameter in parameters:
            if parameter.name != USE_SIM_TIME_NAME:
                continue
            if parameter.type_ != Parameter.Type.BOOL:
                reason = f'{USE_SIM_TIME_NAME} parameter set to something besides a bool'
                node = self._node()
                if node is not None:
                    node.get_logger().error(reason)
                return SetParametersResult(successful=False, reason=reason)
            self.ros_time_is_active = parameter.value
            break
        return SetParametersResult(successful=True)
