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

"""Standalone services (rmw_cyclonedds' mapping), parameter services, events and /rosout."""

from __future__ import annotations

from collections.abc import Callable
from collections.abc import Iterator
import json
import math
from pathlib import Path
import struct
import threading
import time
from typing import Any

from conftest import PARAMETER_SERVICES
from conftest import STANDALONE_ONLY
import pytest

pytest.importorskip('cyclonedds', reason=STANDALONE_ONLY)

from tf_demo.msgs import cdr
from tf_demo.msgs import geometry_msgs
from tf_demo.msgs import rcl_interfaces
from tf_demo.msgs import tf2_msgs
from tf_demo.transport import dds_backend
from tf_demo.transport.dds import service_wire
from tf_demo.transport.dds import wire as dds_wire
from tf_demo.transport.dds.qos import qos_profile_rosout_default
from tf_demo.transport.parameters import Parameter
from tf_demo.transport.parameters import ParameterDescriptor
from tf_demo.transport.parameters import SetParametersResult
from tf_demo.transport.qos import qos_profile_parameter_events

pytestmark = [pytest.mark.standalone, pytest.mark.dds]

GOLDEN = Path(__file__).resolve().parent.parent / 'data' / 'golden' / 'services'

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


# -- wire format (pure) -------------------------------------------------------------------------


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


def test_request_sample_layout_is_rmw_cyclonedds() -> None:
    """Encapsulation, then client id and sequence number (8 + 8 bytes), then the CDR body."""
    request = rcl_interfaces.GetParameters.Request(names=['radius'])
    header = service_wire.RequestHeader(0x0102030405060708, 7)
    sample = service_wire.encode_sample(header, request)
    body = cdr.serialize(request)
    assert sample[:4] == b'\x00\x01\x00\x00'
    assert sample[4:20] == struct.pack('<Qq', 0x0102030405060708, 7)
    assert sample[20:] == body[4:]
    decoded_header, decoded = service_wire.decode_sample(
        rcl_interfaces.GetParameters.Request, sample
    )
    assert decoded_header == header
    assert decoded == request


def test_big_endian_samples_decode() -> None:
    """The header follows the sample's byte order (byte 1 of the encapsulation)."""
    big = b'\x00\x00\x00\x00' + struct.pack('>Qq', 5, 9) + struct.pack('>I', 0)
    header, request = service_wire.decode_sample(rcl_interfaces.GetParameters.Request, big)
    assert (header.guid, header.sequence_number) == (5, 9)
    assert list(request.names) == []


@pytest.mark.parametrize('data', [b'', b'\x00\x01\x00\x00', b'\x00\x01\x00\x00' + bytes(15)])
def test_short_or_garbage_samples_raise_cdr_error(data: bytes) -> None:
    """Samples without a full header or body raise CdrError (dropped by the node)."""
    with pytest.raises(cdr.CdrError):
        service_wire.decode_sample(rcl_interfaces.GetParameters.Request, data)


def test_client_service_ids_are_spelled_as_rmw_cyclonedds() -> None:
    """GUID prefix + big-endian counter, hex, first byte width 2, dots between."""
    guid = bytes(range(1, 17))
    text = service_wire.client_service_id(guid, counter=0x0102)
    assert text == ' 1.2.3.4.5.6.7.8.9.a.b.c.0.0.1.2'
    assert service_wire.parse_user_data(f'clientid={text};typehash=RIHS01_x;'.encode()) == {
        'clientid': text,
        'typehash': 'RIHS01_x',
    }


GOLDEN_CASES = sorted(GOLDEN.glob('*.cdr'))


@pytest.mark.parametrize('path', GOLDEN_CASES, ids=[p.stem for p in GOLDEN_CASES])
def test_golden_service_samples_from_real_jazzy(path: Path) -> None:
    """Samples a real Jazzy rclpy client/server sent decode, and re-encode to the same bytes."""
    entry = json.loads((GOLDEN / 'index.json').read_text())[path.stem]
    module = {'rcl_interfaces': rcl_interfaces, 'tf2_msgs': tf2_msgs}[entry['package']]
    msg_type = getattr(getattr(module, entry['service']), entry['part'])
    data = path.read_bytes()
    assert len(data) == entry['bytes']
    header, message = service_wire.decode_sample(msg_type, data)
    assert header.sequence_number >= 1
    again = service_wire.encode_sample(header, message)
    assert again == data[: len(again)]
    assert not any(data[len(again) :])  # only DDS padding after it
    assert GOLDEN_VALUES[path.stem](message)


GOLDEN_VALUES: dict[str, Callable[[Any], bool]] = {
    'rcl_interfaces__GetParameters__Request': lambda m: m.names == ['radius', 'use_sim_time'],
    'rcl_interfaces__SetParameters__Request': lambda m: (
        [(p.name, p.value.type, p.value.double_value) for p in m.parameters]
        == [('radius', 3, 2.5)]
    ),
    'tf2_msgs__FrameGraph__Request': lambda m: m.structure_needs_at_least_one_member == 0,
    'rcl_interfaces__GetParameters__Response': lambda m: (
        [v.type for v in m.values] == [3, 4, 7]
        and m.values[0].double_value == 1.5
        and m.values[1].string_value == 'odom'
        and list(m.values[2].integer_array_value) == [1, 2, 3]
    ),
    'rcl_interfaces__DescribeParameters__Response': lambda m: (
        [d.name for d in m.descriptors] == ['radius', 'ranged']
        and m.descriptors[1].description == 'a range'
        and m.descriptors[1].floating_point_range[0].to_value == 1.0
    ),
    'rcl_interfaces__ListParameters__Response': lambda m: (
        'radius' in m.result.names and m.result.prefixes == ['nested']
    ),
}


# -- in-process ---------------------------------------------------------------------------------


@pytest.fixture
def world(dds_env: dict[str, str]) -> Iterator[None]:
    """An initialised standalone world on the test's private domain, shut down afterwards."""
    dds_backend.init()
    yield
    dds_backend.shutdown()


class Spinner:
    """Spins nodes in a background thread (as a test's other process would)."""

    def __init__(self, *nodes: Any, executor: Any = None) -> None:
        self.executor = executor or dds_backend.SingleThreadedExecutor()
        for node in nodes:
            self.executor.add_node(node)
        self._stop = threading.Event()
        self.errors: list[BaseException] = []
        self._thread = threading.Thread(target=self._run, daemon=True)
        self._thread.start()

    def _run(self) -> None:
        while not self._stop.is_set():
            try:
                self.executor.spin_once(timeout_sec=0.05)
            except Exception as error:
                self.errors.append(error)

    def stop(self) -> None:
        self._stop.set()
        self._thread.join(10)
        self.executor.shutdown()
        assert not self.errors


def call(client: Any, request: Any, timeout: float = 20.0) -> Any:
    """Wait for the service, call it and return the response (fails the test on timeout)."""
    assert client.wait_for_service(timeout_sec=timeout)
    response = client.call(request, timeout_sec=timeout)
    assert response is not None, f'no reply from {client.srv_name}'
    return response


def wait_for(check: Callable[[], Any], timeout: float = 20.0) -> Any:
    deadline = time.monotonic() + timeout
    while True:
        value = check()
        if value or time.monotonic() > deadline:
            return value
        time.sleep(0.05)


def test_a_client_calls_a_server_in_the_same_process(world: None) -> None:
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


def test_a_callback_calls_a_service_on_a_multi_threaded_executor(world: None) -> None:
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


def parameter_node() -> Any:
    node = dds_backend.DdsNode('params')
    node.declare_parameter('radius', 1.5)
    node.declare_parameter('frame', 'odom')
    node.declare_parameter('rate', 10, ParameterDescriptor(description='Hz', read_only=True))
    node.declare_parameter('nested.a', True)

    def refuse_negative(parameters: list[Parameter]) -> SetParametersResult:
        for parameter in parameters:
            if parameter.name == 'radius' and parameter.value < 0:
                return SetParametersResult(successful=False, reason='radius must be >= 0')
        return SetParametersResult(successful=True)

    node.add_on_set_parameters_callback(refuse_negative)
    return node


def test_parameter_services_follow_rclpy(world: None) -> None:
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


def test_garbage_requests_do_not_stop_the_node(world: None) -> None:
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


def test_rosout_carries_node_and_child_logger_lines(world: None) -> None:
    """Log lines of a node's logger and its children go to /rosout with rcl's fields."""
    node = dds_backend.DdsNode('talker_node', start_parameter_services=False)
    quiet = dds_backend.DdsNode('quiet', enable_rosout=False, start_parameter_services=False)
    listener = dds_backend.DdsNode('rosout_reader', start_parameter_services=False)
    received: list[Any] = []
    listener.create_subscription(
        rcl_interfaces.Log, '/rosout', received.append, qos_profile_rosout_default
    )
    spinner = Spinner(listener)
    try:
        node.get_logger().info('hello from the node')
        node.get_logger().get_child('part').warning('hello from a child')
        quiet.get_logger().info('not on rosout')
        assert wait_for(lambda: len([m for m in received if 'hello' in m.msg]) >= 2)
        time.sleep(0.5)
    finally:
        spinner.stop()
    by_text = {m.msg: m for m in received}
    parent = by_text['hello from the node']
    assert (parent.level, parent.name) == (20, 'talker_node')
    assert parent.file.endswith('test_dds_services.py')
    assert parent.function == 'test_rosout_carries_node_and_child_logger_lines'
    assert parent.line > 0
    assert parent.stamp.sec > 0
    child = by_text['hello from a child']
    assert (child.level, child.name) == (30, 'talker_node.part')
    assert 'not on rosout' not in by_text


def test_a_buffer_given_a_node_offers_tf2_frames(world: None) -> None:
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


# -- across processes ---------------------------------------------------------------------------


def test_parameters_of_a_standalone_process(world: None, spawn: Any) -> None:
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
