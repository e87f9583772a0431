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

"""The test bags: what tf_demo.testing.bags writes, read back with rosbags' own reader."""

from __future__ import annotations

from pathlib import Path

import pytest
from tf_demo.msgs.cdr import deserialize
from tf_demo.msgs.tf2_msgs import TFMessage
from tf_demo.testing.bags import STORAGES
from tf_demo.testing.bags import tf_bytes
from tf_demo.testing.bags import transform
from tf_demo.testing.bags import write_bag

rosbag2 = pytest.importorskip('rosbags.rosbag2', reason="needs the 'bag' extra (rosbags)")


@pytest.mark.parametrize('storage', STORAGES)
def test_written_bags_hold_what_was_written(tmp_path: Path, storage: str):
    data = tf_bytes(transform('a', 'b', 5, (1, 2, 3), 0.5))
    write_bag(tmp_path / 'b', storage, [('/tf', 7, data), ('/tf_static', 9, data)])
    with rosbag2.Reader(tmp_path / 'b') as reader:
        read = [(c.topic, t, bytes(d)) for c, t, d in reader.messages()]
    assert read == [('/tf', 7, data), ('/tf_static', 9, data)]
    message = deserialize(TFMessage, data)
    assert message.transforms[0].child_frame_id == 'b'
    assert message.transforms[0].header.stamp.nanosec == 5
