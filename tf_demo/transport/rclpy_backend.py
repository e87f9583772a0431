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
the package takes a node. These are the runtime functions :mod:`tf_demo.transport` forwards to
the world's backend (``init`` turns rcl's refusal of the ``--ros-args`` into RosArgsError); the
world's classes come from the facades (:mod:`tf_demo.transport.clock`, ``qos``, ``parameters``,
``logging``, ``node``, ``executors``, ``callback_groups``), which import rclpy's own modules in
the rclpy world.
"""

from __future__ import annotations

from typing import Any

import rclpy
import rclpy.executors
import rclpy.impl.implementation_singleton
import rclpy.node
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
SingleThreadedExecutor = rclpy.executors.SingleThreadedExecutor
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
