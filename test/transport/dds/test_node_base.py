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

"""What every part of a node shares: its names, and the refusal once it was destroyed."""

from __future__ import annotations

from conftest import STANDALONE_ONLY
import pytest

pytest.importorskip('cyclonedds', reason=STANDALONE_ONLY)

from tf_demo.msgs import std_msgs
from tf_demo.transport import dds_backend


@pytest.mark.dds
def test_destroyed_node_refuses_new_entities(dds_world):
    """After destroy_node, creating a publisher says the node was destroyed."""
    node = dds_backend.DdsNode('gone', namespace='ns')
    assert node.get_fully_qualified_name() == '/ns/gone'
    node.destroy_node()
    with pytest.raises(RuntimeError, match="node '/ns/gone' was destroyed"):
        node.create_publisher(std_msgs.String, 'x', 1)
