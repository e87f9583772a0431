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
The standalone world's ``rcl_interfaces`` messages and services (rclpy-compatible).

The messages (``rcl_interfaces/msg``) and, as :class:`~tf_demo.msgs._message.Service` types
with ``Request``/``Response``/``Event``, the parameter services (``rcl_interfaces/srv``). The
fields come from :data:`tf_demo.msgs._schema.DEFINITIONS` and ``SERVICE_DEFINITIONS``.
"""

from __future__ import annotations

from tf_demo.msgs._message import Message
from tf_demo.msgs._message import Service
import tf_demo.msgs.builtin_interfaces
import tf_demo.msgs.service_msgs  # noqa: F401 - the services' event messages nest it

__all__ = [
    'DescribeParameters',
    'FloatingPointRange',
    'GetParameterTypes',
    'GetParameters',
    'IntegerRange',
    'ListParameters',
    'ListParametersResult',
    'Log',
    'Parameter',
    'ParameterDescriptor',
    'ParameterEvent',
    'ParameterType',
    'ParameterValue',
    'SetParameters',
    'SetParametersAtomically',
    'SetParametersResult',
]


class ParameterType(Message):
    """rcl_interfaces/msg/ParameterType (constants only)."""

    PARAMETER_NOT_SET = 0
    PARAMETER_BOOL = 1
    PARAMETER_INTEGER = 2
    PARAMETER_DOUBLE = 3
    PARAMETER_STRING = 4
    PARAMETER_BYTE_ARRAY = 5
    PARAMETER_BOOL_ARRAY = 6
    PARAMETER_INTEGER_ARRAY = 7
    PARAMETER_DOUBLE_ARRAY = 8
    PARAMETER_STRING_ARRAY = 9


class ParameterValue(Message):
    """rcl_interfaces/msg/ParameterValue."""


class Parameter(Message):
    """rcl_interfaces/msg/Parameter."""


class FloatingPointRange(Message):
    """rcl_interfaces/msg/FloatingPointRange."""


class IntegerRange(Message):
    """rcl_interfaces/msg/IntegerRange."""


class ParameterDescriptor(Message):
    """rcl_interfaces/msg/ParameterDescriptor."""


class SetParametersResult(Message):
    """rcl_interfaces/msg/SetParametersResult."""


class ListParametersResult(Message):
    """rcl_interfaces/msg/ListParametersResult."""


class ParameterEvent(Message):
    """rcl_interfaces/msg/ParameterEvent."""


class Log(Message):
    """rcl_interfaces/msg/Log."""

    DEBUG = 10
    INFO = 20
    WARN = 30
    ERROR = 40
    FATAL = 50


class ListParameters(Service):
    """rcl_interfaces/srv/ListParameters."""

    DEPTH_RECURSIVE = 0


class GetParameters(Service):
    """rcl_interfaces/srv/GetParameters."""


class SetParameters(Service):
    """rcl_interfaces/srv/SetParameters."""


class SetParametersAtomically(Service):
    """rcl_interfaces/srv/SetParametersAtomically."""


class DescribeParameters(Service):
    """rcl_interfaces/srv/DescribeParameters."""


class GetParameterTypes(Service):
    """rcl_interfaces/srv/GetParameterTypes."""
