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
The rclpy world: a thin pass-through to rclpy's documented API.

Nothing is wrapped: ``Node`` is ``rclpy.node.Node``, so a user's own rclpy node works wherever
the package takes a node. The ``*_exports()`` functions hand rclpy's objects to
:mod:`tf_demo.transport.qos`, ``clock``, ``parameters`` and ``logging`` under the names those
modules define for the standalone world. This is the only module (with ``messages.py``) that
imports rclpy.
"""

from __future__ import annotations

from typing import Any

import rclpy
import rclpy.callback_groups
import rclpy.clock
import rclpy.duration
import rclpy.exceptions
import rclpy.executors
import rclpy.impl.implementation_singleton
import rclpy.logging
import rclpy.node
import rclpy.parameter
import rclpy.qos
import rclpy.time
import rclpy.time_source
import rclpy.utilities

shutdown = rclpy.shutdown
try_shutdown = rclpy.utilities.try_shutdown
ok = rclpy.utilities.ok
spin = rclpy.spin
spin_once = rclpy.spin_once
create_node = rclpy.create_node
Node = rclpy.node.Node
Executor = rclpy.executors.Executor
SingleThreadedExecutor = rclpy.executors.SingleThreadedExecutor
MultiThreadedExecutor = rclpy.executors.MultiThreadedExecutor
ExternalShutdownException = rclpy.executors.ExternalShutdownException
spin_until_future_complete = rclpy.spin_until_future_complete
remove_ros_args = rclpy.utilities.remove_ros_args
_rclpy_impl = rclpy.impl.implementation_singleton.rclpy_implementation


def init(*, args: list[str] | None = None, **kwargs: Any) -> None:
    """
    Run ``rclpy.init``; rcl's verdict on the ``--ros-args`` is the one that counts.

    rcl parses the arguments here (once). Its refusal becomes a :class:`RosArgsError` with
    rcl's text on one line, shortened and with advice (``explain_rcl_error``), so ``run_node``
    reports it as it reports any bad argument; other failures are rclpy's own.
    """
    # Imported here: ros_args imports logging, which imports this module.
    from tf_demo.transport.ros_args import explain_rcl_error
    from tf_demo.transport.ros_args import RosArgsError

    try:
        rclpy.init(args=args, **kwargs)
    except _rclpy_impl.UnknownROSArgsError as error:
        msg = f'Found unknown ROS arguments: {error}'
        raise RosArgsError(msg) from None
    except _rclpy_impl.RCLError as error:
        text = str(error)
        if "Couldn't parse" not in text:
            raise
        raise RosArgsError(explain_rcl_error(text, args or [])) from None


CallbackGroup = rclpy.callback_groups.CallbackGroup
MutuallyExclusiveCallbackGroup = rclpy.callback_groups.MutuallyExclusiveCallbackGroup
ReentrantCallbackGroup = rclpy.callback_groups.ReentrantCallbackGroup


def _public(module: Any, names: list[str]) -> dict[str, Any]:
    return {name: getattr(module, name) for name in names if hasattr(module, name)}


def qos_exports() -> dict[str, Any]:
    """Return rclpy's QoS objects under the names of :mod:`tf_demo.transport.qos`."""
    exports = _public(
        rclpy.qos,
        [
            'DurabilityPolicy', 'HistoryPolicy', 'InvalidQoSProfileException',
            'LivelinessPolicy', 'QoSDurabilityPolicy', 'QoSHistoryPolicy',
            'QoSLivelinessPolicy', 'QoSPresetProfiles', 'QoSProfile', 'QoSReliabilityPolicy',
            'ReliabilityPolicy', 'qos_profile_action_status_default', 'qos_profile_best_available',
            'qos_profile_default',
            'qos_profile_parameter_events', 'qos_profile_parameters',
            'qos_profile_rosout_default', 'qos_profile_sensor_data',
            'qos_profile_services_default', 'qos_profile_system_default', 'qos_profile_unknown',
        ],
    )  # fmt: skip
    return exports


def clock_exports() -> dict[str, Any]:
    """Return rclpy's time and clock objects under the names of ``clock``."""
    exports = _public(
        rclpy.clock,
        ['Clock', 'ClockChange', 'ClockType', 'JumpHandle', 'JumpThreshold', 'ROSClock',
         'TimeJump'],
    )  # fmt: skip
    exports['Time'] = rclpy.time.Time
    exports['Duration'] = rclpy.duration.Duration
    exports.update(_public(rclpy.duration, ['Infinite']))
    exports['TimeSource'] = rclpy.time_source.TimeSource
    return exports


def parameter_exports() -> dict[str, Any]:
    """Return rclpy's parameter objects under the names of ``parameters``."""
    from rcl_interfaces.msg import FloatingPointRange
    from rcl_interfaces.msg import IntegerRange
    from rcl_interfaces.msg import ParameterDescriptor
    from rcl_interfaces.msg import SetParametersResult

    exports = _public(
        rclpy.exceptions,
        ['InvalidParameterException', 'InvalidParameterTypeException',
         'InvalidParameterValueException', 'ParameterAlreadyDeclaredException',
         'ParameterException', 'ParameterImmutableException', 'ParameterNotDeclaredException',
         'ParameterUninitializedException'],
    )  # fmt: skip
    exports['Parameter'] = rclpy.parameter.Parameter
    exports['ParameterType'] = rclpy.parameter.Parameter.Type
    exports['ParameterDescriptor'] = ParameterDescriptor
    exports['FloatingPointRange'] = FloatingPointRange
    exports['IntegerRange'] = IntegerRange
    exports['SetParametersResult'] = SetParametersResult
    return exports


def logging_exports() -> dict[str, Any]:
    """Return rclpy's logging functions under the names of ``logging``."""
    return _public(
        rclpy.logging,
        ['LoggingSeverity', 'get_logger', 'get_logger_effective_level', 'get_logger_level',
         'get_logging_severity_from_string', 'set_logger_level'],
    )  # fmt: skip
