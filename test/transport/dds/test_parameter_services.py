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

"""A standalone node's parameter services and /parameter_events, as rclpy provides them."""

from __future__ import annotations

import math
from typing import Any

from conftest import PARAMETER_SERVICES
from conftest import STANDALONE_ONLY
import pytest

pytest.importorskip('cyclonedds', reason=STANDALONE_ONLY)

from dds_helpers import call
from dds_helpers import parameter_node
from dds_helpers import Spinner
from dds_helpers import wait_for
from tf_demo.msgs import rcl_interfaces
from tf_demo.msgs import tf2_msgs
from tf_demo.transport import dds_backend
from tf_demo.transport.qos import qos_profile_parameter_events

pytestmark = [pytest.mark.standalone, pytest.mark.dds]


def test_parameter_services_follow_rclpy(dds_world: None) -> None:
    """list/get/get_types/describe/set/set_atomically on a standalone node's parameters."""
    node = parameter_node()
    caller = dds_backend.DdsNode('caller', start_parameter_services=False)
    names = sorted(s.srv_name for s in node.services)
    assert names == [f'/params/{suffix}' for suffix in PARAMETER_SERVICES]
    events: list[Any] = []
    caller.create_subscription(
        rcl_interfaces.ParameterEvent,
        '/parameter_events',
        events.append,
        qos_profile_parameter_events,
    )
    clients = {
        name: caller.create_client(getattr(rcl_interfaces, srv), f'/params/{name}')
        for name, srv in (
            ('list_parameters', 'ListParameters'),
            ('get_parameters', 'GetParameters'),
            ('get_parameter_types', 'GetParameterTypes'),
            ('describe_parameters', 'DescribeParameters'),
            ('set_parameters', 'SetParameters'),
            ('set_parameters_atomically', 'SetParametersAtomically'),
        )
    }
    spinner = Spinner(node, caller)
    try:
        listed = call(clients['list_parameters'], rcl_interfaces.ListParameters.Request())
        assert {'radius', 'frame', 'rate', 'nested.a', 'use_sim_time'} <= set(listed.result.names)
        assert listed.result.prefixes == ['nested']
        shallow = call(clients['list_parameters'], rcl_interfaces.ListParameters.Request(depth=1))
        assert 'nested.a' not in shallow.result.names

        got = call(
            clients['get_parameters'],
            rcl_interfaces.GetParameters.Request(names=['radius', 'frame']),
        )
        assert [(v.type, v.double_value, v.string_value) for v in got.values] == [
            (3, 1.5, ''),
            (4, 0.0, 'odom'),
        ]
        missing = call(
            clients['get_parameters'],
            rcl_interfaces.GetParameters.Request(names=['radius', 'nope']),
        )
        assert list(missing.values) == []  # rclpy: one unknown name empties the answer

        types = call(
            clients['get_parameter_types'],
            rcl_interfaces.GetParameterTypes.Request(names=['radius', 'rate', 'nested.a']),
        )
        assert list(types.types) == [3, 2, 1]

        described = call(
            clients['describe_parameters'],
            rcl_interfaces.DescribeParameters.Request(names=['rate']),
        )
        [descriptor] = described.descriptors
        assert (descriptor.name, descriptor.type, descriptor.description) == ('rate', 2, 'Hz')
        assert descriptor.read_only

        value = rcl_interfaces.ParameterValue(type=3, double_value=2.5)
        set_reply = call(
            clients['set_parameters'],
            rcl_interfaces.SetParameters.Request(
                parameters=[
                    rcl_interfaces.Parameter(name='radius', value=value),
                    rcl_interfaces.Parameter(
                        name='radius',
                        value=rcl_interfaces.ParameterValue(type=3, double_value=-1.0),
                    ),
                    rcl_interfaces.Parameter(
                        name='rate', value=rcl_interfaces.ParameterValue(type=2, integer_value=5)
                    ),
                    rcl_interfaces.Parameter(name='undeclared', value=value),
                    rcl_interfaces.Parameter(
                        name='frame', value=rcl_interfaces.ParameterValue(type=2, integer_value=1)
                    ),
                    rcl_interfaces.Parameter(
                        name='radius', value=rcl_interfaces.ParameterValue(type=42)
                    ),
                ]
            ),
        )
        assert [r.successful for r in set_reply.results] == [
            True,
            False,
            False,
            False,
            False,
            False,
        ]
        assert set_reply.results[1].reason == 'radius must be >= 0'
        assert 'read-only' in set_reply.results[2].reason
        assert node.get_parameter('radius').value == 2.5

        atomic = call(
            clients['set_parameters_atomically'],
            rcl_interfaces.SetParametersAtomically.Request(
                parameters=[
                    rcl_interfaces.Parameter(
                        name='frame',
                        value=rcl_interfaces.ParameterValue(type=4, string_value='map'),
                    ),
                    rcl_interfaces.Parameter(
                        name='radius',
                        value=rcl_interfaces.ParameterValue(type=3, double_value=-2.0),
                    ),
                ]
            ),
        )
        assert not atomic.result.successful
        assert node.get_parameter('frame').value == 'odom'

        assert wait_for(lambda: any(e.changed_parameters for e in events))
        [event] = [e for e in events if e.changed_parameters]
        assert event.node == '/params'
        assert [(p.name, p.value.double_value) for p in event.changed_parameters] == [
            ('radius', 2.5)
        ]
        assert event.stamp.sec > 0
        node.declare_parameter('later', 'x')
        assert wait_for(
            lambda: any([p.name for p in e.new_parameters] == ['later'] for e in events)
        )
    finally:
        spinner.stop()


def test_parameters_of_a_standalone_process(dds_world: None, spawn: Any) -> None:
    """Another process's dynamic_tf_pub answers list/get/set; the new radius takes effect."""
    spawn.start('dynamic_tf_pub')
    caller = dds_backend.DdsNode('caller', start_parameter_services=False)
    lister = caller.create_client(rcl_interfaces.ListParameters, '/dynamic_tf_pub/list_parameters')
    setter = caller.create_client(rcl_interfaces.SetParameters, '/dynamic_tf_pub/set_parameters')
    getter = caller.create_client(rcl_interfaces.GetParameters, '/dynamic_tf_pub/get_parameters')
    radii: list[float] = []

    def on_tf(message: Any) -> None:
        for transform in message.transforms:
            translation = transform.transform.translation
            radii.append(math.hypot(translation.x, translation.y))

    caller.create_subscription(tf2_msgs.TFMessage, '/tf', on_tf, 100)
    spinner = Spinner(caller)
    try:
        listed = call(lister, rcl_interfaces.ListParameters.Request(), timeout=60)
        assert 'radius' in listed.result.names
        value = rcl_interfaces.ParameterValue(type=3, double_value=3.25)
        reply = call(
            setter,
            rcl_interfaces.SetParameters.Request(
                parameters=[rcl_interfaces.Parameter(name='radius', value=value)]
            ),
        )
        assert reply.results[0].successful, reply.results[0].reason
        got = call(getter, rcl_interfaces.GetParameters.Request(names=['radius']))
        assert got.values[0].double_value == 3.25
        count = len(radii)
        assert wait_for(lambda: any(abs(r - 3.25) < 1e-9 for r in radii[count:]))
    finally:
        spinner.stop()
