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

"""
tf_demo's bags and ROS 2 Jazzy's rosbag2, both ways (skipped where rosbag2 is not installed).

Bags recorded by the real ``ros2 bag record`` (MCAP, Jazzy's default, and SQLite3) are read by
``tf_demo.bag`` and ``tf_echo --bag``; bags written by ``tf_record`` are described by the real
``ros2 bag info`` and played by the real ``ros2 bag play`` to the real ``tf2_echo``.
"""

from __future__ import annotations

from pathlib import Path
import re
import time

from conftest import run_captured
import pytest
from ros_world.jazzy import require_package
from ros_world.jazzy import ros2
from ros_world.jazzy import running
from ros_world.jazzy import started

pytestmark = [pytest.mark.rclpy_world, pytest.mark.timeout(180)]
rosbag2_reader = pytest.importorskip('rosbags.rosbag2', reason="needs the 'bag' extra")

STORAGES = ('mcap', 'sqlite3')
CAMERA = '- Translation: [0.500, 0.000, 0.200]'  # static_tf_pub's base_link -> camera_link


def require_rosbag2(env: dict[str, str], storage: str) -> None:
    """Skip unless ``ros2 bag`` and the storage plugin are installed."""
    require_package(env, 'ros2bag', 'rosbag2 (ros2 bag) is not installed in this Jazzy')
    require_package(env, f'rosbag2_storage_{storage}')


@pytest.mark.parametrize('storage', STORAGES)
def test_a_bag_recorded_by_ros2_bag_record_is_read(
    jazzy_env: dict[str, str], tmp_path: Path, storage: str
) -> None:
    """The real recorder's bag: both topics, the latched static, and tf_echo --bag's block."""
    from tf_demo.bag import load_buffer
    from tf_demo.bag import open_tf_bag

    require_rosbag2(jazzy_env, storage)
    bag = tmp_path / 'recorded'
    record = ['ros2', 'bag', 'record', '-o', str(bag), '-s', storage, '/tf', '/tf_static']
    with (
        started(['ros2', 'run', 'tf_demo', 'static_tf_pub'], jazzy_env),
        started(['ros2', 'run', 'tf_demo', 'dynamic_tf_pub'], jazzy_env),
        running(record, jazzy_env) as recorder,
    ):
        for topic in ('/tf', '/tf_static'):
            recorder.wait_for_line(f"Subscribed to topic '{topic}'", timeout=60, anywhere=True)
        time.sleep(2.0)  # the input of the scenario: about 40 messages of dynamic_tf_pub
    assert (bag / 'metadata.yaml').is_file(), recorder.lines
    with open_tf_bag(bag) as tf_bag:
        assert sorted(tf_bag.topics) == ['/tf', '/tf_static']
        records = list(tf_bag.records())
    statics = [t for r in records if r.is_static for t in r.transforms]
    assert [(t[0], t[1]) for t in statics] == [('base_link', 'camera_link')]
    assert sum(1 for r in records if not r.is_static) >= 5
    core = load_buffer(bag)
    assert core.can_transform('odom', 'camera_link', 0)
    echo = ['ros2', 'run', 'tf_demo', 'tf_echo', '--bag', str(bag), 'base_link', 'camera_link']
    completed = run_captured([*echo, '--limit', '1'], jazzy_env)
    assert completed.returncode == 0, completed.stderr
    assert CAMERA in completed.stdout.splitlines()


@pytest.mark.parametrize('storage', STORAGES)
def test_ros2_bag_describes_and_plays_a_tf_record_bag(
    jazzy_env: dict[str, str], tmp_path: Path, storage: str
) -> None:
    """tf_record's bag: ros2 bag info lists it; ros2 bag play feeds the real tf2_echo."""
    require_rosbag2(jazzy_env, storage)
    require_package(jazzy_env, 'tf2_ros')
    bag = tmp_path / 'ours'
    recorder = ['ros2', 'run', 'tf_demo', 'tf_record', '-o', str(bag), '--storage', storage]
    with (
        started(['ros2', 'run', 'tf_demo', 'static_tf_pub'], jazzy_env),
        started(['ros2', 'run', 'tf_demo', 'dynamic_tf_pub'], jazzy_env),
    ):
        recorded = run_captured([*recorder, '--duration', '3'], jazzy_env, timeout=120)
    assert recorded.returncode == 0, recorded.stderr
    info = ros2(jazzy_env, 'bag', 'info', str(bag))
    assert info.returncode == 0, info.stderr
    assert f'Storage id:        {storage}' in info.stdout
    counts = dict(
        re.findall(r'Topic: (/tf\w*) \| Type: tf2_msgs/msg/TFMessage \| Count: (\d+)', info.stdout)
    )
    assert int(counts['/tf_static']) == 1
    assert int(counts['/tf']) >= 20  # 3 s of 20 Hz
    assert 'Serialization Format: cdr' in info.stdout
    echo = ['ros2', 'run', 'tf2_ros', 'tf2_echo', 'base_link', 'camera_link']
    with (
        running(['ros2', 'bag', 'play', str(bag), '--loop'], jazzy_env),
        running(echo, jazzy_env) as tf2_echo,
    ):
        tf2_echo.wait_for_line(CAMERA, timeout=60)


def test_the_humble_format_fixture_is_a_bag_real_rosbag2_reads(
    jazzy_env: dict[str, str], tmp_path: Path
) -> None:
    """The hand-written Humble (SQLite3, metadata 5) test bag is one Jazzy's rosbag2 opens."""
    from tf_demo.testing.bags import SECOND
    from tf_demo.testing.bags import tf_bytes
    from tf_demo.testing.bags import transform
    from tf_demo.testing.bags import write_humble_bag

    require_rosbag2(jazzy_env, 'sqlite3')
    start = 1_700_000_000 * SECOND
    stamps = [start + k * SECOND // 10 for k in range(10)]
    bag = write_humble_bag(
        tmp_path / 'humble',
        [('/tf', stamp, tf_bytes(transform('a', 'b', stamp, (1, 0, 0)))) for stamp in stamps],
    )
    info = ros2(jazzy_env, 'bag', 'info', str(bag))
    assert info.returncode == 0, info.stderr
    assert 'Messages:          10' in info.stdout
    assert 'Duration:          0.900000000s' in info.stdout
    assert 'Topic: /tf | Type: tf2_msgs/msg/TFMessage | Count: 10' in info.stdout
