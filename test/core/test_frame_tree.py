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
Tests of tf_demo/core/frame_tree.py on its own: one side of the walk, the walks, the chain.

BufferCore's tests (test_buffer_core*.py, the differential test against tf2's C++ core) cover
these through the public API; here the tree is built by hand, cache by cache, so each shape of
route and each branch of the walks is reached on purpose.
"""

from __future__ import annotations

import math

from hypothesis import given
from hypothesis import settings
from hypothesis import strategies as st
import pytest
from tf_demo.core import math3d
from tf_demo.core.exceptions import ConnectivityException
from tf_demo.core.exceptions import ExtrapolationException
from tf_demo.core.exceptions import LookupException
from tf_demo.core.frame_tree import FrameTree
from tf_demo.core.frame_tree import MAX_GRAPH_DEPTH
from tf_demo.core.links import ROUTE_ACROSS
from tf_demo.core.links import ROUTE_DOWN
from tf_demo.core.links import ROUTE_UP
from tf_demo.core.time_cache import StaticCache
from tf_demo.core.time_cache import TimeCache

S = 1_000_000_000
Link = tuple[math3d.Vec3, math3d.Quat]


def _link(
    parent: str, child: str, tree: FrameTree, *, static: bool = True
) -> TimeCache | StaticCache:
    """Give ``child`` a cache whose samples will name ``parent`` (interned child first, as tf2)."""
    child_id = tree._intern(child)
    tree._intern(parent)
    cache: TimeCache | StaticCache = (
        StaticCache(child_id) if static else TimeCache(child_id=child_id)
    )
    tree._caches[child_id] = cache
    return cache


def _put(
    tree: FrameTree, parent: str, child: str, link: Link, stamp_ns: int = 0, *, static: bool = True
) -> None:
    cache = tree._caches[tree._ids[child]] if child in tree._ids else None
    if cache is None:
        cache = _link(parent, child, tree, static=static)
    (x, y, z), (qx, qy, qz, qw) = link
    assert cache.insert(stamp_ns, (x, y, z, qx, qy, qz, qw, tree._ids[parent]))


def _turn(axis: int, angle: float) -> math3d.Quat:
    half = [0.0, 0.0, 0.0]
    half[axis] = math.sin(angle / 2)
    return (half[0], half[1], half[2], math.cos(angle / 2))


def _compose(outer: Link, inner: Link) -> Link:
    """``outer * inner`` through math3d (the reference the inlined walk is pinned to)."""
    (ot, oq), (it, iq) = outer, inner
    moved = math3d.rotate_vector(oq, it)
    return (ot[0] + moved[0], ot[1] + moved[1], ot[2] + moved[2]), math3d.quat_multiply(oq, iq)


def _close(found: tuple[float, ...], expected: tuple[float, ...]) -> bool:
    return all(math.isclose(a, b, abs_tol=1e-9) for a, b in zip(found, expected, strict=True))


_links = st.lists(
    st.tuples(
        st.tuples(*[st.floats(-10, 10)] * 3),
        st.tuples(st.integers(0, 2), st.floats(-math.pi, math.pi)),
    ),
    min_size=1,
    max_size=8,
)


@settings(max_examples=100, deadline=None)
@given(_links)
def test_a_chain_is_one_route_up_composed_as_math3d_composes_it(
    drawn: list[tuple[math3d.Vec3, tuple[int, float]]],
) -> None:
    """A chain f0 <- f1 <- ... <- fn: fn to f0 is a route up, f0_T_fn its composition."""
    tree = FrameTree()
    expected: Link = (math3d.ZERO_VEC, math3d.IDENTITY_QUAT)
    for index, (translation, (axis, angle)) in enumerate(drawn):
        link = (translation, _turn(axis, angle))
        _put(tree, f'f{index}', f'f{index + 1}', link)
        expected = _compose(expected, link)
    top, bottom = tree._ids['f0'], tree._ids[f'f{len(drawn)}']
    shape, source_links, target_links = tree._route(top, bottom, 5 * S)
    assert (shape, len(source_links), target_links) == (ROUTE_UP, len(drawn), ())
    values, stamp = tree._walk(top, bottom, 5 * S)
    translation, rotation = values[:3], values[3:]
    assert stamp == 5 * S
    assert _close((*translation, *rotation), (*expected[0], *expected[1]))


def test_routes_go_up_down_and_across_with_the_links_tf2s_walk_takes() -> None:
    tree = FrameTree()
    shift: Link = ((1.0, 0.0, 0.0), math3d.IDENTITY_QUAT)
    _put(tree, 'a', 'b', shift)
    _put(tree, 'b', 'c', shift)
    _put(tree, 'c', 'd', shift, 2 * S, static=False)
    _put(tree, 'c', 'd', shift, 3 * S, static=False)
    _put(tree, 'a', 'e', shift)
    ids = tree._ids
    caches = tree._caches

    # The target above the source: the source's links up to (not with) the target's.
    assert tree._route(ids['b'], ids['d'], 2 * S) == (
        ROUTE_UP, [caches[ids['d']], caches[ids['c']]], (),
    )  # fmt: skip
    # The source above the target: the target's links up to the source's.
    assert tree._route(ids['d'], ids['b'], 2 * S) == (
        ROUTE_DOWN, (), [caches[ids['d']], caches[ids['c']]],
    )  # fmt: skip
    # Across: both sides up to the top, a (which has no cache).
    assert tree._route(ids['e'], ids['d'], 2 * S) == (
        ROUTE_ACROSS,
        [caches[ids['d']], caches[ids['c']], caches[ids['b']]],
        [caches[ids['e']]],
    )
    # d has data from 2 s to 3 s only: at 4 s tf2's walk fails on d.
    with pytest.raises(ExtrapolationException, match='extrapolation into the future'):
        tree._route(ids['e'], ids['d'], 4 * S)
    assert tree._walk(ids['a'], ids['d'], 2 * S + S // 2)[0][0] == 3.0  # translation x


def test_a_loop_is_tf2s_lookup_error() -> None:
    tree = FrameTree()
    identity: Link = (math3d.ZERO_VEC, math3d.IDENTITY_QUAT)
    _put(tree, 'b', 'a', identity)
    _put(tree, 'a', 'b', identity)
    _put(tree, 'a', 'c', identity)
    with pytest.raises(LookupException, match='contains a loop'):
        tree._route(tree._ids['c'], tree._ids['b'], S)
    assert tree._plan(tree._ids['c'], tree._ids['b']) is None
    assert MAX_GRAPH_DEPTH == 1000  # tf2's limit on a walk's length


def _fork() -> FrameTree:
    """map <- odom <- base <- arm (dynamic odom, 1 s to 3 s) and map <- dock (static)."""
    tree = FrameTree()
    _put(tree, 'map', 'odom', ((1.0, 0.0, 0.0), math3d.IDENTITY_QUAT), S, static=False)
    _put(tree, 'map', 'odom', ((3.0, 0.0, 0.0), math3d.IDENTITY_QUAT), 3 * S, static=False)
    _put(tree, 'odom', 'base', ((0.0, 1.0, 0.0), _turn(2, math.pi / 2)), 2 * S, static=False)
    _put(tree, 'odom', 'base', ((0.0, 1.0, 0.0), _turn(2, math.pi / 2)), 5 * S, static=False)
    _put(tree, 'base', 'arm', ((1.0, 0.0, 0.0), math3d.IDENTITY_QUAT))
    _put(tree, 'map', 'dock', ((0.0, 0.0, 2.0), math3d.IDENTITY_QUAT))
    return tree


def test_latest_common_time_is_the_oldest_newest_stamp_on_the_path() -> None:
    tree = _fork()
    ids = tree._ids
    # odom's newest is 3 s, base's 5 s: the common time of a path through both is 3 s.
    assert tree._latest_common_time(ids['map'], ids['arm']) == 3 * S
    assert tree._latest_common_time(ids['arm'], ids['dock']) == 3 * S
    # base -> arm is static: no constraint; base's own cache gives 5 s.
    assert tree._latest_common_time(ids['base'], ids['arm']) == 0
    assert tree._latest_common_time(ids['odom'], ids['base']) == 5 * S
    assert tree._latest_common_time(ids['base'], ids['base']) == 5 * S
    lonely = tree._intern('lonely')
    _put(tree, 'elsewhere', 'lonely', ((0.0, 0.0, 0.0), math3d.IDENTITY_QUAT))
    with pytest.raises(ConnectivityException, match="between 'arm' and 'lonely'"):
        tree._latest_common_time(ids['arm'], lonely)


def test_walk_across_the_fork_equals_the_composed_links() -> None:
    tree = _fork()
    ids = tree._ids
    values, stamp = tree._walk(ids['dock'], ids['arm'], 0)
    translation, rotation = values[:3], values[3:]
    assert stamp == 3 * S
    # map_T_arm = odom(3,0,0) * base(0,1,0; 90 deg about z) * arm(1,0,0) = (3, 2, 0); dock is 2 up.
    assert _close(translation, (3.0, 2.0, -2.0))
    assert _close(rotation, _turn(2, math.pi / 2))
    # The inverse walk inverts it.
    back_values, _ = tree._walk(ids['arm'], ids['dock'], 3 * S)
    back, back_rotation = back_values[:3], back_values[3:]
    assert _close(math3d.rotate_vector(rotation, back), (-3.0, -2.0, 2.0))
    assert _close(math3d.quat_multiply(rotation, back_rotation), math3d.IDENTITY_QUAT) or _close(
        math3d.quat_multiply(rotation, back_rotation), (0.0, 0.0, 0.0, -1.0)
    )


def test_walk_failures_are_tf2s() -> None:
    tree = _fork()
    ids = tree._ids
    with pytest.raises(ExtrapolationException, match='extrapolation into the future'):
        tree._walk(ids['dock'], ids['arm'], 4 * S)  # odom ends at 3 s
    with pytest.raises(ExtrapolationException, match='extrapolation into the past'):
        tree._walk(ids['dock'], ids['arm'], S + S // 2)  # base starts at 2 s
    assert 'extrapolation into the future' in (
        tree._can_walk(ids['dock'], ids['arm'], 4 * S) or ''
    )
    assert tree._can_walk(ids['dock'], ids['arm'], 3 * S) is None
    _put(tree, 'nowhere', 'island', ((0.0, 0.0, 0.0), math3d.IDENTITY_QUAT))
    with pytest.raises(ConnectivityException):
        tree._walk(ids['arm'], tree._ids['island'], 3 * S)
    island_text = tree._can_walk(ids['arm'], tree._ids['island'], 3 * S) or ''
    assert 'not part of the same tree' in island_text
    # Where the arm's side has no data, tf2 names the extrapolation, not the two trees.
    with pytest.raises(ExtrapolationException, match='extrapolation into the past'):
        tree._walk(ids['arm'], tree._ids['island'], S)
    _put(tree, 'loop_b', 'loop_a', ((0.0, 0.0, 0.0), math3d.IDENTITY_QUAT))
    _put(tree, 'loop_a', 'loop_b', ((0.0, 0.0, 0.0), math3d.IDENTITY_QUAT))
    with pytest.raises(LookupException, match='contains a loop'):
        tree._walk(ids['arm'], tree._ids['loop_a'], S)


def test_walk_chain_names_the_frames_between_with_tf2s_pruning() -> None:
    tree = _fork()
    ids = tree._ids
    names = tree._names
    # Across the fork tf2's pruning (walkToTopParent's, kept as it is) drops the frames from
    # the one below the top: arm, base, odom, map + dock becomes arm, base + dock.
    assert [names[i] for i in tree._walk_chain(ids['dock'], ids['arm'], 0)] == [
        'arm', 'base', 'dock',
    ]  # fmt: skip
    # Straight up: the chain stops at the target.
    assert [names[i] for i in tree._walk_chain(ids['odom'], ids['arm'], 0)] == ['arm', 'base']
    # Straight down: at the common time (5 s) odom has no data, so the source side stops at
    # odom itself, and the target's side is appended from the top down.
    assert [names[i] for i in tree._walk_chain(ids['arm'], ids['odom'], 0)] == [
        'odom', 'base', 'arm',
    ]  # fmt: skip
    assert tree._walk_chain(ids['arm'], ids['arm'], 0) == []


def test_validate_names_the_argument_and_the_rule() -> None:
    tree = _fork()
    assert tree._validate('target_frame', 'map') == tree._ids['map']
    with pytest.raises(LookupException, match='"ghost" passed to target_frame does not exist'):
        tree._validate('target_frame', 'ghost')
    frame_id, text = tree._validate_quietly('source_frame', '/map')
    assert frame_id == 0
    assert text == (
        'Invalid frame ID "/map" passed to source_frame - '
        "in tf2 frame_ids cannot start with a '/'"
    )
