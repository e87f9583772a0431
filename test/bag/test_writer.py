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

"""TfBagWriter: bags that rosbags reads back with the topics' types, cdr and offered QoS."""

from __future__ import annotations

from pathlib import Path

import pytest
from tf_demo.bag import BagError
from tf_demo.bag import load_buffer
from tf_demo.bag import TfBagWriter
from tf_demo.testing.bags import STORAGES
from tf_demo.testing.bags import tf_bytes
from tf_demo.testing.bags import transform

rosbag2 = pytest.importorskip('rosbags.rosbag2', reason="needs the 'bag' extra (rosbags)")

SECOND = 1_000_000_000
T0 = 1_700_000_000 * SECOND


@pytest.mark.parametrize('storage', STORAGES)
def test_written_messages_read_back(tmp_path: Path, storage: str):
    path = tmp_path / 'out'
    with TfBagWriter(path, ['/tf', '/tf_static'], storage) as bag:
        bag.write('/tf_static', T0, tf_bytes(transform('a', 'b', T0, (0, 0, 1))))
        bag.write('/tf', T0 + 1, tf_bytes(transform('b', 'c', T0, (1, 0, 0))))
        assert bag.count == 2
    with rosbag2.Reader(path) as reader:
        read = [(c.topic, t) for c, t, _ in reader.messages()]
        qos = {c.topic: c.ext.offered_qos_profiles[0] for c in reader.connections}
        types = {c.topic: (c.msgtype, c.ext.serialization_format) for c in reader.connections}
    assert read == [('/tf_static', T0), ('/tf', T0 + 1)]
    assert types['/tf'] == ('tf2_msgs/msg/TFMessage', 'cdr')
    assert (qos['/tf_static'].durability.name, qos['/tf_static'].depth) == ('TRANSIENT_LOCAL', 1)
    assert (qos['/tf'].durability.name, qos['/tf'].depth) == ('VOLATILE', 100)
    assert load_buffer(path).lookup_transform('a', 'c', T0).translation == (1.0, 0.0, 1.0)


def test_refusals_name_the_problem(tmp_path: Path):
    with pytest.raises(BagError, match=r"cannot record topics \['/chatter'\]"):
        TfBagWriter(tmp_path / 'x', ['/chatter'])
    with pytest.raises(BagError, match=r'cannot record rosbag1'):
        TfBagWriter(tmp_path / 'y', ['/tf'], 'rosbag1')
    (tmp_path / 'z').mkdir()
    with pytest.raises(BagError, match=r'z: already exists'):
        TfBagWriter(tmp_path / 'z', ['/tf'])
