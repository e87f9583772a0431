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

"""do_transform_* against upstream tf2_geometry_msgs test vectors and hand-computed values."""

from __future__ import annotations

import copy
from dataclasses import dataclass
from dataclasses import field
import math

import numpy as np
import pytest
from tf_demo.msgs import geometry_msgs
from tf_demo.msgs import std_msgs
from tf_demo.msgs.convert import QuaternionLike
from tf_demo.msgs.convert import Vector3Like
from tf_demo.ros import geometry
from tf_demo.ros.geometry import do_transform_point
from tf_demo.ros.geometry import do_transform_polygon_stamped
from tf_demo.ros.geometry import do_transform_pose
from tf_demo.ros.geometry import do_transform_pose_stamped
from tf_demo.ros.geometry import do_transform_pose_with_covariance_stamped
from tf_demo.ros.geometry import do_transform_quaternion_stamped
from tf_demo.ros.geometry import do_transform_vector3
from tf_demo.ros.geometry import do_transform_wrench_stamped
from tf_demo.ros.geometry import ros_type_name
from tf_demo.ros.geometry import TRANSFORM_FUNCTIONS

UPSTREAM_COVARIANCE = [1.0, 2.0, 3.0, 4.0, 5.0, 6.0] * 6
UPSTREAM_EXPECTED_COVARIANCE = [
    1.0, -2.0, -3.0, 4.0, -5.0, -6.0,
    -1.0, 2.0, 3.0, -4.0, 5.0, 6.0,
    -1.0, 2.0, 3.0, -4.0, 5.0, 6.0,
    1.0, -2.0, -3.0, 4.0, -5.0, -6.0,
    -1.0, 2.0, 3.0, -4.0, 5.0, 6.0,
    -1.0, 2.0, 3.0, -4.0, 5.0, 6.0,
]  # fmt: skip


def make_transform(
    translation: tuple[float, float, float],
    rotation_xyzw: tuple[float, float, float, float],
    parent: str = 'b',
    child: str = 'a',
    stamp: tuple[int, int] = (2, 500),
) -> geometry_msgs.TransformStamped:
    t = geometry_msgs.TransformStamped()
    t.header.frame_id = parent
    t.header.stamp.sec, t.header.stamp.nanosec = stamp
    t.child_frame_id = child
    tr, q = t.transform.translation, t.transform.rotation
    tr.x, tr.y, tr.z = translation
    q.x, q.y, q.z, q.w = rotation_xyzw
    return t


def point_stamped(x: float, y: float, z: float, frame: str = 'a') -> geometry_msgs.PointStamped:
    p = geometry_msgs.PointStamped()
    p.header.frame_id = frame
    p.point.x, p.point.y, p.point.z = x, y, z
    return p


def xyz(v: Vector3Like) -> tuple[float, float, float]:
    return (v.x, v.y, v.z)


def xyzw(q: QuaternionLike) -> tuple[float, float, float, float]:
    return (q.x, q.y, q.z, q.w)


SQRT_HALF = math.sqrt(0.5)


def test_point_upstream_vector_inverse_of_x_flip() -> None:
    """Upstream: b_T_a (inverse of t=(1,0,0), q=x-flip) maps (1,2,3) to (0,-2,-3) exactly."""
    b_t_a = make_transform((-1.0, 0.0, 0.0), (1.0, 0.0, 0.0, 0.0))
    out = do_transform_point(point_stamped(1.0, 2.0, 3.0), b_t_a)
    assert xyz(out.point) == (0.0, -2.0, -3.0)


def test_point_hand_computed_yaw_90() -> None:
    """A 90 degree yaw plus translation (1,2,3) maps (1,0,0) to (1,3,3)."""
    t = make_transform((1.0, 2.0, 3.0), (0.0, 0.0, SQRT_HALF, SQRT_HALF))
    out = do_transform_point(point_stamped(1.0, 0.0, 0.0), t)
    assert xyz(out.point) == pytest.approx((1.0, 3.0, 3.0), abs=1e-12)


def test_point_output_header_is_a_copy_of_the_transform_header() -> None:
    """The result carries the transform's frame and stamp, in its own header object."""
    t = make_transform((0.0, 0.0, 0.0), (0.0, 0.0, 0.0, 1.0), parent='map', stamp=(7, 9))
    out = do_transform_point(point_stamped(1.0, 2.0, 3.0, frame='ignored'), t)
    assert out.header.frame_id == 'map'
    assert (out.header.stamp.sec, out.header.stamp.nanosec) == (7, 9)
    assert out.header is not t.header
    out.header.frame_id = 'changed'
    assert t.header.frame_id == 'map'


def test_non_unit_quaternion_is_normalised_like_upstream() -> None:
    """A quaternion of norm 2 rotates like its unit version (upstream divides by |q|^2)."""
    t = make_transform((0.0, 0.0, 0.0), (0.0, 0.0, 2.0 * SQRT_HALF, 2.0 * SQRT_HALF))
    out = do_transform_point(point_stamped(1.0, 0.0, 0.0), t)
    assert xyz(out.point) == pytest.approx((0.0, 1.0, 0.0), abs=1e-12)


def test_vector3_ignores_translation_upstream_vectors() -> None:
    """Upstream: identity rotation keeps (1,0,0); 180 degrees about y gives (-1,0,0)."""
    v = geometry_msgs.Vector3Stamped()
    v.vector.x = 1.0
    identity = make_transform((1.0, 2.0, 3.0), (0.0, 0.0, 0.0, 1.0))
    assert xyz(do_transform_vector3(v, identity).vector) == (1.0, 0.0, 0.0)
    flip_y = make_transform((1.0, 2.0, 3.0), (0.0, 1.0, 0.0, 0.0))
    assert xyz(do_transform_vector3(v, flip_y).vector) == (-1.0, 0.0, 0.0)


def test_vector3_does_not_zero_the_callers_translation() -> None:
    """Unlike Jazzy (ros/geometry2#233), the transform passed in keeps its translation."""
    t = make_transform((1.0, 2.0, 3.0), (0.0, 1.0, 0.0, 0.0))
    before = copy.deepcopy(t)
    do_transform_vector3(geometry_msgs.Vector3Stamped(), t)
    assert t == before


def test_pose_with_covariance_upstream_vector() -> None:
    """Upstream: x-flip, t=(1,2,3) on pose (1,2,3)/x-flip gives (2,0,0), identity, R C R^T."""
    t = make_transform((1.0, 2.0, 3.0), (1.0, 0.0, 0.0, 0.0))
    v = geometry_msgs.PoseWithCovarianceStamped()
    v.header.frame_id = 'a'
    v.pose.covariance = np.array(UPSTREAM_COVARIANCE)
    v.pose.pose.position.x, v.pose.pose.position.y, v.pose.pose.position.z = 1.0, 2.0, 3.0
    q = v.pose.pose.orientation
    q.x, q.y, q.z, q.w = 1.0, 0.0, 0.0, 0.0
    before = copy.deepcopy(v)
    out = do_transform_pose_with_covariance_stamped(v, t)
    assert xyz(out.pose.pose.position) == (2.0, 0.0, 0.0)
    assert xyzw(out.pose.pose.orientation) == pytest.approx((0.0, 0.0, 0.0, 1.0), abs=1e-15)
    assert list(out.pose.covariance) == UPSTREAM_EXPECTED_COVARIANCE
    assert v == before


def test_covariance_yaw_90_swaps_x_and_y_variances() -> None:
    """Hand-computed: a 90 degree yaw swaps the x/y and roll/pitch variances."""
    t = make_transform((5.0, 6.0, 7.0), (0.0, 0.0, SQRT_HALF, SQRT_HALF))
    covariance = np.diag([1.0, 2.0, 3.0, 4.0, 5.0, 6.0]).flatten()
    out = geometry.transform_covariance(covariance, t)
    assert np.allclose(np.diag(np.array(out).reshape(6, 6)), [2.0, 1.0, 3.0, 5.0, 4.0, 6.0])
    assert np.allclose(
        np.array(out).reshape(6, 6) - np.diag(np.diag(np.array(out).reshape(6, 6))), 0
    )


def test_covariance_of_wrong_size_is_a_clear_error() -> None:
    """A covariance that is not 36 numbers is rejected with its size."""
    with pytest.raises(ValueError, match='36 elements, got 35'):
        geometry.transform_covariance([0.0] * 35, make_transform((0, 0, 0), (0, 0, 0, 1)))


def test_pose_stamped_orientation_composes_and_has_positive_w() -> None:
    """Yaw 90 on a pose with yaw 90 gives yaw 180 as (0,0,1,0), position rotated and moved."""
    t = make_transform((1.0, 0.0, 0.0), (0.0, 0.0, SQRT_HALF, SQRT_HALF))
    pose = geometry_msgs.PoseStamped()
    pose.pose.position.x = 2.0
    q = pose.pose.orientation
    q.x, q.y, q.z, q.w = 0.0, 0.0, SQRT_HALF, SQRT_HALF
    out = do_transform_pose_stamped(pose, t)
    assert xyz(out.pose.position) == pytest.approx((1.0, 2.0, 0.0), abs=1e-12)
    assert xyzw(out.pose.orientation) == pytest.approx((0.0, 0.0, 1.0, 0.0), abs=1e-12)
    assert out.header.frame_id == 'b'


def test_pose_orientation_sign_is_canonical_w_nonnegative() -> None:
    """The output orientation has w >= 0 even when the input quaternion has w < 0."""
    t = make_transform((0.0, 0.0, 0.0), (0.0, 0.0, 0.0, 1.0))
    pose = geometry_msgs.Pose()
    q = pose.orientation
    q.x, q.y, q.z, q.w = 0.0, 0.0, -0.6, -0.8
    out = do_transform_pose(pose, t)
    assert xyzw(out.orientation) == pytest.approx((0.0, 0.0, 0.6, 0.8), abs=1e-12)
    assert type(out) is geometry_msgs.Pose


def test_polygon_points_transformed_as_points() -> None:
    """Every Point32 of a polygon goes through R p + t and stays a Point32."""
    t = make_transform((1.0, 2.0, 3.0), (0.0, 0.0, SQRT_HALF, SQRT_HALF))
    polygon = geometry_msgs.PolygonStamped()
    polygon.polygon.points = [
        geometry_msgs.Point32(x=1.0, y=0.0, z=0.0),
        geometry_msgs.Point32(x=0.0, y=1.0, z=0.5),
    ]
    before = copy.deepcopy(polygon)
    out = do_transform_polygon_stamped(polygon, t)
    assert [type(p) for p in out.polygon.points] == [geometry_msgs.Point32] * 2
    assert xyz(out.polygon.points[0]) == pytest.approx((1.0, 3.0, 3.0), abs=1e-6)
    assert xyz(out.polygon.points[1]) == pytest.approx((0.0, 2.0, 3.5), abs=1e-6)
    assert polygon == before


@dataclass
class QuaternionStamped:
    """A message class of its own (no such class in the standalone set): duck typing is enough."""

    header: std_msgs.Header = field(default_factory=std_msgs.Header)
    quaternion: geometry_msgs.Quaternion = field(default_factory=geometry_msgs.Quaternion)


@dataclass
class _Wrench:
    force: geometry_msgs.Vector3 = field(default_factory=geometry_msgs.Vector3)
    torque: geometry_msgs.Vector3 = field(default_factory=geometry_msgs.Vector3)


@dataclass
class WrenchStamped:
    header: std_msgs.Header = field(default_factory=std_msgs.Header)
    wrench: _Wrench = field(default_factory=_Wrench)


def test_quaternion_stamped_is_rotated_by_any_message_class() -> None:
    """Duck-typed message classes work: a yaw of 90 on yaw 90 gives yaw 180."""
    t = make_transform((9.0, 9.0, 9.0), (0.0, 0.0, SQRT_HALF, SQRT_HALF))
    q = QuaternionStamped(quaternion=geometry_msgs.Quaternion(z=SQRT_HALF, w=SQRT_HALF))
    out = do_transform_quaternion_stamped(q, t)
    assert type(out) is QuaternionStamped
    assert xyzw(out.quaternion) == pytest.approx((0.0, 0.0, 1.0, 0.0), abs=1e-12)


def test_wrench_force_and_torque_are_rotated_only() -> None:
    """C++ semantics: force and torque are rotated; translation does not add a moment."""
    t = make_transform((1.0, 2.0, 3.0), (0.0, 0.0, SQRT_HALF, SQRT_HALF))
    force = geometry_msgs.Vector3(x=1.0)
    w = WrenchStamped(wrench=_Wrench(force=force, torque=geometry_msgs.Vector3(y=1.0)))
    out = do_transform_wrench_stamped(w, t)
    assert xyz(out.wrench.force) == pytest.approx((0.0, 1.0, 0.0), abs=1e-12)
    assert xyz(out.wrench.torque) == pytest.approx((-1.0, 0.0, 0.0), abs=1e-12)


def test_registered_types_are_the_upstream_five_plus_extras() -> None:
    """The table covers upstream's registered types by ROS type name."""
    for name in (
        'PointStamped',
        'Vector3Stamped',
        'PoseStamped',
        'PoseWithCovarianceStamped',
        'PolygonStamped',
    ):
        assert ros_type_name(getattr(geometry_msgs, name)) == f'geometry_msgs/msg/{name}'
        assert f'geometry_msgs/msg/{name}' in TRANSFORM_FUNCTIONS
    with pytest.raises(TypeError):
        TRANSFORM_FUNCTIONS['x'] = do_transform_point  # type: ignore[index]
