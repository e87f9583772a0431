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

"""tf_demo.bag's reader on bags written by rosbags (MCAP and SQLite3), good and hostile."""

from __future__ import annotations

import math
from pathlib import Path

import pytest
from tf_demo.bag import BagError
from tf_demo.bag import load_bag
from tf_demo.bag import load_buffer
from tf_demo.bag import open_tf_bag
from tf_demo.core.exceptions import ExtrapolationException
from tf_demo.msgs.geometry_msgs import TransformStamped
from tf_demo.testing.bags import STORAGES
from tf_demo.testing.bags import tf_bytes
from tf_demo.testing.bags import transform
from tf_demo.testing.bags import write_bag
from tf_demo.testing.bags import write_humble_bag

rosbag2 = pytest.importorskip('rosbags.rosbag2', reason="tf_demo.bag needs the 'bag' extra")

SECOND = 1_000_000_000
T0 = 1_700_000_000 * SECOND
RADIUS = 1.0


def circle(k: int) -> TransformStamped:
    """dynamic_tf_pub's odom -> base_link at sample k (20 Hz): x = r cos t, y = r sin t, yaw t."""
    t = k / 20
    return transform(
        'odom',
        'base_link',
        T0 + k * SECOND // 20,
        (RADIUS * math.cos(t), RADIUS * math.sin(t), 0.0),
        t,
    )


def circle_bag(path: Path, storage: str, samples: int = 41) -> Path:
    """Two seconds of the circle on /tf, the static camera recorded late on /tf_static."""
    messages = [('/tf', T0 + k * SECOND // 20, tf_bytes(circle(k))) for k in range(samples)]
    camera = transform('base_link', 'camera_link', T0 + SECOND, (0.5, 0.0, 0.2))
    messages.insert(20, ('/tf_static', T0 + SECOND, tf_bytes(camera)))
    return write_bag(path, storage, messages)


@pytest.mark.parametrize('storage', STORAGES)
def test_the_circle_reads_back_exactly(tmp_path: Path, storage: str):
    """Every recorded sample is looked up exactly; the static one counts from the bag's start."""
    core = load_buffer(circle_bag(tmp_path / 'circle', storage))
    for k in (0, 7, 40):
        expected = circle(k).transform
        got = core.lookup_transform('odom', 'base_link', T0 + k * SECOND // 20)
        assert got.translation == (expected.translation.x, expected.translation.y, 0.0)
        assert math.isclose(got.rotation[2], expected.rotation.z, abs_tol=1e-15)
    early = core.lookup_transform('odom', 'camera_link', T0)  # before /tf_static was recorded
    assert early.translation[2] == 0.2
    with pytest.raises(ExtrapolationException):
        core.lookup_transform('odom', 'base_link', T0 + 3 * SECOND)  # the publisher stopped


def test_a_bag_in_humbles_sqlite3_format_reads_back(tmp_path: Path) -> None:
    """Metadata version 5 (QoS as a YAML string), schema 3: the same buffer as a Jazzy bag."""
    messages = [('/tf', T0 + k * SECOND // 20, tf_bytes(circle(k))) for k in range(41)]
    camera = transform('base_link', 'camera_link', T0 + SECOND, (0.5, 0.0, 0.2))
    messages.insert(20, ('/tf_static', T0 + SECOND, tf_bytes(camera)))
    humble = write_humble_bag(tmp_path / 'humble', messages)
    jazzy = write_bag(tmp_path / 'jazzy', 'sqlite3', messages)
    with open_tf_bag(humble) as bag:
        assert (bag.start_ns, bag.end_ns) == (T0, T0 + 2 * SECOND)
        assert [(r.bag_time_ns, r.is_static) for r in bag.records()][19:22] == [
            (T0 + 19 * SECOND // 20, False),
            (T0 + SECOND, True),
            (T0 + SECOND, False),
        ]
    ours, theirs = load_buffer(humble), load_buffer(jazzy)
    for when in (T0, T0 + 777_000_000, T0 + 2 * SECOND):
        assert ours.lookup_transform('odom', 'camera_link', when) == theirs.lookup_transform(
            'odom', 'camera_link', when
        )


@pytest.mark.parametrize('storage', STORAGES)
def test_records_stream_in_order_with_their_topic(tmp_path: Path, storage: str):
    path = circle_bag(tmp_path / 'circle', storage)
    single_file = next(p for p in path.iterdir() if p.suffix in {'.mcap', '.db3'})
    for where in (path, single_file):  # the directory, or the storage file alone
        with open_tf_bag(where) as bag:
            assert sorted(bag.topics) == ['/tf', '/tf_static']
            assert (bag.start_ns, bag.end_ns) == (T0, T0 + 2 * SECOND)
            records = list(bag.records())
        assert [r.bag_time_ns for r in records] == sorted(r.bag_time_ns for r in records)
        assert len(records) == 42
        static = [r for r in records if r.is_static]
        assert [(t[0], t[1]) for r in static for t in r.transforms] == [
            ('base_link', 'camera_link')
        ]


def test_topic_names_can_be_chosen(tmp_path: Path):
    path = write_bag(tmp_path / 'ns', 'mcap', [('/robot1/tf', T0, tf_bytes(circle(0)))])
    with pytest.raises(
        BagError, match=r'no /tf or /tf_static topic in the bag \(topics: /robot1/tf\)'
    ):
        open_tf_bag(path)
    core = load_buffer(path, tf_topic='/robot1/tf')
    assert core.frame_exists('base_link')


def test_missing_and_not_a_bag(tmp_path: Path):
    with pytest.raises(BagError, match=r'nowhere: no such bag'):
        open_tf_bag(tmp_path / 'nowhere')
    (tmp_path / 'empty').mkdir()
    with pytest.raises(BagError, match=r'empty: not a readable rosbag2: '):
        open_tf_bag(tmp_path / 'empty')
    garbage = tmp_path / 'garbage.mcap'
    garbage.write_bytes(b'\x89NOT A BAG' + bytes(200))
    with pytest.raises(BagError, match=r'garbage\.mcap: not a readable rosbag2: '):
        open_tf_bag(garbage)


def test_wrong_type_and_serialization_are_named(tmp_path: Path):
    path = write_bag(
        tmp_path / 'typed',
        'mcap',
        [('/tf', T0, b'\x00\x01\x00\x00')],
        msgtype='std_msgs/msg/String',
    )
    with pytest.raises(
        BagError, match=r'/tf holds std_msgs/msg/String, not tf2_msgs/msg/TFMessage'
    ):
        open_tf_bag(path)


def test_an_undecodable_message_is_named_after_what_came_before(tmp_path: Path):
    """Good, good, garbage: two records arrive, then one line with the bag time."""
    messages = [('/tf', T0 + k, tf_bytes(circle(k))) for k in range(2)]
    messages.append(('/tf', T0 + 5, b'\x00\x01\x00\x00\xff\xff\xff\x7f'))
    path = write_bag(tmp_path / 'bad', 'sqlite3', messages)
    with open_tf_bag(path) as bag:
        records = bag.records()
        assert next(records).bag_time_ns == T0
        assert next(records).bag_time_ns == T0 + 1
        with pytest.raises(
            BagError,
            match=r'message on /tf at bag time 1700000000\.000000005 s is not a TFMessage',
        ):
            next(records)


def test_load_bag_keeps_what_precedes_the_damage(tmp_path: Path):
    """A garbage message after a second of the circle: that second is in the buffer, the
    damage is named, and the strict load_buffer refuses the bag."""
    messages = [('/tf', T0 + k * SECOND // 20, tf_bytes(circle(k))) for k in range(21)]
    messages.append(('/tf', T0 + 2 * SECOND, b'\x00\x01\x00\x00\xff\xff\xff\x7f'))
    messages.append(('/tf', T0 + 3 * SECOND, tf_bytes(circle(60))))
    path = write_bag(tmp_path / 'damaged', 'mcap', messages)
    loaded = load_bag(path)
    assert (loaded.start_ns, loaded.end_ns) == (T0, T0 + SECOND)
    assert loaded.damage is not None
    assert 'at bag time 1700000002.000000000 s is not a TFMessage' in str(loaded.damage)
    got = loaded.core.lookup_transform('odom', 'base_link', T0 + SECOND)
    assert got.translation[0] == circle(20).transform.translation.x
    with pytest.raises(ExtrapolationException):  # nothing after the damage
        loaded.core.lookup_transform('odom', 'base_link', T0 + 3 * SECOND)
    with pytest.raises(BagError, match='is not a TFMessage'):
        load_buffer(path)
    whole = load_bag(circle_bag(tmp_path / 'whole', 'mcap'))
    assert (whole.damage, whole.end_ns) == (None, T0 + 2 * SECOND)


def test_a_truncated_mcap_is_refused_in_one_line(tmp_path: Path):
    """Half an MCAP file: refused at open (its summary is gone) or where the damage starts."""
    path = circle_bag(tmp_path / 'circle', 'mcap', samples=400)
    mcap = next(p for p in path.iterdir() if p.suffix == '.mcap')
    data = mcap.read_bytes()
    mcap.write_bytes(data[: len(data) // 2])

    def read_all() -> int:
        with open_tf_bag(mcap) as bag:
            return len(list(bag.records()))

    with pytest.raises(BagError, match=r'circle\.mcap: (not a readable rosbag2|damaged after)'):
        read_all()


def test_an_unclosed_mcap_reads_up_to_its_last_flush(tmp_path: Path):
    """A recorder killed after a flush: the copy of its .mcap gives the flushed messages, then
    one line saying the file was not closed (tf_record flushes every second)."""
    from tf_demo.bag import TfBagWriter

    writer = TfBagWriter(tmp_path / 'live', ['/tf'])
    for k in range(10):
        writer.write('/tf', T0 + k * SECOND // 20, tf_bytes(circle(k)))
    writer.flush()
    writer.write('/tf', T0 + SECOND, tf_bytes(circle(20)))  # not flushed: lost in a crash
    crashed = tmp_path / 'crashed.mcap'
    crashed.write_bytes(next((tmp_path / 'live').glob('*.mcap')).read_bytes())
    writer.close()
    with open_tf_bag(crashed) as bag:
        assert bag.topics == ['/tf']
        assert (bag.start_ns, bag.end_ns) == (T0, T0 + 9 * SECOND // 20)
        records = bag.records()
        assert [next(records).bag_time_ns for _ in range(10)][-1] == T0 + 9 * SECOND // 20
        with pytest.raises(BagError, match=r'ends without its summary \(the recording was not'):
            next(records)
    loaded = load_bag(crashed)
    assert loaded.damage is not None
    assert loaded.core.lookup_transform('odom', 'base_link', T0 + 9 * SECOND // 20)
