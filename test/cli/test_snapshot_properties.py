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

"""Property tests: any valid snapshot survives dump and parse exactly."""

import math

from hypothesis import given
from hypothesis import strategies as st
import pytest
from tf_demo.cli._snapshot import dump_snapshot
from tf_demo.cli._snapshot import parse_snapshot
from tf_demo.cli._snapshot import Snapshot
from tf_demo.cli._snapshot import SnapshotTransform

pytestmark = [pytest.mark.property]

names = st.text(alphabet=st.characters(blacklist_categories=('Cc', 'Cs')), min_size=1, max_size=20)
finite = st.floats(allow_nan=False, allow_infinity=False)
stamps = st.integers(min_value=-(2**31) * 10**9, max_value=(2**31 - 1) * 10**9)


@st.composite
def unit_quaternions(draw):
    raw = draw(st.tuples(*[st.floats(-1, 1, allow_nan=False)] * 4))
    norm = math.sqrt(sum(c * c for c in raw))
    if norm < 1e-3:
        return (0.0, 0.0, 0.0, 1.0)
    return tuple(c / norm for c in raw)


@st.composite
def snapshots(draw):
    frames = draw(st.lists(names, min_size=2, max_size=8, unique=True))
    entries = []
    for index, child in enumerate(frames[1:], start=1):
        parent = frames[draw(st.integers(0, index - 1))]
        entries.append(
            SnapshotTransform(
                parent,
                child,
                draw(st.tuples(finite, finite, finite)),
                draw(unit_quaternions()),
                draw(st.booleans()),
                draw(st.none() | stamps),
                draw(st.none() | names),
                draw(st.none() | st.floats(0, 1e6)),
                draw(st.none() | st.integers(0, 10**6)),
            )
        )
    return Snapshot(tuple(entries), draw(st.none() | stamps))


@given(snapshots())
def test_dump_parse_round_trip(snapshot):
    """parse(dump(s)) == s for every valid snapshot, floats bit for bit."""
    assert parse_snapshot(dump_snapshot(snapshot)) == snapshot
