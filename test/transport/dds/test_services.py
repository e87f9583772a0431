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

"""Standalone services as rmw_cyclonedds maps them: types, calls, nested calls, bad input."""

from __future__ import annotations

from typing import Any

from conftest import STANDALONE_ONLY
import pytest

pytest.importorskip('cyclonedds', reason=STANDALONE_ONLY)

from dds_helpers import call
from dds_helpers import parameter_node
from dds_helpers import Spinner
from dds_helpers import wait_for
from tf_demo.msgs import geometry_msgs
from tf_demo.msgs import rcl_interfaces
from tf_demo.msgs import tf2_msgs
from tf_demo.transport import dds_backend
from tf_demo.transport.dds import service_wire
from tf_demo.transport.dds import wire as dds_wire

pytestmark = [pytest.mark.standalone, pytest.mark.dds]


#: Jazzy's hashes, from /opt/ros/jazzy/share/<pkg>/srv/*.json (rosidl_generator_type_description).
JAZZY_HASHES = {
    'rcl_interfaces/srv/GetParameters': (
        'RIHS01_bf9803d5c74cf989a5de3e0c2e99444599a627c7ff75f97b8c05b01003675cbc'
    ),
    'rcl_interfaces/srv/GetParameters_Request': (
        'RIHS01_135a9e1c3d7cebef792f6687d7ddf99949b21a0bd9a320d863a9110a3f5cf4d6'
    ),
    'rcl_interfaces/srv/GetParameters_Response': (
        'RIHS01_9fa773b46e39cc5d02db6224d8fd520bb9caeeffc2b27c96c1e59431baba9f2a'
    ),
    'rcl_interfaces/srv/DescribeParameters': (
        'RIHS01_845b484d71eb0673dae682f2e3ba3c4851a65a3dcfb97bddd82c5b57e91e4cff'
    ),
    'rcl_interfaces/srv/GetParameterTypes': (
        'RIHS01_da199c878688b3e530bdfe3ca8f74cb9fa0c303101e980a9e8f260e25e1c80ca'
    ),
    'rcl_interfaces/msg/ParameterDescriptor': (
        'RIHS01_52175dbfda6c51153101d33d2a9da05743f66f02d5ab2ca9ec4709b46b73d704'
    ),
    'rcl_interfaces/msg/ParameterValue': (
        'RIHS01_115fc089a387e23c7ecd3525c9189c379109119d6ab82e8dfbde0fdf6a7f9b68'
    ),
    'service_msgs/msg/ServiceEventInfo': (
        'RIHS01_41bcbbe07a75c9b52bc96bfd5c24d7f0fc0a08c0cb7921b3373c5732345a6f45'
    ),
}


@pytest.mark.parametrize(('typename', 'expected'), sorted(JAZZY_HASHES.items()))
def test_service_type_hashes_are_jazzys(typename: str, expected: str) -> None:
    """RIHS01 of services and their messages equal rosidl's (bounded sequences, events)."""
    from tf_demo.msgs.typehash import type_hash

    assert type_hash(typename) == expected


def test_service_types_have_rmw_names() -> None:
    """Request/response classes carry rmw_cyclonedds' srv DDS type names and hashes."""
    srv = rcl_interfaces.GetParameters
    assert srv.Request.__dds_typename__ == 'rcl_interfaces::srv::dds_::GetParameters_Request_'
    assert srv.Response.__dds_typename__ == 'rcl_interfaces::srv::dds_::GetParameters_Response_'
    assert srv.__typehash__ == JAZZY_HASHES['rcl_interfaces/srv/GetParameters']
    assert srv.Request.__typehash__ == JAZZY_HASHES['rcl_interfaces/srv/GetParameters_Request']
    assert (
        repr(srv.Request(names=['a'])) == "rcl_interfaces.srv.GetParameters_Request(names=['a'])"
    )
    assert tf2_msgs.FrameGraph.Request().structure_needs_at_least_one_member == 0


def test_a_client_calls_a_server_in_the_same_process(dds_world: None) -> None:
    """call_async/call, sequence numbers, service_is_ready and destroy, as rclpy's."""
    server_node = dds_backend.DdsNode('server')
    client_node = dds_backend.DdsNode('client', start_parameter_services=False)
    seen: list[list[str]] = []

    def answer(request: Any, response: Any) -> Any:
        seen.append(list(request.names))
        response.values = [
            rcl_interfaces.ParameterValue(type=4, string_value=name.upper())
            for name in request.names
        ]
        return response

    service = server_node.create_service(rcl_interfaces.GetParameters, 'shout', answer)
    client = client_node.create_client(rcl_interfaces.GetParameters, '/shout')
    assert service.srv_name == '/shout'
    assert service in server_node.services
    assert client in client_node.clients
    spinner = Spinner(server_node, client_node)
    try:
        first = call(client, rcl_interfaces.GetParameters.Request(names=['a', 'b']))
        assert [v.string_value for v in first.values] == ['A', 'B']
        futures = [
            client.call_async(rcl_interfaces.GetParameters.Request(names=[str(i)]))
            for i in range(5)
        ]
        assert wait_for(lambda: all(f.done() for f in futures))
        assert [f.result().values[0].string_value for f in futures] == [str(i) for i in range(5)]
        with pytest.raises(TypeError):
            client.call_async(rcl_interfaces.SetParameters.Request())  # type: ignore[arg-type]
        assert server_node.destroy_service(service)
        assert wait_for(lambda: not client.service_is_ready())
    finally:
        spinner.stop()
    assert seen[0] == ['a', 'b']


def test_a_callback_calls_a_service_on_a_multi_threaded_executor(dds_world: None) -> None:
    """rclpy's pattern: a timer in one group blocks on client.call; another thread answers."""
    node = dds_backend.DdsNode('worker', start_parameter_services=False)
    assert node.services == []
    reentrant = dds_backend.ReentrantCallbackGroup()

    def answer(request: Any, response: Any) -> Any:
        response.frame_yaml = 'answered'
        return response

    node.create_service(tf2_msgs.FrameGraph, 'frames', answer, callback_group=reentrant)
    client = node.create_client(tf2_msgs.FrameGraph, 'frames', callback_group=reentrant)
    results: list[Any] = []

    def tick() -> None:
        if not results and client.wait_for_service(timeout_sec=20):
            results.append(client.call(tf2_msgs.FrameGraph.Request(), timeout_sec=20))

    node.create_timer(0.05, tick)
    spinner = Spinner(node, executor=dds_backend.MultiThreadedExecutor(num_threads=3))
    try:
        assert wait_for(lambda: results, timeout=40)
    finally:
        spinner.stop()
    assert results[0] is not None
    assert results[0].frame_yaml == 'answered'


def test_garbage_requests_do_not_stop_the_node(dds_world: None) -> None:
    """Malformed request samples are logged and dropped; the service keeps answering."""
    node = parameter_node()
    caller = dds_backend.DdsNode('caller', start_parameter_services=False)
    client = caller.create_client(rcl_interfaces.GetParameters, '/params/get_parameters')
    participant = dds_wire.get_participant()
    raw = participant.create_writer(
        service_wire.request_topic('/params/get_parameters'),
        rcl_interfaces.GetParameters.Request.__dds_typename__,
        dds_wire.EndpointQos(depth=10),
        b'clientid=garbage;',
    )
    spinner = Spinner(node, caller)
    try:
        assert client.wait_for_service(timeout_sec=20)
        assert wait_for(lambda: raw.matched_count() >= 1)
        for junk in (
            b'\x00\x01\x00\x00\x01',  # no request header
            b'\x00\x01\x00\x00' + bytes(16),  # no body
            b'\x00\x01\x00\x00' + bytes(16) + b'\xff\xff\xff\x7f',  # absurd count
            b'\x00\x01\x00\x00' + bytes(16) + b'\x01\x00\x00\x00\x05\x00\x00\x00abc',
        ):
            raw.write(junk)
        response = call(client, rcl_interfaces.GetParameters.Request(names=['radius']))
        assert response.values[0].double_value == 1.5
    finally:
        spinner.stop()
        raw.close()


def test_a_buffer_given_a_node_offers_tf2_frames(dds_world: None) -> None:
    """Buffer(node=...) answers tf2_msgs/srv/FrameGraph with all_frames_as_yaml, as tf2_ros."""
    from tf_demo.ros import Buffer

    node = dds_backend.DdsNode('buffer_node', start_parameter_services=False)
    buffer = Buffer(node=node)
    transform = geometry_msgs.TransformStamped()
    transform.header.frame_id = 'world'
    transform.child_frame_id = 'robot'
    transform.transform.rotation.w = 1.0
    buffer.set_transform_static(transform, 'test_authority')
    caller = dds_backend.DdsNode('caller', start_parameter_services=False)
    client = caller.create_client(tf2_msgs.FrameGraph, '/tf2_frames')
    spinner = Spinner(node, caller)
    try:
        response = call(client, tf2_msgs.FrameGraph.Request())
    finally:
        spinner.stop()
    assert response.frame_yaml == buffer.all_frames_as_yaml()
    assert 'robot:' in response.frame_yaml
    assert "parent: 'world'" in response.frame_yaml
