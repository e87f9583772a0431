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
ROS 2 services over DDS, mapped exactly as Jazzy's rmw_cyclonedds_cpp maps them.

A server's request reader and reply writer carry ``serviceid=<id>;`` in USER_DATA, a client's
request writer and reply reader ``clientid=<id>;`` (then ``typehash=`` of the request or response
type): that is how either side pairs the two endpoints of its peer. A client sees a server as
available once it matched a request reader and a reply writer with the same service id; a server
answers only once it matched the reply reader of the requesting client (waiting up to 100 ms,
as rmw_cyclonedds does). The wire format is :mod:`tf_demo.transport.dds.service_wire`'s.

:class:`DdsService` and :class:`DdsClient` have rclpy's ``Service`` and ``Client`` API; the
executors serve them like subscriptions (read condition, callback group, ``take_messages`` then
``callback`` per item).
"""

from __future__ import annotations

from collections.abc import Callable
import itertools
import threading
import time
from typing import Any
from typing import Generic
from typing import Protocol
from typing import TypeAlias
from typing import TypeVar
import weakref

from cyclonedds import _clayer
from cyclonedds.builtin_types import cqos_to_qos
from cyclonedds.builtin_types import endpoint_constructor
from cyclonedds.qos import Policy
from tf_demo.msgs import cdr
from tf_demo.msgs._message import Message
from tf_demo.transport.dds import wire as dds_wire
from tf_demo.transport.dds.callback_groups import CallbackGroup
from tf_demo.transport.dds.cyclone_c import instance_handle
from tf_demo.transport.dds.cyclone_c import matched_handles
from tf_demo.transport.dds.logging import Logger
from tf_demo.transport.dds.qos import QoSProfile
from tf_demo.transport.dds.service_wire import client_service_id
from tf_demo.transport.dds.service_wire import decode_sample
from tf_demo.transport.dds.service_wire import encode_sample
from tf_demo.transport.dds.service_wire import parse_user_data
from tf_demo.transport.dds.service_wire import reply_topic
from tf_demo.transport.dds.service_wire import request_topic
from tf_demo.transport.dds.service_wire import RequestHeader
from tf_demo.transport.future import Future

__all__ = [
    'AnyClient',
    'AnyService',
    'DdsClient',
    'DdsService',
    'Future',
    'RequestT',
    'ResponseT',
    'ServiceType',
]

RequestT = TypeVar('RequestT', bound=Message)
ResponseT = TypeVar('ResponseT', bound=Message)
_RequestT_co = TypeVar('_RequestT_co', bound=Message, covariant=True)
_ResponseT_co = TypeVar('_ResponseT_co', bound=Message, covariant=True)


class ServiceType(Protocol[_RequestT_co, _ResponseT_co]):
    """A service type of :mod:`tf_demo.msgs` (``rcl_interfaces.GetParameters``...)."""

    @property
    def Request(self) -> type[_RequestT_co]: ...  # noqa: N802 - rosidl's name

    @property
    def Response(self) -> type[_ResponseT_co]: ...  # noqa: N802 - rosidl's name


class _ServiceNode(Protocol):
    """What a service server or client asks of its node."""

    @property
    def _participant(self) -> dds_wire.DdsParticipant: ...

    @property
    def _destroyed(self) -> bool: ...

    def get_logger(self) -> Logger: ...

    def destroy_service(self, service: DdsService[RequestT, ResponseT]) -> bool: ...

    def destroy_client(self, client: DdsClient[RequestT, ResponseT]) -> bool: ...


#: The decoded samples of a server's or client's reader: ``(header, message, publication)``.
_MessageT = TypeVar('_MessageT', bound=Message)
_Sample: TypeAlias = 'tuple[RequestHeader, _MessageT, int]'

_TAKE_BATCH = 64
#: How long a server waits for the requesting client's reply reader (rmw_cyclonedds: 100 ms).
_REPLY_READER_WAIT_S = 0.1
_POLL_S = 0.01


def _user_data_key(entity: int, handle: int, key: str, *, subscription: bool) -> str | None:
    """Return USER_DATA ``key`` of the matched endpoint ``handle`` of ``entity``, if any."""
    get = (
        _clayer.ddspy_get_matched_subscription_data
        if subscription
        else _clayer.ddspy_get_matched_publication_data
    )
    try:
        endpoint = get(entity, handle, endpoint_constructor, cqos_to_qos)
    except Exception:
        return None
    qos = getattr(endpoint, 'qos', None)
    if qos is None or Policy.Userdata not in qos:
        return None
    return parse_user_data(bytes(qos[Policy.Userdata].data)).get(key)


def _type_info(srv_type: ServiceType[Message, Message]) -> tuple[type[Message], type[Message]]:
    request, response = getattr(srv_type, 'Request', None), getattr(srv_type, 'Response', None)
    for part in (request, response):
        if not isinstance(getattr(part, '__dds_typename__', None), str):
            msg = f'{srv_type!r} is not a service type of tf_demo.msgs (no Request/Response)'
            raise TypeError(msg)
    return srv_type.Request, srv_type.Response


class _Endpoints:
    """The reader and writer of one service server or client, with the USER_DATA they carry."""

    def __init__(
        self,
        participant: dds_wire.DdsParticipant,
        service_name: str,
        srv_type: ServiceType[Message, Message],
        qos: dds_wire.EndpointQos,
        *,
        server: bool,
    ) -> None:
        request, response = _type_info(srv_type)
        self.id = client_service_id(participant.guid)
        key = 'serviceid' if server else 'clientid'
        read_type, write_type = (request, response) if server else (response, request)
        read_topic, write_topic = (
            (request_topic(service_name), reply_topic(service_name))
            if server
            else (reply_topic(service_name), request_topic(service_name))
        )
        self.writer = participant.create_writer(
            write_topic,
            write_type.__dds_typename__,
            qos,
            f'{key}={self.id};typehash={write_type.__typehash__};'.encode(),
        )
        try:
            self.reader = participant.create_reader(
                read_topic,
                read_type.__dds_typename__,
                qos,
                f'{key}={self.id};typehash={read_type.__typehash__};'.encode(),
            )
        except BaseException:
            self.writer.close()
            raise
        self.writer_handle = instance_handle(self.writer.handle)

    def close(self) -> None:
        self.reader.close()
        self.writer.close()


class _Entity(Generic[RequestT, ResponseT]):
    """What services and clients share: node, names, endpoints, group, executor hooks."""

    wants_message_info = False
    raw = False

    def __init__(
        self,
        node: _ServiceNode,
        srv_type: ServiceType[RequestT, ResponseT],
        srv_name: str,
        qos_profile: QoSProfile,
        callback_group: CallbackGroup,
        *,
        server: bool,
    ) -> None:
        self._node_ref = weakref.ref(node)
        self.srv_type = srv_type
        self.srv_name = srv_name
        self.qos_profile = qos_profile
        self.callback_group = callback_group
        self._logger = node.get_logger()
        self._endpoints = _Endpoints(
            node._participant,
            srv_name,
            srv_type,
            dds_wire.endpoint_qos_from_profile(qos_profile),
            server=server,
        )

    @property
    def service_name(self) -> str:
        """The fully qualified service name."""
        return self.srv_name

    @property
    def read_condition(self) -> int:
        """The read condition of the reader (requests for a server, replies for a client)."""
        return int(self._endpoints.reader.read_condition)

    @property
    def reader_gid(self) -> bytes:
        """The GUID of the reader, for ``ros_discovery_info``."""
        return self._endpoints.reader.guid

    @property
    def writer_gid(self) -> bytes:
        """The GUID of the writer, for ``ros_discovery_info``."""
        return self._endpoints.writer.guid

    def _take_decoded(self, msg_type: type[_MessageT]) -> list[_Sample[_MessageT]]:
        items: list[_Sample[_MessageT]] = []
        for payload, _source_ns, publication in self._endpoints.reader.take_with_info(_TAKE_BATCH):
            try:
                header, message = decode_sample(msg_type, payload)
            except (cdr.CdrError, ValueError) as error:
                self._logger.error(
                    f"Dropped a malformed {msg_type.__msgtype__} on '{self.srv_name}': {error}"
                )
                continue
            items.append((header, message, publication))
        return items

    def _close(self) -> None:
        self._endpoints.close()


class DdsService(_Entity[RequestT, ResponseT]):
    """
    A service server (rclpy ``Service`` subset); requests are answered in the executor.

    ``callback(request, response)`` fills and returns the response (``None`` or an exception
    is logged and no reply is sent, as rclpy would propagate it).
    """

    def __init__(  # noqa: PLR0917 - rclpy's Service signature
        self,
        node: _ServiceNode,
        srv_type: ServiceType[RequestT, ResponseT],
        srv_name: str,
        callback: Callable[[RequestT, ResponseT], ResponseT],
        qos_profile: QoSProfile,
        callback_group: CallbackGroup,
    ) -> None:
        super().__init__(node, srv_type, srv_name, qos_profile, callback_group, server=True)
        self.user_callback = callback
        self.callback: Callable[[_Sample[RequestT]], None] = self._handle

    def take_messages(self) -> list[tuple[_Sample[RequestT], None]]:
        """Take waiting requests: ``((header, request, publication handle), None)`` items."""
        return [(item, None) for item in self._take_decoded(self.srv_type.Request)]

    def _handle(self, item: _Sample[RequestT]) -> None:
        header, request, publication = item
        response = self.user_callback(request, self.srv_type.Response())
        if not isinstance(response, self.srv_type.Response):
            msg = (
                f"service callback of '{self.srv_name}' returned {type(response).__name__}, "
                f'expected {self.srv_type.Response.__name__}'
            )
            raise TypeError(msg)
        self.send_response(response, header, publication)

    def send_response(
        self, response: ResponseT, header: RequestHeader, publication: int = 0
    ) -> None:
        """Send ``response`` to the client that sent the request with ``header``."""
        if publication and not self._client_reader_matched(publication):
            return
        self._endpoints.writer.write(encode_sample(header, response))

    def _client_reader_matched(self, publication: int) -> bool:
        """Wait up to 100 ms for the client's reply reader; False when it never showed up."""
        endpoints = self._endpoints
        client_id = _user_data_key(
            endpoints.reader.handle, publication, 'clientid', subscription=False
        )
        if client_id is None:
            # Gone, or an old client without an id: rmw_cyclonedds sends when the latter.
            return publication in matched_handles(endpoints.reader.handle, subscriptions=False)
        deadline = time.monotonic() + _REPLY_READER_WAIT_S
        while True:
            for handle in matched_handles(endpoints.writer.handle, subscriptions=True):
                found = _user_data_key(
                    endpoints.writer.handle, handle, 'clientid', subscription=True
                )
                if found == client_id:
                    return True
            if time.monotonic() >= deadline:
                self._logger.warning(
                    f"Service '{self.srv_name}': the client's reply reader was not found in "
                    'time; dropping the response'
                )
                return False
            time.sleep(_POLL_S)

    def destroy(self) -> bool:
        """Destroy this service (same as ``node.destroy_service(self)``)."""
        node = self._node_ref()
        return bool(node.destroy_service(self)) if node is not None else False


_sequence_numbers = itertools.count(1)
_sequence_lock = threading.Lock()


class DdsClient(_Entity[RequestT, ResponseT]):
    """A service client (rclpy ``Client`` subset): ``call_async``, ``call``, readiness."""

    def __init__(
        self,
        node: _ServiceNode,
        srv_type: ServiceType[RequestT, ResponseT],
        srv_name: str,
        qos_profile: QoSProfile,
        callback_group: CallbackGroup,
    ) -> None:
        super().__init__(node, srv_type, srv_name, qos_profile, callback_group, server=False)
        self._pending: dict[int, Future[ResponseT]] = {}
        self._pending_lock = threading.Lock()
        self.callback: Callable[[_Sample[ResponseT]], None] = self._complete

    def service_is_ready(self) -> bool:
        """Whether a server's request reader and reply writer (same service id) are matched."""
        endpoints = self._endpoints
        readers = matched_handles(endpoints.writer.handle, subscriptions=True)
        writers = matched_handles(endpoints.reader.handle, subscriptions=False)
        ids = {
            found
            for handle in readers
            if (
                found := _user_data_key(
                    endpoints.writer.handle, handle, 'serviceid', subscription=True
                )
            )
            is not None
        }
        if not ids:
            return bool(readers) and bool(writers)
        return any(
            _user_data_key(endpoints.reader.handle, handle, 'serviceid', subscription=False) in ids
            for handle in writers
        )

    def wait_for_service(self, timeout_sec: float | None = None) -> bool:
        """Wait until :meth:`service_is_ready` (``None``: no limit); whether it is."""
        deadline = None if timeout_sec is None else time.monotonic() + timeout_sec
        while not self.service_is_ready():
            node = self._node_ref()
            if node is None or node._destroyed:
                return False
            if deadline is not None and time.monotonic() >= deadline:
                return False
            time.sleep(0.05)
        return True

    def call_async(self, request: RequestT) -> Future[ResponseT]:
        """Send ``request``; the returned future completes when the executor takes the reply."""
        if not isinstance(request, self.srv_type.Request):
            msg = f'Expected {self.srv_type.Request.__name__}, got {type(request).__name__}'
            raise TypeError(msg)
        with _sequence_lock:
            sequence_number = next(_sequence_numbers)
        future: Future[ResponseT] = Future()
        with self._pending_lock:
            self._pending[sequence_number] = future
        header = RequestHeader(self._endpoints.writer_handle, sequence_number)
        try:
            self._endpoints.writer.write(encode_sample(header, request))
        except BaseException:
            with self._pending_lock:
                self._pending.pop(sequence_number, None)
            raise
        return future

    def call(self, request: RequestT, timeout_sec: float | None = None) -> ResponseT | None:
        """
        Send ``request`` and block until the reply (another thread must spin the node).

        :return: the response, or None after ``timeout_sec``.
        """
        future = self.call_async(request)
        if not future.wait(timeout_sec):
            self.remove_pending_request(future)
        error = future.exception()
        if error is not None:
            raise error
        return future.result()

    def remove_pending_request(self, future: Future[ResponseT]) -> None:
        """Forget a pending request; its reply, if one comes, is dropped."""
        with self._pending_lock:
            for key, pending in list(self._pending.items()):
                if pending is future:
                    del self._pending[key]

    def take_messages(self) -> list[tuple[_Sample[ResponseT], None]]:
        """Take this client's replies: ``((header, response, publication handle), None)``."""
        mine = self._endpoints.writer_handle
        return [
            (item, None)
            for item in self._take_decoded(self.srv_type.Response)
            if item[0].guid == mine
        ]

    def _complete(self, item: _Sample[ResponseT]) -> None:
        header, response, _ = item
        with self._pending_lock:
            future = self._pending.pop(header.sequence_number, None)
        if future is not None:
            future.set_result(response)

    def _close(self) -> None:
        with self._pending_lock:
            pending, self._pending = list(self._pending.values()), {}
        for future in pending:
            future.cancel()
        super()._close()

    def destroy(self) -> bool:
        """Destroy this client (same as ``node.destroy_client(self)``)."""
        node = self._node_ref()
        return bool(node.destroy_client(self)) if node is not None else False


AnyService: TypeAlias = 'DdsService[Any, Any]'
"""A service server of any service type (a node's list of them)."""
AnyClient: TypeAlias = 'DdsClient[Any, Any]'
"""A service client of any service type (a node's list of them)."""
