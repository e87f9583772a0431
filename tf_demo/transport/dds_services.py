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

A service ``/a/b`` is a request topic ``rq/a/bRequest`` (type ``pkg::srv::dds_::Name_Request_``)
and a reply topic ``rr/a/bReply`` (``..._Response_``). Every sample carries rmw_cyclonedds'
request header in front of the CDR body: after the 4-byte encapsulation header, the client's
64-bit id (the instance handle of its request writer) and the 64-bit sequence number, in the
sample's byte order; the body follows, its alignment unchanged (16 is a multiple of 8).
A server's request reader and reply writer carry ``serviceid=<id>;`` in USER_DATA, a client's
request writer and reply reader ``clientid=<id>;`` (then ``typehash=`` of the request or response
type): that is how either side pairs the two endpoints of its peer. A client sees a server as
available once it matched a request reader and a reply writer with the same service id; a server
answers only once it matched the reply reader of the requesting client (waiting up to 100 ms,
as rmw_cyclonedds does).

:class:`DdsService` and :class:`DdsClient` have rclpy's ``Service`` and ``Client`` API; the
executors serve them like subscriptions (read condition, callback group, ``take_messages`` then
``callback`` per item).
"""

from __future__ import annotations

from collections.abc import Callable
import ctypes
import itertools
import struct
import threading
import time
from typing import Any
from typing import cast
import weakref

from cyclonedds import _clayer
from cyclonedds.builtin_types import cqos_to_qos
from cyclonedds.builtin_types import endpoint_constructor
from cyclonedds.qos import Policy
from tf_demo.msgs import cdr
from tf_demo.transport import dds_participant
from tf_demo.transport import dds_wire
from tf_demo.transport.dds.context import _graph_changed
from tf_demo.transport.dds.qos import qos_profile_services_default
from tf_demo.transport.future import Future

__all__ = [
    'DdsClient',
    'DdsService',
    'Future',
    'NodeServicesMixin',
    'RequestHeader',
    'client_service_id',
    'decode_sample',
    'encode_sample',
    'parse_user_data',
    'reply_topic',
    'request_topic',
]


_TAKE_BATCH = 64
_HEADER = {1: struct.Struct('<Qq'), 0: struct.Struct('>Qq')}
_HEADER_SIZE = 4 + 16
#: How long a server waits for the requesting client's reply reader (rmw_cyclonedds: 100 ms).
_REPLY_READER_WAIT_S = 0.1
_POLL_S = 0.01

_lib: Any = dds_participant._lib
_lib.dds_get_instance_handle.restype = ctypes.c_int32
_lib.dds_get_instance_handle.argtypes = [ctypes.c_int32, ctypes.POINTER(ctypes.c_uint64)]
for _name in ('dds_get_matched_subscriptions', 'dds_get_matched_publications'):
    getattr(_lib, _name).restype = ctypes.c_int32
    getattr(_lib, _name).argtypes = [
        ctypes.c_int32,
        ctypes.POINTER(ctypes.c_uint64),
        ctypes.c_size_t,
    ]


# --------------------------------------------------------------------------------------------
# Wire format (pure)
# --------------------------------------------------------------------------------------------


class RequestHeader(tuple[int, int]):
    """rmw_cyclonedds' ``cdds_request_header_t``: ``(client id, sequence number)``."""

    __slots__ = ()

    def __new__(cls, guid: int, sequence_number: int) -> RequestHeader:
        """Make a header from the client's 64-bit id and the request's sequence number."""
        return super().__new__(cls, (guid, sequence_number))

    @property
    def guid(self) -> int:
        """The client's id: the instance handle of its request writer."""
        return self[0]

    @property
    def sequence_number(self) -> int:
        """The request's sequence number (the reply repeats it)."""
        return self[1]


def encode_sample(header: RequestHeader, message: Any) -> bytes:
    """Serialize ``message`` with rmw_cyclonedds' request header after the encapsulation."""
    payload = cdr.serialize(message)
    return payload[:4] + _HEADER[1].pack(header.guid, header.sequence_number) + payload[4:]


def decode_sample(msg_type: Any, data: bytes) -> tuple[RequestHeader, Any]:
    """
    Split a request or reply sample into its header and decoded message.

    :raises cdr.CdrError: too short, wrong encapsulation or a malformed body.
    """
    if len(data) < _HEADER_SIZE or data[0] != 0 or data[1] > 1:
        msg = f'not a ROS 2 service sample ({len(data)} bytes, header {bytes(data[:4]).hex()})'
        raise cdr.CdrError(msg)
    guid, sequence_number = _HEADER[data[1]].unpack_from(data, 4)
    message = cdr.deserialize(msg_type, bytes(data[:4]) + bytes(data[_HEADER_SIZE:]))
    return RequestHeader(guid, sequence_number), message


def request_topic(service_name: str) -> str:
    """Return the DDS request topic of the fully qualified ``service_name``."""
    return f'rq{service_name}Request'


def reply_topic(service_name: str) -> str:
    """Return the DDS reply topic of the fully qualified ``service_name``."""
    return f'rr{service_name}Reply'


_id_counter = itertools.count(1)
_id_lock = threading.Lock()


def client_service_id(participant_guid: bytes, counter: int | None = None) -> str:
    """
    Return a new client/service id as rmw_cyclonedds spells it in USER_DATA.

    The participant's 12-byte GUID prefix and a big-endian 32-bit counter, in hex, the first
    byte two characters wide (space padded), the others unpadded, separated by dots.
    """
    if counter is None:
        with _id_lock:
            counter = next(_id_counter)
    data = participant_guid[:12] + (counter & 0xFFFFFFFF).to_bytes(4, 'big')
    return f'{data[0]:2x}' + ''.join(f'.{byte:x}' for byte in data[1:])


def parse_user_data(data: bytes) -> dict[str, str]:
    """Parse ``key=value;`` USER_DATA as rmw_dds_common does (later keys win)."""
    result: dict[str, str] = {}
    for item in data.split(b';'):
        key, sep, value = item.partition(b'=')
        if sep and key:
            result[key.decode(errors='replace')] = value.decode(errors='replace')
    return result


# --------------------------------------------------------------------------------------------
# Endpoints
# --------------------------------------------------------------------------------------------


def _instance_handle(entity: int) -> int:
    handle = ctypes.c_uint64()
    dds_participant._check(
        _lib.dds_get_instance_handle(entity, ctypes.byref(handle)), 'instance handle'
    )
    return int(handle.value)


def _matched(entity: int, *, subscriptions: bool) -> list[int]:
    function = (
        _lib.dds_get_matched_subscriptions if subscriptions else _lib.dds_get_matched_publications
    )
    count = function(entity, None, 0)
    if count <= 0:
        return []
    handles = (ctypes.c_uint64 * count)()
    count = function(entity, handles, count)
    return [int(handles[i]) for i in range(max(count, 0))]


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


def _type_info(srv_type: Any) -> tuple[Any, Any]:
    request, response = getattr(srv_type, 'Request', None), getattr(srv_type, 'Response', None)
    for part in (request, response):
        if not isinstance(getattr(part, '__dds_typename__', None), str):
            msg = f'{srv_type!r} is not a service type of tf_demo.msgs (no Request/Response)'
            raise TypeError(msg)
    return request, response


class _Endpoints:
    """The reader and writer of one service server or client, with the USER_DATA they carry."""

    def __init__(
        self,
        participant: dds_wire.DdsParticipant,
        service_name: str,
        srv_type: Any,
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
        self.writer_handle = _instance_handle(self.writer.handle)

    def close(self) -> None:
        self.reader.close()
        self.writer.close()


class _Entity:
    """What services and clients share: node, names, endpoints, group, executor hooks."""

    wants_message_info = False
    raw = False

    def __init__(
        self,
        node: Any,
        srv_type: Any,
        srv_name: str,
        qos_profile: Any,
        callback_group: Any,
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

    def _take_decoded(self, msg_type: Any) -> list[tuple[RequestHeader, Any, int]]:
        items = []
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


class DdsService(_Entity):
    """
    A service server (rclpy ``Service`` subset); requests are answered in the executor.

    ``callback(request, response)`` fills and returns the response (``None`` or an exception
    is logged and no reply is sent, as rclpy would propagate it).
    """

    def __init__(  # noqa: PLR0917 - rclpy's Service signature
        self,
        node: Any,
        srv_type: Any,
        srv_name: str,
        callback: Callable[[Any, Any], Any],
        qos_profile: Any,
        callback_group: Any,
    ) -> None:
        super().__init__(node, srv_type, srv_name, qos_profile, callback_group, server=True)
        self.user_callback = callback
        self.callback: Callable[[Any], None] = self._handle

    def take_messages(self) -> list[tuple[Any, None]]:
        """Take waiting requests: ``((header, request, publication handle), None)`` items."""
        return [(item, None) for item in self._take_decoded(self.srv_type.Request)]

    def _handle(self, item: tuple[RequestHeader, Any, int]) -> None:
        header, request, publication = item
        response = self.user_callback(request, self.srv_type.Response())
        if not isinstance(response, self.srv_type.Response):
            msg = (
                f"service callback of '{self.srv_name}' returned {type(response).__name__}, "
                f'expected {self.srv_type.Response.__name__}'
            )
            raise TypeError(msg)
        self.send_response(response, header, publication)

    def send_response(self, response: Any, header: RequestHeader, publication: int = 0) -> None:
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
            return publication in _matched(endpoints.reader.handle, subscriptions=False)
        deadline = time.monotonic() + _REPLY_READER_WAIT_S
        while True:
            for handle in _matched(endpoints.writer.handle, subscriptions=True):
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


class DdsClient(_Entity):
    """A service client (rclpy ``Client`` subset): ``call_async``, ``call``, readiness."""

    def __init__(
        self,
        node: Any,
        srv_type: Any,
        srv_name: str,
        qos_profile: Any,
        callback_group: Any,
    ) -> None:
        super().__init__(node, srv_type, srv_name, qos_profile, callback_group, server=False)
        self._pending: dict[int, Future[Any]] = {}
        self._pending_lock = threading.Lock()
        self.callback: Callable[[Any], None] = self._complete

    def service_is_ready(self) -> bool:
        """Whether a server's request reader and reply writer (same service id) are matched."""
        endpoints = self._endpoints
        readers = _matched(endpoints.writer.handle, subscriptions=True)
        writers = _matched(endpoints.reader.handle, subscriptions=False)
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

    def call_async(self, request: Any) -> Future[Any]:
        """Send ``request``; the returned future completes when the executor takes the reply."""
        if not isinstance(request, self.srv_type.Request):
            msg = f'Expected {self.srv_type.Request.__name__}, got {type(request).__name__}'
            raise TypeError(msg)
        with _sequence_lock:
            sequence_number = next(_sequence_numbers)
        future: Future[Any] = Future()
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

    def call(self, request: Any, timeout_sec: float | None = None) -> Any:
        """
        Send ``request`` and block until the reply (another thread must spin the node).

        :return: the response, or None after ``timeout_sec``.
        """
        future = self.call_async(request)
        if not future.wait(timeout_sec):
            self.remove_pending_request(future)
        if future.exception() is not None:
            raise cast('BaseException', future.exception())
        return future.result()

    def remove_pending_request(self, future: Future[Any]) -> None:
        """Forget a pending request; its reply, if one comes, is dropped."""
        with self._pending_lock:
            for key, pending in list(self._pending.items()):
                if pending is future:
                    del self._pending[key]

    def take_messages(self) -> list[tuple[Any, None]]:
        """Take this client's replies: ``((header, response, publication handle), None)``."""
        mine = self._endpoints.writer_handle
        return [
            (item, None)
            for item in self._take_decoded(self.srv_type.Response)
            if item[0].guid == mine
        ]

    def _complete(self, item: tuple[RequestHeader, Any, int]) -> None:
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


# --------------------------------------------------------------------------------------------
# The node's side
# --------------------------------------------------------------------------------------------


class NodeServicesMixin:
    """
    rclpy's service and client methods of :class:`~tf_demo.transport.dds.node.DdsNode`.

    The node provides ``_lock``, ``_services``, ``_clients``, ``_participant``,
    ``_default_callback_group``, ``resolve_topic_name``, ``get_logger``, ``_check_alive``,
    ``_wake_executors`` and ``_detach``.
    """

    _lock: Any
    _services: list[DdsService]
    _clients: list[DdsClient]
    _default_callback_group: Any

    def create_service(
        self,
        srv_type: Any,
        srv_name: str,
        callback: Callable[[Any, Any], Any],
        *,
        qos_profile: Any = qos_profile_services_default,
        callback_group: Any = None,
    ) -> DdsService:
        """
        Create a service server; ``callback(request, response)`` returns the response.

        It is answered by the executor that spins the node, in ``callback_group`` (default:
        the node's default group); QoS default: ``qos_profile_services_default``.
        """
        node = cast('Any', self)
        node._check_alive()
        group = callback_group or self._default_callback_group
        name = node.resolve_topic_name(srv_name)
        service = DdsService(
            node,
            srv_type,
            name,
            callback,
            qos_profile,
            group,
        )
        group.add_entity(service)
        with self._lock:
            self._services.append(service)
        node._wake_executors()
        _graph_changed()
        return service

    def create_client(
        self,
        srv_type: Any,
        srv_name: str,
        *,
        qos_profile: Any = qos_profile_services_default,
        callback_group: Any = None,
    ) -> DdsClient:
        """Create a service client (replies are taken by the executor that spins the node)."""
        node = cast('Any', self)
        node._check_alive()
        group = callback_group or self._default_callback_group
        name = node.resolve_topic_name(srv_name)
        client = DdsClient(node, srv_type, name, qos_profile, group)
        group.add_entity(client)
        with self._lock:
            self._clients.append(client)
        node._wake_executors()
        _graph_changed()
        return client

    def destroy_service(self, service: DdsService) -> bool:
        """Destroy ``service``."""
        node = cast('Any', self)
        if not node._detach(self._services, service):
            return False
        node._wake_executors()
        service._close()
        _graph_changed()
        return True

    def destroy_client(self, client: DdsClient) -> bool:
        """Destroy ``client`` (its pending futures are cancelled)."""
        node = cast('Any', self)
        if not node._detach(self._clients, client):
            return False
        node._wake_executors()
        client._close()
        _graph_changed()
        return True

    @property
    def services(self) -> list[DdsService]:
        """The node's service servers (the parameter services included, as in rclpy)."""
        return list(self._services)

    @property
    def clients(self) -> list[DdsClient]:
        """The node's service clients."""
        return list(self._clients)

    def _service_reader_gids(self) -> list[bytes]:
        """Request readers of servers, reply readers of clients (rmw's graph entries)."""
        return [entity.reader_gid for entity in [*self._services, *self._clients]]

    def _service_writer_gids(self) -> list[bytes]:
        """Reply writers of servers, request writers of clients."""
        return [entity.writer_gid for entity in [*self._services, *self._clients]]
