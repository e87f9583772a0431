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

"""frame_broadcaster: base_link -> camera_link re-sent on /tf with a fresh stamp."""

from __future__ import annotations

from typing import Any

from conftest import Processes
from conftest import Spinning
import pytest
from rsp_world import refused_in_one_line
from rsp_world import wait_until

pytestmark = pytest.mark.dds


def test_the_transform_is_re_sent_on_tf_with_fresh_stamps(nodes: Spinning) -> None:
    """Its defaults: base_link -> camera_link (0.1, 0.2, 0.3), no rotation, stamped now."""
    from tf_demo.nodes.frame_broadcaster import FrameBroadcaster
    from tf_demo.transport.messages import tf2_msgs

    nodes.add(FrameBroadcaster())
    listener = nodes.node('frame_listener')
    received: list[Any] = []
    listener.create_subscription(tf2_msgs.TFMessage, '/tf', received.append, 100)
    nodes.start()
    wait_until(lambda: len(received) >= 2, timeout=30.0, what='two messages on /tf')
    stamps = []
    for message in received[:2]:
        [transform] = message.transforms
        assert (transform.header.frame_id, transform.child_frame_id) == (
            'base_link',
            'camera_link',
        )
        t = transform.transform.translation
        q = transform.transform.rotation
        assert (t.x, t.y, t.z) == (0.1, 0.2, 0.3)
        assert (q.x, q.y, q.z, q.w) == (0.0, 0.0, 0.0, 1.0)
        stamps.append((transform.header.stamp.sec, transform.header.stamp.nanosec))
    assert stamps[0] < stamps[1]


def test_the_same_parent_and_child_frame_is_refused_in_one_line(spawn: Processes) -> None:
    """-p child_frame:=base_link (its parent): exit code 1, one line naming the frame."""
    line = refused_in_one_line(
        spawn, 'frame_broadcaster', '--ros-args', '-p', 'child_frame:=base_link'
    )
    assert "parent_frame and child_frame are both 'base_link'" in line
