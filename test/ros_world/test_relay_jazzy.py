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

"""``ros2 run tf_demo tf_relay`` inside Jazzy, read by the real ``tf2_echo`` on the global /tf."""

from __future__ import annotations

from functools import partial

from conftest import eventually
import pytest
from ros_world.jazzy import running
from test_side_by_side import echo_blocks
from test_side_by_side import ours_run
from test_side_by_side import require_executable
from test_side_by_side import upstream_run

pytestmark = [pytest.mark.rclpy_world, pytest.mark.timeout(300)]

IN_ROBOT1 = ('--ros-args', '-r', '__ns:=/robot1', '-r', '/tf:=tf', '-r', '/tf_static:=tf_static')


def test_tf2_echo_reads_a_namespaced_robot_through_tf_relay(jazzy_env: dict[str, str]) -> None:
    """The real static_transform_publisher and our dynamic_tf_pub in /robot1, relayed."""
    env = jazzy_env
    require_executable(env, 'tf2_ros', 'tf2_echo')
    require_executable(env, 'tf2_ros', 'static_transform_publisher')
    static = upstream_run(
        'tf2_ros',
        'static_transform_publisher',
        *('--x', '1', '--frame-id', 'base_link', '--child-frame-id', 'laser'),
        *IN_ROBOT1,
    )
    tf2_echo = partial(upstream_run, 'tf2_ros', 'tf2_echo')
    with (
        running(static, env),
        running(ours_run('dynamic_tf_pub', *IN_ROBOT1), env),
        running(ours_run('tf_relay', '/robot1'), env) as relay,
        running(tf2_echo('robot1/base_link', 'robot1/laser'), env) as mount,
        running(tf2_echo('robot1/odom', 'robot1/base_link'), env) as moving,
    ):
        assert eventually(lambda: echo_blocks(mount.stdout), 60), (mount.stdout, relay.stderr)
        assert eventually(lambda: len(echo_blocks(moving.stdout)) >= 2, 60), moving.stdout
    block = echo_blocks(mount.stdout)[0]
    assert block[1] == '- Translation: [1.000, 0.000, 0.000]'
    first, second = echo_blocks(moving.stdout)[:2]
    assert first[0] != second[0]  # the stamps move: relayed as dynamic_tf_pub sends them
    assert any('Relaying /robot1 onto /tf and /tf_static' in line for line in relay.lines)
