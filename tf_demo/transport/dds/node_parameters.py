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

"""A node's parameter methods (rclpy's names and signatures), delegated to a ``ParameterStore``."""

from __future__ import annotations

from collections.abc import Iterable
from collections.abc import Sequence

from tf_demo.transport.dds.parameter_store import ParameterStore
from tf_demo.transport.dds.parameters import OnSetCallback
from tf_demo.transport.dds.parameters import Parameter
from tf_demo.transport.dds.parameters import ParameterDescriptor
from tf_demo.transport.dds.parameters import PostSetCallback
from tf_demo.transport.dds.parameters import PreSetCallback
from tf_demo.transport.dds.parameters import SetParametersResult


class NodeParametersMixin:
    """The ``rclpy.node.Node`` parameter methods of :class:`~.node.DdsNode`."""

    _parameters: ParameterStore

    def declare_parameter(
        self,
        name: str,
        value: object = None,
        descriptor: ParameterDescriptor | None = None,
        ignore_override: bool = False,
    ) -> Parameter:
        """Declare one parameter (rclpy semantics; overrides from ``--ros-args`` apply)."""
        return self._parameters.declare_parameter(name, value, descriptor, ignore_override)

    def declare_parameters(
        self,
        namespace: str,
        parameters: Sequence[Sequence[object]],
        ignore_override: bool = False,
    ) -> list[Parameter]:
        """Declare several parameters: tuples of ``(name[, value[, descriptor]])``."""
        return self._parameters.declare_parameters(namespace, parameters, ignore_override)

    def undeclare_parameter(self, name: str) -> None:
        """Undeclare a parameter."""
        self._parameters.undeclare_parameter(name)

    def has_parameter(self, name: str) -> bool:
        """Return whether ``name`` is declared."""
        return self._parameters.has_parameter(name)

    def get_parameter(self, name: str) -> Parameter:
        """Return the ``Parameter`` named ``name``."""
        return self._parameters.get_parameter(name)

    def get_parameters(self, names: Iterable[str]) -> list[Parameter]:
        """Return several parameters."""
        return self._parameters.get_parameters(names)

    def get_parameter_or(self, name: str, alternative_value: Parameter | None = None) -> Parameter:
        """Return the parameter, or ``alternative_value`` when it is not declared."""
        return self._parameters.get_parameter_or(name, alternative_value)

    def get_parameters_by_prefix(self, prefix: str) -> dict[str, Parameter]:
        """Return the parameters under ``prefix.`` keyed by the rest of their names."""
        return self._parameters.get_parameters_by_prefix(prefix)

    def describe_parameter(self, name: str) -> ParameterDescriptor:
        """Return the descriptor of a parameter."""
        return self._parameters.describe_parameter(name)

    def set_parameters(self, parameter_list: Sequence[Parameter]) -> list[SetParametersResult]:
        """Set parameters one by one; returns one ``SetParametersResult`` each."""
        return self._parameters.set_parameters(parameter_list)

    def set_parameters_atomically(
        self, parameter_list: Sequence[Parameter]
    ) -> SetParametersResult:
        """Set parameters all or nothing."""
        return self._parameters.set_parameters_atomically(parameter_list)

    def add_on_set_parameters_callback(self, callback: OnSetCallback) -> None:
        """Register a callback that may reject parameter changes."""
        self._parameters.add_on_set_parameters_callback(callback)

    def remove_on_set_parameters_callback(self, callback: OnSetCallback) -> None:
        """Remove a callback registered with :meth:`add_on_set_parameters_callback`."""
        self._parameters.remove_on_set_parameters_callback(callback)

    def add_pre_set_parameters_callback(self, callback: PreSetCallback) -> None:
        """Register a callback that may modify a parameter list before it is set."""
        self._parameters.add_pre_set_parameters_callback(callback)

    def remove_pre_set_parameters_callback(self, callback: PreSetCallback) -> None:
        """Remove a callback registered with :meth:`add_pre_set_parameters_callback`."""
        self._parameters.remove_pre_set_parameters_callback(callback)

    def add_post_set_parameters_callback(self, callback: PostSetCallback) -> None:
        """Register a callback told about parameters after they were set."""
        self._parameters.add_post_set_parameters_callback(callback)

    def remove_post_set_parameters_callback(self, callback: PostSetCallback) -> None:
        """Remove a callback registered with :meth:`add_post_set_parameters_callback`."""
        self._parameters.remove_post_set_parameters_callback(callback)
