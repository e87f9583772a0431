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


"""tf2's ``lookupVelocity`` arithmetic (``tf_demo.core.velocity``), step by step."""

from __future__ import annotations

import math

import pytest
from tf_demo.core import math3d
from tf_demo.core.velocity import c_divide
from tf_demo.core.velocity import time_from_sec
from tf_demo.core.velocity import twist
from tf_demo.core.velocity import velocity_window

S = 1_000_000_000


def test_time_from_sec_rounds_half_nanoseconds_away_from_zero_as_std_round():
    """0.5 ns up (Python's round would go to the even 0), 1.5 ns up, 2.5 ns up (not to 2)."""
    assert time_from_sec(0.5e-9) == 1
    assert time_from_sec(1.5e-9) == 2
    assert time_from_sec(0.25) == S // 4
    assert time_from_sec(-0.25) == -S // 4
    halves = [k + 0.5 for k in range(0, 40, 2)]  # even + 0.5: where the two roundings differ
    assert [time_from_sec(h * 1e-9) for h in halves] == [math.floor(h) + 1 for h in halves]


def test_c_divide_gives_what_cpp_doubles_give_for_a_zero_window():
    """Finite by non-zero as usual; by zero: signed inf, NaN for 0 / 0 and NaN / 0."""
    assert c_divide(1.0, 4.0) == 0.25
    assert c_divide(2.0, 0.0) == math.inf
    assert c_divide(-2.0, 0.0) == -math.inf
    assert c_divide(2.0, -0.0) == -math.inf
    assert math.isnan(c_divide(0.0, 0.0))
    assert math.isnan(c_divide(math.nan, 0.0))


def test_velocity_window_is_clamped_to_the_latest_common_time():
    """Centred on the time while data lasts; else it ends at the latest time, one window long."""
    inside = velocity_window(5 * S, S, 10 * S)
    assert (inside.start_ns, inside.end_ns, inside.reference_ns) == (
        4_500_000_000,
        5_500_000_000,
        5 * S,
    )
    assert inside.seconds == pytest.approx(1.0)
    late = velocity_window(10 * S, S, 10 * S)
    assert (late.start_ns, late.end_ns) == (9 * S, 10 * S)
    static = velocity_window(S, S, 0)  # no dynamic link: tf2 ends the window at time 0
    assert static.end_ns == 0
    assert static.seconds == pytest.approx(-1e-5)


def test_the_averaging_interval_is_in_seconds_as_std_chrono_gives_it():
    """
    ns / 1e9, as ``std::chrono::duration<double>``; timeToSec's 1e-9 * ns would leave this
    window 1.7e-21 s long where tf2's vanishes (and answers NaN: Jazzy's core, by the
    differential test).
    """
    assert velocity_window(9_000, 2_000, S).seconds == 0.0


def test_twist_of_a_translation_and_of_a_turn():
    """2 m along x in 0.5 s is 4 m/s; a quarter turn about z in 1 s is pi/2 rad/s about z."""
    still = (0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0)
    moved = (2.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0)
    linear, angular = twist(still, moved, still, 0.5)
    assert linear == pytest.approx((4.0, 0.0, 0.0), abs=1e-12)
    assert angular == pytest.approx((0.0, 0.0, 0.0), abs=1e-12)
    turned = (0.0, 0.0, 0.0, *math3d.quat_from_rpy(0.0, 0.0, math.pi / 2))
    linear, angular = twist(still, turned, still, 1.0)
    assert angular == pytest.approx((0.0, 0.0, math.pi / 2), abs=1e-9)
    # tf2 adds the reference origin's lever arm, origin x angular: (0, 1, 0) x (0, 0, pi/2).
    lever = (0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0)
    linear, _ = twist(still, turned, lever, 1.0)
    assert linear == pytest.approx((math.pi / 2, 0.0, 0.0), abs=1e-9)
