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

"""Hypothesis strategies for any message of the schema table."""

from __future__ import annotations

from typing import Any

from hypothesis import strategies as st
import numpy
from tf_demo.msgs._message import message_class
from tf_demo.msgs._schema import FieldSpec
from tf_demo.msgs._schema import PRIMITIVES
from tf_demo.msgs._schema import spec_for

_INT_BITS = {'int8': 8, 'int16': 16, 'int32': 32, 'int64': 64}
# ROS strings are NUL-terminated C strings of UTF-8: no NUL inside, no lone surrogates.
TEXT = st.text(
    st.characters(blacklist_categories=['Cs'], blacklist_characters='\x00'), max_size=40
)


def _element(field: FieldSpec) -> st.SearchStrategy[Any]:
    """Return a strategy for one element of ``field``."""
    if field.is_nested:
        return message_strategy(field.base)
    if field.base == 'string':
        return TEXT
    if field.base == 'bool':
        return st.booleans()
    if field.base == 'byte':
        return st.binary(min_size=1, max_size=1)
    if field.base == 'float64':
        return st.floats(allow_nan=False)
    if field.base == 'float32':
        return st.floats(allow_nan=False, width=32)
    if field.base in _INT_BITS:
        bits = _INT_BITS[field.base]
        return st.integers(-(2 ** (bits - 1)), 2 ** (bits - 1) - 1)
    bits = PRIMITIVES[field.base].size * 8
    return st.integers(0, 2**bits - 1)


def _field(field: FieldSpec) -> st.SearchStrategy[Any]:
    """Return a strategy for the whole value of ``field``."""
    element = _element(field)
    if field.kind == 'single':
        return element
    if field.kind == 'array':
        values = st.lists(element, min_size=field.size, max_size=field.size)
        prim = PRIMITIVES.get(field.base)
        if prim is not None and prim.numpy_dtype:
            return values.map(lambda items: numpy.array(items, dtype=prim.numpy_dtype))
        return values
    return st.lists(element, max_size=min(4, field.size) if field.size else 4)


def message_strategy(msgtype: str) -> st.SearchStrategy[Any]:
    """Return a strategy for messages of ``msgtype`` with arbitrary valid field values."""
    spec = spec_for(msgtype)
    cls = message_class(spec.msgtype)
    return st.builds(cls, **{field.name: _field(field) for field in spec.fields})


def _sample_element(field: FieldSpec, index: int) -> Any:
    """Return a deterministic element of ``field`` (the ``index``-th of its sequence)."""
    if field.is_nested:
        return filled_message(field.base)
    if field.base == 'string':
        return 'frame_' + 'x' * index
    if field.base == 'bool':
        return bool(index % 2)
    if field.base == 'byte':
        return bytes([index])
    if field.base in ('float32', 'float64'):
        return 0.5 + index
    return index + 1


def filled_message(msgtype: str) -> Any:
    """Return a fixed message: every string set, every sequence of 2 (or of its bound)."""
    spec = spec_for(msgtype)
    values: dict[str, Any] = {}
    for field in spec.fields:
        if field.kind == 'single':
            values[field.name] = _sample_element(field, 1)
            continue
        count = field.size if field.kind == 'array' else min(2, field.size or 2)
        items = [_sample_element(field, index) for index in range(count)]
        prim = PRIMITIVES.get(field.base)
        if field.kind == 'array' and prim is not None and prim.numpy_dtype:
            values[field.name] = numpy.array(items, dtype=prim.numpy_dtype)
        else:
            values[field.name] = items
    return message_class(spec.msgtype)(**values)
