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
