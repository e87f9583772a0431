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
Parameter values typed as ``rcl_yaml_param_parser`` types them (rcl's ``parse.c``).

:func:`rcl_scalar` types one YAML scalar (``get_value``); :class:`Variant` keeps the slots of
the ``rcl_variant_t`` a value fills and picks the one rclpy reads. The YAML readers that feed
them are :mod:`tf_demo.transport.params_yaml` (``-p`` values) and
:mod:`tf_demo.transport.params_file` (``--params-file``).
"""

from __future__ import annotations

import math
from typing import cast
from typing import TypeAlias

from tf_demo.transport.params_c_numbers import c_strtod
from tf_demo.transport.params_c_numbers import c_strtoll

__all__ = ['ParamValue', 'RuleError', 'Scalar', 'Variant', 'rcl_scalar']

Scalar: TypeAlias = bool | int | float | str
"""One typed YAML scalar."""
ParamValue: TypeAlias = Scalar | list[bool] | list[int] | list[float] | list[str]
"""A parameter value rcl can give: a scalar or a homogeneous array."""

_RCL_TRUE = frozenset({'Y', 'y', 'yes', 'Yes', 'YES', 'true', 'True', 'TRUE', 'on', 'On', 'ON'})
_RCL_FALSE = frozenset({'N', 'n', 'no', 'No', 'NO', 'false', 'False', 'FALSE', 'off', 'Off'})
_RCL_FALSE |= {'OFF'}
_RCL_SPECIAL_DOUBLES = {
    f'{sign}.{word}': value
    for word, value in (('inf', math.inf), ('Inf', math.inf), ('INF', math.inf))
    for sign in ('', '+')
} | {f'-.{word}': -math.inf for word in ('inf', 'Inf', 'INF')}
_RCL_SPECIAL_DOUBLES |= {f'.{word}': math.nan for word in ('nan', 'NaN', 'NAN')}


class RuleError(ValueError):
    """Why one ``--ros-args`` rule or value is malformed (``parse_ros_args`` words it as rcl)."""


def rcl_scalar(text: str, *, quoted: bool = False, str_tag: bool = False) -> Scalar:
    """
    Type one YAML scalar as rcl does: ``!!str`` or quoted stays a string; else bool, int, double.

    The bools are exactly rcl's (``y``/``n``/``yes``/``on``/``off``... in three spellings), ints
    what ``strtoll`` base 0 reads whole in int64 (``0x1F``, octal ``010``), doubles what
    ``strtod`` reads whole without ERANGE (``1e3``, ``inf``, ``nan``, ``.inf``, ``0x1p3``); an
    integer beyond int64 is a double and a number beyond a double stays a string, as in rcl.
    """
    if str_tag or quoted:
        return text
    if text in _RCL_TRUE:
        return True
    if text in _RCL_FALSE:
        return False
    integer = c_strtoll(text)
    if integer is not None:
        return integer
    special = _RCL_SPECIAL_DOUBLES.get(text)
    if special is not None:
        return special
    double = c_strtod(text)
    if double is None or double.length != len(text) or double.out_of_range:
        return text
    return double.value


_KIND_ORDER = (bool, int, float, str)  # rclpy's order when a value fills several slots
_RCL_KIND_NAMES = {bool: 'bool', int: 'integer', float: 'double', str: 'string'}


class Variant:
    """
    The slots of the ``rcl_variant_t`` one value fills, and the one rclpy reads from them.

    rcl keeps a slot per type: a scalar after a sequence (``[[1], 2]``) or a second inner
    sequence (``[[1, 2], [3]]``) fills or replaces a slot, and rclpy takes the first filled
    slot in its order (scalars bool, int, double, string, then the arrays in the same order).
    """

    def __init__(self) -> None:
        self.scalars: dict[type, Scalar] = {}
        self.arrays: dict[type, list[Scalar]] = {}
        self._sequence_kind: type | None = None

    def start_sequence(self) -> None:
        """Begin a YAML sequence: its items fill one array slot afresh."""
        self._sequence_kind = None

    def add(self, value: Scalar, in_sequence: bool, line: int) -> None:
        """Fill the slot of ``value`` (an array item when ``in_sequence``); rcl's mixed error."""
        kind = type(value)
        if not in_sequence:
            self.scalars[kind] = value
            return
        if self._sequence_kind is None:
            self._sequence_kind = kind
            self.arrays[kind] = []
        elif self._sequence_kind is not kind:
            msg = (
                f"Sequence should be of same type. Value type '{_RCL_KIND_NAMES[kind]}' "
                f'do not belong at line_num {line}'
            )
            raise RuleError(msg)
        self.arrays[kind].append(value)

    def value(self) -> ParamValue | None:
        """Return the value rclpy reads (None when no slot is filled: the type is unknown)."""
        for kind in _KIND_ORDER:
            if kind in self.scalars:
                return self.scalars[kind]
        for kind in _KIND_ORDER:
            if kind in self.arrays:
                return cast('ParamValue', self.arrays[kind])  # one kind per array
        return None
