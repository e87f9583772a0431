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
type name. Configuration and QoS come from :mod:`tf_demo.transport.dds.wire_config`.
"""

from __future__ import annotations

import atexit
from collections.abc import Callable
from collections.abc import Mapping
import contextlib
import ctypes
import os
import threading
from typing import Any

from cyclonedds import _clayer
from cyclonedds.builtin import BuiltinDataReader
from cyclonedds.builtin import BuiltinTopicDcpsPublication
from cyclonedds.builtin import BuiltinTopicDcpsSubscription
from cyclonedds.core import DDSException
from cyclonedds.core import InstanceState
from cyclonedds.core import ReadCondition
from cyclonedds.core import SampleState
from cyclonedds.core import ViewState
from cyclonedds.domain import Domain
from cyclonedds.domain import DomainParticipant
from cyclonedds.qos import Policy
from cyclonedds.qos import Qos
from tf_demo.transport.dds.cyclone_c import check
from tf_demo.transport.dds.cyclone_c import CQos
from tf_demo.transport.dds.cyclone_c import entity_guid
from tf_demo.transport.dds.cyclone_c import lib
from tf_demo.transport.dds.cyclone_c import Listener
from tf_demo.transport.dds.cyclone_c import placeholder_type
from tf_demo.transport.dds.cyclone_c import type_information
from tf_demo.transport.dds.cyclone_c import withdraw_type_information
from tf_demo.transport.dds.raw_endpoints import RawReader
from tf_demo.transport.dds.raw_endpoints import RawWriter
from tf_demo.transport.dds.wire_config import cyclone_config
from tf_demo.transport.dds.wire_config import DdsConfigError
from tf_demo.transport.dds.wire_config import DdsWireError
from tf_demo.transport.dds.wire_config import discovery_config_from_env
from tf_demo.transport.dds.wire_config import domain_id_from_env
from tf_demo.transport.dds.wire_qos import cyclone_qos
from tf_demo.transport.dds.wire_qos import EndpointQos
from tf_demo.transport.dds.wire_qos import incompatible_policy_name

__all__ = [
    'DdsParticipant',
    'close_participant',
    'get_participant',
]


IncompatibleQosHandler = Callable[[str], None]


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
        self.guid = entity_guid(self.handle)
        self._lock = threading.Lock()
        self._topics: dict[str, tuple[int, str]] = {}
        self._listeners: dict[int, Listener] = {}
        self._builtin_readers: dict[bool, tuple[BuiltinDataReader, ReadCondition]] = {}
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
            placeholder = placeholder_type(type_name)
            handle: int = _clayer.ddspy_topic_create(
                self.handle, dds_topic, placeholder, None, None
            )
            check(handle, f'creating DDS topic {dds_topic!r} of type {type_name!r}')
            withdraw_type_information(handle, type_information(placeholder))
            self._topics[dds_topic] = (handle, type_name)
            return handle

    def _endpoint_listener(
        self, on_incompatible_qos: IncompatibleQosHandler | None, *, writer: bool
    ) -> Listener | None:
        if on_incompatible_qos is None:
            return None
        handler = on_incompatible_qos

        def report(_entity: object, status: ctypes.Structure) -> None:
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
            lib.dds_create_writer,
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
            lib.dds_create_reader,
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
        cqos = CQos.qos_to_cqos(qos)
        try:
            handle = create(self.handle, topic, cqos, listener._ref if listener else None)
        finally:
            CQos.cqos_destroy(cqos)
        check(handle, f'creating a DDS {kind} on {dds_topic!r}')
        if listener is not None:
            self._listeners[handle] = listener
        return handle, listener

    def count_endpoints(self, dds_topic: str, *, publications: bool) -> int:
        """Count the live writers (``publications``) or readers on ``dds_topic`` in the domain."""
        return len(self.endpoints(dds_topic, publications=publications))

    def endpoints(self, dds_topic: str, *, publications: bool) -> list[Any]:
        """
        Return the live writers (``publications``) or readers on ``dds_topic`` in the domain.

        Each is Cyclone's built-in topic sample: ``key`` (the GUID), ``type_name``, ``qos``.
        """
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
        return [sample for sample in samples if sample.topic_name == dds_topic]

    def forget(self, handle: int) -> None:
        """Drop the bookkeeping of a deleted endpoint."""
        self._listeners.pop(handle, None)

    def close(self) -> None:
        """Delete the participant and everything in it."""
        if self._closed:
            return
        self._closed = True
        lib.dds_delete(self.handle)
        if self._domain is not None:
            lib.dds_delete(self._domain._ref)


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
