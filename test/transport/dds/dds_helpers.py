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

"""What the standalone tests of transport.dds share: spinning, service calls, a /tf message."""

from __future__ import annotations

from collections.abc import Callable
import threading
import time
from typing import Any

from conftest import STANDALONE_ONLY
import pytest

pytest.importorskip('cyclonedds', reason=STANDALONE_ONLY)

from tf_demo.msgs import geometry_msgs
from tf_demo.msgs import tf2_msgs
from tf_demo.transport import dds_backend
from tf_demo.transport.parameters import Parameter
from tf_demo.transport.parameters import ParameterDescriptor
from tf_demo.transport.parameters import SetParametersResult


def spin_until(
    executor: dds_backend.DdsExecutor, done: Callable[[], bool], timeout: float = 10.0
) -> bool:
    deadline = time.monotonic() + timeout
    while not done() and time.monotonic() < deadline:
        executor.spin_once(timeout_sec=0.05)
    return done()


def one_transform(x: float) -> tf2_msgs.TFMessage:
    transform = geometry_msgs.TransformStamped()
    transform.header.frame_id = 'odom'
    transform.child_frame_id = 'base_link'
    transform.transform.translation.x = x
    transform.transform.rotation.w = 1.0
    return tf2_msgs.TFMessage(transforms=[transform])


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
