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
tf2_geometry_msgs for Python: apply a ``TransformStamped`` to geometry messages.

Numerically these follow Jazzy's ``tf2_geometry_msgs.py``: the transform becomes a 4x4 affine
matrix whose rotation comes from the (normalised) quaternion, output orientations are extracted
with the Bar-Itzhack eigenvector method with ``w >= 0``, and covariances are rotated block by block
as ``R @ C @ R.T`` with ``R`` built from the unnormalised quaternion formula.

Differences from upstream, all compatible:

- inputs are never modified (upstream's ``do_transform_vector3`` zeroes the translation of the
  transform it is given, ros/geometry2#233);
- the output header is a *copy* of ``transform.header`` (upstream shares the object);
- outputs are built with ``type(input)()``, so the functions work on rclpy messages and on the
  standalone world's messages alike;
- nothing is registered as an import side effect: :data:`TRANSFORM_FUNCTIONS` is a read-only
  table keyed by ROS type name that :meth:`tf_demo.ros.Buffer.transform` consults.
"""

from __future__ import annotations

from collections.abc import Callable
from collections.abc import Mapping
from collections.abc import Sequence
from types import MappingProxyType
from typing import Any
from typing import Protocol
from typing import TYPE_CHECKING
from typing import TypeVar

from tf_demo.core.lazy_import import lazy_module

if TYPE_CHECKING:
    import numpy as np
    import numpy.typing as npt
    from tf_demo.msgs.convert import HeaderLike
    from tf_demo.msgs.convert import QuaternionLike
    from tf_demo.msgs.convert import TransformStampedLike
    from tf_demo.msgs.convert import Vector3Like
    from tf_demo.msgs.geometry_msgs import PointStamped
    from tf_demo.msgs.geometry_msgs import PolygonStamped
    from tf_demo.msgs.geometry_msgs import Pose
    from tf_demo.msgs.geometry_msgs import PoseStamped
    from tf_demo.msgs.geometry_msgs import PoseWithCovarianceStamped
    from tf_demo.msgs.geometry_msgs import Vector3Stamped

    FloatArray = npt.NDArray[np.float64]
else:
    np = lazy_module('numpy')

#: ``do_transform_*(msg, transform)``: the table holds one per message type, so ``msg`` (and the
#: result, of the same type) can only be typed per function.
TransformFunction = Callable[[Any, 'TransformStampedLike'], Any]


class _Stamped(Protocol):
    @property
    def header(self) -> HeaderLike: ...


class QuaternionStampedLike(_Stamped, Protocol):
    """A ``geometry_msgs/QuaternionStamped`` of any message class (none in the standalone set)."""

    @property
    def quaternion(self) -> QuaternionLike: ...


class _WrenchLike(Protocol):
    @property
    def force(self) -> Vector3Like: ...

    @property
    def torque(self) -> Vector3Like: ...


class WrenchStampedLike(_Stamped, Protocol):
    """A ``geometry_msgs/WrenchStamped`` of any message class (none in the standalone set)."""

    @property
    def wrench(self) -> _WrenchLike: ...


QuaternionStampedT = TypeVar('QuaternionStampedT', bound=QuaternionStampedLike)
WrenchStampedT = TypeVar('WrenchStampedT', bound=WrenchStampedLike)


def ros_type_name(msg_type: type) -> str:
    """Return the ROS type name (``pkg/msg/Name``) of a message class from either world."""
    declared = getattr(msg_type, '__msgtype__', None)
    if isinstance(declared, str):
        return declared
    package = msg_type.__module__.split('.', 1)[0]
    return f'{package}/msg/{msg_type.__name__}'


def _matrix_from_quat_wxyz(w: float, x: float, y: float, z: float) -> FloatArray:
    """Rotation matrix of a quaternion, normalised by its squared norm (identity if ~0)."""
    quat = np.array([w, x, y, z], dtype=np.float64)
    norm_sq = float(np.sum(np.square(quat)))
    if norm_sq < np.finfo(np.float64).eps:
        return np.eye(3)
    scaled = quat[1:] * 2.0 / norm_sq
    w_s = scaled * quat[0]
    x_s = scaled * quat[1]
    y_s = scaled[1:] * quat[2]
    z_s = scaled[2] * quat[3]
    return np.array(
        [
            [1.0 - (y_s[0] + z_s), x_s[1] - w_s[2], x_s[2] + w_s[1]],
            [x_s[1] + w_s[2], 1.0 - (x_s[0] + z_s), y_s[1] - w_s[0]],
            [x_s[2] - w_s[1], y_s[1] + w_s[0], 1.0 - (x_s[0] + y_s[0])],
        ]
    )


def _quat_wxyz_from_matrix(rotation: FloatArray) -> FloatArray:
    """Quaternion (w, x, y, z) of a rotation matrix, Bar-Itzhack's method, with ``w >= 0``."""
    qxx, qyx, qzx, qxy, qyy, qzy, qxz, qyz, qzz = rotation.flat
    k_matrix = (
        np.array(
            [
                [qxx - qyy - qzz, 0.0, 0.0, 0.0],
                [qyx + qxy, qyy - qxx - qzz, 0.0, 0.0],
                [qzx + qxz, qzy + qyz, qzz - qxx - qyy, 0.0],
                [qyz - qzy, qzx - qxz, qxy - qyx, qxx + qyy + qzz],
            ]
        )
        / 3.0
    )
    values, vectors = np.linalg.eigh(k_matrix)
    quat: FloatArray = vectors[[3, 0, 1, 2], np.argmax(values)]
    if quat[0] < 0:
        quat = -quat
    return quat


def _affine(
    rotation_wxyz: Sequence[float] | None = None, translation: Sequence[float] | None = None
) -> FloatArray:
    affine = np.eye(4)
    if rotation_wxyz is not None:
        affine[:3, :3] = _matrix_from_quat_wxyz(*rotation_wxyz)
    if translation is not None:
        affine[:3, 3] = np.asarray(translation, dtype=np.float64)
    return affine


def _affine_from_transform(
    transform: TransformStampedLike, *, with_translation: bool = True
) -> FloatArray:
    rotation = transform.transform.rotation
    translation = transform.transform.translation
    return _affine(
        (rotation.w, rotation.x, rotation.y, rotation.z),
        (translation.x, translation.y, translation.z) if with_translation else None,
    )


def _apply_to_xyz(affine: FloatArray, x: float, y: float, z: float) -> tuple[float, float, float]:
    moved = np.matmul(affine, _affine(translation=(x, y, z)))[:3, 3]
    return float(moved[0]), float(moved[1]), float(moved[2])


def _copy_header_from_transform(out: _Stamped, transform: TransformStampedLike) -> None:
    """Set ``out.header`` to a copy of the transform's header (target frame, transform stamp)."""
    out.header.frame_id = transform.header.frame_id
    out.header.stamp.sec = transform.header.stamp.sec
    out.header.stamp.nanosec = transform.header.stamp.nanosec


def _set_xyz(target: Vector3Like, xyz: tuple[float, float, float]) -> None:
    target.x, target.y, target.z = xyz


def _set_quat_from_wxyz(target: QuaternionLike, quat_wxyz: FloatArray) -> None:
    target.w = float(quat_wxyz[0])
    target.x = float(quat_wxyz[1])
    target.y = float(quat_wxyz[2])
    target.z = float(quat_wxyz[3])


def _rotation_matrix_unnormalised(transform: TransformStampedLike) -> FloatArray:
    """Rotation matrix from the unit-quaternion formula (no normalisation), as upstream."""
    rotation = transform.transform.rotation
    q0, q1, q2, q3 = rotation.w, rotation.x, rotation.y, rotation.z
    return np.array(
        [
            [2 * (q0 * q0 + q1 * q1) - 1, 2 * (q1 * q2 - q0 * q3), 2 * (q1 * q3 + q0 * q2)],
            [2 * (q1 * q2 + q0 * q3), 2 * (q0 * q0 + q2 * q2) - 1, 2 * (q2 * q3 - q0 * q1)],
            [2 * (q1 * q3 - q0 * q2), 2 * (q2 * q3 + q0 * q1), 2 * (q0 * q0 + q3 * q3) - 1],
        ]
    )


def transform_covariance(
    covariance: npt.ArrayLike, transform: TransformStampedLike
) -> list[float]:
    """
    Rotate a row-major 6x6 pose covariance: each 3x3 block ``C`` becomes ``R @ C @ R.T``.

    :param covariance: 36 numbers, row-major (x, y, z, rot x, rot y, rot z).
    :param transform: a ``TransformStamped``; only its rotation is used.
    :return: the rotated covariance as 36 floats.
    """
    values = np.asarray(covariance, dtype=np.float64)
    if values.shape != (36,):
        msg = f'covariance must have 36 elements, got {values.size}'
        raise ValueError(msg)
    rotation = _rotation_matrix_unnormalised(transform)
    full = values.reshape(6, 6)
    out = np.empty((6, 6))
    for row in (0, 3):
        for col in (0, 3):
            block = full[row : row + 3, col : col + 3]
            out[row : row + 3, col : col + 3] = rotation @ block @ rotation.T
    return [float(v) for v in out.flat]


def do_transform_point(point: PointStamped, transform: TransformStampedLike) -> PointStamped:
    """
    Transform a ``PointStamped``: ``p' = R p + t``; header from the transform.

    :param point: the stamped point (not modified).
    :param transform: target_T_source as a ``TransformStamped`` (not modified).
    :return: a new ``PointStamped`` of the input's type.
    """
    res = type(point)()
    src = point.point
    _set_xyz(res.point, _apply_to_xyz(_affine_from_transform(transform), src.x, src.y, src.z))
    _copy_header_from_transform(res, transform)
    return res


def do_transform_vector3(
    vector3: Vector3Stamped, transform: TransformStampedLike
) -> Vector3Stamped:
    """
    Transform a ``Vector3Stamped``: rotation only (``v' = R v``); inputs are not modified.

    :param vector3: the stamped vector.
    :param transform: target_T_source as a ``TransformStamped``.
    :return: a new ``Vector3Stamped`` of the input's type.
    """
    res = type(vector3)()
    src = vector3.vector
    affine = _affine_from_transform(transform, with_translation=False)
    _set_xyz(res.vector, _apply_to_xyz(affine, src.x, src.y, src.z))
    _copy_header_from_transform(res, transform)
    return res


def do_transform_pose(pose: Pose, transform: TransformStampedLike) -> Pose:
    """
    Transform an unstamped ``Pose`` (position and orientation) by a ``TransformStamped``.

    :param pose: the pose (not modified).
    :param transform: target_T_source.
    :return: a new ``Pose`` of the input's type; orientation with ``w >= 0``.
    """
    position, orientation = pose.position, pose.orientation
    moved = np.matmul(
        _affine_from_transform(transform),
        _affine(
            (orientation.w, orientation.x, orientation.y, orientation.z),
            (position.x, position.y, position.z),
        ),
    )
    res = type(pose)()
    _set_xyz(res.position, (float(moved[0, 3]), float(moved[1, 3]), float(moved[2, 3])))
    _set_quat_from_wxyz(res.orientation, _quat_wxyz_from_matrix(moved[:3, :3]))
    return res


def do_transform_pose_stamped(pose: PoseStamped, transform: TransformStampedLike) -> PoseStamped:
    """
    Transform a ``PoseStamped``; header from the transform.

    :param pose: the stamped pose (not modified).
    :param transform: target_T_source.
    :return: a new ``PoseStamped`` of the input's type.
    """
    res = type(pose)()
    res.pose = do_transform_pose(pose.pose, transform)
    _copy_header_from_transform(res, transform)
    return res


def do_transform_pose_with_covariance_stamped(
    pose: PoseWithCovarianceStamped, transform: TransformStampedLike
) -> PoseWithCovarianceStamped:
    """
    Transform a ``PoseWithCovarianceStamped``: the pose as above, covariance ``R C Rᵀ``.

    :param pose: the stamped pose with covariance (not modified).
    :param transform: target_T_source.
    :return: a new ``PoseWithCovarianceStamped`` of the input's type.
    """
    res = type(pose)()
    res.pose.pose = do_transform_pose(pose.pose.pose, transform)
    res.pose.covariance = transform_covariance(pose.pose.covariance, transform)
    _copy_header_from_transform(res, transform)
    return res


def do_transform_polygon_stamped(
    polygon: PolygonStamped, transform: TransformStampedLike
) -> PolygonStamped:
    """
    Transform every ``Point32`` of a ``PolygonStamped`` as a point.

    :param polygon: the stamped polygon (not modified).
    :param transform: target_T_source.
    :return: a new ``PolygonStamped`` of the input's type.
    """
    res = type(polygon)()
    affine = _affine_from_transform(transform)
    points = []
    for src in polygon.polygon.points:
        out = type(src)()
        _set_xyz(out, _apply_to_xyz(affine, src.x, src.y, src.z))
        points.append(out)
    res.polygon.points = points
    _copy_header_from_transform(res, transform)
    return res


def do_transform_quaternion_stamped(
    quaternion: QuaternionStampedT, transform: TransformStampedLike
) -> QuaternionStampedT:
    """
    Rotate a ``QuaternionStamped`` (as C++ tf2_geometry_msgs does); ``w >= 0`` on output.

    :param quaternion: the stamped orientation (not modified).
    :param transform: target_T_source; its translation is irrelevant.
    :return: a new ``QuaternionStamped`` of the input's type.
    """
    src = quaternion.quaternion
    rotated = np.matmul(
        _affine_from_transform(transform, with_translation=False),
        _affine((src.w, src.x, src.y, src.z)),
    )
    res = type(quaternion)()
    _set_quat_from_wxyz(res.quaternion, _quat_wxyz_from_matrix(rotated[:3, :3]))
    _copy_header_from_transform(res, transform)
    return res


def do_transform_wrench_stamped(
    wrench: WrenchStampedT, transform: TransformStampedLike
) -> WrenchStampedT:
    """
    Rotate the force and torque of a ``WrenchStamped`` (C++ tf2_geometry_msgs semantics).

    :param wrench: the stamped wrench (not modified).
    :param transform: target_T_source; only the rotation is applied, as in C++.
    :return: a new ``WrenchStamped`` of the input's type.
    """
    res = type(wrench)()
    affine = _affine_from_transform(transform, with_translation=False)
    force, torque = wrench.wrench.force, wrench.wrench.torque
    _set_xyz(res.wrench.force, _apply_to_xyz(affine, force.x, force.y, force.z))
    _set_xyz(res.wrench.torque, _apply_to_xyz(affine, torque.x, torque.y, torque.z))
    _copy_header_from_transform(res, transform)
    return res


TRANSFORM_FUNCTIONS: Mapping[str, TransformFunction] = MappingProxyType(
    {
        'geometry_msgs/msg/PointStamped': do_transform_point,
        'geometry_msgs/msg/Vector3Stamped': do_transform_vector3,
        'geometry_msgs/msg/PoseStamped': do_transform_pose_stamped,
        'geometry_msgs/msg/PoseWithCovarianceStamped': do_transform_pose_with_covariance_stamped,
        'geometry_msgs/msg/PolygonStamped': do_transform_polygon_stamped,
        'geometry_msgs/msg/QuaternionStamped': do_transform_quaternion_stamped,
        'geometry_msgs/msg/WrenchStamped': do_transform_wrench_stamped,
    }
)
"""Built-in ``do_transform`` functions by ROS type name; read-only, no import side effects."""
