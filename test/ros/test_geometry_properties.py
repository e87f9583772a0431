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

"""Property tests: do_transform_* agree with core.math3d and with Buffer lookups."""

from __future__ import annotations

from hypothesis import given
import pytest
from tf_demo.core.math3d import compose
from tf_demo.core.math3d import rotate_vector
from tf_demo.msgs import geometry_msgs
from tf_demo.nodes.helpers import make_transform_stamped
from tf_demo.ros import Buffer
from tf_demo.ros.geometry import do_transform_point
from tf_demo.ros.geometry import do_transform_pose
from tf_demo.ros.geometry import do_transform_vector3
from tf_demo.testing.strategies import profile_settings
from tf_demo.testing.strategies import transforms
from tf_demo.testing.strategies import translations

pytestmark = pytest.mark.property

Vec3 = tuple[float, float, float]
Quat = tuple[float, float, float, float]


def same_rotation(a: Quat, b: Quat) -> bool:
    """q and -q are the same rotation."""
    dot = sum(x * y for x, y in zip(a, b, strict=True))
    return abs(abs(dot) - 1.0) < 1e-9


@profile_settings(max_examples=60)
@given(transform=transforms(), pose=transforms())
def test_pose_matches_math3d_compose(
    transform: tuple[Vec3, Quat], pose: tuple[Vec3, Quat]
) -> None:
    """do_transform_pose equals compose(T, pose) from the independent core implementation."""
    (t_t, q_t), (t_p, q_p) = transform, pose
    msg = geometry_msgs.Pose()
    msg.position.x, msg.position.y, msg.position.z = t_p
    o = msg.orientation
    o.x, o.y, o.z, o.w = q_p
    out = do_transform_pose(msg, make_transform_stamped('t', 's', 0, t_t, q_t))
    expected_t, expected_q = compose(t_t, q_t, t_p, q_p)
    position = (out.position.x, out.position.y, out.position.z)
    assert position == pytest.approx(expected_t, abs=1e-9)
    q = out.orientation
    assert same_rotation((q.x, q.y, q.z, q.w), expected_q)
    assert q.w >= 0.0


@profile_settings(max_examples=60)
@given(transform=transforms(), point=translations())
def test_point_and_vector_match_math3d(transform: tuple[Vec3, Quat], point: Vec3) -> None:
    """Points get R p + t and vectors R v, as core.math3d computes them."""
    t_t, q_t = transform
    tf = make_transform_stamped('t', 's', 0, t_t, q_t)
    stamped = geometry_msgs.PointStamped()
    stamped.point.x, stamped.point.y, stamped.point.z = point
    vector = geometry_msgs.Vector3Stamped()
    vector.vector.x, vector.vector.y, vector.vector.z = point
    rotated = rotate_vector(q_t, point)
    out_point = do_transform_point(stamped, tf).point
    out_vector = do_transform_vector3(vector, tf).vector
    expected_point = tuple(r + t for r, t in zip(rotated, t_t, strict=True))
    assert (out_point.x, out_point.y, out_point.z) == pytest.approx(expected_point, abs=1e-9)
    assert (out_vector.x, out_vector.y, out_vector.z) == pytest.approx(rotated, abs=1e-9)


@profile_settings(max_examples=40)
@given(a_t_b=transforms(), point=translations())
def test_buffer_transform_round_trip_returns_the_point(
    a_t_b: tuple[Vec3, Quat], point: Vec3
) -> None:
    """Transforming a point a -> b -> a through the buffer gives it back."""
    buffer = Buffer()
    buffer.set_transform_static(make_transform_stamped('a', 'b', 0, *a_t_b), 'test')
    stamped = geometry_msgs.PointStamped()
    stamped.header.frame_id = 'a'
    stamped.point.x, stamped.point.y, stamped.point.z = point
    back = buffer.transform(buffer.transform(stamped, 'b'), 'a')
    assert back.header.frame_id == 'a'
    assert (back.point.x, back.point.y, back.point.z) == pytest.approx(point, abs=1e-9)
