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
Parameters with rclpy's classes, rules and error texts (the standalone world's).

:class:`Parameter`, :class:`SetParametersResult`, :class:`ParameterDescriptor` and the
exceptions match ``rclpy.parameter``, ``rcl_interfaces.msg`` and ``rclpy.exceptions``; the
``parameter_*_msg`` functions convert to and from ``rcl_interfaces`` messages. The rclpy world
uses rclpy's own classes (:mod:`tf_demo.transport.parameters` chooses).
"""

from __future__ import annotations

import array
from collections.abc import Callable
from collections.abc import Iterable
from dataclasses import dataclass
from dataclasses import field
from enum import Enum
import math
from typing import Any

from tf_demo.msgs import rcl_interfaces

#: rclpy's public names (the facade star-imports these); the rest is this world's own.
__all__ = [
    'FloatingPointRange',
    'IntegerRange',
    'InvalidParameterException',
    'InvalidParameterTypeException',
    'InvalidParameterValueException',
    'Parameter',
    'ParameterAlreadyDeclaredException',
    'ParameterDescriptor',
    'ParameterException',
    'ParameterImmutableException',
    'ParameterNotDeclaredException',
    'ParameterType',
    'ParameterUninitializedException',
    'SetParametersResult',
]


class ParameterType(Enum):
    """The type of a parameter value (``rcl_interfaces/msg/ParameterType`` values)."""

    NOT_SET = 0
    BOOL = 1
    INTEGER = 2
    DOUBLE = 3
    STRING = 4
    BYTE_ARRAY = 5
    BOOL_ARRAY = 6
    INTEGER_ARRAY = 7
    DOUBLE_ARRAY = 8
    STRING_ARRAY = 9

    def __str__(self) -> str:
        return f'Type.{self.name}'

    @classmethod
    def from_parameter_value(cls, parameter_value: object) -> ParameterType:
        """
        Return the type rclpy infers for ``parameter_value``.

        :raises TypeError: for a value no parameter can hold.
        """
        if parameter_value is None:
            return cls.NOT_SET
        if isinstance(parameter_value, bool):
            return cls.BOOL
        if isinstance(parameter_value, int):
            return cls.INTEGER
        if isinstance(parameter_value, float):
            return cls.DOUBLE
        if isinstance(parameter_value, str):
            return cls.STRING
        if isinstance(parameter_value, (list, tuple, array.array)):
            for element_type, array_type in _ARRAY_TYPES:
                if all(isinstance(item, element_type) for item in parameter_value):
                    return array_type
            msg = f"The given value is not a list of one of the allowed types '{parameter_value}'."
            raise TypeError(msg)
        msg = f"The given value is not one of the allowed types '{parameter_value}'."
        raise TypeError(msg)

    def check(self, parameter_value: object) -> bool:
        """
        Whether ``parameter_value`` can be held by a parameter of this type (rclpy's rule).

        As in rclpy a ``bool`` passes for INTEGER (it is an ``int``), BYTE_ARRAY items are
        ``bytes`` of length 1, and only the INTEGER and DOUBLE arrays may be ``array.array``.
        """
        if self is ParameterType.NOT_SET:
            return parameter_value is None
        scalar = _SCALAR_TYPES.get(self)
        if scalar is not None:
            return isinstance(parameter_value, scalar)
        element = _ARRAY_ELEMENT_TYPES[self]
        numeric = self in (ParameterType.INTEGER_ARRAY, ParameterType.DOUBLE_ARRAY)
        if isinstance(parameter_value, array.array) and numeric:
            items: Iterable[object] = parameter_value
        elif isinstance(parameter_value, (list, tuple)):
            items = parameter_value
        else:
            return False
        if element is bytes:
            return all(isinstance(item, bytes) and len(item) == 1 for item in items)
        return all(isinstance(item, element) for item in items)


# rclpy's class is ``Parameter.Type``: reprs read ``<Type.DOUBLE: 3>`` and pickles find it there
ParameterType.__name__ = 'Type'
ParameterType.__qualname__ = 'Parameter.Type'

_ARRAY_TYPES: tuple[tuple[type, ParameterType], ...] = (
    (bytes, ParameterType.BYTE_ARRAY),
    (bool, ParameterType.BOOL_ARRAY),
    (int, ParameterType.INTEGER_ARRAY),
    (float, ParameterType.DOUBLE_ARRAY),
    (str, ParameterType.STRING_ARRAY),
)
_ARRAY_ELEMENT_TYPES = {array_type: element for element, array_type in _ARRAY_TYPES}
_SCALAR_TYPES: dict[ParameterType, type] = {
    ParameterType.BOOL: bool,
    ParameterType.INTEGER: int,
    ParameterType.DOUBLE: float,
    ParameterType.STRING: str,
}


class Parameter:
    """A named, typed parameter value (``rclpy.parameter.Parameter``; compared by identity)."""

    Type = ParameterType

    def __init__(
        self, name: str, type_: ParameterType | None = None, value: object = None
    ) -> None:
        if type_ is None:
            type_ = ParameterType.from_parameter_value(value)
        if not isinstance(type_, ParameterType):
            msg = f"type must be an instance of '{ParameterType!r}'"
            raise TypeError(msg)
        if not type_.check(value):
            msg = f"Type '{type_}' and value '{value}' do not agree"
            raise ValueError(msg)
        self._name = name
        self._type = type_
        self._value = value

    @property
    def name(self) -> str:
        """The parameter's name (dots separate namespaces)."""
        return self._name

    @property
    def type_(self) -> ParameterType:
        """The parameter's type."""
        return self._type

    @property
    def value(self) -> Any:
        """
        The parameter's value (``None`` when NOT_SET).

        Typed as rclpy (Jazzy) types it, not at all: its type is :attr:`type_`'s, which the
        declaration fixes, so the caller knows it (a union would make every reader narrow it).
        """
        return self._value

    def get_parameter_value(self) -> rcl_interfaces.ParameterValue:
        """Return the value as an ``rcl_interfaces/msg/ParameterValue`` (``.string_value``...)."""
        return parameter_value_to_msg(self)

    def to_parameter_msg(self) -> rcl_interfaces.Parameter:
        """Return the ``rcl_interfaces/msg/Parameter`` of this parameter."""
        return parameter_to_msg(self)

    @classmethod
    def from_parameter_msg(cls, param_msg: rcl_interfaces.Parameter) -> Parameter:
        """Return the parameter a ``rcl_interfaces/msg/Parameter`` carries."""
        return parameter_from_msg(param_msg)

    def __repr__(self) -> str:
        return f'Parameter(name={self._name!r}, type_={self._type}, value={self._value!r})'


#: ParameterValue field of each parameter type.
_VALUE_FIELDS = {
    ParameterType.BOOL: 'bool_value',
    ParameterType.INTEGER: 'integer_value',
    ParameterType.DOUBLE: 'double_value',
    ParameterType.STRING: 'string_value',
    ParameterType.BYTE_ARRAY: 'byte_array_value',
    ParameterType.BOOL_ARRAY: 'bool_array_value',
    ParameterType.INTEGER_ARRAY: 'integer_array_value',
    ParameterType.DOUBLE_ARRAY: 'double_array_value',
    ParameterType.STRING_ARRAY: 'string_array_value',
}


def parameter_value_to_msg(parameter: Parameter) -> rcl_interfaces.ParameterValue:
    """Return the ``ParameterValue`` message of ``parameter`` (rclpy's get_parameter_value)."""
    message = rcl_interfaces.ParameterValue(type=parameter.type_.value)
    field = _VALUE_FIELDS.get(parameter.type_)
    if field is not None:
        value = parameter.value
        if parameter.type_ in (ParameterType.INTEGER_ARRAY, ParameterType.DOUBLE_ARRAY):
            value = array.array(
                'q' if parameter.type_ is ParameterType.INTEGER_ARRAY else 'd', value
            )
        elif isinstance(value, tuple | array.array):
            value = list(value)
        setattr(message, field, value)
    return message


def parameter_to_msg(parameter: Parameter) -> rcl_interfaces.Parameter:
    """Return the ``rcl_interfaces/msg/Parameter`` of ``parameter``."""
    return rcl_interfaces.Parameter(name=parameter.name, value=parameter_value_to_msg(parameter))


def parameter_from_msg(message: rcl_interfaces.Parameter) -> Parameter:
    """
    Return the parameter a ``rcl_interfaces/msg/Parameter`` carries (rclpy's from_parameter_msg).

    :raises ValueError: for an unknown type or a value the type cannot hold.
    """
    type_ = ParameterType(int(message.value.type))
    field = _VALUE_FIELDS.get(type_)
    value = None if field is None else getattr(message.value, field)
    if isinstance(value, array.array):
        value = value.tolist()
    return Parameter(message.name, type_, value)


@dataclass
class SetParametersResult:
    """Outcome of setting parameters (``rcl_interfaces/msg/SetParametersResult``)."""

    successful: bool = False
    reason: str = ''


@dataclass
class FloatingPointRange:
    """Allowed range of a DOUBLE parameter (``rcl_interfaces/msg/FloatingPointRange``)."""

    from_value: float = 0.0
    to_value: float = 0.0
    step: float = 0.0


@dataclass
class IntegerRange:
    """Allowed range of an INTEGER parameter (``rcl_interfaces/msg/IntegerRange``)."""

    from_value: int = 0
    to_value: int = 0
    step: int = 0


@dataclass
class ParameterDescriptor:
    """Description and constraints of a parameter (``rcl_interfaces/msg/ParameterDescriptor``)."""

    name: str = ''
    type: int = 0
    description: str = ''
    additional_constraints: str = ''
    read_only: bool = False
    dynamic_typing: bool = False
    floating_point_range: list[FloatingPointRange] = field(default_factory=list)
    integer_range: list[IntegerRange] = field(default_factory=list)


class ParameterException(Exception):  # noqa: N818 - rclpy's name
    """Base of the parameter errors; the text ends with the parameter name(s), as in rclpy."""

    def __init__(self, error_msg: str, parameters: str | list[str]) -> None:
        super().__init__(f'{error_msg}: {parameters}')


class ParameterNotDeclaredException(ParameterException):
    """A parameter was used without being declared."""

    def __init__(self, parameters: str | list[str]) -> None:
        super().__init__('Invalid access to undeclared parameter(s)', parameters)


class ParameterAlreadyDeclaredException(ParameterException):
    """A parameter was declared twice."""

    def __init__(self, parameters: str | list[str]) -> None:
        super().__init__('Parameter(s) already declared', parameters)


class InvalidParameterException(ParameterException):
    """A parameter name is not valid."""

    def __init__(self, parameter_name: str) -> None:
        super().__init__('Invalid parameter name', parameter_name)


class InvalidParameterTypeException(ParameterException):
    """A value of the wrong type was given to a statically typed parameter."""

    def __init__(self, desired_parameter: Parameter, expected_type: str) -> None:
        try:
            given = ParameterType.from_parameter_value(desired_parameter.value).name
        except TypeError:
            given = type(desired_parameter.value).__name__
        super().__init__(
            f"Trying to set parameter '{desired_parameter.name}' to "
            f"'{desired_parameter.value}' of type '{given}', expecting type '{expected_type}'",
            desired_parameter.name,
        )


class InvalidParameterValueException(ParameterException):
    """A value was rejected by an on-set callback or by the descriptor."""

    def __init__(self, parameter: str, value: object, reason: str) -> None:
        super().__init__(
            f'Invalid parameter value ({value}) for parameter. Reason: {reason}', parameter
        )


class ParameterImmutableException(ParameterException):
    """A read-only parameter was modified."""

    def __init__(self, parameter_name: str) -> None:
        super().__init__('Attempted to modify read-only parameter', parameter_name)


class ParameterUninitializedException(ParameterException):
    """A statically typed parameter declared without a value was read."""

    def __init__(self, parameter_name: str) -> None:
        super().__init__(f"The parameter '{parameter_name}' is not initialized", parameter_name)


OnSetCallback = Callable[[list[Parameter]], SetParametersResult]
PreSetCallback = Callable[[list[Parameter]], list[Parameter]]
PostSetCallback = Callable[[list[Parameter]], None]
ParameterEventSink = Callable[[list[Parameter], list[Parameter], list[Parameter]], None]
# Relative tolerance of floating point range checks (rclpy's Node.PARAM_REL_TOL).
PARAM_REL_TOL = 1e-6


def check_integer_range(parameter: Parameter, allowed: IntegerRange) -> SetParametersResult:
    low = min(allowed.from_value, allowed.to_value)
    high = max(allowed.from_value, allowed.to_value)
    value = parameter.value
    if value in (low, high):
        return SetParametersResult(successful=True)
    if not low < value < high:
        reason = (
            f'Parameter {parameter.name} out of range. Min: {low}, Max: {high}, value: {value}'
        )
        return SetParametersResult(successful=False, reason=reason)
    if allowed.step != 0 and (value - low) % allowed.step != 0:
        reason = (
            f'The parameter value for {parameter.name} is not a valid step. '
            f'Min: {low}, max: {high}, value: {value}, step: {allowed.step}'
        )
        return SetParametersResult(successful=False, reason=reason)
    return SetParametersResult(successful=True)


def check_floating_point_range(
    parameter: Parameter, allowed: FloatingPointRange
) -> SetParametersResult:
    low = min(allowed.from_value, allowed.to_value)
    high = max(allowed.from_value, allowed.to_value)
    value = parameter.value
    if math.isclose(value, low, rel_tol=PARAM_REL_TOL) or math.isclose(
        value, high, rel_tol=PARAM_REL_TOL
    ):
        return SetParametersResult(successful=True)
    if not low < value < high:
        reason = f'Parameter {parameter.name} out of range Min: {low}, Max: {high}, value: {value}'
        return SetParametersResult(successful=False, reason=reason)
    if allowed.step != 0.0:
        steps = round((value - low) / allowed.step)
        if not math.isclose(low + steps * allowed.step, value, rel_tol=PARAM_REL_TOL):
            reason = (
                f'The parameter value for {parameter.name} is not close enough to a valid step. '
                f'Min: {low}, max: {high}, value: {value}, step: {allowed.step}'
            )
            return SetParametersResult(successful=False, reason=reason)
    return SetParametersResult(successful=True)
