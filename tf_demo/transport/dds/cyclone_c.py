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
The parts of Cyclone's C API that cyclonedds-python does not wrap, declared once for ctypes.

Entity creation and deletion, GUIDs, waitsets and guard conditions, matched-status counts,
and the placeholder topic type whose XTypes information is withdrawn so that endpoints are
announced as rmw_cyclonedds announces them (:func:`withdraw_type_information`).
"""

from __future__ import annotations

import ctypes
import itertools
from typing import Any
from typing import TypeAlias

from cyclonedds.core import Listener as _CycloneListener
from cyclonedds.idl import IdlStruct
from cyclonedds.idl import make_idl_struct
from cyclonedds.idl import types as idl_types
from cyclonedds.internal import DDS
from cyclonedds.qos import _CQos as _CycloneCQos
from tf_demo.transport.dds.wire_config import DdsWireError

__all__ = [
    'ANY_STATE',
    'NOT_READ_ANY',
    'TAKE_BATCH',
    'CQos',
    'Listener',
    'PublicationMatched',
    'check',
    'entity_guid',
    'instance_handle',
    'lib',
    'matched_handles',
    'placeholder_type',
    'type_information',
    'withdraw_type_information',
]

Untyped: TypeAlias = Any
"""
cyclonedds-python's classes whose methods carry no annotations (the type checker would refuse
every call into them): named through this alias, the one place the standalone world gives up
static types.
"""

lib = DDS._dll_handle
"""Cyclone's C library (``ctypes.CDLL``): the functions below get their ctypes signatures."""
CQos: Untyped = _CycloneCQos
Listener: Untyped = _CycloneListener


class _Guid(ctypes.Structure):
    _fields_ = [('v', ctypes.c_uint8 * 16)]


class PublicationMatched(ctypes.Structure):
    _fields_ = [
        ('total_count', ctypes.c_uint32),
        ('total_count_change', ctypes.c_int32),
        ('current_count', ctypes.c_uint32),
        ('current_count_change', ctypes.c_int32),
        ('last_handle', ctypes.c_uint64),
    ]


def _declare(
    name: str, restype: type[ctypes._CData] | None, *argtypes: type[ctypes._CData]
) -> None:
    function = getattr(lib, name)
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
    ctypes.POINTER(PublicationMatched),
)
_declare(
    'dds_get_subscription_matched_status',
    ctypes.c_int32,
    _entity,
    ctypes.POINTER(PublicationMatched),
)

ANY_STATE = 0x7F
NOT_READ_ANY = 0x02 | 0x0C | 0x70
TAKE_BATCH = 256
_placeholder_ids = itertools.count()


def check(result: int, what: str) -> int:
    if result < 0:
        msg = f'{what} failed (DDS return code {result})'
        raise DdsWireError(msg)
    return result


def entity_guid(handle: int) -> bytes:
    guid = _Guid()
    check(lib.dds_get_guid(handle, ctypes.byref(guid)), 'dds_get_guid')
    return bytes(guid.v)


def placeholder_type(type_name: str) -> type[IdlStruct]:
    """Build a fresh one-octet IDL struct named ``type_name`` (its layout stays local)."""
    placeholder = make_idl_struct(
        f'Placeholder{next(_placeholder_ids)}', type_name, {'opaque': idl_types.uint8}
    )
    idl: Untyped = placeholder.__idl__
    idl.populate()
    idl.fill_type_data()
    return placeholder


def type_information(placeholder: type[IdlStruct]) -> bytes:
    """Return the serialized XTypes TypeInformation of a :func:`placeholder_type`."""
    idl: Untyped = placeholder.__idl__
    information: bytes = idl._xt_bytedata[0]
    return information


def withdraw_type_information(topic: int, type_information: bytes) -> None:
    """
    Make the topic's sertype report no XTypes TypeInformation, like rmw_cyclonedds' sertype.

    cyclonedds-python needs the type information once, to build the sertype's CDR stream
    descriptor when the topic is created; afterwards it is only consulted to announce
    endpoints. Its serialized copy is located by content inside the sertype and its length set
    to zero, so readers and writers created later are announced without it.
    """
    sertype = ctypes.c_void_p()
    check(lib.dds_get_entity_sertype(topic, ctypes.byref(sertype)), 'dds_get_entity_sertype')
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


lib.dds_get_instance_handle.restype = ctypes.c_int32
lib.dds_get_instance_handle.argtypes = [ctypes.c_int32, ctypes.POINTER(ctypes.c_uint64)]
for _name in ('dds_get_matched_subscriptions', 'dds_get_matched_publications'):
    getattr(lib, _name).restype = ctypes.c_int32
    getattr(lib, _name).argtypes = [
        ctypes.c_int32,
        ctypes.POINTER(ctypes.c_uint64),
        ctypes.c_size_t,
    ]


def instance_handle(entity: int) -> int:
    handle = ctypes.c_uint64()
    check(lib.dds_get_instance_handle(entity, ctypes.byref(handle)), 'instance handle')
    return int(handle.value)


def matched_handles(entity: int, *, subscriptions: bool) -> list[int]:
    function = (
        lib.dds_get_matched_subscriptions if subscriptions else lib.dds_get_matched_publications
    )
    count = function(entity, None, 0)
    if count <= 0:
        return []
    handles = (ctypes.c_uint64 * count)()
    count = function(entity, handles, count)
    return [int(handles[i]) for i in range(max(count, 0))]
