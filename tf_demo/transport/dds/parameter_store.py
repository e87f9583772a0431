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
The parameter half of a standalone node (``rclpy.node.Node``'s parameter API, Jazzy).

``declare_parameter`` takes overrides from ``--ros-args`` (``-p``, ``--params-file``) and from
the node's constructor, values are statically typed unless the descriptor says
``dynamic_typing``, and on-set callbacks may reject a change with a reason.
"""

from __future__ import annotations

from collections.abc import Iterable
from collections.abc import Mapping
from collections.abc import Sequence
import threading
import warnings

from tf_demo.transport.dds.parameters import check_floating_point_range
from tf_demo.transport.dds.parameters import check_integer_range
from tf_demo.transport.dds.parameters import InvalidParameterException
from tf_demo.transport.dds.parameters import InvalidParameterTypeException
from tf_demo.transport.dds.parameters import InvalidParameterValueException
from tf_demo.transport.dds.parameters import OnSetCallback
from tf_demo.transport.dds.parameters import Parameter
from tf_demo.transport.dds.parameters import ParameterAlreadyDeclaredException
from tf_demo.transport.dds.parameters import ParameterDescriptor
from tf_demo.transport.dds.parameters import ParameterEventSink
from tf_demo.transport.dds.parameters import ParameterImmutableException
from tf_demo.transport.dds.parameters import ParameterNotDeclaredException
from tf_demo.transport.dds.parameters import ParameterType
from tf_demo.transport.dds.parameters import ParameterUninitializedException
from tf_demo.transport.dds.parameters import PostSetCallback
from tf_demo.transport.dds.parameters import PreSetCallback
from tf_demo.transport.dds.parameters import SetParametersResult

__all__ = ['ParameterStore']

_WRONG_TYPE_PREFIX = 'Wrong parameter type'


class ParameterStore:
    """
    The declared parameters of one node, with the semantics of ``rclpy.node.Node`` (Jazzy).

    Declaring takes the override when there is one, infers a static type from the default
    (``dynamic_typing`` lifts it), and runs the on-set callbacks, which may reject. Setting runs
    pre-set, on-set and post-set callbacks; a value of type NOT_SET undeclares a dynamically
    typed parameter. Not thread-unsafe: one lock guards every change.

    :param overrides: values that replace declared defaults, in precedence order already
        resolved (``--params-file`` and ``-p`` for this node, then the constructor's
        ``parameter_overrides``); see :func:`tf_demo.transport.ros_args.resolve_node_arguments`.
    :param allow_undeclared_parameters: as the rclpy Node argument of that name.
    :param automatically_declare_parameters_from_overrides: as the rclpy Node argument.
    """

    def __init__(
        self,
        overrides: Mapping[str, Parameter] | None = None,
        *,
        allow_undeclared_parameters: bool = False,
        automatically_declare_parameters_from_overrides: bool = False,
    ) -> None:
        self._lock = threading.RLock()
        self._overrides: dict[str, Parameter] = dict(overrides or {})
        self._parameters: dict[str, Parameter] = {}
        self._descriptors: dict[str, ParameterDescriptor] = {}
        self._pre_set_callbacks: list[PreSetCallback] = []
        self._on_set_callbacks: list[OnSetCallback] = []
        self._post_set_callbacks: list[PostSetCallback] = []
        self._allow_undeclared = allow_undeclared_parameters
        self.event_sink: ParameterEventSink | None = None
        """Told ``(new, changed, deleted)`` after every successful set (``/parameter_events``)."""
        if automatically_declare_parameters_from_overrides:
            # rclpy declares every override statically typed (type of its value), overrides
            # ignored (the value is the override already).
            self.declare_parameters(
                '',
                [
                    (name, parameter.value, ParameterDescriptor())
                    for name, parameter in self._overrides.items()
                ],
                ignore_override=True,
            )

    @property
    def overrides(self) -> dict[str, Parameter]:
        """A copy of the overrides this store was built with."""
        return dict(self._overrides)

    # -- declaring -----------------------------------------------------------------------------

    def declare_parameter(
        self,
        name: str,
        value: object = None,
        descriptor: ParameterDescriptor | None = None,
        ignore_override: bool = False,
    ) -> Parameter:
        """
        Declare one parameter and return it, with the override applied unless ignored.

        Only a name (no value, no descriptor) declares a dynamically typed parameter (rclpy
        warns that this is deprecated). ``value`` may be a :class:`Parameter.Type` to declare a
        statically typed parameter without a default (reading it before it is set raises
        ParameterUninitializedException).

        :raises ParameterAlreadyDeclaredException: when ``name`` is already declared.
        :raises InvalidParameterTypeException: when the override has another type.
        :raises InvalidParameterValueException: when an on-set callback or a range rejects it.
        :raises ValueError: for a static parameter with no type (rclpy's texts).
        """
        if value is None and descriptor is None:
            entry: tuple[object, ...] = (name,)
        else:
            entry = (name, value, descriptor if descriptor is not None else ParameterDescriptor())
        return self.declare_parameters('', [entry], ignore_override)[0]

    def declare_parameters(
        self,
        namespace: str,
        parameters: Sequence[Sequence[object]],
        ignore_override: bool = False,
    ) -> list[Parameter]:
        """Declare several parameters: tuples of ``(name[, value or type[, descriptor]])``."""
        parameter_list: list[Parameter] = []
        descriptors: dict[str, ParameterDescriptor] = {}
        for index, entry in enumerate(parameters):
            if not 1 <= len(entry) <= 3:  # rclpy checks only the length (a list works too)
                msg = (
                    f'Invalid parameter tuple length at index {index} in parameters list: '
                    f'{entry}; expecting length between 1 and 3'
                )
                raise TypeError(msg)
            name = entry[0]
            if not isinstance(name, str):
                msg = f'First element {name} at index {index} in parameters list is not a str.'
                raise TypeError(msg)
            if namespace:
                name = f'{namespace}.{name}'
            if not name:
                raise InvalidParameterException(name)
            second = entry[1] if len(entry) > 1 else None
            given = entry[2] if len(entry) > 2 else ParameterDescriptor()
            if not isinstance(given, ParameterDescriptor):
                msg = (
                    f'Third element {given} at index {index} in parameters list '
                    'is not a ParameterDescriptor.'
                )
                raise TypeError(msg)
            descriptor = ParameterDescriptor(**vars(given))
            value: object = None
            if len(entry) == 1:
                warnings.warn(
                    f"when declaring parameter named '{name}', "
                    'declaring a parameter only providing its name is deprecated. '
                    'You have to either:\n'
                    '\t- Pass a name and a default value different to "PARAMETER NOT SET"'
                    ' (and optionally a descriptor).\n'
                    '\t- Pass a name and a parameter type.\n'
                    '\t- Pass a name and a descriptor with `dynamic_typing=True',
                    stacklevel=3,
                )
                descriptor.dynamic_typing = True
            if isinstance(second, ParameterType):
                if second is ParameterType.NOT_SET:
                    msg = (
                        f'Cannot declare parameter {{{name}}} as statically typed of type NOT_SET'
                    )
                    raise ValueError(msg)
                if descriptor.dynamic_typing:
                    msg = (
                        f'When declaring parameter {{{name}}} passing a descriptor with'
                        '`dynamic_typing=True` is not allowed when the parameter type is provided'
                    )
                    raise ValueError(msg)
                descriptor.type = second.value
            else:
                value = second
                if not descriptor.dynamic_typing:
                    descriptor.type = ParameterType.from_parameter_value(value).value
                    if descriptor.type == ParameterType.NOT_SET.value:
                        msg = (
                            'Cannot declare a statically typed parameter with default value '
                            'of type PARAMETER_NOT_SET'
                        )
                        raise ValueError(msg)
            if not ignore_override and name in self._overrides:
                value = self._overrides[name].value
            parameter_list.append(Parameter(name, value=value))
            descriptors[name] = descriptor
        with self._lock:
            already = [p.name for p in parameter_list if p.name in self._parameters]
            if already:
                raise ParameterAlreadyDeclaredException(already)
            self._declare_common(parameter_list, descriptors)
            return [self._parameters[p.name] for p in parameter_list]

    def _declare_common(
        self, parameter_list: list[Parameter], descriptors: dict[str, ParameterDescriptor]
    ) -> None:
        for parameter in parameter_list:
            result = self._set_common([parameter], descriptors, allow_not_set_type=True)
            if not result.successful:
                if result.reason.startswith(_WRONG_TYPE_PREFIX):
                    expected = ParameterType(descriptors[parameter.name].type).name
                    raise InvalidParameterTypeException(parameter, expected)
                raise InvalidParameterValueException(
                    parameter.name, parameter.value, result.reason
                )

    def undeclare_parameter(self, name: str) -> None:
        """Remove a declared parameter; read-only parameters cannot be removed."""
        with self._lock:
            if name not in self._parameters:
                raise ParameterNotDeclaredException(name)
            if self._descriptors[name].read_only:
                raise ParameterImmutableException(name)
            del self._parameters[name]
            del self._descriptors[name]

    # -- reading -------------------------------------------------------------------------------

    def has_parameter(self, name: str) -> bool:
        """Whether ``name`` is declared."""
        return name in self._parameters

    def get_parameter(self, name: str) -> Parameter:
        """
        Return the declared parameter ``name``.

        :raises ParameterNotDeclaredException: when it is not declared (and undeclared
            parameters are not allowed).
        :raises ParameterUninitializedException: for a static parameter without a value yet.
        """
        with self._lock:
            parameter = self._parameters.get(name)
            if parameter is None:
                if self._allow_undeclared:
                    return Parameter(name, ParameterType.NOT_SET, None)
                raise ParameterNotDeclaredException(name)
            if parameter.type_ is ParameterType.NOT_SET and not (
                self._descriptors[name].dynamic_typing
            ):
                raise ParameterUninitializedException(name)
            return parameter

    def get_parameters(self, names: Iterable[str]) -> list[Parameter]:
        """
        Return the parameters named in ``names`` (see :meth:`get_parameter`).

        :raises TypeError: when a name is not a ``str`` (rclpy's text).
        """
        if not all(isinstance(name, str) for name in names):
            msg = 'All names must be instances of type str'
            raise TypeError(msg)
        return [self.get_parameter(name) for name in names]

    def get_parameter_or(self, name: str, alternative_value: Parameter | None = None) -> Parameter:
        """
        Return the parameter, else ``alternative_value``.

        As rclpy, the alternative also stands for a declared parameter without a value (type
        NOT_SET), statically or dynamically typed.
        """
        if alternative_value is None:
            alternative_value = Parameter(name, ParameterType.NOT_SET)
        with self._lock:
            parameter = self._parameters.get(name)
            if parameter is None or parameter.type_ is ParameterType.NOT_SET:
                return alternative_value
            return parameter

    def get_parameters_by_prefix(self, prefix: str) -> dict[str, Parameter]:
        """Return the parameters under ``prefix.`` keyed by the rest of their names."""
        start = f'{prefix}.' if prefix else ''
        with self._lock:
            return {
                name[len(start) :]: parameter
                for name, parameter in self._parameters.items()
                if name.startswith(start)
            }

    def describe_parameter(self, name: str) -> ParameterDescriptor:
        """Return the descriptor of a declared parameter."""
        with self._lock:
            descriptor = self._descriptors.get(name)
            if descriptor is not None:
                return descriptor
            if self._allow_undeclared:
                return ParameterDescriptor()
            raise ParameterNotDeclaredException(name)

    def names(self) -> list[str]:
        """Return the declared parameter names, sorted."""
        with self._lock:
            return sorted(self._parameters)

    # -- setting -------------------------------------------------------------------------------

    def set_parameters(self, parameter_list: Sequence[Parameter]) -> list[SetParametersResult]:
        """
        Set parameters one by one; each gets its own result (a rejection is not an error).

        :raises ParameterNotDeclaredException: at the first parameter that is not declared
            (the ones before it stay set, as in rclpy).
        """
        return [self._set_atomically([parameter]) for parameter in parameter_list]

    def set_parameters_atomically(
        self, parameter_list: Sequence[Parameter]
    ) -> SetParametersResult:
        """Set all parameters or none of them."""
        return self._set_atomically(list(parameter_list))

    def _set_atomically(self, parameter_list: list[Parameter]) -> SetParametersResult:
        with self._lock:
            if self._pre_set_callbacks:
                modified: list[Parameter] = []
                for callback in list(self._pre_set_callbacks):
                    modified.extend(callback(parameter_list))
                parameter_list = modified
                if not parameter_list:
                    return SetParametersResult(
                        successful=False,
                        reason='parameter list cannot be empty, this might be due to '
                        'pre_set_parameters_callback modifying the original parameters list.',
                    )
            if not all(isinstance(parameter, Parameter) for parameter in parameter_list):
                msg = f"parameter must be instance of type '{Parameter!r}'"
                raise TypeError(msg)
            undeclared = [p.name for p in parameter_list if p.name not in self._parameters]
            if undeclared and not self._allow_undeclared:
                raise ParameterNotDeclaredException(undeclared)
            return self._set_common(parameter_list, None, allow_not_set_type=False)

    def _set_common(
        self,
        parameter_list: list[Parameter],
        descriptors: dict[str, ParameterDescriptor] | None,
        *,
        allow_not_set_type: bool,
    ) -> SetParametersResult:
        with self._lock:
            known = descriptors if descriptors is not None else self._descriptors
            for parameter in parameter_list:
                descriptor = known.get(parameter.name)
                if descriptor is None:
                    continue
                result = self._apply_descriptor(
                    parameter, descriptor, check_read_only=descriptors is None
                )
                if not result.successful:
                    return result
            for callback in list(self._on_set_callbacks):
                # rclpy passes its own list and reads ``successful`` (AttributeError on None)
                result = callback(parameter_list)
                if not result.successful:
                    return result
            new: list[Parameter] = []
            changed: list[Parameter] = []
            deleted: list[Parameter] = []
            for parameter in parameter_list:
                if not allow_not_set_type and parameter.type_ is ParameterType.NOT_SET:
                    deleted.append(parameter)
                    self._parameters.pop(parameter.name, None)
                    self._descriptors.pop(parameter.name, None)
                    continue
                previous = self._parameters.get(parameter.name)
                if previous is None or previous.type_ is ParameterType.NOT_SET:
                    new.append(parameter)
                else:
                    changed.append(parameter)
                if descriptors is not None:
                    self._descriptors[parameter.name] = descriptors[parameter.name]
                elif parameter.name not in self._descriptors:
                    self._descriptors[parameter.name] = ParameterDescriptor(dynamic_typing=True)
                self._parameters[parameter.name] = parameter
            post_callbacks = list(self._post_set_callbacks)
            event_sink = self.event_sink
        if event_sink is not None:
            event_sink(new, changed, deleted)
        for post_callback in post_callbacks:
            post_callback(parameter_list)
        return SetParametersResult(successful=True)

    def _apply_descriptor(
        self, parameter: Parameter, descriptor: ParameterDescriptor, *, check_read_only: bool
    ) -> SetParametersResult:
        """Check a value against its descriptor: read-only, static type, ranges (rclpy's)."""
        descriptor.name = parameter.name
        if check_read_only and descriptor.read_only:
            reason = f'Trying to set a read-only parameter: {parameter.name}.'
            return SetParametersResult(successful=False, reason=reason)
        if descriptor.dynamic_typing:
            descriptor.type = parameter.type_.value
        elif parameter.name in self._parameters and parameter.type_ is ParameterType.NOT_SET:
            return SetParametersResult(
                successful=False, reason='Static parameter cannot be undeclared'
            )
        elif (
            parameter.type_ is not ParameterType.NOT_SET
            and parameter.type_.value != descriptor.type
        ):
            reason = (
                f"Wrong parameter type, expected '{ParameterType(descriptor.type)}' "
                f"got '{parameter.type_}'"
            )
            return SetParametersResult(successful=False, reason=reason)
        if parameter.type_ is ParameterType.INTEGER and descriptor.integer_range:
            return check_integer_range(parameter, descriptor.integer_range[0])
        if parameter.type_ is ParameterType.DOUBLE and descriptor.floating_point_range:
            return check_floating_point_range(parameter, descriptor.floating_point_range[0])
        return SetParametersResult(successful=True)

    # -- callbacks -----------------------------------------------------------------------------

    def add_pre_set_parameters_callback(self, callback: PreSetCallback) -> None:
        """Add a callback that may rewrite the list before validation (newest runs first)."""
        with self._lock:
            self._pre_set_callbacks.insert(0, callback)

    def add_on_set_parameters_callback(self, callback: OnSetCallback) -> None:
        """Add a validation callback; the newest one runs first, as in rclpy."""
        with self._lock:
            self._on_set_callbacks.insert(0, callback)

    def add_post_set_parameters_callback(self, callback: PostSetCallback) -> None:
        """Add a callback run after parameters were set (newest runs first)."""
        with self._lock:
            self._post_set_callbacks.insert(0, callback)

    def remove_pre_set_parameters_callback(self, callback: PreSetCallback) -> None:
        """Remove a pre-set callback (ValueError when absent, as list.remove)."""
        with self._lock:
            self._pre_set_callbacks.remove(callback)

    def remove_on_set_parameters_callback(self, callback: OnSetCallback) -> None:
        """Remove an on-set callback (ValueError when absent, as list.remove)."""
        with self._lock:
            self._on_set_callbacks.remove(callback)

    def remove_post_set_parameters_callback(self, callback: PostSetCallback) -> None:
        """Remove a post-set callback (ValueError when absent, as list.remove)."""
        with self._lock:
            self._post_set_callbacks.remove(callback)
