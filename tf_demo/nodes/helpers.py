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
Small helpers shared by the tutorial nodes: typed parameters, rotations, message building.

Parameters are declared with ``dynamic_typing`` so that ``-p x:=1`` (an integer) is accepted where
a float is expected, which rclpy otherwise rejects; values are then checked here with one-line
errors (:class:`NodeConfigError`) that name the parameter.
"""

from __future__ import annotations

from collections.abc import Callable
from collections.abc import Sequence
import math
from typing import TYPE_CHECKING
from typing import TypeVar

from tf_demo.core.math3d import Quat
from tf_demo.core.math3d import quat_from_rpy
from tf_demo.core.math3d import Vec3
from tf_demo.msgs.convert import fill_transform_stamped
from tf_demo.transport.backend import NodeConfigError

if TYPE_CHECKING:
    from tf_demo.msgs.geometry_msgs import TransformStamped
    from tf_demo.transport.node import Node
    from tf_demo.transport.qos import QoSProfile

__all__ = [
    'MAX_PERIOD_S',
    'MIN_RATE_HZ',
    'NodeConfigError',
    'as_float',
    'as_frame',
    'as_period_s',
    'as_positive_float',
    'as_rate_hz',
    'as_vector3',
    'declare_checked',
    'declare_flexible',
    'make_transform_stamped',
    'now_ns',
    'rate_error',
    'require_distinct_frames',
    'rotation_from_values',
]

T = TypeVar('T')


def declare_flexible(node: Node, name: str, default: object) -> object:
    """Declare ``name`` with ``default`` and dynamic typing; return its value."""
    from tf_demo.transport.parameters import ParameterDescriptor

    descriptor = ParameterDescriptor(dynamic_typing=True)
    return node.declare_parameter(name, default, descriptor).value


def declare_checked(
    node: Node, name: str, default: object, check: Callable[[str, object], T]
) -> T:
    """Declare ``name`` as :func:`declare_flexible` does; return ``check(name, value)``."""
    return check(name, declare_flexible(node, name, default))


def require_distinct_frames(parent_frame: str, child_frame: str) -> None:
    """Raise :class:`NodeConfigError` when ``parent_frame`` and ``child_frame`` are the same."""
    if parent_frame == child_frame:
        msg = f'parent_frame and child_frame are both {parent_frame!r}'
        raise NodeConfigError(msg)


def as_float(name: str, value: object) -> float:
    """Return ``value`` as a finite float, or raise a one-line error naming ``name``."""
    return _finite_number(
        value,
        lambda: f'parameter {name!r} must be a number, got {_show(value)}',
        lambda: f'parameter {name!r} must be finite, got {_show(value)}',
    )


def _finite_number(
    value: object, not_a_number: Callable[[], str], not_finite: Callable[[], str]
) -> float:
    """Return ``value`` as a finite float; else raise with the text the matching callable makes."""
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        raise NodeConfigError(not_a_number())
    number = _finite_float(value)
    if number is None:
        raise NodeConfigError(not_finite())
    return number


def _finite_float(value: float) -> float | None:
    """``value`` as a float, or None when it is not finite or too large for a double."""
    try:
        number = float(value)
    except OverflowError:  # an int of hundreds of digits
        return None
    return number if math.isfinite(number) else None


def as_positive_float(name: str, value: object) -> float:
    """Return ``value`` as a float > 0, or raise a one-line error naming ``name``."""
    number = as_float(name, value)
    if number <= 0.0:
        msg = f'parameter {name!r} must be > 0, got {_show(value)}'
        raise NodeConfigError(msg)
    return number


MAX_PERIOD_S = (2**63 - 1) / 1e9
"""The longest timer period (``rclcpp::Rate``, rclpy timers): int64 nanoseconds, ~292 years."""
MIN_RATE_HZ = 1.0 / MAX_PERIOD_S


def rate_error(rate_hz: float) -> str | None:
    """Why ``rate_hz`` is not a usable rate (positive, finite, period within int64 ns), or None."""
    if not (rate_hz > 0.0 and math.isfinite(rate_hz)):
        return 'must be a positive finite number of Hz'
    if rate_hz < MIN_RATE_HZ:
        return f'is too small: the period 1/rate must be at most {int(MAX_PERIOD_S)} s'
    return None


def as_rate_hz(name: str, value: object) -> float:
    """Return ``value`` as a rate a timer can run at (see :func:`rate_error`), or raise."""
    number = as_float(name, value)
    problem = rate_error(number)
    if problem is not None:
        msg = f'parameter {name!r} {problem}, got {_show(value)}'
        raise NodeConfigError(msg)
    return number


def as_period_s(name: str, value: object) -> float:
    """Return ``value`` as a timer period in seconds: > 0 and within int64 nanoseconds."""
    number = as_positive_float(name, value)
    if number > MAX_PERIOD_S:
        msg = f'parameter {name!r} must be at most {int(MAX_PERIOD_S)} s, got {_show(value)}'
        raise NodeConfigError(msg)
    return number


def as_frame(name: str, value: object) -> str:
    """Return a valid tf2 frame id (non-empty, no leading '/'), or raise naming ``name``."""
    if not isinstance(value, str) or not value.strip():
        msg = f'parameter {name!r} must be a non-empty frame id, got {value!r}'
        raise NodeConfigError(msg)
    if value.startswith('/'):
        msg = f"parameter {name!r}: tf2 frame ids cannot start with '/', got {value!r}"
        raise NodeConfigError(msg)
    return value


def as_vector3(name: str, value: object) -> Vec3:
    """Return three finite floats, or raise a one-line error naming ``name``."""
    values = _number_list(name, value)
    if len(values) != 3:
        msg = f'{name} must be 3 numbers [x, y, z], got {_show(value)}'
        raise NodeConfigError(msg)
    return values[0], values[1], values[2]


def rotation_from_values(name: str, value: object) -> Quat:
    """
    Return a unit quaternion (x, y, z, w) from 3 numbers (roll, pitch, yaw) or 4 (x, y, z, w).

    :raises NodeConfigError: for another count or a zero quaternion.
    """
    values = _number_list(name, value)
    if len(values) == 3:
        return quat_from_rpy(values[0], values[1], values[2])
    if len(values) == 4:
        norm = math.sqrt(sum(v * v for v in values))
        if norm < 1e-9:
            msg = f'{name} quaternion [x, y, z, w] must not be zero, got {_show(value)}'
            raise NodeConfigError(msg)
        return (values[0] / norm, values[1] / norm, values[2] / norm, values[3] / norm)
    msg = (
        f'{name} must be 3 numbers [roll, pitch, yaw] or 4 [x, y, z, w] (quaternion), '
        f'got {_show(value)}'
    )
    raise NodeConfigError(msg)


def _number_list(name: str, value: object) -> list[float]:
    if hasattr(value, 'tolist'):
        value = value.tolist()
    if isinstance(value, (str, bytes)) or not isinstance(value, Sequence):
        msg = f'{name} must be a list of numbers, got {_show(value)}'
        raise NodeConfigError(msg)
    items = value
    return [
        _finite_number(
            item,
            lambda: f'{name} must be a list of numbers, got {_show(items)}',
            lambda: f'{name} must contain finite numbers, got {_show(items)}',
        )
        for item in items
    ]


MAX_SHOWN_CHARS = 200
"""A value quoted in an error is cut to this many characters."""
_HUGE_INT_BITS = 256


def _show_one(value: object) -> str:
    """``repr`` of one value; an integer too long to print usefully is described instead."""
    if isinstance(value, int) and value.bit_length() > _HUGE_INT_BITS:
        return f'<an integer of about {int(value.bit_length() * math.log10(2)) + 1} digits>'
    return repr(value)


def _show(value: object) -> str:
    """``repr`` of a parameter value for an error, huge integers described, cut to a length."""
    if hasattr(value, 'tolist'):
        value = value.tolist()
    if isinstance(value, (list, tuple)):
        text = '[' + ', '.join(_show_one(item) for item in value) + ']'
    else:
        text = _show_one(value)
    return text if len(text) <= MAX_SHOWN_CHARS else text[: MAX_SHOWN_CHARS - 3] + '...'


def make_transform_stamped(
    parent: str, child: str, stamp_ns: int, translation: Sequence[float], rotation: Sequence[float]
) -> TransformStamped:
    """Build the world's ``geometry_msgs/TransformStamped`` for target_T_source values."""
    from tf_demo.transport.messages import geometry_msgs

    msg = geometry_msgs.TransformStamped()
    fill_transform_stamped(msg, parent, child, stamp_ns, tuple(translation), tuple(rotation))
    return msg


def declare_qos_overrides(
    node: Node, topic: str, entity: str, profile: QoSProfile, policies: Sequence[str]
) -> QoSProfile:
    """
    Apply rclcpp's ``qos_overrides.<topic>.<entity>.<policy>`` parameters to ``profile``.

    Declared read-only with rclcpp's descriptions, as upstream's C++ nodes declare them: they
    take effect from overrides (``-p``, params files) only.

    :raises NodeConfigError: for a value that is not a policy of that name.
    """
    from tf_demo.transport.parameters import ParameterDescriptor
    from tf_demo.transport.qos import DurabilityPolicy
    from tf_demo.transport.qos import HistoryPolicy
    from tf_demo.transport.qos import ReliabilityPolicy

    enums: dict[str, type[HistoryPolicy | ReliabilityPolicy | DurabilityPolicy]] = {
        'history': HistoryPolicy,
        'reliability': ReliabilityPolicy,
        'durability': DurabilityPolicy,
    }
    for policy in policies:
        name = f'qos_overrides.{topic}.{entity}.{policy}'
        current = getattr(profile, policy)
        default = current if policy == 'depth' else current.name.lower()
        descriptor = ParameterDescriptor(
            description=f'qos policy {{{policy}}} for {entity} {{{topic}}}', read_only=True
        )
        value = node.declare_parameter(name, default, descriptor).value
        try:
            if policy == 'depth':
                profile.depth = int(value)
            else:
                setattr(profile, policy, enums[policy][str(value).upper()])
        except (KeyError, ValueError):
            msg = f'invalid value {value!r} for parameter {name}'
            raise NodeConfigError(msg) from None
    return profile


def now_ns(node: Node) -> int:
    """Return the node clock's current time in integer nanoseconds."""
    return int(node.get_clock().now().nanoseconds)
