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

"""Quaternion and transform math against tf2's LinearMath values (spec/tf2.md §9)."""

from __future__ import annotations

from collections.abc import Sequence
import math
import random

import numpy as np
import pytest
from tf_demo.core import math3d as m3


def _close(a: Sequence[float], b: Sequence[float], tol: float = 1e-9) -> bool:
    return all(abs(x - y) <= tol for x, y in zip(a, b, strict=True))


def _same_rotation(a: Sequence[float], b: Sequence[float], tol: float = 1e-9) -> bool:
    return _close(a, b, tol) or _close(a, [-v for v in b], tol)


def _random_quat(rng: random.Random) -> m3.Quat:
    x, y, z, w = (rng.gauss(0, 1) for _ in range(4))
    n = math.sqrt(x * x + y * y + z * z + w * w)
    return (x / n, y / n, z / n, w / n)


def test_set_rpy_matches_tf2_value():
    """setRPY(0.1, 0.2, 0.3) equals the value tf2 prints."""
    q = m3.quat_from_rpy(0.1, 0.2, 0.3)
    assert _close(q, (0.034270799, 0.106020511, 0.143572175, 0.983347443), 1e-9)


def test_rpy_is_fixed_axis_xyz():
    """quat_from_rpy is Rz(yaw) * Ry(pitch) * Rx(roll)."""
    roll, pitch, yaw = 0.4, -0.7, 1.9
    qx = m3.quat_from_axis_angle((1.0, 0.0, 0.0), roll)
    qy = m3.quat_from_axis_angle((0.0, 1.0, 0.0), pitch)
    qz = m3.quat_from_axis_angle((0.0, 0.0, 1.0), yaw)
    expected = m3.quat_multiply(qz, m3.quat_multiply(qy, qx))
    assert _same_rotation(m3.quat_from_rpy(roll, pitch, yaw), expected)


def test_rpy_round_trip_inside_range():
    """rpy_from_quat inverts quat_from_rpy for |pitch| < pi/2."""
    rng = random.Random(3)
    for _ in range(200):
        rpy = (rng.uniform(-3.1, 3.1), rng.uniform(-1.5, 1.5), rng.uniform(-3.1, 3.1))
        assert _close(m3.rpy_from_quat(m3.quat_from_rpy(*rpy)), rpy, 1e-9)


def test_rpy_round_trip_outside_pitch_range_matches_tf2():
    """setRPY(0.1, 2.0, 0.1) comes back as tf2's (-3.0416, 1.1416, -3.0416)."""
    roll, pitch, yaw = m3.rpy_from_quat(m3.quat_from_rpy(0.1, 2.0, 0.1))
    assert _close((roll, pitch, yaw), (0.1 - math.pi, math.pi - 2.0, 0.1 - math.pi), 1e-9)


def test_rpy_gimbal_lock_convention():
    """At gimbal lock yaw is 0, pitch is +-pi/2 and roll is atan2(R21, R22) (tf2 returns 0.3)."""
    matrix = ((0.0, 0.0, 1.0), (0.0, 1.0, 0.0), (-1.0, 0.0, 0.0))
    roll, pitch, yaw = m3.rpy_from_matrix(matrix)
    assert (roll, pitch, yaw) == (0.0, math.pi / 2, 0.0)
    down = ((0.0, 0.0, -1.0), (0.0, 1.0, 0.0), (1.0, 0.0, 0.0))
    assert m3.rpy_from_matrix(down)[1] == -math.pi / 2
    # Matrix3x3::setRPY(0.3, pi/2, 0.2).getRPY() gives roll 0.3, pitch pi/2, yaw 0 in tf2.
    roll, pitch, yaw = m3.rpy_from_matrix(m3.matrix_from_rpy(0.3, math.pi / 2, 0.2))
    assert (pitch, yaw) == (math.pi / 2, 0.0)
    assert roll == pytest.approx(0.3, abs=1e-15)


def test_matrix_from_rpy_equals_quaternion_matrix():
    """Matrix3x3::setRPY and Quaternion::setRPY describe the same rotation."""
    rng = random.Random(19)
    for _ in range(100):
        rpy = (rng.uniform(-3, 3), rng.uniform(-3, 3), rng.uniform(-3, 3))
        a = np.array(m3.matrix_from_rpy(*rpy))
        b = np.array(m3.matrix_from_quat(m3.quat_from_rpy(*rpy)))
        assert np.allclose(a, b, atol=1e-12)


def test_slerp_matches_tf2_short_path_value():
    """slerp(identity, (0,0,-.7071,-.7071), 0.5) is (0,0,0.3827,0.9239) as in tf2."""
    s = math.sqrt(0.5)
    q = m3.slerp((0.0, 0.0, 0.0, 1.0), (0.0, 0.0, -s, -s), 0.5)
    assert _close(q, (0.0, 0.0, math.sin(math.pi / 8), math.cos(math.pi / 8)), 1e-12)


def test_slerp_equal_inputs_return_first_unchanged():
    """A zero angle returns q0 unchanged, with no renormalisation."""
    q = (0.0, 0.0, 0.0, 2.0)
    assert m3.slerp(q, q, 0.3) == q


def test_slerp_endpoints():
    """Ratio 0 gives q0 and ratio 1 gives the nearer sign of q1."""
    rng = random.Random(5)
    for _ in range(100):
        a, b = _random_quat(rng), _random_quat(rng)
        assert _close(m3.slerp(a, b, 0.0), a)
        end = m3.slerp(a, b, 1.0)
        assert _same_rotation(end, b)
        assert sum(x * y for x, y in zip(end, a, strict=True)) >= -1e-12


def test_matrix_round_trip_and_canonical_sign():
    """quat_from_matrix(matrix_from_quat(q)) is q up to tf2's canonical sign."""
    assert m3.canonical_quat((0.0, 0.0, 0.0, -1.0)) == (0.0, 0.0, 0.0, 1.0)
    assert _close(
        m3.canonical_quat((0.0, 0.0, -0.7071, -0.7071)), (0, 0, math.sqrt(0.5), math.sqrt(0.5))
    )
    assert m3.canonical_quat((0.0, 0.0, -1.0, 0.0)) == (0.0, 0.0, 1.0, 0.0)
    assert m3.canonical_quat((0.0, 0.0, 0.0, 2.0)) == (0.0, 0.0, 0.0, 1.0)
    stored = m3.canonical_quat((0.1, 0.2, 0.3, -0.9))
    assert _close(stored, (-0.102598, -0.205196, -0.307794, 0.923381), 1e-6)
    rng = random.Random(7)
    for _ in range(200):
        q = _random_quat(rng)
        assert _same_rotation(m3.quat_from_matrix(m3.matrix_from_quat(q)), q, 1e-12)


def test_canonical_quat_of_zero_or_inf_is_nan():
    """Zero and infinite quaternions turn into NaNs, which tf2 then rejects."""
    assert all(math.isnan(v) for v in m3.canonical_quat((0.0, 0.0, 0.0, 0.0)))
    assert any(math.isnan(v) for v in m3.canonical_quat((math.inf, 0.0, 0.0, 1.0)))


def test_rotate_vector_matches_matrix():
    """rotate_vector agrees with the rotation matrix."""
    rng = random.Random(11)
    for _ in range(100):
        q = _random_quat(rng)
        v = (rng.uniform(-5, 5), rng.uniform(-5, 5), rng.uniform(-5, 5))
        m = np.array(m3.matrix_from_quat(q))
        assert _close(m3.rotate_vector(q, v), m @ np.array(v), 1e-12)


def test_compose_and_invert_match_homogeneous_matrices():
    """compose/invert agree with 4x4 matrix products and inverses."""
    rng = random.Random(13)
    for _ in range(100):
        ta = (rng.uniform(-5, 5), rng.uniform(-5, 5), rng.uniform(-5, 5))
        tb = (rng.uniform(-5, 5), rng.uniform(-5, 5), rng.uniform(-5, 5))
        qa, qb = _random_quat(rng), _random_quat(rng)
        t, q = m3.compose(ta, qa, tb, qb)
        expected = m3.homogeneous_from_transform(ta, qa) @ m3.homogeneous_from_transform(tb, qb)
        assert np.allclose(m3.homogeneous_from_transform(t, q), expected, atol=1e-12)
        ti, qi = m3.invert(ta, qa)
        inverse = np.linalg.inv(m3.homogeneous_from_transform(ta, qa))
        assert np.allclose(m3.homogeneous_from_transform(ti, qi), inverse, atol=1e-12)
        t_back, q_back = m3.transform_from_homogeneous(expected)
        assert _close(t_back, t, 1e-12)
        assert _same_rotation(q_back, q, 1e-12)


def test_transform_from_homogeneous_rejects_bad_shape():
    """A non-4x4 matrix is rejected with a message naming the shape."""
    with pytest.raises(ValueError, match='4x4'):
        m3.transform_from_homogeneous(np.eye(3))


def test_axis_angle_and_normalize_errors():
    """Zero axes and zero quaternions are reported, not silently accepted."""
    with pytest.raises(ValueError, match='zero vector'):
        m3.quat_from_axis_angle((0.0, 0.0, 0.0), 1.0)
    with pytest.raises(ValueError, match='normalise'):
        m3.quat_normalize((0.0, 0.0, 0.0, 0.0))
    assert _close(m3.quat_normalize((0.0, 0.0, 0.0, 3.0)), (0, 0, 0, 1))
    q = m3.quat_from_axis_angle((0.0, 0.0, 2.0), math.pi / 2)
    assert _close(q, (0, 0, math.sqrt(0.5), math.sqrt(0.5)))


def test_batch_helpers_equal_scalar_versions():
    """The numpy batch helpers agree with the scalar functions row by row."""
    rng = random.Random(17)
    qa = np.array([_random_quat(rng) for _ in range(50)])
    qb = np.array([_random_quat(rng) for _ in range(50)])
    qb[0] = qa[0]
    ta = np.array([[rng.uniform(-3, 3) for _ in range(3)] for _ in range(50)])
    tb = np.array([[rng.uniform(-3, 3) for _ in range(3)] for _ in range(50)])
    ratio = np.array([rng.uniform(0, 1) for _ in range(50)])
    t_out, q_out = m3.compose_batch(ta, qa, tb, qb)
    s_out = m3.slerp_batch(qa, qb, ratio)
    for i in range(50):
        t, q = m3.compose(tuple(ta[i]), tuple(qa[i]), tuple(tb[i]), tuple(qb[i]))
        assert _close(t_out[i], t, 1e-12)
        assert _close(q_out[i], q, 1e-12)
        assert _close(s_out[i], m3.slerp(tuple(qa[i]), tuple(qb[i]), float(ratio[i])), 1e-12)


def test_lerp_endpoints_and_midpoint():
    """lerp gives v0 at 0, v1 at 1 and (1 - r) v0 + r v1 between (tf2's setInterpolate3)."""
    v0, v1 = (1.0, -2.0, 3.0), (5.0, 6.0, -7.0)
    assert m3.lerp(v0, v1, 0.0) == v0
    assert m3.lerp(v0, v1, 1.0) == v1
    assert _close(m3.lerp(v0, v1, 0.25), (2.0, 0.0, 0.5), 1e-15)


def test_matrix_products_match_numpy():
    """matrix_times, matrix_apply and matrix_transpose agree with numpy's products."""
    rng = random.Random(29)
    a = m3.matrix_from_quat(_random_quat(rng))
    b = m3.matrix_from_quat(_random_quat(rng))
    v = (rng.uniform(-3, 3), rng.uniform(-3, 3), rng.uniform(-3, 3))
    assert np.allclose(m3.matrix_times(a, b), np.array(a) @ np.array(b), rtol=0, atol=1e-15)
    assert np.allclose(m3.matrix_apply(a, v), np.array(a) @ np.array(v), rtol=0, atol=1e-15)
    assert m3.matrix_transpose(a) == tuple(map(tuple, np.array(a).T.tolist()))
    assert np.allclose(m3.matrix_times(m3.matrix_transpose(a), a), np.eye(3), atol=1e-15)


def test_matrix_inverse_matches_numpy_and_the_transpose_of_a_rotation():
    """matrix_inverse (tf2's cofactors) inverts a matrix; a rotation's inverse is its transpose."""
    rng = random.Random(31)
    rows = [(rng.uniform(-2, 2), rng.uniform(-2, 2), rng.uniform(-2, 2)) for _ in range(3)]
    general = (rows[0], rows[1], rows[2])
    expected = np.linalg.inv(np.array(general))
    assert np.allclose(m3.matrix_inverse(general), expected, rtol=1e-12, atol=1e-12)
    rotation = m3.matrix_from_quat(_random_quat(rng))
    assert np.allclose(m3.matrix_inverse(rotation), np.array(rotation).T, rtol=0, atol=1e-15)
