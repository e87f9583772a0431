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

"""The vocabulary of tf_doctor's checks: per-frame statistics, value comparison, message texts."""

from tf_demo.cli._doctor_model import distinct_values
from tf_demo.cli._doctor_model import format_members
from tf_demo.cli._doctor_model import gather
from tf_demo.cli._doctor_model import same_value
from tf_demo.cli._doctor_model import seconds
from tf_demo.cli._observations import Observation
from tf_demo.cli._observations import ObservedTransform
from tf_demo.cli._observations import TF_STATIC_TOPIC
from tf_demo.cli._observations import TF_TOPIC

IDENTITY = ((0.0, 0.0, 0.0), (0.0, 0.0, 0.0, 1.0))


def test_gather_collects_each_child_frame_in_reception_order() -> None:
    """Parents, topics, publishers, static values and dynamic samples are counted per child."""
    observations = [
        Observation(TF_TOPIC, 20, (ObservedTransform('odom', 'base', 15, (2.0, 0.0, 0.0)),), '/b'),
        Observation(TF_STATIC_TOPIC, 5, (ObservedTransform('map', 'odom', 0),), '/s'),
        Observation(TF_TOPIC, 10, (ObservedTransform('map', 'base', 9, (1.0, 0.0, 0.0)),), '/a'),
    ]
    stats = gather(observations)
    assert sorted(stats) == ['base', 'odom']
    base = stats['base']
    assert base.parents == {'map': 1, 'odom': 1}
    assert base.topics == {TF_TOPIC: 2}
    assert base.publishers == {'/a', '/b'}
    assert base.dynamic_publishers == ['/a', '/b']
    assert [(receive, stamp) for receive, stamp, _, _ in base.dynamic] == [(10, 9), (20, 15)]
    assert base.latest_parent == 'odom'  # the last one received
    assert base.static_values == []
    assert stats['odom'].static_values == [IDENTITY]
    assert stats['odom'].parent_by_topic == {TF_STATIC_TOPIC: {'map'}}


def test_values_compare_within_the_tolerance() -> None:
    """Translations and rotations agree when every component is within the tolerance."""
    nudged = ((1e-10, 0.0, 0.0), (0.0, 0.0, 0.0, 1.0))
    moved = ((1e-3, 0.0, 0.0), (0.0, 0.0, 0.0, 1.0))
    assert same_value(IDENTITY, nudged, 1e-9)
    assert not same_value(IDENTITY, moved, 1e-9)
    assert distinct_values([IDENTITY, nudged, moved, IDENTITY], 1e-9) == [IDENTITY, moved]


def test_message_texts_list_members_and_seconds() -> None:
    """At most ``limit`` members are named, with how many more; nanoseconds print as seconds."""
    assert format_members(['a', 'b']) == 'a, b'
    assert format_members([str(i) for i in range(5)], limit=3) == '0, 1, 2, … (2 more)'
    assert seconds(1_500_000_000) == '1.500 s'
