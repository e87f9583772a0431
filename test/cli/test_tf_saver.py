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

"""Tests of tf_saver's pure selection: newest links, normalization, chosen-frame chains."""

import math

import pytest
from tf_demo.cli._live import ToolError
from tf_demo.cli._observations import Observation
from tf_demo.cli._observations import ObservedTransform
from tf_demo.cli._observations import TF_STATIC_TOPIC
from tf_demo.cli._observations import TF_TOPIC
from tf_demo.cli.tf_saver import latest_links
from tf_demo.cli.tf_saver import select_links
from tf_demo.core.math3d import Quat
from tf_demo.core.math3d import Vec3

S = 1_000_000_000


def message(topic: str, receive_s: float, *transforms: ObservedTransform) -> Observation:
    return Observation(topic, int(receive_s * S), tuple(transforms))


def link(
    parent: str,
    child: str,
    stamp_s: float = 0.0,
    t: Vec3 = (0.0, 0.0, 0.0),
    q: Quat = (0.0, 0.0, 0.0, 1.0),
) -> ObservedTransform:
    return ObservedTransform(parent, child, int(stamp_s * S), t, q)


def test_newest_link_rate_and_normalization():
    """The newest stamp wins, the rate comes from the stamps, quaternions are normalized."""
    observations = [
        message(TF_STATIC_TOPIC, 0.0, link('map', 'odom', q=(0.0, 0.0, 2.0, 0.0))),
        *(
            message(TF_TOPIC, i / 10, link('odom', 'base', i / 10, (i, 0.0, 0.0)))
            for i in range(11)
        ),
        message(TF_TOPIC, 2.0, link('odom', 'base', 0.05, (99.0, 0.0, 0.0))),
    ]
    links = latest_links(observations)
    assert links['odom'].rotation == (0.0, 0.0, 1.0, 0.0)
    assert links['odom'].is_static
    assert links['base'].translation == (10.0, 0.0, 0.0)
    assert links['base'].stamp_ns == S
    rate_hz = links['base'].rate_hz
    assert rate_hz is not None
    assert math.isclose(rate_hz, 11.0)
    assert links['base'].sample_count == 12


def test_links_tf2_would_ignore_are_skipped():
    """NaN, zero quaternions and self transforms never reach the file."""
    observations = [
        message(TF_STATIC_TOPIC, 0.0, link('a', 'b', t=(math.nan, 0.0, 0.0))),
        message(TF_STATIC_TOPIC, 0.0, link('a', 'c', q=(0.0, 0.0, 0.0, 0.0))),
        message(TF_STATIC_TOPIC, 0.0, link('d', 'd')),
    ]
    assert latest_links(observations) == {}


def test_select_links_between_frames():
    """Chosen frames give the chains joining them, parents first; all links without frames."""
    observations = [
        message(
            TF_STATIC_TOPIC,
            0.0,
            link('map', 'odom'),
            link('odom', 'base'),
            link('base', 'laser'),
            link('base', 'cam'),
            link('x', 'y'),
        )
    ]
    links = latest_links(observations)
    chosen = select_links(links, ['laser', 'cam'])
    assert [(e.parent, e.child) for e in chosen] == [('base', 'cam'), ('base', 'laser')]
    chosen = select_links(links, ['odom', 'laser'])
    assert [(e.parent, e.child) for e in chosen] == [('odom', 'base'), ('base', 'laser')]
    assert len(select_links(links, [])) == 5
    with pytest.raises(ToolError, match='no transforms for frame'):
        select_links(links, ['map', 'nowhere'])
    with pytest.raises(ToolError, match="frames 'map' and 'y' are not connected"):
        select_links(links, ['map', 'y'])
