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

"""Buffer: tf2_ros's API over the real core (its waits: test_buffer_waits.py)."""

from __future__ import annotations

from collections.abc import Callable
import copy
from typing import Any
from typing import cast

import pytest
from tf_demo.core.exceptions import ExtrapolationException
from tf_demo.core.exceptions import ForwardExtrapolationException
from tf_demo.ros import Buffer
from tf_demo.ros import TypeException
from tf_demo.transport.clock import Duration
from tf_demo.transport.clock import ROSClock
from tf_demo.transport.clock import Time
from tf_demo.transport.messages import builtin_interfaces
from tf_demo.transport.messages import geometry_msgs

S = 1_000_000_000


def transform_msg(
    parent: str,
    child: str,
    stamp_ns: int,
    translation: tuple[float, float, float] = (0.0, 0.0, 0.0),
    rotation: tuple[float, float, float, float] = (0.0, 0.0, 0.0, 1.0),
) -> geometry_msgs.TransformStamped:
    t = geometry_msgs.TransformStamped()
    t.header.frame_id = parent
    t.header.stamp.sec, t.header.stamp.nanosec = divmod(stamp_ns, S)
    t.child_frame_id = child
    tr, q = t.transform.translation, t.transform.rotation
    tr.x, tr.y, tr.z = translation
    q.x, q.y, q.z, q.w = rotation
    return t


def sim_clock(start_s: float) -> ROSClock:
    clock = ROSClock()
    clock._set_ros_time_is_active(True)
    clock.set_ros_time_override(Time(seconds=start_s))
    return clock


def test_lookup_returns_the_worlds_transform_stamped() -> None:
    """lookup_transform gives a geometry_msgs TransformStamped with target/source and stamp."""
    buffer = Buffer()
    buffer.set_transform(transform_msg('a', 'b', 2 * S, (1.0, 0.0, 0.0), (1.0, 0, 0, 0)), 'x')
    out = buffer.lookup_transform('a', 'b', Time(seconds=2), Duration(seconds=2))
    assert type(out) is geometry_msgs.TransformStamped
    assert (out.header.frame_id, out.child_frame_id) == ('a', 'b')
    assert (out.header.stamp.sec, out.header.stamp.nanosec) == (2, 0)
    assert out.transform.translation.x == 1.0
    assert out.transform.rotation.x == 1.0


def test_time_arguments_accept_time_message_and_int_ns() -> None:
    """Times may be rclpy-style Time, a builtin_interfaces Time message or int nanoseconds."""
    buffer = Buffer()
    buffer.set_transform(transform_msg('a', 'b', 1 * S, (1.0, 0.0, 0.0)), 'x')
    buffer.set_transform(transform_msg('a', 'b', 3 * S, (3.0, 0.0, 0.0)), 'x')
    as_msg = builtin_interfaces.Time(sec=2, nanosec=0)
    for when in (Time(seconds=2), as_msg, 2 * S):
        assert buffer.lookup_transform('a', 'b', when).transform.translation.x == 2.0


def test_bad_time_type_raises_tf2_py_type_error() -> None:
    """Anything without nanoseconds or sec/nanosec is refused with tf2_py's text."""
    buffer = Buffer()
    # Wrong on purpose (the casts only tell the type checker so): the run-time checks answer.
    with pytest.raises(TypeError, match=r'time must have sec and nanosec, or nanoseconds\.'):
        buffer.lookup_transform('a', 'b', cast('int', 1.5))
    with pytest.raises(TypeError, match=r'duration must have sec and nanosec, or nanoseconds\.'):
        buffer.can_transform('a', 'b', 0, cast('int', 'soon'))


def test_can_transform_debug_tuple_and_core_names() -> None:
    """can_transform(return_debug_tuple=True) and can_transform_core give (bool, text)."""
    buffer = Buffer()
    answer = buffer.can_transform('a', 'b', 0, return_debug_tuple=True)
    assert isinstance(answer, tuple)
    ok, text = answer
    assert ok is False
    assert text == (
        'Invalid frame ID "a" passed to canTransform argument target_frame - frame does not exist'
    )
    assert buffer.can_transform_core('a', 'b', 0) == (ok, text)


def test_set_transform_returns_none_and_static_survives_clear() -> None:
    """set_transform* return None (tf2_ros); NaN is not stored; clear() keeps statics."""
    buffer = Buffer()
    # Typed '-> None'; called through 'object' callables to check what they return at run time.
    set_transform: Callable[..., object] = buffer.set_transform
    set_transform_static: Callable[..., object] = buffer.set_transform_static
    assert set_transform(transform_msg('a', 'b', S, (float('nan'), 0.0, 0.0)), 'x') is None
    assert not buffer.can_transform('a', 'b', S)
    assert set_transform_static(transform_msg('a', 's', 0, (0.0, 1.0, 0.0)), 'x') is None
    assert set_transform(transform_msg('a', 'd', S), 'x') is None
    assert buffer.can_transform('a', 'd', S)
    buffer.clear()
    assert buffer.lookup_transform('a', 's', 0).transform.translation.y == 1.0
    assert not buffer.can_transform('a', 'd', S)


def test_lookup_full_and_latest_common_time() -> None:
    """lookup_transform_full travels through a fixed frame; get_latest_common_time is a Time."""
    buffer = Buffer()
    buffer.set_transform(transform_msg('odom', 'base', 1 * S, (1.0, 0.0, 0.0)), 'x')
    buffer.set_transform(transform_msg('odom', 'base', 2 * S, (3.0, 0.0, 0.0)), 'x')
    out = buffer.lookup_transform_full('base', 2 * S, 'base', 1 * S, 'odom')
    assert out.transform.translation.x == pytest.approx(-2.0)
    assert buffer.get_latest_common_time('odom', 'base').nanoseconds == 2 * S


def test_backward_time_jump_clears_dynamic_keeps_static() -> None:
    """A /clock jump back by 5 s clears the buffer except static transforms."""
    clock = sim_clock(100.0)
    buffer = Buffer(clock=clock)
    buffer.set_transform(transform_msg('a', 'd', 99 * S), 'x')
    buffer.set_transform_static(transform_msg('a', 's', 0), 'x')
    clock.set_ros_time_override(Time(seconds=100.5))
    assert buffer.can_transform('a', 'd', 99 * S)
    clock.set_ros_time_override(Time(seconds=95.0))
    assert not buffer.can_transform('a', 'd', 99 * S)
    assert buffer.can_transform('a', 's', 0)


def test_the_jump_warning_is_on_tf2_buffer_even_with_a_node(
    world_env: dict[str, str], capfd: pytest.CaptureFixture[str]
) -> None:
    """tf2_ros logs the clearing on the logger ``tf2_buffer``, not on the buffer's node."""
    del world_env
    from tf_demo import transport

    transport.init(args=['test'])
    try:
        node = transport.create_node('jumpy')
        clock = sim_clock(100.0)
        buffer = Buffer(node=node, clock=clock)
        clock.set_ros_time_override(Time(seconds=95.0))
        node.destroy_node()
    finally:
        transport.try_shutdown()
    del buffer
    err = capfd.readouterr().err
    assert '[tf2_buffer]: Detected jump back in time. Clearing tf buffer.' in err
    assert '[jumpy]: Detected jump' not in err


def upstream_buffer() -> Buffer:
    """Upstream test_tf2_geometry_msgs setup: a -> b is t=(1,0,0), x-flip, at 2 s."""
    buffer = Buffer()
    buffer.set_transform(transform_msg('a', 'b', 2 * S, (1.0, 0.0, 0.0), (1.0, 0, 0, 0)), 'x')
    return buffer


def stamped(msg: Any, frame: str = 'a') -> Any:
    msg.header.frame_id = frame
    msg.header.stamp.sec = 2
    return msg


def test_transform_point_upstream_vector() -> None:
    """Upstream: PointStamped (1,2,3) in a, transformed to b, is (0,-2,-3); input unchanged."""
    point = stamped(geometry_msgs.PointStamped())
    point.point.x, point.point.y, point.point.z = 1.0, 2.0, 3.0
    before = copy.deepcopy(point)
    out = upstream_buffer().transform(point, 'b', new_type=geometry_msgs.PointStamped)
    assert (out.point.x, out.point.y, out.point.z) == (0.0, -2.0, -3.0)
    assert out.header.frame_id == 'b'
    assert point == before


def test_transform_pose_and_pose_with_covariance_upstream_vectors() -> None:
    """Upstream: poses at (1,2,3) with an x-flip map to (0,-2,-3) in b."""
    buffer = upstream_buffer()
    pose = stamped(geometry_msgs.PoseStamped())
    pose.pose.position.x, pose.pose.position.y, pose.pose.position.z = 1.0, 2.0, 3.0
    pose.pose.orientation = geometry_msgs.Quaternion(x=1.0, y=0.0, z=0.0, w=0.0)
    out = buffer.transform(pose, 'b')
    assert (out.pose.position.x, out.pose.position.y, out.pose.position.z) == (0, -2, -3)
    with_cov = stamped(geometry_msgs.PoseWithCovarianceStamped())
    with_cov.pose.pose = copy.deepcopy(pose.pose)
    out_cov = buffer.transform(with_cov, 'b')
    position = out_cov.pose.pose.position
    assert (position.x, position.y, position.z) == (0, -2, -3)


def test_transform_vector3_and_polygon() -> None:
    """Vector3Stamped is rotated only; PolygonStamped points are moved as points."""
    buffer = upstream_buffer()
    vector = stamped(geometry_msgs.Vector3Stamped())
    vector.vector.x, vector.vector.y, vector.vector.z = 1.0, 2.0, 3.0
    out = buffer.transform(vector, 'b')
    assert (out.vector.x, out.vector.y, out.vector.z) == pytest.approx((1.0, -2.0, -3.0))
    polygon = stamped(geometry_msgs.PolygonStamped())
    polygon.polygon.points = [geometry_msgs.Point32(x=1.0, y=2.0, z=3.0)]
    out_polygon = buffer.transform(polygon, 'b')
    point = out_polygon.polygon.points[0]
    assert (point.x, point.y, point.z) == pytest.approx((0.0, -2.0, -3.0))


def test_transform_full_and_unsupported_type() -> None:
    """transform_full works through a fixed frame; an unknown type raises TypeException."""
    buffer = upstream_buffer()
    point = stamped(geometry_msgs.PointStamped())
    point.point.x = 1.0
    out = buffer.transform_full(point, 'b', 2 * S, 'a')
    assert out.point.x == pytest.approx(0.0)
    with pytest.raises(TypeException, match='is not loaded or supported'):
        buffer.transform(stamped(geometry_msgs.TransformStamped()), 'b')


def test_extrapolation_subclasses_are_exposed() -> None:
    """Python code can tell a future extrapolation from other errors (a tf_demo extra)."""
    buffer = upstream_buffer()
    buffer.set_transform(transform_msg('a', 'b', 3 * S), 'x')
    with pytest.raises(ForwardExtrapolationException, match='extrapolation into the future'):
        buffer.lookup_transform('a', 'b', 5 * S)
    with pytest.raises(ExtrapolationException, match='extrapolation into the past'):
        buffer.lookup_transform('a', 'b', 1 * S)


class _Unreadable:
    """A number whose value cannot be read: the core refuses it with a TypeError."""

    def __init__(self, value: float) -> None:
        self.value = value

    def __float__(self) -> float:
        raise ValueError('unreadable')


def test_insert_decoded_is_the_listeners_fast_path() -> None:
    """Decoded tuples go into the core; a transform whose insert raises is returned, not fatal."""
    buffer = Buffer()
    failures = buffer.insert_decoded(
        [
            ('a', 'b', S, (1.0, 0.0, 0.0), (0.0, 0.0, 0.0, 1.0)),
            ('a', 'bad', S, (cast('float', _Unreadable(1.0)), 0.0, 0.0), (0.0, 0.0, 0.0, 1.0)),
            ('a', 'nan', S, (float('nan'), 0.0, 0.0), (0.0, 0.0, 0.0, 1.0)),
            ('b', 'c', S, (0.0, 2.0, 0.0), (0.0, 0.0, 0.0, 1.0)),
        ],
        'default_authority',
        bytes(16),
        False,
    )
    assert [(parent, child, type(error)) for parent, child, error in failures] == [
        ('a', 'bad', TypeError)
    ]
    assert buffer.lookup_transform('a', 'c', S).transform.translation.y == 2.0
    assert not buffer.can_transform('a', 'nan', S)
    assert 'default_authority' in buffer.all_frames_as_yaml()


def test_the_core_and_tf2_py_names() -> None:
    """Buffer holds its BufferCore (tf_demo's extensions); tf2_py's names answer as upstream."""
    buffer = Buffer()
    buffer.set_transform(transform_msg('odom', 'base', 1 * S, (1.0, 0.0, 0.0)), 'x')
    buffer.set_transform(transform_msg('odom', 'base', 2 * S, (3.0, 0.0, 0.0)), 'x')
    assert buffer.core.frame_ids() == buffer._getFrameStrings() == ['base', 'odom']
    assert buffer.frame_ids() == ['base', 'odom']
    assert buffer._frameExists('odom')
    assert 'odom' in buffer._allFramesAsDot()
    linear, angular = buffer.lookupVelocityCore('base', 'odom', Time(seconds=1.5), S // 2)
    assert (linear, angular) == buffer.core.lookup_velocity('base', 'odom', 3 * S // 2, S // 2)
    assert linear[0] == pytest.approx(2.0)
