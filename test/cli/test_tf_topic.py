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

"""tf_topic echo and hz: ros2 topic's output for the TF topics, in both worlds."""

from __future__ import annotations

import re
from typing import Any

from conftest import ProcessOutput
from conftest import REPO_ROOT
from tf_demo.cli.formatting import format_message_yaml
from tf_demo.cli.tf_topic import HzStats
from tf_demo.msgs.sensor_msgs import JointState
from tf_demo.testing.bags import transform

MS = 1_000_000


def test_hz_reports_ros2_topic_hz_numbers_once_a_second():
    """20 Hz exactly: nothing until a second after the first report point, then 20.000."""
    stats = HzStats()
    assert stats.report() is None
    for k in range(21):
        stats.add(10**12 + k * 50 * MS)
    assert stats.report() is None  # the first call only marks the start, as ros2 topic hz
    for k in range(21, 42):
        stats.add(10**12 + k * 50 * MS)
    assert stats.report() == (
        'average rate: 20.000\n\tmin: 0.050s max: 0.050s std dev: 0.00000s window: 41'
    )
    assert stats.report() is None  # no second has passed since
    stats.add(10**11)  # the clock went back: start again
    assert not stats.intervals


def test_the_window_keeps_the_newest_intervals():
    stats = HzStats(window=3)
    for stamp in (0, 10, 30, 60, 100):
        stats.add(stamp * MS)
    assert list(stats.intervals) == [20 * MS, 30 * MS, 40 * MS]


def test_messages_print_as_block_yaml_in_field_order():
    """As rosidl_runtime_py's message_to_yaml: nested mappings, lists, '' for an empty string."""
    from tf_demo.msgs.tf2_msgs import TFMessage

    message = TFMessage()
    message.transforms = [transform('map', 'odom', 5 * 10**9 + 7, (1.5, 0, 0))]
    assert format_message_yaml(message) == (
        'transforms:\n- header:\n    stamp:\n      sec: 5\n      nanosec: 7\n'
        '    frame_id: map\n  child_frame_id: odom\n  transform:\n    translation:\n'
        '      x: 1.5\n      y: 0.0\n      z: 0.0\n    rotation:\n      x: 0.0\n      y: 0.0\n'
        '      z: 0.0\n      w: 1.0\n'
    )
    joints = JointState()
    joints.name = ['a']
    joints.position = [0.25]
    assert format_message_yaml(joints) == (
        "header:\n  stamp:\n    sec: 0\n    nanosec: 0\n  frame_id: ''\nname:\n- a\n"
        'position:\n- 0.25\nvelocity: []\neffort: []\n'
    )


def test_echo_once_gets_the_latched_static_transform(spawn: Any) -> None:
    """A late subscriber to /tf_static still gets static_tf_pub's transform, then exits 0."""
    spawn.start('static_tf_pub')
    echo = spawn.start('tf_topic', 'echo', '/tf_static', '--once')
    out, _ = echo.communicate(timeout=60)
    assert echo.returncode == 0
    assert re.fullmatch(
        r'transforms:\n- header:\n    stamp:\n      sec: \d+\n      nanosec: \d+\n'
        r'    frame_id: base_link\n  child_frame_id: camera_link\n  transform:\n'
        r'    translation:\n      x: 0.5\n      y: 0.0\n      z: 0.2\n    rotation:\n'
        r'      x: 0.0\n      y: 0.0\n      z: 0.0\n      w: 1.0\n---\n',
        out,
    ), out


def test_hz_measures_dynamic_tf_pub(spawn: Any) -> None:
    """dynamic_tf_pub sends at 20 Hz: tf_topic hz /tf says about 20."""
    spawn.start('dynamic_tf_pub')
    hz = ProcessOutput(spawn.start('tf_topic', 'hz', '/tf'))
    line = hz.wait_for_line('average rate: ', timeout=60)
    assert 10.0 < float(line.split()[-1]) < 30.0
    assert hz.wait_for_line('\tmin: ', timeout=10)


def test_a_namespaced_topic_by_its_name(spawn: Any) -> None:
    """A robot's /robot1/tf_static (its statics remapped there) is read as tf_static: latched."""
    spawn.start('static_tf_pub', '--ros-args', '-r', '/tf_static:=/robot1/tf_static')
    echo = spawn.start('tf_topic', 'echo', '/robot1/tf_static', '--once')
    out, err = echo.communicate(timeout=60)
    assert echo.returncode == 0, err
    assert 'child_frame_id: camera_link' in out


def test_any_other_name_takes_its_type_from_the_graph(spawn: Any) -> None:
    """An unknown name gets the publisher's type and durability: latched TFMessage here."""
    spawn.start('static_tf_pub', '--ros-args', '-r', '/tf_static:=/fleet/statics')
    echo = spawn.start('tf_topic', 'echo', '/fleet/statics', '--once')
    out, err = echo.communicate(timeout=60)
    assert echo.returncode == 0, err
    assert 'child_frame_id: camera_link' in out


def test_refuses_a_topic_of_another_type(spawn: Any) -> None:
    """robot_state_publisher's /robot_description is a std_msgs String: refused, exit 1."""
    spawn.start('robot_state_publisher', str(REPO_ROOT / 'urdf' / 'example_fixed.urdf'))
    process = spawn.start('tf_topic', 'echo', '/robot_description')
    _, err = process.communicate(timeout=60)
    assert process.returncode == 1
    assert "topic '/robot_description' has type std_msgs/msg/String" in err


def test_refuses_a_topic_nobody_publishes(spawn: Any) -> None:
    process = spawn.start('tf_topic', 'echo', '/chatter')
    _, err = process.communicate(timeout=60)
    assert process.returncode == 1
    assert "no publisher on '/chatter'" in err
