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
The standalone world's node: the subset of ``rclpy.node.Node`` the package uses, over DDS.

:class:`DdsNode` has rclpy's method names and signatures for publishers, subscriptions, timers,
clock, parameters (the node-API's
:class:`~tf_demo.transport.dds.parameter_store.ParameterStore`), logger and graph counts. Names
are expanded and validated as rcl does (relative names get the node's namespace, ``~`` is the
node's fully qualified name) and remapped by ``--ros-args -r``.

Executors are waitset based and schedule as rclpy's: the spinning thread waits on the read
conditions of the subscriptions its nodes may run now, a guard condition and the earliest timer
deadline; everything that wait found ready (node by node: timers, then subscriptions) is handed
out, one entity per ``spin_once``, before the next wait, so an always-overdue timer cannot starve
a subscription. :class:`SingleThreadedExecutor` runs callbacks in the spinning thread,
:class:`MultiThreadedExecutor` in a thread pool, honouring callback groups. Each process also
publishes its nodes on ``ros_discovery_info`` so that ``ros2 node list`` shows them.
"""

from __future__ import annotations

from tf_demo.transport.dds.callback_groups import CallbackGroup
from tf_demo.transport.dds.callback_groups import MutuallyExclusiveCallbackGroup
from tf_demo.transport.dds.callback_groups import ReentrantCallbackGroup
from tf_demo.transport.dds.context import init
from tf_demo.transport.dds.context import ok
from tf_demo.transport.dds.context import shutdown
from tf_demo.transport.dds.context import try_shutdown
from tf_demo.transport.dds.endpoints import DdsPublisher
from tf_demo.transport.dds.endpoints import DdsSubscription
from tf_demo.transport.dds.executors import DdsExecutor
from tf_demo.transport.dds.executors import ExternalShutdownException
from tf_demo.transport.dds.executors import SingleThreadedExecutor
from tf_demo.transport.dds.multi_threaded_executor import MultiThreadedExecutor
from tf_demo.transport.dds.names import expand_topic_name
from tf_demo.transport.dds.names import InvalidNameError
from tf_demo.transport.dds.names import validate_namespace
from tf_demo.transport.dds.names import validate_node_name
from tf_demo.transport.dds.node import create_node
from tf_demo.transport.dds.node import DdsNode
from tf_demo.transport.dds.node import Node
from tf_demo.transport.dds.spin import serve_subscriptions
from tf_demo.transport.dds.spin import spin
from tf_demo.transport.dds.spin import spin_once
from tf_demo.transport.dds.spin import spin_until_future_complete
from tf_demo.transport.dds.tasks import DdsTask
from tf_demo.transport.dds.timers import DdsTimer

__all__ = [
    'CallbackGroup',
    'DdsExecutor',
    'DdsNode',
    'DdsPublisher',
    'DdsSubscription',
    'DdsTask',
    'DdsTimer',
    'ExternalShutdownException',
    'InvalidNameError',
    'MultiThreadedExecutor',
    'MutuallyExclusiveCallbackGroup',
    'Node',
    'ReentrantCallbackGroup',
    'SingleThreadedExecutor',
    'create_node',
    'expand_topic_name',
    'init',
    'ok',
    'serve_subscriptions',
    'shutdown',
    'spin',
    'spin_once',
    'spin_until_future_complete',
    'try_shutdown',
    'validate_namespace',
    'validate_node_name',
]
