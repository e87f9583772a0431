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
Raw-bytes DDS writers and readers and the waitset that wakes a spinning thread.

The payload never passes through cyclonedds-python's interpreted serializer: writers take the
CDR bytes produced by ``tf_demo.msgs.cdr`` and readers hand back the received bytes
(``ddspy_write``/``ddspy_take``, private to cyclonedds-python, hence the exact version pin).
"""

from __future__ import annotations

import ctypes
from typing import Protocol

from cyclonedds import _clayer
from cyclonedds.builtin_types import cqos_to_qos
from cyclonedds.builtin_types import endpoint_constructor
from cyclonedds.internal import SampleInfo
from tf_demo.transport.dds.cyclone_c import ANY_STATE
from tf_demo.transport.dds.cyclone_c import check
from tf_demo.transport.dds.cyclone_c import entity_guid
from tf_demo.transport.dds.cyclone_c import lib
from tf_demo.transport.dds.cyclone_c import Listener
from tf_demo.transport.dds.cyclone_c import NOT_READ_ANY
from tf_demo.transport.dds.cyclone_c import PublicationMatched
from tf_demo.transport.dds.cyclone_c import TAKE_BATCH
from tf_demo.transport.dds.wire_config import DdsWireError
from tf_demo.transport.dds.wire_qos import DDS_INFINITY

__all__ = ['EndpointOwner', 'RawReader', 'RawWriter', 'WaitSet']


class EndpointOwner(Protocol):
    """What an endpoint asks of its participant: the handle, and to forget a deleted entity."""

    handle: int

    def forget(self, handle: int) -> None: ...


class _RawEndpoint:
    """What writers and readers share: the handle, its GUID, the listener kept alive, deletion."""

    def __init__(self, participant: EndpointOwner, handle: int, listener: Listener | None) -> None:
        self._participant = participant
        self.handle = handle
        self._listener = listener
        self.guid = entity_guid(handle)

    def _delete(self) -> None:
        """Delete the entity (once) and drop the participant's bookkeeping of it."""
        if self.handle <= 0:
            return
        lib.dds_delete(self.handle)
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
        status = PublicationMatched()
        lib.dds_get_publication_matched_status(self.handle, ctypes.byref(status))
        return int(status.current_count)

    def wait_for_acks(self, timeout_ns: int) -> bool:
        """Block until every matched reliable reader acknowledged all samples."""
        return bool(lib.dds_wait_for_acks(self.handle, timeout_ns) == 0)

    def close(self, flush_timeout_ns: int = 0) -> None:
        """Delete the writer, first waiting up to ``flush_timeout_ns`` for acknowledgements."""
        if self.handle > 0 and flush_timeout_ns > 0:
            self.wait_for_acks(flush_timeout_ns)
        self._delete()


class RawReader(_RawEndpoint):
    """A DDS reader that hands back received CDR payloads."""

    def __init__(self, participant: EndpointOwner, handle: int, listener: Listener | None) -> None:
        super().__init__(participant, handle, listener)
        self.read_condition = check(
            lib.dds_create_readcondition(handle, NOT_READ_ANY), 'dds_create_readcondition'
        )
        self._publisher_gids: dict[int, bytes] = {}

    def take(self, max_samples: int = TAKE_BATCH) -> list[bytes]:
        """Take up to ``max_samples`` payloads (valid data only), oldest first."""
        return [payload for payload, info in self._take(max_samples) if info.valid_data]

    def take_with_info(self, max_samples: int = TAKE_BATCH) -> list[tuple[bytes, int, int]]:
        """Take payloads with their source timestamp (ns) and publication handle."""
        return [
            (payload, int(info.source_timestamp), int(info.publication_handle))
            for payload, info in self._take(max_samples)
            if info.valid_data
        ]

    def _take(self, max_samples: int) -> list[tuple[bytes, SampleInfo]]:
        """Take up to ``max_samples`` ``(payload, sample_info)`` pairs; none once closed."""
        if self.handle <= 0:
            return []
        samples = _clayer.ddspy_take(self.handle, ANY_STATE, max_samples)
        if isinstance(samples, int):
            if samples < 0:
                msg = f'dds_take failed (DDS return code {samples})'
                raise DdsWireError(msg)
            return []
        taken: list[tuple[bytes, SampleInfo]] = samples  # what ddspy_take returns (untyped C)
        return taken

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
        status = PublicationMatched()
        lib.dds_get_subscription_matched_status(self.handle, ctypes.byref(status))
        return int(status.current_count)

    def close(self) -> None:
        """Delete the reader (and its read condition)."""
        self._delete()


class WaitSet:
    """A Cyclone waitset with a guard condition to wake it from another thread."""

    def __init__(self, participant: EndpointOwner) -> None:
        self._handle = check(lib.dds_create_waitset(participant.handle), 'dds_create_waitset')
        self._guard = check(
            lib.dds_create_guardcondition(participant.handle), 'dds_create_guardcondition'
        )
        check(lib.dds_waitset_attach(self._handle, self._guard, self._guard), 'attach')
        self._attached: set[int] = set()
        self._buffer = (ctypes.c_ssize_t * 64)()

    def attach(self, condition: int) -> None:
        """Wake on ``condition`` (a read condition handle)."""
        if condition not in self._attached:
            check(lib.dds_waitset_attach(self._handle, condition, condition), 'attach')
            self._attached.add(condition)

    def detach(self, condition: int) -> None:
        """Stop waking on ``condition``."""
        if condition in self._attached:
            self._attached.discard(condition)
            lib.dds_waitset_detach(self._handle, condition)

    def wake(self) -> None:
        """Make a concurrent or the next :meth:`wait` return at once."""
        lib.dds_set_guardcondition(self._guard, True)

    def wait(self, timeout_ns: int) -> list[int]:
        """Block (without the GIL) until a condition triggers or the timeout; triggered ones."""
        count = lib.dds_waitset_wait(
            self._handle, self._buffer, len(self._buffer), max(0, min(timeout_ns, DDS_INFINITY))
        )
        if count <= 0:
            return []
        triggered = [self._buffer[i] for i in range(min(count, len(self._buffer)))]
        if self._guard in triggered:
            flag = ctypes.c_bool()
            lib.dds_take_guardcondition(self._guard, ctypes.byref(flag))
            triggered.remove(self._guard)
        return triggered

    def close(self) -> None:
        """Delete the waitset and its guard condition."""
        if self._handle > 0:
            lib.dds_delete(self._guard)
            lib.dds_delete(self._handle)
            self._handle = 0
