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
The rclpy world's fast ``geometry_msgs/TransformStamped``: rclpy's own class, built directly.

A lookup answers with a TransformStamped of seven nested rclpy messages. Their generated
constructors build every default and then go through a property setter per field, which costs
more than the lookup itself; :func:`new_transform_stamped` makes the same objects with
``__new__`` and writes the fields' slots (``_x``, ``_header``, ...), the layout
``rosidl_generator_py`` generates. Each object gets the ``_check_fields`` its own constructor
would give it (``ROS_PYTHON_CHECK_FIELDS`` as its module read it at import), so the result is
indistinguishable from ``TransformStamped(...)`` filled field by field; a test in the rclpy world
compares them slot by slot. The values are what the setters would accept anyway (floats, str,
``sec``/``nanosec`` split and range-checked by :func:`~tf_demo.msgs.convert.stamp_fields_from_ns`).
"""

from __future__ import annotations

from collections.abc import Sequence
import sys

from builtin_interfaces.msg import Time
from geometry_msgs.msg import Quaternion
from geometry_msgs.msg import Transform
from geometry_msgs.msg import TransformStamped
from geometry_msgs.msg import Vector3
from std_msgs.msg import Header
from tf_demo.msgs.convert import stamp_fields_from_ns


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


def new_transform_stamped(
    parent: str,
    child: str,
    stamp_ns: int,
    translation: Sequence[float],
    rotation: Sequence[float],
) -> TransformStamped:
    """
    Return rclpy's TransformStamped of ``parent`` -> ``child`` at ``stamp_ns``.

    :param translation: ``(x, y, z)``, as the core answers.
    :param rotation: quaternion as ``(x, y, z, w)``.
    :raises ValueError: the stamp does not fit ``builtin_interfaces/Time``.
    """
    tx, ty, tz = translation
    qx, qy, qz, qw = rotation
    sec, nanosec = stamp_fields_from_ns(stamp_ns)
    stamp = Time.__new__(Time)
    stamp._check_fields = _CHECK_TIME
    stamp._sec = sec
    stamp._nanosec = nanosec
    header = Header.__new__(Header)
    header._check_fields = _CHECK_HEADER
    header._stamp = stamp
    header._frame_id = str(parent)
    vector = Vector3.__new__(Vector3)
    vector._check_fields = _CHECK_VECTOR3
    vector._x, vector._y, vector._z = float(tx), float(ty), float(tz)
    quaternion = Quaternion.__new__(Quaternion)
    quaternion._check_fields = _CHECK_QUATERNION
    quaternion._x, quaternion._y = float(qx), float(qy)
    quaternion._z, quaternion._w = float(qz), float(qw)
    transform = Transform.__new__(Transform)
    transform._check_fields = _CHECK_TRANSFORM
    transform._translation = vector
    transform._rotation = quaternion
    message = TransformStamped.__new__(TransformStamped)
    message._check_fields = _CHECK_STAMPED
    message._header = header
    message._child_frame_id = str(child)
    message._transform = transform
    return message
