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
A standalone node's parameter services and ``/parameter_events``, as rclpy provides them.

:class:`ParameterService` offers ``~/describe_parameters``, ``~/get_parameters``,
``~/get_parameter_types``, ``~/list_parameters``, ``~/set_parameters`` and
``~/set_parameters_atomically`` with the semantics of rclpy's ``ParameterService`` (Jazzy), on
top of the node's parameter store; :class:`ParameterEventPublisher` publishes a
``rcl_interfaces/msg/ParameterEvent`` for every successful declare or set, as rclpy's node does.
Requests the store cannot take (bad types, values) get a failed result instead of an exception,
so that no remote request can stop the node.
"""

from __future__ import annotations

from array import array
from collections.abc import Callable
import contextlib
from typing import Protocol
import weakref

from tf_demo.msgs import builtin_interfaces
from tf_demo.msgs import cdr
from tf_demo.msgs import rcl_interfaces
from tf_demo.transport.dds import wire as dds_wire
from tf_demo.transport.dds.clock import Clock
from tf_demo.transport.dds.logging import Logger
from tf_demo.transport.dds.parameter_store import ParameterStore
from tf_demo.transport.dds.parameters import Parameter
from tf_demo.transport.dds.parameters import parameter_from_msg
from tf_demo.transport.dds.parameters import parameter_to_msg
from tf_demo.transport.dds.parameters import parameter_value_to_msg
from tf_demo.transport.dds.parameters import ParameterDescriptor
from tf_demo.transport.dds.parameters import ParameterException
from tf_demo.transport.dds.parameters import ParameterNotDeclaredException
from tf_demo.transport.dds.parameters import ParameterType
from tf_demo.transport.dds.parameters import ParameterUninitializedException
from tf_demo.transport.dds.parameters import SetParametersResult
from tf_demo.transport.dds.qos import qos_profile_parameter_events
from tf_demo.transport.dds.qos import qos_profile_parameters
from tf_demo.transport.dds.qos import QoSProfile
from tf_demo.transport.dds.rosout import RosoutPublisher
from tf_demo.transport.dds.services import RequestT
from tf_demo.transport.dds.services import ResponseT
from tf_demo.transport.dds.services import ServiceType

__all__ = [
    'ParameterEventPublisher',
    'ParameterService',
    'descriptor_to_msg',
    'list_parameters',
    'parameter_from_msg',
    'parameter_to_msg',
    'parameter_value_to_msg',
]

_SEPARATOR = '.'
_DEPTH_RECURSIVE = 0


class _InterfacesNode(Protocol):
    """What the parameter services, the event publisher and ``/rosout`` ask of their node."""

    @property
    def _parameters(self) -> ParameterStore: ...

    @property
    def _participant(self) -> dds_wire.DdsParticipant: ...

    def get_name(self) -> str: ...

    def get_fully_qualified_name(self) -> str: ...

    def get_clock(self) -> Clock: ...

    def get_logger(self) -> Logger: ...

    def create_service(
        self,
        srv_type: ServiceType[RequestT, ResponseT],
        srv_name: str,
        callback: Callable[[RequestT, ResponseT], ResponseT],
        *,
        qos_profile: QoSProfile = ...,
    ) -> object: ...


def descriptor_to_msg(
    name: str, descriptor: ParameterDescriptor
) -> rcl_interfaces.ParameterDescriptor:
    """Return the ``ParameterDescriptor`` message of a store descriptor."""
    return rcl_interfaces.ParameterDescriptor(
        name=descriptor.name or name,
        type=int(descriptor.type),
        description=descriptor.description,
        additional_constraints=descriptor.additional_constraints,
        read_only=bool(descriptor.read_only),
        dynamic_typing=bool(descriptor.dynamic_typing),
        floating_point_range=[
            rcl_interfaces.FloatingPointRange(
                from_value=float(item.from_value),
                to_value=float(item.to_value),
                step=float(item.step),
            )
            for item in descriptor.floating_point_range
        ],
        integer_range=[
            rcl_interfaces.IntegerRange(
                from_value=int(item.from_value), to_value=int(item.to_value), step=int(item.step)
            )
            for item in descriptor.integer_range
        ],
    )


def list_parameters(
    names: list[str], prefixes: list[str], depth: int
) -> tuple[list[str], list[str]]:
    """
    Select parameter names by prefixes and depth as rclpy's ``Node.list_parameters``.

    :return: ``(names, prefixes)`` of the ``ListParametersResult``.
    :raises ValueError: for a negative depth.
    """
    if depth < 0:
        msg = 'The depth must be greater than or equal to zero'
        raise ValueError(msg)

    def shallow(name: str) -> bool:
        return name.count(_SEPARATOR) < depth

    recursive = not prefixes and depth == _DEPTH_RECURSIVE
    result_names: list[str] = []
    result_prefixes: list[str] = []
    for name in names:
        if not recursive and not (not prefixes and shallow(name)):
            matches = any(
                name == prefix
                or (
                    name.startswith(prefix + _SEPARATOR)
                    and (depth == _DEPTH_RECURSIVE or shallow(name[len(prefix) + 1 :]))
                )
                for prefix in prefixes
            )
            if not matches:
                continue
        result_names.append(name)
        last = name.rfind(_SEPARATOR)
        if last != -1 and name[:last] not in result_prefixes:
            result_prefixes.append(name[:last])
    return result_names, result_prefixes


def _result_msg(result: SetParametersResult) -> rcl_interfaces.SetParametersResult:
    # read defensively: an on-set callback may return another world's result class
    return rcl_interfaces.SetParametersResult(
        successful=bool(getattr(result, 'successful', False)),
        reason=str(getattr(result, 'reason', '')),
    )


class ParameterService:
    """The six parameter services of one node (rclpy's ``ParameterService``)."""

    def __init__(self, node: _InterfacesNode) -> None:
        self._store = node._parameters  # no reference to the node: no cycle through it
        name = node.get_name()

        def offer(
            srv_type: ServiceType[RequestT, ResponseT],
            suffix: str,
            callback: Callable[[RequestT, ResponseT], ResponseT],
        ) -> None:
            node.create_service(
                srv_type, f'{name}/{suffix}', callback, qos_profile=qos_profile_parameters
            )

        offer(rcl_interfaces.DescribeParameters, 'describe_parameters', self._describe)
        offer(rcl_interfaces.GetParameters, 'get_parameters', self._get)
        offer(rcl_interfaces.GetParameterTypes, 'get_parameter_types', self._get_types)
        offer(rcl_interfaces.ListParameters, 'list_parameters', self._list)
        offer(rcl_interfaces.SetParameters, 'set_parameters', self._set)
        offer(
            rcl_interfaces.SetParametersAtomically,
            'set_parameters_atomically',
            self._set_atomically,
        )

    def _describe(
        self,
        request: rcl_interfaces.DescribeParameters_Request,
        response: rcl_interfaces.DescribeParameters_Response,
    ) -> rcl_interfaces.DescribeParameters_Response:
        for name in request.names:
            try:
                descriptor = self._store.describe_parameter(name)
            except ParameterNotDeclaredException:
                response.descriptors = []
                return response
            response.descriptors.append(descriptor_to_msg(name, descriptor))
        return response

    def _get(
        self,
        request: rcl_interfaces.GetParameters_Request,
        response: rcl_interfaces.GetParameters_Response,
    ) -> rcl_interfaces.GetParameters_Response:
        for name in request.names:
            try:
                parameter = self._store.get_parameter(name)
            except (ParameterNotDeclaredException, ParameterUninitializedException):
                response.values = []
                return response
            response.values.append(parameter_value_to_msg(parameter))
        return response

    def _get_types(
        self,
        request: rcl_interfaces.GetParameterTypes_Request,
        response: rcl_interfaces.GetParameterTypes_Response,
    ) -> rcl_interfaces.GetParameterTypes_Response:
        types = []
        for name in request.names:
            try:
                types.append(self._store.get_parameter(name).type_.value)
            except ParameterNotDeclaredException:
                types = []
                break
            except ParameterUninitializedException:
                types.append(ParameterType.NOT_SET.value)
        response.types = array('B', types)
        return response

    def _list(
        self,
        request: rcl_interfaces.ListParameters_Request,
        response: rcl_interfaces.ListParameters_Response,
    ) -> rcl_interfaces.ListParameters_Response:
        names: list[str] = []
        prefixes: list[str] = []
        with contextlib.suppress(TypeError, ValueError):
            names, prefixes = list_parameters(
                self._store.names(), list(request.prefixes), int(request.depth)
            )
        response.result = rcl_interfaces.ListParametersResult(names=names, prefixes=prefixes)
        return response

    def _set_one_list(self, messages: list[rcl_interfaces.Parameter]) -> SetParametersResult:
        try:
            parameters = [parameter_from_msg(message) for message in messages]
            return self._store.set_parameters_atomically(parameters)
        except ParameterException as error:
            return SetParametersResult(successful=False, reason=str(error))
        except (TypeError, ValueError) as error:
            return SetParametersResult(successful=False, reason=f'invalid parameter: {error}')

    def _set(
        self,
        request: rcl_interfaces.SetParameters_Request,
        response: rcl_interfaces.SetParameters_Response,
    ) -> rcl_interfaces.SetParameters_Response:
        response.results = [_result_msg(self._set_one_list([p])) for p in request.parameters]
        return response

    def _set_atomically(
        self,
        request: rcl_interfaces.SetParametersAtomically_Request,
        response: rcl_interfaces.SetParametersAtomically_Response,
    ) -> rcl_interfaces.SetParametersAtomically_Response:
        response.result = _result_msg(self._set_one_list(list(request.parameters)))
        return response


class ParameterEventPublisher:
    """Publishes the node's ``/parameter_events`` (fed by the parameter store's event sink)."""

    def __init__(self, node: _InterfacesNode) -> None:
        self._clock = node.get_clock()
        self._node_name = node.get_fully_qualified_name()
        message_type = rcl_interfaces.ParameterEvent
        self.writer = node._participant.create_writer(
            dds_wire.dds_topic_name('/parameter_events'),
            message_type.__dds_typename__,
            dds_wire.endpoint_qos_from_profile(qos_profile_parameter_events),
            f'typehash={message_type.__typehash__};'.encode(),
        )
        self._serialize = cdr.serialize

    def publish(
        self, new: list[Parameter], changed: list[Parameter], deleted: list[Parameter]
    ) -> None:
        """Publish one event, stamped with the node's clock."""
        sec, nanosec = divmod(int(self._clock.now().nanoseconds), 1_000_000_000)
        event = rcl_interfaces.ParameterEvent(
            stamp=builtin_interfaces.Time(sec=sec, nanosec=nanosec),
            node=self._node_name,
            new_parameters=[parameter_to_msg(p) for p in new],
            changed_parameters=[parameter_to_msg(p) for p in changed],
            deleted_parameters=[parameter_to_msg(p) for p in deleted],
        )
        self.writer.write(self._serialize(event))

    def close(self) -> None:
        """Delete the writer."""
        self.writer.close(flush_timeout_ns=100_000_000)


class NodeInterfaces:
    """
    What rcl and rclpy add to every node: ``/parameter_events``, ``/rosout``, parameter services.

    :param enable_rosout: create the node's ``/rosout`` publisher (rcl's node option).
    :param start_parameter_services: offer the six parameter services (rclpy's option).
    """

    def __init__(
        self,
        node: _InterfacesNode,
        *,
        enable_rosout: bool = True,
        start_parameter_services: bool = True,
    ) -> None:
        self.events = ParameterEventPublisher(node)
        self.rosout: RosoutPublisher | None = None
        try:
            if enable_rosout:
                self.rosout = RosoutPublisher(node._participant, node.get_logger().name)
            node._parameters.event_sink = self.events.publish
            self.parameter_service = ParameterService(node) if start_parameter_services else None
        except BaseException:
            self.close()
            raise
        # A node dropped without destroy_node() (e.g. its constructor failed) still releases
        # its /rosout registration and writers.
        finalizer = weakref.finalize(node, self.close)
        finalizer.atexit = False
        self._finalizer = finalizer

    def writer_gids(self) -> list[bytes]:
        """Return the GUIDs of the event and rosout writers, for ``ros_discovery_info``."""
        writers = [self.events.writer]
        if self.rosout is not None:
            writers.append(self.rosout.writer)
        return [writer.guid for writer in writers if writer.handle > 0]

    def close(self) -> None:
        """Delete the event and rosout writers (the services go with the node's); once."""
        finalizer = getattr(self, '_finalizer', None)
        if finalizer is not None:
            finalizer.detach()
        if self.rosout is not None:
            self.rosout.close()
            self.rosout = None
        self.events.close()
