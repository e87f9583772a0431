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
The rclpy world's fast ``geometry_msgs/TransformStamped``: rclpy's own class, built and read.

A lookup answers with a TransformStamped of seven nested rclpy messages. Their generated
constructors build every default and then go through a property setter per field, which costs
more than the lookup itself; :func:`new_transform_stamped` makes the same objects with
``__new__`` and writes the fields' slots (``_x``, ``_header``, ...), the layout
``rosidl_generator_py`` generates. Each object gets the ``_check_fields`` its own constructor
would give it (``ROS_PYTHON_CHECK_FIELDS`` as its module read it at import), so the result is
indistinguishable from ``TransformStamped(...)`` filled field by field; a test in the rclpy world
compares them slot by slot. The values are what the setters would accept anyway (floats, str,
``sec``/``nanosec`` split and range-checked by :func:`~tf_demo.msgs.convert.stamp_fields_from_ns`).
:func:`transform_stamped_args` reads one through the same slots, for ``Buffer.set_transform``.
"""

from __future__ import annotations

import sys
from typing import Protocol
from typing import TypeVar

from builtin_interfaces.msg import Time
from geometry_msgs.msg import Quaternion
from geometry_msgs.msg import Transform
from geometry_msgs.msg import TransformStamped
from geometry_msgs.msg import Vector3
from std_msgs.msg import Header
from tf_demo.core.buffer_core import TransformResult
from tf_demo.core.math3d import Quat
from tf_demo.core.math3d import Vec3
from tf_demo.msgs import convert
from tf_demo.msgs.convert import NS_PER_S
from tf_demo.msgs.convert import stamp_fields_from_ns
from tf_demo.msgs.convert import TransformStampedLike


class _GeneratedMessage(Protocol):
    """What rosidl_generator_py gives every message object: its field-check switch."""

    _check_fields: bool


M = TypeVar('M', bound=_GeneratedMessage)


def _checks_fields(cls: type) -> bool:
    """Return the ``_check_fields`` that ``cls()`` gives its instances (its module's setting)."""
    return bool(getattr(sys.modules[cls.__module__], 'ros_python_check_fields', '') == '1')


_CHECK = {cls: _checks_fields(cls) for cls in (Time, Header, Vector3, Quaternion, Transform)}
_CHECK_TIME = _CHECK[Time]
_CHECK_HEADER = _CHECK[Header]
_CHECK_VECTOR3 = _CHECK[Vector3]
_CHECK_QUATERNION = _CHECK[Quaternion]
_CHECK_TRANSFORM = _CHECK[Transform]
_CHECK_STAMPED = _checks_fields(TransformStamped)


def _blank(cls: type[M], check_fields: bool) -> M:
    """Return an instance of rclpy's message class ``cls`` with no field set yet."""
    message = cls.__new__(cls)
    message._check_fields = check_fields
    return message


def new_transform_stamped(target: str, source: str, result: TransformResult) -> TransformStamped:
    """Return the core's ``result`` as rclpy's TransformStamped of ``target`` <- ``source``."""
    sec, nanosec = stamp_fields_from_ns(result.stamp_ns)
    tx, ty, tz = result.translation
    qx, qy, qz, qw = result.rotation
    stamp = _blank(Time, _CHECK_TIME)
    stamp._sec, stamp._nanosec = sec, nanosec
    header = _blank(Header, _CHECK_HEADER)
    header._stamp, header._frame_id = stamp, str(target)
    vector = _blank(Vector3, _CHECK_VECTOR3)
    vector._x, vector._y, vector._z = float(tx), float(ty), float(tz)
    quaternion = _blank(Quaternion, _CHECK_QUATERNION)
    quaternion._x, quaternion._y = float(qx), float(qy)
    quaternion._z, quaternion._w = float(qz), float(qw)
    transform = _blank(Transform, _CHECK_TRANSFORM)
    transform._translation, transform._rotation = vector, quaternion
    message = _blank(TransformStamped, _CHECK_STAMPED)
    message._header, message._child_frame_id, message._transform = header, str(source), transform
    return message


def transform_stamped_args(msg: TransformStampedLike) -> tuple[str, str, int, Vec3, Quat]:
    """
    Return ``(parent, child, stamp_ns, translation, rotation)`` of a TransformStamped.

    rclpy's own message is read through its slots (no property call per field); anything else,
    or one holding foreign objects in its fields, as
    :func:`tf_demo.msgs.convert.transform_stamped_args` reads it.
    """
    if isinstance(msg, TransformStamped):
        try:
            header = msg._header
            stamp = header._stamp
            transform = msg._transform
            t = transform._translation
            r = transform._rotation
            return (
                header._frame_id,
                msg._child_frame_id,
                int(stamp._sec) * NS_PER_S + int(stamp._nanosec),
                (t._x, t._y, t._z),
                (r._x, r._y, r._z, r._w),
            )
        except AttributeError:
            pass
    return convert.transform_stamped_args(msg)
