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
the package takes a node. It also names rclpy's time, QoS, parameter and logging objects
as :mod:`tf_demo.transport.clock`, ``qos``, ``parameters`` and ``logging`` name the standalone
ones; those facades import them from here in the rclpy world. This is the only module (with
``messages.py``) that imports rclpy.
"""

from __future__ import annotations

from typing import Any

import rcl_interfaces.msg
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
from tf_demo.transport.ros_args import explain_rcl_error
from tf_demo.transport.ros_args import RosArgsError

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


# rclpy's objects under the names the facades (``clock``, ``qos``, ``parameters``,
# ``logging``) give the standalone ones.
Clock = rclpy.clock.Clock
ClockChange = rclpy.clock.ClockChange
ClockType = rclpy.clock.ClockType
JumpHandle = rclpy.clock.JumpHandle
JumpThreshold = rclpy.clock.JumpThreshold
ROSClock = rclpy.clock.ROSClock
TimeJump = rclpy.clock.TimeJump
Time = rclpy.time.Time
Duration = rclpy.duration.Duration
Infinite = rclpy.duration.Infinite
TimeSource = rclpy.time_source.TimeSource

DurabilityPolicy = rclpy.qos.DurabilityPolicy
HistoryPolicy = rclpy.qos.HistoryPolicy
InvalidQoSProfileException = rclpy.qos.InvalidQoSProfileException
LivelinessPolicy = rclpy.qos.LivelinessPolicy
QoSDurabilityPolicy = rclpy.qos.QoSDurabilityPolicy
QoSHistoryPolicy = rclpy.qos.QoSHistoryPolicy
QoSLivelinessPolicy = rclpy.qos.QoSLivelinessPolicy
QoSPresetProfiles = rclpy.qos.QoSPresetProfiles
QoSProfile = rclpy.qos.QoSProfile
QoSReliabilityPolicy = rclpy.qos.QoSReliabilityPolicy
ReliabilityPolicy = rclpy.qos.ReliabilityPolicy
qos_profile_action_status_default = rclpy.qos.qos_profile_action_status_default
qos_profile_best_available = rclpy.qos.qos_profile_best_available
qos_profile_default = rclpy.qos.qos_profile_default
qos_profile_parameter_events = rclpy.qos.qos_profile_parameter_events
qos_profile_parameters = rclpy.qos.qos_profile_parameters
qos_profile_sensor_data = rclpy.qos.qos_profile_sensor_data
qos_profile_services_default = rclpy.qos.qos_profile_services_default
qos_profile_system_default = rclpy.qos.qos_profile_system_default
qos_profile_unknown = rclpy.qos.qos_profile_unknown

InvalidParameterException = rclpy.exceptions.InvalidParameterException
InvalidParameterTypeException = rclpy.exceptions.InvalidParameterTypeException
InvalidParameterValueException = rclpy.exceptions.InvalidParameterValueException
ParameterAlreadyDeclaredException = rclpy.exceptions.ParameterAlreadyDeclaredException
ParameterException = rclpy.exceptions.ParameterException
ParameterImmutableException = rclpy.exceptions.ParameterImmutableException
ParameterNotDeclaredException = rclpy.exceptions.ParameterNotDeclaredException
ParameterUninitializedException = rclpy.exceptions.ParameterUninitializedException
Parameter = rclpy.parameter.Parameter
ParameterType = rclpy.parameter.Parameter.Type
FloatingPointRange = rcl_interfaces.msg.FloatingPointRange
IntegerRange = rcl_interfaces.msg.IntegerRange
ParameterDescriptor = rcl_interfaces.msg.ParameterDescriptor
SetParametersResult = rcl_interfaces.msg.SetParametersResult

LoggingSeverity = rclpy.logging.LoggingSeverity
get_logger = rclpy.logging.get_logger
get_logger_effective_level = rclpy.logging.get_logger_effective_level
get_logger_level = rclpy.logging.get_logger_level
get_logging_severity_from_string = rclpy.logging.get_logging_severity_from_string
set_logger_level = rclpy.logging.set_logger_level
