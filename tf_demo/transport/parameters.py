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
Parameters: rclpy's own classes in the rclpy world, else the standalone ones.

The world is chosen once, when the module is first imported; the type checker sees the
standalone classes (:mod:`tf_demo.transport.dds.parameters`). The standalone node's own
parameter machinery lives in :mod:`tf_demo.transport.dds.parameter_store`.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from tf_demo.transport.backend import rclpy_world

if TYPE_CHECKING or not rclpy_world():
    from tf_demo.transport.dds.parameters import FloatingPointRange
    from tf_demo.transport.dds.parameters import IntegerRange
    from tf_demo.transport.dds.parameters import InvalidParameterException
    from tf_demo.transport.dds.parameters import InvalidParameterTypeException
    from tf_demo.transport.dds.parameters import InvalidParameterValueException
    from tf_demo.transport.dds.parameters import Parameter
    from tf_demo.transport.dds.parameters import ParameterAlreadyDeclaredException
    from tf_demo.transport.dds.parameters import ParameterDescriptor
    from tf_demo.transport.dds.parameters import ParameterException
    from tf_demo.transport.dds.parameters import ParameterImmutableException
    from tf_demo.transport.dds.parameters import ParameterNotDeclaredException
    from tf_demo.transport.dds.parameters import ParameterType
    from tf_demo.transport.dds.parameters import ParameterUninitializedException
    from tf_demo.transport.dds.parameters import SetParametersResult
else:  # pragma: no cover - needs a ROS 2 installation
    from tf_demo.transport.rclpy_backend import FloatingPointRange
    from tf_demo.transport.rclpy_backend import IntegerRange
    from tf_demo.transport.rclpy_backend import InvalidParameterException
    from tf_demo.transport.rclpy_backend import InvalidParameterTypeException
    from tf_demo.transport.rclpy_backend import InvalidParameterValueException
    from tf_demo.transport.rclpy_backend import Parameter
    from tf_demo.transport.rclpy_backend import ParameterAlreadyDeclaredException
    from tf_demo.transport.rclpy_backend import ParameterDescriptor
    from tf_demo.transport.rclpy_backend import ParameterException
    from tf_demo.transport.rclpy_backend import ParameterImmutableException
    from tf_demo.transport.rclpy_backend import ParameterNotDeclaredException
    from tf_demo.transport.rclpy_backend import ParameterType
    from tf_demo.transport.rclpy_backend import ParameterUninitializedException
    from tf_demo.transport.rclpy_backend import SetParametersResult

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
