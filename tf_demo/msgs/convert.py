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
Conversions between ROS messages and the core's plain values.

Duck-typed: the functions read and write fields by name, so they work on rclpy's messages and on
:mod:`tf_demo.msgs`'s alike; the protocols below say which fields (rclpy's classes are untyped,
:mod:`tf_demo.msgs`'s satisfy them). Time is integer nanoseconds throughout the core.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Protocol
from typing import TypeVar

from tf_demo.core.math3d import Quat
from tf_demo.core.math3d import Vec3

NS_PER_S = 1_000_000_000
_INT32_MIN, _INT32_MAX = -(2**31), 2**31 - 1


class StampLike(Protocol):
    """A ``builtin_interfaces/Time`` or ``Duration`` of either world."""

    sec: int
    nanosec: int


class HeaderLike(Protocol):
    """A ``std_msgs/Header`` of either world."""

    frame_id: str

    @property
    def stamp(self) -> StampLike: ...


class Vector3Like(Protocol):
    """A ``geometry_msgs/Vector3`` of either world."""

    x: float
    y: float
    z: float


class QuaternionLike(Vector3Like, Protocol):
    """A ``geometry_msgs/Quaternion`` of either world."""

    w: float


class TransformLike(Protocol):
    """A ``geometry_msgs/Transform`` of either world."""

    @property
    def translation(self) -> Vector3Like: ...

    @property
    def rotation(self) -> QuaternionLike: ...


class TransformStampedLike(Protocol):
    """A ``geometry_msgs/TransformStamped`` of either world."""

    child_frame_id: str

    @property
    def header(self) -> HeaderLike: ...

    @property
    def transform(self) -> TransformLike: ...


TransformStampedT = TypeVar('TransformStampedT', bound=TransformStampedLike)


def ns_from_stamp(time_msg: StampLike) -> int:
    """Return the nanoseconds of a ``builtin_interfaces/Time`` (or ``Duration``)."""
    return int(time_msg.sec) * NS_PER_S + int(time_msg.nanosec)


def stamp_fields_from_ns(ns: int) -> tuple[int, int]:
    """
    Split nanoseconds into ``(sec, nanosec)`` with ``0 <= nanosec < 1e9``, as rclpy does.

    :raises ValueError: ``sec`` does not fit the message's int32.
    """
    sec, nanosec = divmod(int(ns), NS_PER_S)
    if not _INT32_MIN <= sec <= _INT32_MAX:
        msg = f'time {ns} ns is out of the range of builtin_interfaces/Time (int32 seconds)'
        raise ValueError(msg)
    return sec, nanosec


def transform_stamped_args(msg: TransformStampedLike) -> tuple[str, str, int, Vec3, Quat]:
    """Return ``(parent, child, stamp_ns, translation, rotation)`` of a TransformStamped."""
    translation = msg.transform.translation
    rotation = msg.transform.rotation
    return (
        msg.header.frame_id,
        msg.child_frame_id,
        ns_from_stamp(msg.header.stamp),
        (translation.x, translation.y, translation.z),
        (rotation.x, rotation.y, rotation.z, rotation.w),
    )


def fill_transform_stamped(  # noqa: PLR0917 - signature fixed by doc/architecture.md
    msg: TransformStampedT,
    parent: str,
    child: str,
    stamp_ns: int,
    translation: Sequence[float],
    rotation: Sequence[float],
) -> TransformStampedT:
    """
    Write a transform into the TransformStamped ``msg`` (in place) and return ``msg``.

    :param rotation: quaternion as ``(x, y, z, w)``.
    :raises ValueError: the stamp does not fit, or a vector has the wrong length.
    """
    if len(translation) != 3 or len(rotation) != 4:
        text = (
            f'translation needs 3 values and rotation 4, '
            f'got {len(translation)} and {len(rotation)}'
        )
        raise ValueError(text)
    sec, nanosec = stamp_fields_from_ns(stamp_ns)
    msg.header.stamp.sec = sec
    msg.header.stamp.nanosec = nanosec
    msg.header.frame_id = parent
    msg.child_frame_id = child
    out_translation = msg.transform.translation
    out_translation.x, out_translation.y, out_translation.z = (float(v) for v in translation)
    out_rotation = msg.transform.rotation
    out_rotation.x, out_rotation.y, out_rotation.z, out_rotation.w = (float(v) for v in rotation)
    return msg
