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

"""Tests of the shipped hypothesis strategies themselves (``tf_demo.testing.strategies``)."""

from __future__ import annotations

import math

from hypothesis import find
from hypothesis import given
from hypothesis import Phase
from hypothesis import settings
from hypothesis import strategies as st
import pytest
from tf_demo.testing import strategies as tfst

pytestmark = pytest.mark.property


@given(tfst.unit_quaternions())
@tfst.profile_settings(300)
def test_unit_quaternions_have_unit_norm(q: tuple[float, float, float, float]) -> None:
    """Every drawn quaternion is finite and normalised."""
    assert all(math.isfinite(c) for c in q)
    assert math.isclose(math.sqrt(sum(c * c for c in q)), 1.0, abs_tol=1e-12)


@pytest.mark.parametrize('component', range(4))
def test_unit_quaternions_reach_negative_and_positive_components(component: int) -> None:
    """Each component takes both signs (guards against a lower bound typo like -1e-12)."""
    no_shrink = settings(tfst.profile_settings(), phases=[Phase.generate])
    find(tfst.unit_quaternions(), lambda q: q[component] < -0.5, settings=no_shrink)
    find(tfst.unit_quaternions(), lambda q: q[component] > 0.5, settings=no_shrink)


@given(tfst.raw_quaternions())
@tfst.profile_settings(300)
def test_raw_quaternions_are_never_near_zero(q: tuple[float, float, float, float]) -> None:
    """Raw quaternions keep a norm above the filter threshold."""
    assert math.sqrt(sum(c * c for c in q)) > tfst.MIN_QUATERNION_NORM


@given(tfst.frame_names())
@tfst.profile_settings(300)
def test_frame_names_are_valid_tf2_names(name: str) -> None:
    """Names are non-empty, use the restricted alphabet and never start with a slash."""
    assert name
    assert set(name) <= set(tfst.FRAME_ALPHABET)
    assert not name.startswith('/')


@given(tfst.parent_lists(min_frames=1, max_frames=10))
@tfst.profile_settings(300)
def test_parent_lists_describe_a_forest(parents: list[int]) -> None:
    """Frame 0 is a root and every parent index points to an earlier frame (no cycles)."""
    assert parents[0] == -1
    assert all(-1 <= parent < index for index, parent in enumerate(parents))


def test_parent_lists_produce_disconnected_forests() -> None:
    """Some drawn forests have more than one root (disconnected trees)."""
    no_shrink = settings(tfst.profile_settings(), phases=[Phase.generate])
    find(tfst.parent_lists(), lambda parents: parents.count(-1) >= 2, settings=no_shrink)


@given(tfst.rpy_angles())
@tfst.profile_settings(300)
def test_rpy_angles_lie_in_tf2_ranges(rpy: tuple[float, float, float]) -> None:
    """Roll and yaw lie in (-pi, pi], pitch in [-pi/2, pi/2]."""
    roll, pitch, yaw = rpy
    assert -math.pi < roll <= math.pi
    assert -math.pi < yaw <= math.pi
    assert -math.pi / 2 <= pitch <= math.pi / 2


@given(tfst.stamps_ns(0, 10**12))
@tfst.profile_settings(100)
def test_stamps_are_non_negative_ints(stamp: int) -> None:
    """Stamps are plain ints inside the requested range."""
    assert isinstance(stamp, int)
    assert 0 <= stamp <= 10**12


def test_seeded_scenarios_are_reproducible() -> None:
    """The same seed builds the same scenario, a different seed a different one."""
    assert tfst.build_scenario(tfst.SeededChooser(7)) == tfst.build_scenario(tfst.SeededChooser(7))
    assert tfst.build_scenario(tfst.SeededChooser(7)) != tfst.build_scenario(tfst.SeededChooser(8))


def test_scenarios_cover_every_operation_and_edge_case() -> None:
    """Across 300 seeded scenarios every op kind, static and dynamic links and odd names occur."""
    kinds: set[str] = set()
    seen = {'static': False, 'dynamic': False, 'slash': False, 'unknown': False, 'zero': False}
    for seed in range(300):
        scenario = tfst.build_scenario(tfst.SeededChooser(seed))
        for op in scenario['ops']:
            kinds.add(op[0])
            if op[0] == 'set':
                seen['static'] |= op[7]
                seen['dynamic'] |= not op[7]
                seen['slash'] |= str(op[2]).startswith('/')
            if op[0] == 'lookup':
                seen['unknown'] |= 'unknown' in (op[1], op[2])
                seen['zero'] |= op[3] == 0
    assert kinds == {
        'set',
        'clear',
        'lookup',
        'lookup_full',
        'can',
        'can_full',
        'lct',
        'string',
        'yaml',
        'dot',
        'frames',
    }
    assert all(seen.values()), seen


def test_dynamic_links_never_repeat_a_stamp_with_other_data() -> None:
    """Within a scenario a dynamic child never gets two different samples with one stamp."""
    for seed in range(300):
        samples: dict[tuple[str, int], list[object]] = {}
        for op in tfst.build_scenario(tfst.SeededChooser(seed))['ops']:
            if op[0] == 'set' and not op[7] and op[6] != 'bad':
                key = (str(op[2]).removeprefix('/'), op[3])
                data = [str(op[1]).removeprefix('/'), op[4], op[5]]
                assert samples.setdefault(key, data) == data, (seed, op)


def test_prune_flush_repeats_the_newest_sample_before_queries() -> None:
    """The newest sample is re-sent before a query once an insert advanced the newest stamp."""
    ops = [
        ['set', 'a', 'b', 5, [0, 0, 0], [0, 0, 0, 1], 'x', False],
        ['set', 'a', 'b', 9, [1, 0, 0], [0, 0, 0, 1], 'x', False],
        ['set', 'a', 'b', 7, [2, 0, 0], [0, 0, 0, 1], 'x', False],
        ['lookup', 'a', 'b', 0],
        ['set', 'a', 'b', 12, [3, 0, 0], [0, 0, 0, 1], 'x', False],
        ['lookup', 'a', 'b', 0],
    ]
    flushed = tfst.with_prune_flushes(ops, cache_time_ns=3)
    assert flushed[:4] == ops[:4]  # the last insert (7) did not advance the newest stamp
    assert flushed[4:] == [ops[4], ops[4], ops[5]]


@given(st.data())
@tfst.profile_settings(30)
def test_hypothesis_scenarios_are_json_ready(data: st.DataObject) -> None:
    """Scenarios drawn through hypothesis have the oracle protocol's shape."""
    scenario = data.draw(tfst.scenarios())
    assert isinstance(scenario['cache_time_ns'], int)
    assert scenario['cache_time_ns'] > 0
    assert any(op[0] == 'set' for op in scenario['ops'])
    assert scenario['ops'][-1][0] not in ('set', 'clear')
