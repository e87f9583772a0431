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
tf2's ``lookupVelocity`` arithmetic: the averaging window and the twist of three lookups.

Pure functions; ``BufferCore.lookup_velocity`` does the lookups.  Every step is tf2's, down to
its time conversions (double seconds, then ``std::round`` nanoseconds) and its division by a
window that may vanish (NaN or inf, as C++ doubles divide), so the numbers equal Jazzy's core
(the differential test checks them).
"""

from __future__ import annotations

import math
from typing import NamedTuple

from tf_demo.core import math3d
from tf_demo.core.links import Transform7
from tf_demo.core.math3d import Vec3
from tf_demo.core.time_cache import duration_to_sec

__all__ = ['VelocityWindow', 'twist', 'velocity_window']

#: ``TF2SIMD_EPSILON``: below ten of it, tf2's ``Quaternion::getAxis`` answers the x axis.
_EPSILON = 2.220446049250313e-16


class VelocityWindow(NamedTuple):
    """Where tf2 looks up for a velocity: the window's ends, the reference time, its length."""

    start_ns: int
    end_ns: int
    reference_ns: int
    #: The window's length in seconds after clamping (tf2's ``corrected_averaging_interval``).
    seconds: float


def time_from_sec(seconds: float) -> int:
    """
    Convert seconds to nanoseconds as tf2's ``timeFromSec``: floor, then ``std::round`` ns.

    ``std::round`` takes halves away from zero (Python's ``round`` takes them to even).
    """
    sec = math.floor(seconds)
    nanoseconds = (seconds - sec) * 1e9  # in [0, 1e9]
    whole = math.floor(nanoseconds)
    if nanoseconds - whole >= 0.5:
        whole += 1
    return int(sec) * 1_000_000_000 + whole


def c_divide(numerator: float, denominator: float) -> float:
    """Return ``numerator / denominator`` as C++ doubles divide: by zero gives inf or NaN."""
    if denominator:
        return numerator / denominator
    if not numerator or math.isnan(numerator):
        return math.nan
    return math.copysign(math.inf, numerator) * math.copysign(1.0, denominator)


def velocity_window(time_ns: int, averaging_ns: int, latest_ns: int) -> VelocityWindow:
    """Return tf2's window around ``time_ns``, clamped to the latest common time ``latest_ns``."""
    time_s = duration_to_sec(time_ns)
    # std::chrono::duration<double>(averaging_interval): nanoseconds divided by 1e9, where tf2's
    # timeToSec (the times) scales whole seconds and nanoseconds apart.
    interval_s = averaging_ns / 1e9
    end_s = min(time_s + interval_s * 0.5, duration_to_sec(latest_ns))
    start_s = max(0.00001 + interval_s, end_s) - interval_s
    return VelocityWindow(
        time_from_sec(start_s), time_from_sec(end_s), time_from_sec(time_s), end_s - start_s
    )


def twist(
    start: Transform7, end: Transform7, reference: Transform7, seconds: float
) -> tuple[Vec3, Vec3]:
    """
    Return ``(linear, angular)`` from the lookups at the window's ends and at the reference time.

    The rotation between the ends is the start basis' inverse (tf2's cofactors) times the end
    basis, as axis and angle; the translation is differenced; both are divided by ``seconds``
    and expressed at the reference pose (its rotation, and its origin's lever arm).
    """
    start_t, start_q = start[:3], start[3:]
    end_t, end_q = end[:3], end[3:]
    ref_t, ref_q = reference[:3], reference[3:]
    start_basis = math3d.matrix_from_quat(start_q)
    delta = math3d.quat_from_matrix(
        math3d.matrix_times(math3d.matrix_inverse(start_basis), math3d.matrix_from_quat(end_q))
    )
    w = delta[3]
    s_squared = 1.0 - w * w
    if s_squared < 10.0 * _EPSILON:
        axis: Vec3 = (1.0, 0.0, 0.0)
    else:
        s = math.sqrt(s_squared)
        axis = (delta[0] / s, delta[1] / s, delta[2] / s)
    angle = 2.0 * math.acos(max(-1.0, min(1.0, w)))
    ox, oy, oz = math3d.matrix_apply(start_basis, axis)
    scale = c_divide(angle, seconds)
    twist_rot = (ox * scale, oy * scale, oz * scale)
    twist_vel = (
        c_divide(end_t[0] - start_t[0], seconds),
        c_divide(end_t[1] - start_t[1], seconds),
        c_divide(end_t[2] - start_t[2], seconds),
    )
    ref_basis = math3d.matrix_from_quat(ref_q)
    out_rot = math3d.matrix_apply(ref_basis, twist_rot)
    vx, vy, vz = math3d.matrix_apply(ref_basis, twist_vel)
    px, py, pz = ref_t
    cross = (
        py * out_rot[2] - pz * out_rot[1],
        pz * out_rot[0] - px * out_rot[2],
        px * out_rot[1] - py * out_rot[0],
    )
    return (vx + cross[0], vy + cross[1], vz + cross[2]), out_rot
