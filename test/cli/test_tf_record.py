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

"""tf_record: live TF into a rosbag2, read back with rosbags' reader and the mcap package."""

from __future__ import annotations

import contextlib
from pathlib import Path
import signal
import sqlite3
from typing import Any

from conftest import eventually
from conftest import ProcessOutput
import pytest
from tf_demo.bag import load_bag
from tf_demo.bag import load_buffer
from tf_demo.bag import open_tf_bag
from tf_demo.msgs.cdr import deserialize
from tf_demo.msgs.tf2_msgs import TFMessage

rosbag2 = pytest.importorskip('rosbags.rosbag2', reason="tf_record needs the 'bag' extra")


def committed_messages(bag: Path) -> int:
    """How many messages another reader sees in a SQLite3 bag being written (0 if none yet)."""
    database = next(bag.glob('*.db3'), None)
    if database is None:
        return 0
    with contextlib.closing(sqlite3.connect(f'file:{database}?mode=ro', uri=True)) as db:
        try:
            return int(db.execute('SELECT count(*) FROM messages').fetchone()[0])
        except sqlite3.Error:  # the tables are not there yet, or a write is under way
            return 0


def test_a_recording_holds_the_live_tree(spawn: Any, tmp_path: Path) -> None:
    """static_tf_pub (started first: latched) and dynamic_tf_pub, 3 s, MCAP: all there."""
    spawn.start('static_tf_pub')
    spawn.start('dynamic_tf_pub')
    bag = tmp_path / 'run'
    record = ProcessOutput(spawn.start('tf_record', '-o', str(bag), '--duration', '3'))
    assert record.process.wait(timeout=60) == 0
    assert record.wait_for_line('tf_record: recording /tf /tf_static to ', timeout=5)
    with rosbag2.Reader(bag) as reader:  # rosbags' own reader
        topics = {c.topic: (c.msgtype, c.ext.serialization_format) for c in reader.connections}
        statics = [
            deserialize(TFMessage, data)
            for connection, _, data in reader.messages()
            if connection.topic == '/tf_static'
        ]
        durabilities = {
            c.topic: c.ext.offered_qos_profiles[0].durability.name for c in reader.connections
        }
    assert topics == {
        '/tf': ('tf2_msgs/msg/TFMessage', 'cdr'),
        '/tf_static': ('tf2_msgs/msg/TFMessage', 'cdr'),
    }
    assert durabilities == {'/tf': 'VOLATILE', '/tf_static': 'TRANSIENT_LOCAL'}
    assert [t.child_frame_id for m in statics for t in m.transforms] == ['camera_link']
    core = load_buffer(bag)
    assert core.can_transform('odom', 'camera_link', 0)
    mcap_reader = pytest.importorskip('mcap.reader')
    mcap_file = next(bag.glob('*.mcap'))
    with mcap_file.open('rb') as stream:  # the mcap package, independent of rosbags
        summary = mcap_reader.make_reader(stream).get_summary()
    assert summary is not None
    channels = {c.topic: c.message_encoding for c in summary.channels.values()}
    assert channels == {'/tf': 'cdr', '/tf_static': 'cdr'}
    assert summary.statistics.message_count > 20  # 3 s of 20 Hz


def test_ctrl_c_closes_a_sqlite3_bag_cleanly(spawn: Any, tmp_path: Path) -> None:
    spawn.start('dynamic_tf_pub')
    bag = tmp_path / 'run'
    record = ProcessOutput(
        spawn.start('tf_record', '-o', str(bag), '--storage', 'sqlite3', '--topics', '/tf')
    )
    record.wait_for_line('tf_record: recording /tf to ', timeout=60)
    assert eventually(lambda: committed_messages(bag) > 0, 60, 0.05)
    record.process.send_signal(signal.SIGINT)
    assert record.process.wait(timeout=30) == 0
    assert record.wait_for_line('tf_record: ', timeout=5)
    assert (bag / 'metadata.yaml').is_file()  # written on close
    with rosbag2.Reader(bag) as reader:
        assert [c.topic for c in reader.connections] == ['/tf']


def test_an_existing_output_is_refused(spawn: Any, tmp_path: Path) -> None:
    (tmp_path / 'run').mkdir()
    process = spawn.start('tf_record', '-o', str(tmp_path / 'run'))
    _, err = process.communicate(timeout=60)
    assert process.returncode == 1
    assert err.strip().endswith('run: already exists (rosbag2 writes a new directory)')


@pytest.mark.dds
@pytest.mark.usefixtures('ros')
def test_the_metadata_holds_the_qos_the_publishers_offer(
    spawn: Any, nodes: Any, tmp_path: Path
) -> None:
    """A /joint_states publisher with depth 7 and a 2.5 s deadline: rosbag2's metadata says so."""
    from tf_demo.transport.clock import Duration
    from tf_demo.transport.messages import sensor_msgs
    from tf_demo.transport.qos import QoSProfile

    node = nodes.node('joint_source')
    offered = QoSProfile(depth=7, deadline=Duration(seconds=2, nanoseconds=500_000_000))
    publisher = node.create_publisher(sensor_msgs.JointState, '/joint_states', offered)
    node.create_timer(0.05, lambda: publisher.publish(sensor_msgs.JointState(name=['j'])))
    nodes.start()
    bag = tmp_path / 'run'
    record = spawn.start(
        'tf_record', '-o', str(bag), '--duration', '3', '--topics', '/joint_states'
    )
    assert record.wait(timeout=60) == 0, record.communicate()
    with rosbag2.Reader(bag) as reader:
        (connection,) = reader.connections
        profiles = connection.ext.offered_qos_profiles
        count = sum(1 for _ in reader.messages())
    assert count > 5
    (profile,) = profiles
    assert (profile.history.name, profile.depth) == ('KEEP_LAST', 7)
    assert (profile.reliability.name, profile.durability.name) == ('RELIABLE', 'VOLATILE')
    assert (profile.deadline.sec, profile.deadline.nsec) == (2, 500_000_000)
    assert (profile.lifespan.sec, profile.lifespan.nsec) == (9223372036, 854775807)  # infinite


def test_a_crash_leaves_what_was_committed_readable(spawn: Any, tmp_path: Path) -> None:
    """SIGKILL while recording SQLite3: the .db3 left behind opens and holds the /tf so far."""
    spawn.start('dynamic_tf_pub')
    bag = tmp_path / 'run'
    record = spawn.start('tf_record', '-o', str(bag), '--storage', 'sqlite3')
    assert eventually(lambda: committed_messages(bag) >= 5, 60, 0.05)
    record.kill()
    record.wait(timeout=30)
    assert not (bag / 'metadata.yaml').exists()  # it never closed
    with open_tf_bag(next(bag.glob('*.db3'))) as crashed:
        records = list(crashed.records())
    assert len(records) >= 5
    assert {t[1] for r in records for t in r.transforms} == {'base_link'}


def test_a_crashed_mcap_keeps_its_flushed_chunks_for_mcaps_streaming_reader(
    spawn: Any, tmp_path: Path
) -> None:
    """SIGKILL while recording MCAP: no summary, but the chunks flushed each second hold /tf."""
    stream_reader = pytest.importorskip('mcap.stream_reader')
    spawn.start('dynamic_tf_pub')
    bag = tmp_path / 'run'
    record = spawn.start('tf_record', '-o', str(bag))

    def flushed_messages() -> int:
        mcap = next(bag.glob('*.mcap'), None)
        if mcap is None:
            return 0
        count = 0
        with mcap.open('rb') as stream:
            try:
                for item in stream_reader.StreamReader(stream, skip_magic=False).records:
                    count += type(item).__name__ == 'Message'  # read out of the chunks
            except Exception:  # the file ends mid-record (being written, or cut by the kill)
                pass
        return count

    assert eventually(lambda: flushed_messages() >= 10, 60, 0.1)
    record.kill()
    record.wait(timeout=30)
    channels: dict[int, str] = {}
    topics: list[str] = []
    with next(bag.glob('*.mcap')).open('rb') as stream:
        try:
            for item in stream_reader.StreamReader(stream, skip_magic=False).records:
                if type(item).__name__ == 'Channel':
                    channels[item.id] = item.topic
                elif type(item).__name__ == 'Message':
                    topics.append(channels[item.channel_id])
        except Exception:  # no footer after the last chunk: the stream simply ends
            pass
    assert len(topics) >= 10
    assert set(topics) == {'/tf'}
    loaded = load_bag(bag)  # our reader too: what was flushed, then the one-line damage
    assert loaded.core.can_transform('odom', 'base_link', 0)
    assert 'the file ends without its summary (the recording was not closed)' in str(loaded.damage)
