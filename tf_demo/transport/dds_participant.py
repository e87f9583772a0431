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
The process' one DDS participant and its raw-bytes writers, readers and waitsets.

The payload never passes through cyclonedds-python's interpreted serializer: writers take the
CDR bytes produced by ``tf_demo.msgs.cdr`` and readers hand back the received bytes
(``ddspy_write``/``ddspy_take``, private to cyclonedds-python, hence the exact version pin).
Topics are created from a one-octet placeholder type that carries the ROS type name, and its
XTypes type information is withdrawn before any endpoint exists, so readers and writers are
announced exactly like rmw_cyclonedds' (no TypeInformation, XCDR1 only) and match ROS peers by
type name. Configuration and QoS come from :mod:`tf_demo.transport.dds_config`.
"""

from __future__ import annotations

import atexit
from collections.abc import Callable
from collections.abc import Mapping
import contextlib
import ctypes
import itertools
import os
import threading
from typing import Any
from typing import cast

from cyclonedds import _clayer
from cyclonedds.builtin import BuiltinDataReader
from cyclonedds.builtin import BuiltinTopicDcpsPublication
from cyclonedds.builtin import BuiltinTopicDcpsSubscription
from cyclonedds.builtin_types import cqos_to_qos
from cyclonedds.builtin_types import endpoint_constructor
from cyclonedds.core import DDSException
from cyclonedds.core import InstanceState
from cyclonedds.core import Listener as _CycloneListener
from cyclonedds.core import ReadCondition
from cyclonedds.core import SampleState
from cyclonedds.core import ViewState
from cyclonedds.domain import Domain
from cyclonedds.domain import DomainParticipant
from cyclonedds.idl import make_idl_struct
from cyclonedds.idl import types as idl_types
from cyclonedds.internal import DDS
from cyclonedds.qos import _CQos as _CycloneCQos
from cyclonedds.qos import Policy
from cyclonedds.qos import Qos
from tf_demo.transport.dds_config import cyclone_config
from tf_demo.transport.dds_config import cyclone_qos
from tf_demo.transport.dds_config import DDS_INFINITY
from tf_demo.transport.dds_config import DdsConfigError
from tf_demo.transport.dds_config import DdsWireError
from tf_demo.transport.dds_config import discovery_config_from_env
from tf_demo.transport.dds_config import domain_id_from_env
from tf_demo.transport.dds_config import EndpointQos
from tf_demo.transport.dds_config import incompatible_policy_name

__all__ = [
    'DdsParticipant',
    'RawReader',
    'RawWriter',
    'WaitSet',
    'close_participant',
    'get_participant',
]

_lib: Any = DDS._dll_handle
_CQos: Any = _CycloneCQos
Listener: Any = _CycloneListener


class _Guid(ctypes.Structure):
    _fields_ = [('v', ctypes.c_uint8 * 16)]


class _PublicationMatched(ctypes.Structure):
    _fields_ = [
        ('total_count', ctypes.c_uint32),
        ('total_count_change', ctypes.c_int32),
        ('current_count', ctypes.c_uint32),
        ('current_count_change', ctypes.c_int32),
        ('last_handle', ctypes.c_uint64),
    ]


def _declare(name: str, restype: Any, *argtypes: Any) -> None:
    function = getattr(_lib, name)
    function.restype = restype
    function.argtypes = list(argtypes)


_entity = ctypes.c_int32
_declare('dds_get_entity_sertype', ctypes.c_int32, _entity, ctypes.POINTER(ctypes.c_void_p))
_declare('dds_create_writer', _entity, _entity, _entity, ctypes.c_void_p, ctypes.c_void_p)
_declare('dds_create_reader', _entity, _entity, _entity, ctypes.c_void_p, ctypes.c_void_p)
_declare('dds_delete', ctypes.c_int32, _entity)
_declare('dds_get_guid', ctypes.c_int32, _entity, ctypes.POINTER(_Guid))
_declare('dds_wait_for_acks', ctypes.c_int32, _entity, ctypes.c_int64)
_declare('dds_create_waitset', _entity, _entity)
_declare('dds_waitset_attach', ctypes.c_int32, _entity, _entity, ctypes.c_ssize_t)
_declare('dds_waitset_detach', ctypes.c_int32, _entity, _entity)
_declare(
    'dds_waitset_wait',
    ctypes.c_int32,
    _entity,
    ctypes.POINTER(ctypes.c_ssize_t),
    ctypes.c_size_t,
    ctypes.c_int64,
)
_declare('dds_create_readcondition', _entity, _entity, ctypes.c_uint32)
_declare('dds_create_guardcondition', _entity, _entity)
_declare('dds_set_guardcondition', ctypes.c_int32, _entity, ctypes.c_bool)
_declare('dds_take_guardcondition', ctypes.c_int32, _entity, ctypes.POINTER(ctypes.c_bool))
_declare(
    'dds_get_publication_matched_status',
    ctypes.c_int32,
    _entity,
    ctypes.POINTER(_PublicationMatched),
)
_declare(
    'dds_get_subscription_matched_status',
    ctypes.c_int32,
    _entity,
    ctypes.POINTER(_PublicationMatched),
)

_ANY_STATE = 0x7F
_NOT_READ_ANY = 0x02 | 0x0C | 0x70
_TAKE_BATCH = 256
_placeholder_ids = itertools.count()


def _check(result: int, what: str) -> int:
    if result < 0:
        msg = f'{what} failed (DDS return code {result})'
        raise DdsWireError(msg)
    return result


def _entity_guid(handle: int) -> bytes:
    guid = _Guid()
    _check(_lib.dds_get_guid(handle, ctypes.byref(guid)), 'dds_get_guid')
    return bytes(guid.v)


def _placeholder_type(type_name: str) -> Any:
    """Build a fresh one-octet IDL struct named ``type_name`` (its layout stays local)."""
    placeholder: Any = make_idl_struct(
        f'Placeholder{next(_placeholder_ids)}', type_name, {'opaque': idl_types.uint8}
    )
    placeholder.__idl__.populate()
    placeholder.__idl__.fill_type_data()
    return placeholder


def _withdraw_type_information(topic: int, type_information: bytes) -> None:
    """
    Make the topic's sertype report no XTypes TypeInformation, like rmw_cyclonedds' sertype.

    cyclonedds-python needs the type information once, to build the sertype's CDR stream
    descriptor when the topic is created; afterwards it is only consulted to announce
    endpoints. Its serialized copy is located by content inside the sertype and its length set
    to zero, so readers and writers created later are announced without it.
    """
    sertype = ctypes.c_void_p()
    _check(_lib.dds_get_entity_sertype(topic, ctypes.byref(sertype)), 'dds_get_entity_sertype')
    base = sertype.value
    if not base:
        msg = 'topic has no sertype'
        raise DdsWireError(msg)
    pointer_size = ctypes.sizeof(ctypes.c_void_p)
    for offset in range(0, 1024, pointer_size):
        pointer = ctypes.c_void_p.from_address(base + offset).value
        size = ctypes.c_uint32.from_address(base + offset + pointer_size)
        if (
            pointer
            and size.value == len(type_information)
            and ctypes.string_at(pointer, size.value) == type_information
        ):
            size.value = 0
            return
    msg = 'cannot find the type information in the cyclonedds-python sertype (version drift?)'
    raise DdsWireError(msg)


IncompatibleQosHandler = Callable[[str], None]


class _RawEndpoint:
    """What writers and readers share: the handle, its GUID, the listener kept alive, deletion."""

    def __init__(
        self, participant: DdsParticipant, handle: int, listener: Listener | None
    ) -> None:
        self._participant = participant
        self.handle = handle
        self._listener = listener
        self.guid = _entity_guid(handle)

    def _delete(self) -> None:
        """Delete the entity (once) and drop the participant's bookkeeping of it."""
        if self.handle <= 0:
            return
        _lib.dds_delete(self.handle)
        self._participant.forget(self.handle)
        self.handle = 0


class RawWriter(_RawEndpoint):
    """A DDS writer that publishes already serialized CDR payloads."""

    def write(self, payload: bytes) -> None:
        """Publish one CDR payload (with its 4-byte encapsulation header)."""
        result = _clayer.ddspy_write(self.handle, payload)
        if result < 0:
            msg = f'dds_write failed (DDS return code {result})'
            raise DdsWireError(msg)

    def matched_count(self) -> int:
        """Return the number of currently matched readers."""
        status = _PublicationMatched()
        _lib.dds_get_publication_matched_status(self.handle, ctypes.byref(status))
        return int(status.current_count)

    def wait_for_acks(self, timeout_ns: int) -> bool:
        """Block until every matched reliable reader acknowledged all samples."""
        return bool(_lib.dds_wait_for_acks(self.handle, timeout_ns) == 0)

    def close(self, flush_timeout_ns: int = 0) -> None:
        """Delete the writer, first waiting up to ``flush_timeout_ns`` for acknowledgements."""
        if self.handle > 0 and flush_timeout_ns > 0:
            self.wait_for_acks(flush_timeout_ns)
        self._delete()


class RawReader(_RawEndpoint):
    """A DDS reader that hands back received CDR payloads."""

    def __init__(
        self, participant: DdsParticipant, handle: int, listener: Listener | None
    ) -> None:
        super().__init__(participant, handle, listener)
        self.read_condition = _check(
            _lib.dds_create_readcondition(handle, _NOT_READ_ANY), 'dds_create_readcondition'
        )
        self._publisher_gids: dict[int, bytes] = {}

    def take(self, max_samples: int = _TAKE_BATCH) -> list[bytes]:
        """Take up to ``max_samples`` payloads (valid data only), oldest first."""
        return [payload for payload, info in self._take(max_samples) if info.valid_data]

    def take_with_info(self, max_samples: int = _TAKE_BATCH) -> list[tuple[bytes, int, int]]:
        """Take payloads with their source timestamp (ns) and publication handle."""
        return [
            (payload, int(info.source_timestamp), int(info.publication_handle))
            for payload, info in self._take(max_samples)
            if info.valid_data
        ]

    def _take(self, max_samples: int) -> list[tuple[bytes, Any]]:
        """Take up to ``max_samples`` ``(payload, sample_info)`` pairs; none once closed."""
        if self.handle <= 0:
            return []
        samples = _clayer.ddspy_take(self.handle, _ANY_STATE, max_samples)
        if isinstance(samples, int):
            if samples < 0:
                msg = f'dds_take failed (DDS return code {samples})'
                raise DdsWireError(msg)
            return []
        return cast('list[tuple[bytes, Any]]', samples)

    def publisher_gid(self, publication_handle: int) -> bytes:
        """Return the 16-byte GUID of the matched writer behind ``publication_handle``."""
        gid = self._publisher_gids.get(publication_handle)
        if gid is None:
            endpoint = _clayer.ddspy_get_matched_publication_data(
                self.handle, publication_handle, endpoint_constructor, cqos_to_qos
            )
            gid = endpoint.key.bytes if hasattr(endpoint, 'key') else bytes(16)
            self._publisher_gids[publication_handle] = gid
        return gid

    def matched_count(self) -> int:
        """Return the number of currently matched writers."""
        status = _PublicationMatched()
        _lib.dds_get_subscription_matched_status(self.handle, ctypes.byref(status))
        return int(status.current_count)

    def close(self) -> None:
        """Delete the reader (and its read condition)."""
        self._delete()


class WaitSet:
    """A Cyclone waitset with a guard condition to wake it from another thread."""

    def __init__(self, participant: DdsParticipant) -> None:
        self._handle = _check(_lib.dds_create_waitset(participant.handle), 'dds_create_waitset')
        self._guard = _check(
            _lib.dds_create_guardcondition(participant.handle), 'dds_create_guardcondition'
        )
        _check(_lib.dds_waitset_attach(self._handle, self._guard, self._guard), 'attach')
        self._attached: set[int] = set()
        self._buffer = (ctypes.c_ssize_t * 64)()

    def attach(self, condition: int) -> None:
        """Wake on ``condition`` (a read condition handle)."""
        if condition not in self._attached:
            _check(_lib.dds_waitset_attach(self._handle, condition, condition), 'attach')
            self._attached.add(condition)

    def detach(self, condition: int) -> None:
        """Stop waking on ``condition``."""
        if condition in self._attached:
            self._attached.discard(condition)
            _lib.dds_waitset_detach(self._handle, condition)

    def wake(self) -> None:
        """Make a concurrent or the next :meth:`wait` return at once."""
        _lib.dds_set_guardcondition(self._guard, True)

    def wait(self, timeout_ns: int) -> list[int]:
        """Block (without the GIL) until a condition triggers or the timeout; triggered ones."""
        count = _lib.dds_waitset_wait(
            self._handle, self._buffer, len(self._buffer), max(0, min(timeout_ns, DDS_INFINITY))
        )
        if count <= 0:
            return []
        triggered = [self._buffer[i] for i in range(min(count, len(self._buffer)))]
        if self._guard in triggered:
            flag = ctypes.c_bool()
            _lib.dds_take_guardcondition(self._guard, ctypes.byref(flag))
            triggered.remove(self._guard)
        return triggered

    def close(self) -> None:
        """Delete the waitset and its guard condition."""
        if self._handle > 0:
            _lib.dds_delete(self._guard)
            _lib.dds_delete(self._handle)
            self._handle = 0


class DdsParticipant:
    """The process' DDS participant with ROS conventions: topics, raw endpoints, graph."""

    def __init__(
        self, env: Mapping[str, str] | None = None, warn: Callable[[str], None] = print
    ) -> None:
        environ = os.environ if env is None else env
        self.domain_id = domain_id_from_env(environ)
        self.discovery = discovery_config_from_env(environ)
        for text in self.discovery.warnings:
            warn(text)
        config = cyclone_config(self.discovery, environ.get('CYCLONEDDS_URI'), os.getpid())
        try:
            self._domain = Domain(self.domain_id, config) if config is not None else None
            self._participant = DomainParticipant(
                self.domain_id, qos=Qos(Policy.Userdata(b'enclave=/;'))
            )
        except DDSException as error:
            msg = (
                f'cannot create the DDS participant on domain {self.domain_id} '
                f'(CYCLONEDDS_URI={environ.get("CYCLONEDDS_URI")!r}): {error}'
            )
            raise DdsConfigError(msg) from error
        self.handle: int = self._participant._ref
        self.guid = _entity_guid(self.handle)
        self._lock = threading.Lock()
        self._topics: dict[str, tuple[int, str]] = {}
        self._listeners: dict[int, Listener] = {}
        self._builtin_readers: dict[bool, tuple[Any, Any]] = {}
        self._closed = False

    def topic(self, dds_topic: str, type_name: str) -> int:
        """Return the topic handle for ``dds_topic``, creating it for ``type_name`` once."""
        with self._lock:
            known = self._topics.get(dds_topic)
            if known is not None:
                if known[1] != type_name:
                    msg = (
                        f'topic {dds_topic!r} already exists in this process with type '
                        f'{known[1]!r}, cannot use it with {type_name!r}'
                    )
                    raise DdsWireError(msg)
                return known[0]
            placeholder = _placeholder_type(type_name)
            handle: int = _clayer.ddspy_topic_create(
                self.handle, dds_topic, placeholder, None, None
            )
            _check(handle, f'creating DDS topic {dds_topic!r} of type {type_name!r}')
            _withdraw_type_information(handle, placeholder.__idl__._xt_bytedata[0])
            self._topics[dds_topic] = (handle, type_name)
            return handle

    def _endpoint_listener(
        self, on_incompatible_qos: IncompatibleQosHandler | None, *, writer: bool
    ) -> Listener | None:
        if on_incompatible_qos is None:
            return None
        handler = on_incompatible_qos

        def report(_entity: object, status: Any) -> None:
            # Never let a failing log call escape into Cyclone's listener thread.
            with contextlib.suppress(Exception):
                handler(incompatible_policy_name(int(status.last_policy_id)))

        if writer:
            return Listener(on_offered_incompatible_qos=report)
        return Listener(on_requested_incompatible_qos=report)

    def create_writer(
        self,
        dds_topic: str,
        type_name: str,
        qos: EndpointQos,
        user_data: bytes,
        on_incompatible_qos: IncompatibleQosHandler | None = None,
    ) -> RawWriter:
        """Create a raw-bytes writer on ``dds_topic``."""
        handle, listener = self._create_endpoint(
            _lib.dds_create_writer,
            'writer',
            dds_topic=dds_topic,
            type_name=type_name,
            qos=cyclone_qos(qos, user_data),
            listener=self._endpoint_listener(on_incompatible_qos, writer=True),
        )
        return RawWriter(self, handle, listener)

    def create_reader(
        self,
        dds_topic: str,
        type_name: str,
        qos: EndpointQos,
        user_data: bytes,
        on_incompatible_qos: IncompatibleQosHandler | None = None,
        *,
        ignore_local: bool = False,
    ) -> RawReader:
        """Create a raw-bytes reader on ``dds_topic``."""
        handle, listener = self._create_endpoint(
            _lib.dds_create_reader,
            'reader',
            dds_topic=dds_topic,
            type_name=type_name,
            qos=cyclone_qos(qos, user_data, ignore_local=ignore_local),
            listener=self._endpoint_listener(on_incompatible_qos, writer=False),
        )
        return RawReader(self, handle, listener)

    def _create_endpoint(
        self,
        create: Callable[..., int],
        kind: str,
        *,
        dds_topic: str,
        type_name: str,
        qos: Qos,
        listener: Listener | None,
    ) -> tuple[int, Listener | None]:
        """Create a writer or reader with ``create`` and keep its listener alive."""
        topic = self.topic(dds_topic, type_name)
        cqos = _CQos.qos_to_cqos(qos)
        try:
            handle = create(self.handle, topic, cqos, listener._ref if listener else None)
        finally:
            _CQos.cqos_destroy(cqos)
        _check(handle, f'creating a DDS {kind} on {dds_topic!r}')
        if listener is not None:
            self._listeners[handle] = listener
        return handle, listener

    def count_endpoints(self, dds_topic: str, *, publications: bool) -> int:
        """Count the live writers (``publications``) or readers on ``dds_topic`` in the domain."""
        with self._lock:
            known = self._builtin_readers.get(publications)
            if known is None:
                builtin_topic = (
                    BuiltinTopicDcpsPublication if publications else BuiltinTopicDcpsSubscription
                )
                reader = BuiltinDataReader(self._participant, builtin_topic)
                alive = ReadCondition(
                    reader, SampleState.Any | ViewState.Any | InstanceState.Alive
                )
                known = (reader, alive)
                self._builtin_readers[publications] = known
        reader, alive = known
        samples = reader.read(N=100_000, condition=alive)
        return int(sum(1 for sample in samples if sample.topic_name == dds_topic))

    def forget(self, handle: int) -> None:
        """Drop the bookkeeping of a deleted endpoint."""
        self._listeners.pop(handle, None)

    def close(self) -> None:
        """Delete the participant and everything in it."""
        if self._closed:
            return
        self._closed = True
        _lib.dds_delete(self.handle)
        if self._domain is not None:
            _lib.dds_delete(self._domain._ref)


_participant: DdsParticipant | None = None
_participant_lock = threading.Lock()
_exit_hook_installed = False


def get_participant(warn: Callable[[str], None] = print) -> DdsParticipant:
    """Return the process' participant, creating it from the environment on first use."""
    global _participant, _exit_hook_installed
    with _participant_lock:
        if _participant is None or _participant._closed:
            _participant = DdsParticipant(warn=warn)
            if not _exit_hook_installed:
                # Delete the DDS entities (and with them the listener callbacks into Python)
                # before the interpreter starts tearing modules down.
                atexit.register(close_participant)
                _exit_hook_installed = True
        return _participant


def close_participant() -> None:
    """Delete the process' participant (a later :func:`get_participant` makes a new one)."""
    global _participant
    with _participant_lock:
        if _participant is not None:
            _participant.close()
            _participant = None
