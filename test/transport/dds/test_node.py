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

"""DdsNode: its name, namespace, topic remaps and parameters from --ros-args."""

from __future__ import annotations

from conftest import STANDALONE_ONLY
import pytest

pytest.importorskip('cyclonedds', reason=STANDALONE_ONLY)

from tf_demo.msgs import std_msgs
from tf_demo.transport import dds_backend


@pytest.mark.dds
def test_ros_args_rename_remap_and_override(dds_world):
    """__node, __ns, -r and -p from cli_args shape the node's name, topics and parameters."""
    node = dds_backend.DdsNode(
        'original',
        cli_args=[
            '--ros-args', '-r', '__node:=renamed', '-r', '__ns:=/robot',
            '-r', 'chatter:=talk', '-p', 'rate:=5.0',
        ],
    )  # fmt: skip
    assert node.get_name() == 'renamed'
    assert node.get_namespace() == '/robot'
    assert node.get_fully_qualified_name() == '/robot/renamed'
    publisher = node.create_publisher(std_msgs.String, 'chatter', 10)
    assert publisher.topic_name == '/robot/talk'
    assert node.declare_parameter('rate', 1.0).value == 5.0
    assert node.count_publishers('/robot/talk') == 1
    assert node.count_subscribers('/robot/talk') == 0
