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
Tests of tf_demo/core/path_plan.py: remembered paths answer exactly as the full walk does.

The oracle is the same core with plans switched off (every question takes tf2's full walk, which
the differential test holds to tf2's C++ core): drawn sequences of inserts (reparenting, static
and dynamic links, static values changing, loops, two trees) and ``clear()`` interleaved with
``can_transform``, ``transform_error`` and lookups at drawn times and at time 0.
"""

from __future__ import annotations

from typing import Any

from hypothesis import given
from hypothesis import settings
from hypothesis import strategies as st
from tf_demo.core import BufferCore
from tf_demo.core.exceptions import TransformException
from tf_demo.core.links import ROUTE_ACROSS
from tf_demo.core.links import ROUTE_UP
from tf_demo.core.path_plan import common_time
from tf_demo.core.path_plan import has_data
from tf_demo.core.path_plan import PathPlan
from tf_demo.core.time_cache import StaticCache

S = 1_000_000_000
FRAMES = ['a', 'b', 'c', 'd', 'e']


class _WalkOnly(BufferCore):
    """The core with no path plans: every answer comes from the full walk."""

    def _plan(self, target_id: int, source_id: int) -> PathPlan | None:
        return None


def _quiet() -> tuple[BufferCore, BufferCore]:
    return BufferCore(log=lambda level, text: None), _WalkOnly(log=lambda level, text: None)


_insert = st.tuples(
    st.just('set'),
    st.sampled_from(FRAMES),
    st.sampled_from(FRAMES),
    st.integers(1, 4),
    st.booleans(),
    st.floats(-2, 2),
)
_question = st.tuples(
    st.just('ask'), st.sampled_from(FRAMES), st.sampled_from(FRAMES), st.integers(0, 9)
)
_operations = st.lists(
    st.one_of(_insert, _insert, _question, _question, _question, st.just(('clear',))),
    max_size=60,
)


def _answer(core: BufferCore, target: str, source: str, time_ns: int) -> tuple[Any, ...]:
    """Return everything a client can learn from ``core`` about one question."""
    try:
        result = core.lookup_transform(target, source, time_ns)
        looked_up: tuple[Any, ...] = (result.translation, result.rotation, result.stamp_ns)
    except TransformException as error:
        looked_up = (type(error).__name__, str(error))
    return (
        core.can_transform(target, source, time_ns),
        core.transform_error(target, source, time_ns),
        looked_up,
    )


def _assert_same(planned: tuple[Any, ...], walked: tuple[Any, ...]) -> None:
    """The same answers; numbers within 1e-12 (a plan composes runs of static links first)."""
    assert planned[:2] == walked[:2]
    if isinstance(walked[2][0], str):
        assert planned[2] == walked[2]
        return
    (t1, q1, stamp1), (t2, q2, stamp2) = planned[2], walked[2]
    assert stamp1 == stamp2
    for a, b in zip((*t1, *q1), (*t2, *q2), strict=True):
        assert abs(a - b) <= 1e-12, (planned, walked)


@settings(max_examples=400, deadline=None)
@given(_operations)
def test_planned_answers_are_the_full_walks(operations: list[tuple[Any, ...]]) -> None:
    planned, walked = _quiet()
    for operation in operations:
        if operation[0] == 'set':
            _, parent, child, second, is_static, x = operation
            for core in (planned, walked):
                core.set_transform(
                    parent, child, second * S, (x, 0.0, 0.0), (0.0, 0.0, 0.0, 1.0), 'me', is_static
                )
        elif operation[0] == 'clear':
            planned.clear()
            walked.clear()
        else:
            _, target, source, second = operation
            time_ns = second * S // 2
            _assert_same(
                _answer(planned, target, source, time_ns), _answer(walked, target, source, time_ns)
            )


def _chain_core() -> BufferCore:
    """map <- odom (dynamic, 1 s to 3 s) <- base (static) and map <- dock (dynamic, 2 s, 5 s)."""
    core = BufferCore(log=lambda level, text: None)
    identity = (0.0, 0.0, 0.0, 1.0)
    for stamp in (1, 2, 3):
        core.set_transform('map', 'odom', stamp * S, (float(stamp), 0.0, 0.0), identity)
    core.set_transform('odom', 'base', 0, (0.0, 1.0, 0.0), identity, is_static=True)
    for stamp in (2, 5):
        core.set_transform('map', 'dock', stamp * S, (0.0, 0.0, 1.0), identity)
    return core


def test_a_plan_names_the_caches_the_walk_reads_and_the_common_ones() -> None:
    core = _chain_core()
    ids = core._ids
    odom, dock = core._caches[ids['odom']], core._caches[ids['dock']]
    plan = core._plan(ids['dock'], ids['base'])
    assert plan is not None
    assert plan.reads == (odom, dock)
    assert plan.common == (dock, odom)
    assert common_time(plan) == 3 * S  # odom's newest: older than dock's
    assert has_data(plan.reads, 2 * S)
    assert not has_data(plan.reads, S)  # dock starts at 2 s
    assert not has_data(plan.reads, 4 * S)  # odom ends at 3 s
    assert has_data(plan.reads, 0)
    # The route: across the top (map), base's static link and odom; dock.
    base = core._caches[ids['base']]
    assert plan.route == (ROUTE_ACROSS, [base, odom], [dock])
    assert plan.off_route == ()
    # The target above the source: only the source's side, up to and with the target's cache.
    up = core._plan(ids['odom'], ids['base'])
    assert up is not None
    assert (up.reads, up.common) == ((odom,), ())
    assert common_time(up) == 0
    # odom's own data is read though its link is not taken: tf2 fails where odom has none.
    assert up.route == (ROUTE_UP, [base], ())
    assert up.off_route == (odom,)


def test_plans_are_forgotten_when_the_tree_changes_shape() -> None:
    core = _chain_core()
    ids = core._ids
    plan = core._plan(ids['dock'], ids['base'])
    assert core._plan(ids['dock'], ids['base']) is plan  # remembered
    core.set_transform('map', 'odom', 4 * S, (4.0, 0.0, 0.0), (0.0, 0.0, 0.0, 1.0))
    assert core._plan(ids['dock'], ids['base']) is plan  # new data, same shape
    core.set_transform('dock', 'odom', 5 * S, (0.0, 0.0, 0.0), (0.0, 0.0, 0.0, 1.0))
    # odom has had two parents: its path depends on the time, so no plan.
    assert core._plan(ids['dock'], ids['base']) is None
    core.clear()  # dynamic caches emptied: no plan through them until they have data
    assert core._plan(ids['dock'], ids['base']) is None
    core.set_transform('dock', 'odom', 6 * S, (0.0, 0.0, 0.0), (0.0, 0.0, 0.0, 1.0))
    core.set_transform('map', 'dock', 6 * S, (0.0, 0.0, 1.0), (0.0, 0.0, 0.0, 1.0))
    replanned = core._plan(ids['dock'], ids['base'])
    assert replanned is not None
    assert replanned.common == (core._caches[ids['odom']],)


def test_no_plan_across_two_trees_or_a_loop() -> None:
    core = _chain_core()
    identity = (0.0, 0.0, 0.0, 1.0)
    core.set_transform('world', 'island', 0, (0.0, 0.0, 0.0), identity, is_static=True)
    ids = core._ids
    assert core._plan(ids['island'], ids['base']) is None
    core.set_transform('loop_b', 'loop_a', 0, (0.0, 0.0, 0.0), identity, is_static=True)
    core.set_transform('loop_a', 'loop_b', 0, (0.0, 0.0, 0.0), identity, is_static=True)
    assert core._plan(ids['map'], core._ids['loop_a']) is None


def test_the_common_time_ignores_links_above_the_lowest_common_ancestor() -> None:
    """world <- hub (newest 1 s) <- left, right (newest 3 s, 4 s): left-right meet at hub."""
    identity = (0.0, 0.0, 0.0, 1.0)
    planned, walked = _quiet()
    for core in (planned, walked):
        core.set_transform('world', 'hub', S, (1.0, 0.0, 0.0), identity)
        for stamp in (2, 3):
            core.set_transform('hub', 'left', stamp * S, (0.0, float(stamp), 0.0), identity)
        for stamp in (2, 4):
            core.set_transform('hub', 'right', stamp * S, (0.0, 0.0, float(stamp)), identity)
    assert walked.get_latest_common_time('left', 'right') == 3 * S
    assert _answer(planned, 'left', 'right', 0) == _answer(walked, 'left', 'right', 0)
    # The walk from right stops at hub (no data at 3 s) and left's side reaches hub: tf2 answers.
    assert planned.lookup_transform('left', 'right', 0).stamp_ns == 3 * S


def test_runs_of_static_links_fold_into_one_link() -> None:
    """REP-105's camera -> lidar -> base_link -> base_footprint becomes one static link."""
    turn = (0.0, 0.0, 0.3826834323650898, 0.9238795325112867)
    core, walked = _quiet()
    for tree in (core, walked):
        tree.set_transform('base_footprint', 'base_link', 0, (0.0, 0.0, 0.1), turn, '', True)
        tree.set_transform('base_link', 'lidar_link', 0, (0.2, 0.0, 0.3), turn, '', True)
        tree.set_transform('lidar_link', 'camera', 0, (0.05, 0.02, -0.1), turn, '', True)
        for stamp in (1, 2):
            tree.set_transform('odom', 'base_footprint', stamp * S, (float(stamp), 0, 0), turn)
    ids = core._ids
    plan = core._plan(ids['odom'], ids['camera'])
    assert plan is not None
    shape, source_links, target_links = plan.route
    assert (shape, len(source_links), target_links) == (ROUTE_UP, 2, ())
    folded, odom_link = source_links
    assert isinstance(folded, StaticCache)
    assert odom_link is core._caches[ids['base_footprint']]
    for time_ns in (0, S, S + S // 3, 2 * S, 3 * S):
        _assert_same(
            _answer(core, 'odom', 'camera', time_ns), _answer(walked, 'odom', 'camera', time_ns)
        )
        _assert_same(
            _answer(core, 'camera', 'odom', time_ns), _answer(walked, 'camera', 'odom', time_ns)
        )
    # A new static value changes the shape: the folded link is made again.
    for tree in (core, walked):
        tree.set_transform('base_link', 'lidar_link', 0, (0.9, 0.0, 0.3), turn, '', True)
    replanned = core._plan(ids['odom'], ids['camera'])
    assert replanned is not None
    assert replanned is not plan
    _assert_same(_answer(core, 'odom', 'camera', S), _answer(walked, 'odom', 'camera', S))
