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
RIHS01 type hashes (REP-2011), computed as rosidl_generator_type_description computes them.

The hash is the sha256 of the canonical JSON of the type description: the type's own fields plus
every type it references (transitively), sorted by name, with ``default_value`` left out and
``json.dumps(separators=(', ', ': '))`` as the serialisation.
"""

from __future__ import annotations

import functools
import hashlib
import json

from tf_demo.msgs._schema import FieldSpec
from tf_demo.msgs._schema import MessageSpec
from tf_demo.msgs._schema import SERVICE_SPECS
from tf_demo.msgs._schema import spec_for

#: A value of the JSON text that is hashed.
JsonValue = str | int | list['JsonValue'] | dict[str, 'JsonValue']

_VALUE_TYPE_IDS = {
    'nested': 1,
    'int8': 2,
    'uint8': 3,
    'char': 3,  # .msg ``char`` is IDL uint8
    'int16': 4,
    'uint16': 5,
    'int32': 6,
    'uint32': 7,
    'int64': 8,
    'uint64': 9,
    'float32': 10,
    'float64': 11,
    'bool': 15,
    'byte': 16,
    'string': 17,
    'bounded_string': 21,
}
# FieldType.msg: arrays add 48, bounded sequences 96, unbounded sequences 144.
_ARRAY_OFFSET, _BOUNDED_SEQUENCE_OFFSET, _SEQUENCE_OFFSET = 48, 96, 144


def _field_type_id(field: FieldSpec) -> int:
    """Return the type_description_interfaces/FieldType id of ``field``."""
    if field.is_nested:
        value_id = _VALUE_TYPE_IDS['nested']
    elif field.base == 'string':
        value_id = _VALUE_TYPE_IDS['bounded_string' if field.string_bound else 'string']
    else:
        value_id = _VALUE_TYPE_IDS[field.base]
    if field.kind == 'array':
        return value_id + _ARRAY_OFFSET
    if field.kind == 'sequence':
        return value_id + (_BOUNDED_SEQUENCE_OFFSET if field.size else _SEQUENCE_OFFSET)
    return value_id


def _spec(typename: str) -> MessageSpec:
    """Return the parsed definition of a message type or of a service type."""
    service = SERVICE_SPECS.get(typename)
    return service if service is not None else spec_for(typename)


def _individual_description(msgtype: str) -> dict[str, JsonValue]:
    """Return the hashable individual type description of ``msgtype`` (no default values)."""
    spec = _spec(msgtype)
    return {
        'type_name': spec.msgtype,
        'fields': [
            {
                'name': field.name,
                'type': {
                    'type_id': _field_type_id(field),
                    'capacity': field.size,  # array length or sequence bound, else 0
                    'string_capacity': field.string_bound,
                    'nested_type_name': field.base if field.is_nested else '',
                },
            }
            for field in spec.fields
        ],
    }


def type_description(msgtype: str) -> dict[str, JsonValue]:
    """Return the full hashable type description of ``msgtype`` with its referenced types."""
    top = _spec(msgtype)
    referenced: set[str] = set()
    pending = [field.base for field in top.fields if field.is_nested]
    while pending:
        name = pending.pop()
        if name not in referenced:
            referenced.add(name)
            pending.extend(field.base for field in spec_for(name).fields if field.is_nested)
    return {
        'type_description': _individual_description(top.msgtype),
        'referenced_type_descriptions': [
            _individual_description(name) for name in sorted(referenced)
        ],
    }


@functools.cache
def type_hash(msgtype: str) -> str:
    """Return the ``RIHS01_<sha256 hex>`` type hash of ``msgtype`` (a message or a service)."""
    text = json.dumps(
        type_description(msgtype),
        ensure_ascii=True,
        allow_nan=False,
        indent=None,
        separators=(', ', ': '),
        sort_keys=False,
    )
    return 'RIHS01_' + hashlib.sha256(text.encode('utf-8')).hexdigest()
