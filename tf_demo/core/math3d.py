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
Quaternion and rigid-transform math with tf2's LinearMath conventions.

Conventions (the same as tf2):

* Quaternions are ``(x, y, z, w)`` tuples; the identity is ``(0, 0, 0, 1)``.
* A transform is a pair ``(t, q)`` of a translation and a rotation.  ``target_T_source`` is the
  pose of ``source`` expressed in ``target``; it maps coordinates given in ``source`` into
  ``target``: ``p_target = R(q) * p_source + t``.  This is a ``TransformStamped`` with
  ``header.frame_id = target`` and ``child_frame_id = source``.
* ``compose(a_T_b, b_T_c)`` gives ``a_T_c``.

The scalar functions work on plain tuples of floats and follow tf2's arithmetic term by term, so
results agree with tf2's C++ core to the last bits in most cases.  numpy is used only for
matrices (:func:`homogeneous_from_transform`) and for the ``*_batch`` helpers that work on
``(N, 3)`` / ``(N, 4)`` arrays.  :func:`quat_multiply_lanes` and :func:`rotate_vector_lanes`
are the same products on *lanes*: tuples whose components are numpy arrays (one value per lane)
or floats, which is how the vectorised walk (:mod:`tf_demo.core._batch`) and the ``*_batch``
helpers use them.  This module is compiled by mypyc where it can be (``tf_demo.build_info``):
the scalar functions take and return unboxed floats there; numpy is imported by the functions
that use it, on first use.
"""

from __future__ import annotations

from collections.abc import Sequence
import math
from typing import Final
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    import numpy as np
    import numpy.typing as npt

    FloatArray = npt.NDArray[np.float64]
    #: One component for many lanes at once (an array), or the same float for every lane.
    Lane = float | FloatArray
    Lanes3 = tuple[Lane, Lane, Lane]
    Lanes4 = tuple[Lane, Lane, Lane, Lane]

Vec3 = tuple[float, float, float]
Quat = tuple[float, float, float, float]
Matrix3 = tuple[Vec3, Vec3, Vec3]

IDENTITY_QUAT: Quat = (0.0, 0.0, 0.0, 1.0)
ZERO_VEC: Vec3 = (0.0, 0.0, 0.0)

_HALF_PI: Final = math.pi / 2.0

__all__ = [
    'IDENTITY_QUAT',
    'ZERO_VEC',
    'Matrix3',
    'Quat',
    'Vec3',
    'canonical_quat',
    'canonical_quat_batch',
    'canonical_quat_rows',
    'compose',
    'compose_batch',
    'homogeneous_from_transform',
    'invert',
    'lerp',
    'matrix_apply',
    'matrix_from_quat',
    'matrix_from_quat_batch',
    'matrix_from_rpy',
    'matrix_inverse',
    'matrix_times',
    'matrix_transpose',
    'quat_conjugate',
    'quat_from_axis_angle',
    'quat_from_matrix',
    'quat_from_matrix_batch',
    'quat_from_rpy',
    'quat_multiply',
    'quat_multiply_batch',
    'quat_multiply_lanes',
    'quat_normalize',
    'rotate_vector',
    'rotate_vector_batch',
    'rotate_vector_lanes',
    'rpy_from_matrix',
    'rpy_from_quat',
    'slerp',
    'slerp_batch',
    'transform_from_homogeneous',
]


def quat_multiply(a: Quat, b: Quat) -> Quat:
    """Return the Hamilton product ``a * b`` (``b`` is applied first), as tf2's ``operator*``."""
    ax, ay, az, aw = a
    bx, by, bz, bw = b
    return (
        aw * bx + ax * bw + ay * bz - az * by,
        aw * by + ay * bw + az * bx - ax * bz,
        aw * bz + az * bw + ax * by - ay * bx,
        aw * bw - ax * bx - ay * by - az * bz,
    )


def quat_multiply_lanes(a: Lanes4, b: Lanes4) -> Lanes4:
    """:func:`quat_multiply` on lanes (components that are arrays or floats), term for term."""
    ax, ay, az, aw = a
    bx, by, bz, bw = b
    return (
        aw * bx + ax * bw + ay * bz - az * by,
        aw * by + ay * bw + az * bx - ax * bz,
        aw * bz + az * bw + ax * by - ay * bx,
        aw * bw - ax * bx - ay * by - az * bz,
    )


def quat_conjugate(q: Quat) -> Quat:
    """Return ``(-x, -y, -z, w)``: tf2's ``Quaternion::inverse`` (no division by the norm)."""
    return (-q[0], -q[1], -q[2], q[3])


def quat_normalize(q: Quat) -> Quat:
    """
    Return ``q / |q|``.

    :raises ValueError: if ``q`` has zero length or is not finite.
    """
    norm = math.sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3])
    if not norm or not math.isfinite(norm):
        raise ValueError(f'cannot normalise quaternion {q!r} (length {norm})')
    inv = 1.0 / norm
    return (q[0] * inv, q[1] * inv, q[2] * inv, q[3] * inv)


def rotate_vector(q: Quat, v: Vec3) -> Vec3:
    """Rotate ``v`` by ``q``: the vector part of ``q * (v, 0) * conj(q)`` (tf2 ``quatRotate``)."""
    qx, qy, qz, qw = q
    vx, vy, vz = v
    # r = q * v (quaternion times pure vector), then r * conj(q), term order as in tf2.
    rx = qw * vx + qy * vz - qz * vy
    ry = qw * vy + qz * vx - qx * vz
    rz = qw * vz + qx * vy - qy * vx
    rw = -qx * vx - qy * vy - qz * vz
    return (
        rw * -qx + rx * qw + ry * -qz - rz * -qy,
        rw * -qy + ry * qw + rz * -qx - rx * -qz,
        rw * -qz + rz * qw + rx * -qy - ry * -qx,
    )


def rotate_vector_lanes(q: Lanes4, v: Lanes3) -> Lanes3:
    """:func:`rotate_vector` on lanes (components that are arrays or floats), term for term."""
    qx, qy, qz, qw = q
    vx, vy, vz = v
    rx = qw * vx + qy * vz - qz * vy
    ry = qw * vy + qz * vx - qx * vz
    rz = qw * vz + qx * vy - qy * vx
    rw = -qx * vx - qy * vy - qz * vz
    return (
        rw * -qx + rx * qw + ry * -qz - rz * -qy,
        rw * -qy + ry * qw + rz * -qx - rx * -qz,
        rw * -qz + rz * qw + rx * -qy - ry * -qx,
    )


def compose(t_a: Vec3, q_a: Quat, t_b: Vec3, q_b: Quat) -> tuple[Vec3, Quat]:
    """
    Compose two transforms: ``a_T_b`` then ``b_T_c`` gives ``a_T_c``.

    :returns: ``(R(q_a) * t_b + t_a, q_a * q_b)``.
    """
    rx, ry, rz = rotate_vector(q_a, t_b)
    return (rx + t_a[0], ry + t_a[1], rz + t_a[2]), quat_multiply(q_a, q_b)


def invert(t: Vec3, q: Quat) -> tuple[Vec3, Quat]:
    """Invert a transform: ``a_T_b`` gives ``b_T_a`` = ``(-R(conj q) * t, conj q)``."""
    q_inv = (-q[0], -q[1], -q[2], q[3])
    return rotate_vector(q_inv, (-t[0], -t[1], -t[2])), q_inv


def lerp(v0: Vec3, v1: Vec3, ratio: float) -> Vec3:
    """Linear interpolation ``(1 - ratio) * v0 + ratio * v1``, as tf2's ``lerp``."""
    keep = 1.0 - ratio
    return (
        keep * v0[0] + ratio * v1[0],
        keep * v0[1] + ratio * v1[1],
        keep * v0[2] + ratio * v1[2],
    )


def slerp(q0: Quat, q1: Quat, ratio: float) -> Quat:
    """
    Spherical linear interpolation along the shorter arc, exactly as tf2's ``slerp``.

    ``ratio`` 0 gives ``q0`` and 1 gives ``q1`` (or ``-q1``, whichever is nearer ``q0``).  When
    the angle between them is exactly zero ``q0`` is returned unchanged; there is no linear
    fallback for small angles and no renormalisation, as in tf2.
    """
    x0, y0, z0, w0 = q0
    x1, y1, z1, w1 = q1
    dot = x0 * x1 + y0 * y1 + z0 * z1 + w0 * w1
    scale = math.sqrt(
        (x0 * x0 + y0 * y0 + z0 * z0 + w0 * w0) * (x1 * x1 + y1 * y1 + z1 * z1 + w1 * w1)
    )
    cosine = (-dot if dot < 0 else dot) / scale
    if cosine > 1.0:
        cosine = 1.0
    elif cosine < -1.0:
        cosine = -1.0
    theta = math.acos(cosine) * 2.0 / 2.0
    if theta == 0.0:
        return q0
    d = 1.0 / math.sin(theta)
    s0 = math.sin((1.0 - ratio) * theta)
    s1 = math.sin(ratio * theta)
    if dot < 0:
        s1 = -s1
    return (
        (x0 * s0 + x1 * s1) * d,
        (y0 * s0 + y1 * s1) * d,
        (z0 * s0 + z1 * s1) * d,
        (w0 * s0 + w1 * s1) * d,
    )


def _cos_sin(angle: float) -> tuple[float, float]:
    return math.cos(angle), math.sin(angle)


def quat_from_rpy(roll: float, pitch: float, yaw: float) -> Quat:
    """
    Return the quaternion of fixed-axis X-Y-Z angles (tf2 ``Quaternion::setRPY``).

    The rotation is ``Rz(yaw) * Ry(pitch) * Rx(roll)``: roll is applied first.
    """
    cr, sr = _cos_sin(roll * 0.5)
    cp, sp = _cos_sin(pitch * 0.5)
    cy, sy = _cos_sin(yaw * 0.5)
    return (
        sr * cp * cy - cr * sp * sy,
        cr * sp * cy + sr * cp * sy,
        cr * cp * sy - sr * sp * cy,
        cr * cp * cy + sr * sp * sy,
    )


def matrix_from_rpy(roll: float, pitch: float, yaw: float) -> Matrix3:
    """Return the matrix ``Rz(yaw) * Ry(pitch) * Rx(roll)`` (tf2 ``Matrix3x3::setRPY``)."""
    ci, si = _cos_sin(roll)
    cj, sj = _cos_sin(pitch)
    ch, sh = _cos_sin(yaw)
    cc = ci * ch
    cs = ci * sh
    sc = si * ch
    ss = si * sh
    return (
        (cj * ch, sj * sc - cs, sj * cc + ss),
        (cj * sh, sj * ss + cc, sj * cs - sc),
        (-sj, cj * si, cj * ci),
    )


def rpy_from_matrix(m: Matrix3, solution: int = 1) -> tuple[float, float, float]:
    """
    Return ``(roll, pitch, yaw)`` of a rotation matrix (tf2 ``Matrix3x3::getRPY``).

    At gimbal lock (``|m[2][0]| >= 1``) yaw is 0, pitch is +-pi/2 and roll is
    ``atan2(m[2][1], m[2][2])``, literally as tf2 does.  ``solution=2`` gives tf2's second
    solution (pitch' = pi - pitch).
    """
    r20 = m[2][0]
    if abs(r20) >= 1:
        pitch = _HALF_PI if r20 < 0 else -_HALF_PI
        return math.atan2(m[2][1], m[2][2]), pitch, 0.0
    pitch = -math.asin(r20)
    if solution != 1:
        pitch = math.pi - pitch
    cos_pitch = math.cos(pitch)
    roll = math.atan2(m[2][1] / cos_pitch, m[2][2] / cos_pitch)
    yaw = math.atan2(m[1][0] / cos_pitch, m[0][0] / cos_pitch)
    return roll, pitch, yaw


def rpy_from_quat(q: Quat, solution: int = 1) -> tuple[float, float, float]:
    """
    Return ``(roll, pitch, yaw)`` of a quaternion, as ``tf2::Matrix3x3(q).getRPY``.

    Inverse of :func:`quat_from_rpy` for ``|pitch| < pi/2``; see :func:`rpy_from_matrix` for the
    gimbal-lock convention.
    """
    return rpy_from_matrix(matrix_from_quat(q), solution)


def quat_from_axis_angle(axis: Vec3, angle: float) -> Quat:
    """
    Return the rotation of ``angle`` radians about ``axis`` (need not be unit length).

    :raises ValueError: if ``axis`` has zero length.
    """
    length = math.sqrt(axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2])
    if not length:
        raise ValueError('rotation axis must not be the zero vector')
    s = math.sin(angle * 0.5) / length
    return (axis[0] * s, axis[1] * s, axis[2] * s, math.cos(angle * 0.5))


def matrix_from_quat(q: Quat) -> Matrix3:
    """
    Return the 3x3 rotation matrix (row tuples) of ``q``; divides by ``|q|^2`` like tf2.

    A zero quaternion gives a matrix of NaNs (tf2 then rejects the transform).
    """
    x, y, z, w = q
    d = x * x + y * y + z * z + w * w
    s = 2.0 / d if d else math.nan
    xs, ys, zs = x * s, y * s, z * s
    wx, wy, wz = w * xs, w * ys, w * zs
    xx, xy, xz = x * xs, x * ys, x * zs
    yy, yz, zz = y * ys, y * zs, z * zs
    return (
        (1.0 - (yy + zz), xy - wz, xz + wy),
        (xy + wz, 1.0 - (xx + zz), yz - wx),
        (xz - wy, yz + wx, 1.0 - (xx + yy)),
    )


def matrix_times(a: Matrix3, b: Matrix3) -> Matrix3:
    """Return the matrix product ``a * b`` with tf2's ``Matrix3x3`` operation order."""
    rows = [
        (
            r[0] * b[0][0] + r[1] * b[1][0] + r[2] * b[2][0],
            r[0] * b[0][1] + r[1] * b[1][1] + r[2] * b[2][1],
            r[0] * b[0][2] + r[1] * b[1][2] + r[2] * b[2][2],
        )
        for r in a
    ]
    return (rows[0], rows[1], rows[2])


def matrix_apply(m: Matrix3, v: Vec3) -> Vec3:
    """Return the matrix-vector product ``m * v`` (tf2's ``Matrix3x3 * Vector3``)."""
    return (
        m[0][0] * v[0] + m[0][1] * v[1] + m[0][2] * v[2],
        m[1][0] * v[0] + m[1][1] * v[1] + m[1][2] * v[2],
        m[2][0] * v[0] + m[2][1] * v[1] + m[2][2] * v[2],
    )


def matrix_transpose(m: Matrix3) -> Matrix3:
    """Return the transpose of ``m`` (the inverse of a rotation matrix)."""
    return ((m[0][0], m[1][0], m[2][0]), (m[0][1], m[1][1], m[2][1]), (m[0][2], m[1][2], m[2][2]))


def matrix_inverse(m: Matrix3) -> Matrix3:
    """
    Return the inverse of ``m`` by cofactors, with tf2's ``Matrix3x3::inverse`` arithmetic.

    For a rotation it equals :func:`matrix_transpose` to rounding; tf2's velocity uses this.
    """
    (a, b, c), (d, e, f), (g, h, i) = m
    co_x, co_y, co_z = e * i - f * h, f * g - d * i, d * h - e * g
    s = 1.0 / (a * co_x + b * co_y + c * co_z)
    return (
        (co_x * s, (c * h - b * i) * s, (b * f - c * e) * s),
        (co_y * s, (a * i - c * g) * s, (c * d - a * f) * s),
        (co_z * s, (b * g - a * h) * s, (a * e - b * d) * s),
    )


def quat_from_matrix(m: Matrix3) -> Quat:
    """
    Return the unit quaternion of a rotation matrix (tf2 ``Matrix3x3::getRotation``).

    The sign is tf2's canonical one: ``w > 0`` when the trace is positive, otherwise the
    component of the largest diagonal element is positive.
    """
    trace = m[0][0] + m[1][1] + m[2][2]
    if trace > 0.0:
        s = math.sqrt(trace + 1.0)
        w = s * 0.5
        s = 0.5 / s
        return ((m[2][1] - m[1][2]) * s, (m[0][2] - m[2][0]) * s, (m[1][0] - m[0][1]) * s, w)
    # Index of the largest diagonal element, with tf2's tie-breaking.
    i = (2 if m[1][1] < m[2][2] else 1) if m[0][0] < m[1][1] else (2 if m[0][0] < m[2][2] else 0)
    j = (i + 1) % 3
    k = (i + 2) % 3
    arg = m[i][i] - m[j][j] - m[k][k] + 1.0
    s = math.sqrt(arg) if arg >= 0.0 else math.nan
    out = [0.0, 0.0, 0.0, 0.0]
    out[i] = s * 0.5
    s = 0.5 / s if s else math.inf
    out[3] = (m[k][j] - m[j][k]) * s
    out[j] = (m[j][i] + m[i][j]) * s
    out[k] = (m[k][i] + m[i][k]) * s
    return (out[0], out[1], out[2], out[3])


def canonical_quat(q: Sequence[float]) -> Quat:
    """
    Return ``q`` as tf2 stores it: normalised and sign-canonicalised, bit for bit.

    tf2 converts the message quaternion to a matrix (dividing by ``|q|^2``) and back
    (``Matrix3x3::setRotation`` then ``getRotation``).  When the matrix's trace is positive
    (rotations under 120 degrees, the common case) only the entries that ``getRotation`` reads
    are computed, with tf2's arithmetic; otherwise the full round trip runs.  The result equals
    :func:`quat_from_matrix` of :func:`matrix_from_quat` exactly, so printed values near zero
    keep tf2's sign.  Zero, infinite or NaN input yields NaN components.  ``q`` may be any
    sequence of 4 numbers.
    """
    x, y, z, w = q
    d = x * x + y * y + z * z + w * w
    if not d:
        return (math.nan, math.nan, math.nan, math.nan)
    s = 2.0 / d
    xs, ys, zs = x * s, y * s, z * s
    xx, yy, zz = x * xs, y * ys, z * zs
    trace = (1.0 - (yy + zz)) + (1.0 - (xx + zz)) + (1.0 - (xx + yy))
    if trace > 0.0:
        wx, wy, wz = w * xs, w * ys, w * zs
        xy, xz, yz = x * ys, x * zs, y * zs
        root = math.sqrt(trace + 1.0)
        half_inverse = 0.5 / root
        return (
            ((yz + wx) - (yz - wx)) * half_inverse,
            ((xz + wy) - (xz - wy)) * half_inverse,
            ((xy + wz) - (xy - wz)) * half_inverse,
            root * 0.5,
        )
    return quat_from_matrix(matrix_from_quat((x, y, z, w)))


def homogeneous_from_transform(t: Vec3, q: Quat) -> npt.NDArray[np.float64]:
    """Return the 4x4 homogeneous matrix of ``(t, q)``."""
    import numpy as np

    out = np.eye(4)
    out[:3, :3] = matrix_from_quat(q)
    out[:3, 3] = t
    return out


def transform_from_homogeneous(matrix: npt.ArrayLike) -> tuple[Vec3, Quat]:
    """
    Return ``(t, q)`` of a 4x4 homogeneous matrix (rotation part assumed orthonormal).

    :raises ValueError: if ``matrix`` is not 4x4.
    """
    import numpy as np

    m = np.asarray(matrix, dtype=float)
    if m.shape != (4, 4):
        raise ValueError(f'expected a 4x4 matrix, got shape {m.shape}')
    rows = m[:3, :3].tolist()
    rotation: Matrix3 = (
        (rows[0][0], rows[0][1], rows[0][2]),
        (rows[1][0], rows[1][1], rows[1][2]),
        (rows[2][0], rows[2][1], rows[2][2]),
    )
    t = m[:3, 3].tolist()
    return (t[0], t[1], t[2]), quat_from_matrix(rotation)


# --- vectorised helpers on (N, 3) / (N, 4) float64 arrays -----------------------------------


def _columns(array: npt.NDArray[np.float64]) -> tuple[npt.NDArray[np.float64], ...]:
    """Return the last axis of ``array`` as separate component arrays."""
    return tuple(array[..., i] for i in range(array.shape[-1]))


def quat_multiply_batch(
    a: npt.NDArray[np.float64], b: npt.NDArray[np.float64]
) -> npt.NDArray[np.float64]:
    """Row-wise :func:`quat_multiply` of two ``(N, 4)`` arrays (either may broadcast)."""
    import numpy as np

    ax, ay, az, aw = _columns(a)
    bx, by, bz, bw = _columns(b)
    return np.stack(quat_multiply_lanes((ax, ay, az, aw), (bx, by, bz, bw)), axis=-1)


def rotate_vector_batch(
    q: npt.NDArray[np.float64], v: npt.NDArray[np.float64]
) -> npt.NDArray[np.float64]:
    """Row-wise :func:`rotate_vector` of ``(N, 4)`` quaternions and ``(N, 3)`` vectors."""
    import numpy as np

    qx, qy, qz, qw = _columns(q)
    vx, vy, vz = _columns(v)
    return np.stack(rotate_vector_lanes((qx, qy, qz, qw), (vx, vy, vz)), axis=-1)


def compose_batch(
    t_a: npt.NDArray[np.float64],
    q_a: npt.NDArray[np.float64],
    t_b: npt.NDArray[np.float64],
    q_b: npt.NDArray[np.float64],
) -> tuple[npt.NDArray[np.float64], npt.NDArray[np.float64]]:
    """Row-wise :func:`compose`."""
    return rotate_vector_batch(q_a, t_b) + t_a, quat_multiply_batch(q_a, q_b)


def slerp_batch(
    q0: npt.NDArray[np.float64], q1: npt.NDArray[np.float64], ratio: npt.NDArray[np.float64]
) -> npt.NDArray[np.float64]:
    """Row-wise :func:`slerp` with the same special cases (``theta == 0`` returns ``q0``)."""
    import numpy as np

    dot = np.einsum('ij,ij->i', q0, q1)
    scale = np.sqrt(np.einsum('ij,ij->i', q0, q0) * np.einsum('ij,ij->i', q1, q1))
    cosine = np.clip(np.abs(dot) / scale, -1.0, 1.0)
    theta = np.arccos(cosine) * 2.0 / 2.0
    moving = theta != 0.0
    safe_theta = np.where(moving, theta, 1.0)
    d = 1.0 / np.sin(safe_theta)
    s0 = np.sin((1.0 - ratio) * safe_theta)
    s1 = np.sin(ratio * safe_theta)
    s1 = np.where(dot < 0, -s1, s1)
    out = (q0 * s0[:, None] + q1 * s1[:, None]) * d[:, None]
    return np.where(moving[:, None], out, q0)


def matrix_from_quat_batch(q: npt.NDArray[np.float64]) -> npt.NDArray[np.float64]:
    """Row-wise :func:`matrix_from_quat`: ``(N, 4)`` quaternions to ``(N, 3, 3)`` matrices."""
    import numpy as np

    x, y, z, w = q[:, 0], q[:, 1], q[:, 2], q[:, 3]
    with np.errstate(divide='ignore', invalid='ignore'):
        s = 2.0 / (x * x + y * y + z * z + w * w)
    xs, ys, zs = x * s, y * s, z * s
    wx, wy, wz = w * xs, w * ys, w * zs
    xx, xy, xz = x * xs, x * ys, x * zs
    yy, yz, zz = y * ys, y * zs, z * zs
    out = np.empty((q.shape[0], 3, 3))
    out[:, 0, 0] = 1.0 - (yy + zz)
    out[:, 0, 1] = xy - wz
    out[:, 0, 2] = xz + wy
    out[:, 1, 0] = xy + wz
    out[:, 1, 1] = 1.0 - (xx + zz)
    out[:, 1, 2] = yz - wx
    out[:, 2, 0] = xz - wy
    out[:, 2, 1] = yz + wx
    out[:, 2, 2] = 1.0 - (xx + yy)
    return out


def quat_from_matrix_batch(m: npt.NDArray[np.float64]) -> npt.NDArray[np.float64]:
    """Row-wise :func:`quat_from_matrix`: ``(N, 3, 3)`` matrices to ``(N, 4)`` quaternions."""
    import numpy as np

    count = m.shape[0]
    out = np.empty((count, 4))
    trace = m[:, 0, 0] + m[:, 1, 1] + m[:, 2, 2]
    positive = trace > 0.0
    largest = np.where(
        m[:, 0, 0] < m[:, 1, 1],
        np.where(m[:, 1, 1] < m[:, 2, 2], 2, 1),
        np.where(m[:, 0, 0] < m[:, 2, 2], 2, 0),
    )
    with np.errstate(divide='ignore', invalid='ignore'):
        rows = np.flatnonzero(positive)
        if rows.size:
            mm = m[rows]
            s = np.sqrt(trace[rows] + 1.0)
            out[rows, 3] = s * 0.5
            s = 0.5 / s
            out[rows, 0] = (mm[:, 2, 1] - mm[:, 1, 2]) * s
            out[rows, 1] = (mm[:, 0, 2] - mm[:, 2, 0]) * s
            out[rows, 2] = (mm[:, 1, 0] - mm[:, 0, 1]) * s
        for i in range(3):
            rows = np.flatnonzero(~positive & (largest == i))
            if not rows.size:
                continue
            j = (i + 1) % 3
            k = (i + 2) % 3
            mm = m[rows]
            s = np.sqrt(mm[:, i, i] - mm[:, j, j] - mm[:, k, k] + 1.0)
            out[rows, i] = s * 0.5
            s = 0.5 / s
            out[rows, 3] = (mm[:, k, j] - mm[:, j, k]) * s
            out[rows, j] = (mm[:, j, i] + mm[:, i, j]) * s
            out[rows, k] = (mm[:, k, i] + mm[:, i, k]) * s
    return out


def canonical_quat_rows(
    x: FloatArray, y: FloatArray, z: FloatArray, w: FloatArray
) -> tuple[FloatArray, FloatArray, FloatArray, FloatArray]:
    """
    Element-wise :func:`canonical_quat` of four component arrays, bit for bit.

    The same arithmetic as the scalar function, on whole arrays; contiguous components (and
    arrays that fit in cache) make it several times faster than on an ``(N, 4)`` array's columns.
    """
    import numpy as np

    with np.errstate(divide='ignore', invalid='ignore'):
        s = 2.0 / (x * x + y * y + z * z + w * w)
        xs, ys, zs = x * s, y * s, z * s
        xx, yy, zz = x * xs, y * ys, z * zs
        trace = (1.0 - (yy + zz)) + (1.0 - (xx + zz)) + (1.0 - (xx + yy))
        wx, wy, wz = w * xs, w * ys, w * zs
        xy, xz, yz = x * ys, x * zs, y * zs
        root = np.sqrt(trace + 1.0)
        half_inverse = 0.5 / root
        qx = ((yz + wx) - (yz - wx)) * half_inverse
        qy = ((xz + wy) - (xz - wy)) * half_inverse
        qz = ((xy + wz) - (xy - wz)) * half_inverse
        qw = root * 0.5
    rows = np.flatnonzero(~(trace > 0.0))
    if rows.size:  # the full matrix round trip, as the scalar function's other branch
        full = quat_from_matrix_batch(
            matrix_from_quat_batch(np.stack((x[rows], y[rows], z[rows], w[rows]), axis=1))
        )
        qx[rows], qy[rows], qz[rows], qw[rows] = full.T
    return qx, qy, qz, qw


def canonical_quat_batch(
    q: npt.NDArray[np.float64], out: npt.NDArray[np.float64] | None = None
) -> npt.NDArray[np.float64]:
    """
    Row-wise :func:`canonical_quat`, bit for bit (:func:`canonical_quat_rows` on the columns).

    :param out: ``(N, 4)`` array to write into (may be ``q`` itself); a new C-contiguous one
        by default.
    """
    import numpy as np

    components = canonical_quat_rows(q[:, 0], q[:, 1], q[:, 2], q[:, 3])
    result = np.empty((q.shape[0], 4)) if out is None else out
    for column, values in enumerate(components):
        result[:, column] = values
    return result
