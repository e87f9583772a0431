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

"""The world's message modules: node code names one module per ROS package, in both worlds."""

from __future__ import annotations

from conftest import WORLD
from tf_demo.core.buffer_core import TransformResult
from tf_demo.transport import messages


def test_message_and_service_modules_are_the_worlds_own() -> None:
    """``package.msg``/``package.srv`` inside ROS 2, tf_demo's generated module standalone."""
    geometry = messages.message_module('geometry_msgs')
    frames = messages.service_module('tf2_msgs')
    if WORLD == 'rclpy':
        assert (geometry.__name__, frames.__name__) == ('geometry_msgs.msg', 'tf2_msgs.srv')
    else:
        assert (geometry.__name__, frames.__name__) == (
            'tf_demo.msgs.geometry_msgs',
            'tf_demo.msgs.tf2_msgs',
        )
    assert messages.geometry_msgs is geometry
    assert frames.FrameGraph.Response().frame_yaml == ''


def test_new_transform_stamped_carries_the_lookup_result() -> None:
    """The buffer's answer as the world's TransformStamped: frames, stamp, transform."""
    result = TransformResult((1.0, -2.0, 0.5), (0.0, 0.0, 0.6, 0.8), 1_700_000_000_000_000_042)
    message = messages.new_transform_stamped('map', 'base_link', result)
    assert isinstance(message, messages.geometry_msgs.TransformStamped)
    assert (message.header.frame_id, message.child_frame_id) == ('map', 'base_link')
    assert (message.header.stamp.sec, message.header.stamp.nanosec) == (1_700_000_000, 42)
    translation = message.transform.translation
    rotation = message.transform.rotation
    assert (translation.x, translation.y, translation.z) == (1.0, -2.0, 0.5)
    assert (rotation.x, rotation.y, rotation.z, rotation.w) == (0.0, 0.0, 0.6, 0.8)
