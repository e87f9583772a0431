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
Tests of tf_demo/core/links.py: a list of links at one time, and the three shapes of route.

The walk composes with math3d's functions (tested in test_math3d.py); here: which sample each
time reads, None where a link has no data, and how routes combine sides.
"""

from __future__ import annotations

import math

from tf_demo.core import math3d
from tf_demo.core.links import accumulate_links
from tf_demo.core.links import compose_route
from tf_demo.core.links import ROUTE_ACROSS
from tf_demo.core.links import ROUTE_DOWN
from tf_demo.core.links import ROUTE_UP
from tf_demo.core.time_cache import StaticCache
from tf_demo.core.time_cache import TimeCache

S = 1_000_000_000
IDENTITY = (0.0, 0.0, 0.0, 1.0)
QUARTER_TURN = (0.0, 0.0, math.sin(math.pi / 4), math.cos(math.pi / 4))  # 90 degrees about z


def _history(*stamped_x: tuple[int, float]) -> TimeCache:
    cache = TimeCache()
    for stamp, x in stamped_x:
        assert cache.insert(stamp, (x, 0.0, 0.0, *IDENTITY, 1))
    return cache


def _static(translation: tuple[float, float, float], rotation: math3d.Quat) -> StaticCache:
    cache = StaticCache()
    cache.insert(0, (*translation, *rotation, 1))
    return cache


def test_each_time_reads_its_sample_and_none_where_there_is_no_data() -> None:
    cache = _history((2 * S, 2.0), (4 * S, 4.0))
    assert accumulate_links([cache], 2 * S) == (2.0, 0.0, 0.0, *IDENTITY)  # the oldest
    assert accumulate_links([cache], 4 * S) == (4.0, 0.0, 0.0, *IDENTITY)  # the newest
    assert accumulate_links([cache], 0) == (4.0, 0.0, 0.0, *IDENTITY)  # time 0: the newest
    found = accumulate_links([cache], 3 * S)
    assert found is not None
    assert math.isclose(found[0], 3.0)  # interpolated
    assert accumulate_links([cache], S) is None  # before the history
    assert accumulate_links([cache], 5 * S) is None  # after it
    assert accumulate_links([TimeCache()], S) is None  # no data at all
    assert accumulate_links([], S) == (0.0, 0.0, 0.0, *IDENTITY)  # no links: the identity


def test_links_compose_bottom_first() -> None:
    """top_T_bottom = links[-1] * links[0]: turn then move, or move then turn."""
    move = _static((1.0, 0.0, 0.0), IDENTITY)
    turn = _static((0.0, 0.0, 0.0), QUARTER_TURN)
    moved_then_turned = accumulate_links([move, turn], 0)  # turn * move
    assert moved_then_turned is not None
    assert all(
        math.isclose(a, b, abs_tol=1e-12)
        for a, b in zip(moved_then_turned[:3], (0.0, 1.0, 0.0), strict=True)
    )
    turned_then_moved = accumulate_links([turn, move], 0)  # move * turn
    assert turned_then_moved is not None
    assert turned_then_moved[:3] == (1.0, 0.0, 0.0)


def test_routes_combine_the_two_sides_as_tf2s_walk() -> None:
    source = [_static((1.0, 0.0, 0.0), IDENTITY)]  # top_T_source
    target = [_static((0.0, 2.0, 0.0), QUARTER_TURN)]  # top_T_target
    assert compose_route((ROUTE_UP, source, ()), S) == (1.0, 0.0, 0.0, *IDENTITY)
    down = compose_route((ROUTE_DOWN, (), target), S)
    assert down is not None
    translation, rotation = down[:3], down[3:]  # (top_T_target)^-1
    expected_t, expected_q = math3d.invert((0.0, 2.0, 0.0), QUARTER_TURN)
    assert all(
        math.isclose(a, b, abs_tol=1e-12) for a, b in zip(translation, expected_t, strict=True)
    )
    assert all(
        math.isclose(a, b, abs_tol=1e-12) for a, b in zip(rotation, expected_q, strict=True)
    )
    across = compose_route((ROUTE_ACROSS, source, target), S)
    assert across is not None
    expected = math3d.compose(expected_t, expected_q, (1.0, 0.0, 0.0), IDENTITY)
    assert all(
        math.isclose(a, b, abs_tol=1e-12)
        for a, b in zip(across, (*expected[0], *expected[1]), strict=True)
    )
    # A side without data at the time: no answer (the caller takes tf2's full walk).
    assert compose_route((ROUTE_ACROSS, [_history((2 * S, 1.0))], target), S) is None
    assert compose_route((ROUTE_DOWN, (), [_history((2 * S, 1.0))]), S) is None
