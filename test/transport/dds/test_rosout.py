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

"""/rosout for standalone nodes, as rcl_logging_rosout publishes it."""

from __future__ import annotations

import time
from typing import Any

from conftest import STANDALONE_ONLY
import pytest

pytest.importorskip('cyclonedds', reason=STANDALONE_ONLY)

from dds_helpers import Spinner
from dds_helpers import wait_for
from tf_demo.msgs import rcl_interfaces
from tf_demo.transport import dds_backend
from tf_demo.transport.dds.qos import qos_profile_rosout_default

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


def test_rosout_carries_node_and_child_logger_lines(dds_world: None) -> None:
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
    assert parent.file.endswith('test_rosout.py')
    assert parent.function == 'test_rosout_carries_node_and_child_logger_lines'
    assert parent.line > 0
    assert parent.stamp.sec > 0
    child = by_text['hello from a child']
    assert (child.level, child.name) == (30, 'talker_node.part')
    assert 'not on rosout' not in by_text
