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
joint_state_publisher: publishes a JointState for every movable joint of a robot description.

Upstream's contract (``ros/joint_state_publisher`` 2.4.0, spec section 2): free joints start at 0,
or at the middle of their limits when 0 lies outside them, or at ``zeros.<joint>``; limits are
narrowed by ``<safety_controller>`` (``use_smallest_joint_limits``); continuous joints live in
[-pi, pi]; ``<mimic>`` joints follow their source (``use_mimic_tags``), chains included;
``delta`` moves every free joint each tick, bouncing between limits (continuous joints wrap);
``source_list`` topics overwrite free joints' values; ``rate`` is the publishing rate in Hz.
The description comes from a file argument (URDF or xacro) or the latched ``robot_description``
topic; an invalid description received there is reported and the previous one kept.
"""

from __future__ import annotations

from collections.abc import Mapping
from collections.abc import Sequence
from dataclasses import dataclass
from dataclasses import field
import math
import sys
from typing import Any

from tf_demo.nodes import non_ros_arguments
from tf_demo.nodes.helpers import rate_error
from tf_demo.transport import run_node
from tf_demo.transport.messages import builtin_interfaces
from tf_demo.transport.messages import sensor_msgs
from tf_demo.transport.messages import std_msgs
from tf_demo.transport.node import Node
from tf_demo.transport.parameters import Parameter
from tf_demo.transport.qos import DurabilityPolicy
from tf_demo.transport.qos import QoSProfile
from tf_demo.transport.qos import ReliabilityPolicy
from tf_demo.urdf import parse_xacro_args
from tf_demo.urdf import RobotModel
from tf_demo.urdf import UrdfError

__all__ = ['FreeJoint', 'JointStatePublisher', 'JointStateTable', 'joint_state_message', 'main']

NODE_NAME = 'joint_state_publisher'


class JointStatePublisherConfigError(ValueError):
    """The node cannot start (bad parameter or unreadable description file)."""


@dataclass
class FreeJoint:
    """A joint the publisher drives: limits, centre, and current values."""

    minimum: float
    maximum: float
    zero: float
    continuous: bool = False
    position: float | None = None
    velocity: float | None = None
    effort: float | None = None
    forward: bool = True


@dataclass(frozen=True)
class Dependent:
    """A joint computed from another: ``position = factor * parent + offset``."""

    parent: str
    factor: float = 1.0
    offset: float = 0.0


@dataclass
class JointStateTable:
    """
    The state joint_state_publisher publishes, built from a robot model (pure, no ROS).

    :param joint_list: published joint names in URDF document order (free and dependent).
    """

    joint_list: list[str] = field(default_factory=list)
    free_joints: dict[str, FreeJoint] = field(default_factory=dict)
    dependent_joints: dict[str, Dependent] = field(default_factory=dict)
    warnings: list[str] = field(default_factory=list)

    @classmethod
    def from_model(
        cls,
        model: RobotModel,
        *,
        zeros: Mapping[str, float] | None = None,
        dependent_joints: Mapping[str, Dependent] | None = None,
        use_mimic_tags: bool = True,
        use_smallest_joint_limits: bool = True,
        publish_default_positions: bool = True,
        publish_default_velocities: bool = False,
        publish_default_efforts: bool = False,
    ) -> JointStateTable:
        """Select and initialise the joints as upstream's ``init_urdf`` does."""
        table = cls(dependent_joints=dict(dependent_joints or {}))
        zeros = zeros or {}
        for joint in model.joints:
            if joint.type in {'fixed', 'floating', 'planar'}:
                continue
            if joint.type == 'continuous':
                minimum, maximum = -math.pi, math.pi
            else:
                assert joint.limit is not None
                minimum, maximum = joint.limit.lower, joint.limit.upper
            if use_smallest_joint_limits:
                if joint.soft_lower is not None:
                    minimum = max(minimum, joint.soft_lower)
                if joint.soft_upper is not None:
                    maximum = min(maximum, joint.soft_upper)
            table.joint_list.append(joint.name)
            if use_mimic_tags and joint.mimic is not None:
                table.dependent_joints[joint.name] = Dependent(
                    joint.mimic.joint, joint.mimic.multiplier, joint.mimic.offset
                )
                continue
            if joint.name in table.dependent_joints:
                continue
            if joint.name in zeros:
                zero = float(zeros[joint.name])
            elif minimum > 0 or maximum < 0:
                zero = (minimum + maximum) / 2
            else:
                zero = 0.0
            table.free_joints[joint.name] = FreeJoint(
                minimum,
                maximum,
                zero,
                continuous=joint.type == 'continuous',
                position=zero if publish_default_positions else None,
                velocity=0.0 if publish_default_velocities else None,
                effort=0.0 if publish_default_efforts else None,
            )
        for name in list(table.joint_list):
            if name in table.dependent_joints and table.resolve(name) is None:
                table.warnings.append(
                    f"joint '{name}' mimics '{table.dependent_joints[name].parent}', which is not "
                    'a free movable joint; it is not published'
                )
                table.joint_list.remove(name)
        return table

    def resolve(self, name: str) -> tuple[FreeJoint, float, float] | None:
        """Follow a dependent joint to its free joint: ``(joint, factor, offset)``."""
        factor, offset = 1.0, 0.0
        seen = {name}
        current = name
        while current in self.dependent_joints:
            dependent = self.dependent_joints[current]
            offset += factor * dependent.offset
            factor *= dependent.factor
            current = dependent.parent
            if current in seen:
                return None
            seen.add(current)
        joint = self.free_joints.get(current)
        return None if joint is None else (joint, factor, offset)

    def update(self, delta: float) -> None:
        """Move every free joint by ``delta``: bounce at limits, wrap continuous joints."""
        for joint in self.free_joints.values():
            if joint.position is None:
                continue
            if joint.forward:
                joint.position += delta
                if joint.position > joint.maximum:
                    if joint.continuous:
                        joint.position = joint.minimum
                    else:
                        joint.position = joint.maximum
                        joint.forward = False
            else:
                joint.position -= delta
                if joint.position < joint.minimum:
                    joint.position = joint.minimum
                    joint.forward = True

    def apply_source(
        self,
        names: Sequence[str],
        positions: Sequence[float],
        velocities: Sequence[float],
        efforts: Sequence[float],
    ) -> None:
        """Copy values for free joints from a ``source_list`` message (other names ignored)."""
        for index, name in enumerate(names):
            joint = self.free_joints.get(name)
            if joint is None:
                continue
            if index < len(positions):
                joint.position = float(positions[index])
            if index < len(velocities):
                joint.velocity = float(velocities[index])
            if index < len(efforts):
                joint.effort = float(efforts[index])

    def message_fields(
        self,
    ) -> tuple[list[str], list[float], list[float], list[float]] | None:
        """Return ``(name, position, velocity, effort)`` as published, or None when empty."""
        has_position = bool(self.dependent_joints) or any(
            j.position is not None for j in self.free_joints.values()
        )
        has_velocity = any(j.velocity is not None for j in self.free_joints.values())
        has_effort = any(j.effort is not None for j in self.free_joints.values())
        count = len(self.joint_list)
        position = [0.0] * count if has_position else []
        velocity = [0.0] * count if has_velocity else []
        effort = [0.0] * count if has_effort else []
        for index, name in enumerate(self.joint_list):
            resolved = self.resolve(name)
            if resolved is None:
                continue
            joint, factor, offset = resolved
            if has_position and joint.position is not None:
                position[index] = joint.position * factor + offset
            if has_velocity and joint.velocity is not None:
                velocity[index] = joint.velocity * factor
            if has_effort and joint.effort is not None:
                effort[index] = joint.effort
        if not (self.joint_list or position or velocity or effort):
            return None
        return list(self.joint_list), position, velocity, effort


def dependent_joints_from_parameters(values: Mapping[str, Any]) -> dict[str, Dependent]:
    """
    Build the ``dependent_joints.<joint>.{parent,factor,offset}`` table.

    :param values: parameter names below ``dependent_joints.`` (e.g. ``'head.parent'``) -> value.
    :raises ValueError: with upstream's texts for a malformed entry.
    """
    entries: dict[str, dict[str, Any]] = {}
    for name, value in values.items():
        pieces = name.split('.')
        if len(pieces) != 2:
            msg = f"Invalid dependent_joint name '{name}'"
            raise ValueError(msg)
        joint, key = pieces
        if key not in {'parent', 'factor', 'offset'}:
            msg = (
                f"Invalid dependent_joint name '{key}' (allowed values are 'parent', 'factor', "
                "and 'offset')"
            )
            raise ValueError(msg)
        entries.setdefault(joint, {})[key] = value
    table = {}
    for joint, entry in entries.items():
        if entry.get('parent') is None:
            msg = 'All dependent_joints must at least have a parent'
            raise ValueError(msg)
        table[joint] = Dependent(
            str(entry['parent']),
            float(entry.get('factor', 1.0)),
            float(entry.get('offset', 0.0)),
        )
    return table


class JointStatePublisher(Node):
    """The joint_state_publisher node (see the module docstring)."""

    def __init__(self, urdf_file: str | None = None) -> None:
        super().__init__(NODE_NAME, automatically_declare_parameters_from_overrides=True)
        defaults: list[tuple[str, Any]] = [
            ('publish_default_efforts', False),
            ('publish_default_positions', True),
            ('publish_default_velocities', False),
            ('rate', 10),
            ('use_mimic_tags', True),
            ('use_smallest_joint_limits', True),
            ('delta', 0.0),
            ('xacro_args', ''),
        ]
        for name, default in defaults:
            if not self.has_parameter(name):
                self.declare_parameter(name, default)
        try:
            self._dependent = dependent_joints_from_parameters(
                {k: p.value for k, p in self.get_parameters_by_prefix('dependent_joints').items()}
            )
        except ValueError as error:
            raise JointStatePublisherConfigError(str(error)) from None
        self._zeros = {
            k: float(p.value) for k, p in self.get_parameters_by_prefix('zeros').items()
        }
        rate = self._value('rate', 10)
        problem = (
            'must be a number of Hz'
            if isinstance(rate, bool) or not isinstance(rate, (int, float))
            else rate_error(float(rate))
        )
        if problem is not None:
            msg = f'rate {problem}, got {rate!r}'
            raise JointStatePublisherConfigError(msg)
        self._delta = float(self._value('delta', 0.0))
        self._table = JointStateTable()
        if urdf_file is not None:
            try:
                model = RobotModel.from_file(
                    urdf_file, parse_xacro_args(str(self._value('xacro_args', '')))
                )
            except (UrdfError, ValueError) as error:
                raise JointStatePublisherConfigError(str(error)) from None
            self._configure(model)
        else:
            self.get_logger().info(
                'Waiting for robot_description to be published on the robot_description topic...'
            )
            self.create_subscription(
                std_msgs.String,
                'robot_description',
                self._on_description,
                QoSProfile(
                    depth=1,
                    durability=DurabilityPolicy.TRANSIENT_LOCAL,
                    reliability=ReliabilityPolicy.RELIABLE,
                ),
            )
        sources = self._value('source_list', []) if self.has_parameter('source_list') else []
        if not self.has_parameter('source_list'):
            # typed, without a default: an empty list would not carry its element type
            self.declare_parameter('source_list', Parameter.Type.STRING_ARRAY)
        for topic in sources:
            self.create_subscription(sensor_msgs.JointState, topic, self._on_source, 10)
        self._pub = self.create_publisher(sensor_msgs.JointState, 'joint_states', 10)
        self.create_timer(1.0 / rate, self._on_timer)

    def _value(self, name: str, default: Any) -> Any:
        value = self.get_parameter(name).value
        return default if value is None else value

    def _configure(self, model: RobotModel) -> None:
        self.get_logger().debug('Got description, configuring robot')
        for warning in model.description.warnings:
            self.get_logger().warning(warning)
        self._table = JointStateTable.from_model(
            model,
            zeros=self._zeros,
            dependent_joints=self._dependent,
            use_mimic_tags=bool(self._value('use_mimic_tags', True)),
            use_smallest_joint_limits=bool(self._value('use_smallest_joint_limits', True)),
            publish_default_positions=bool(self._value('publish_default_positions', True)),
            publish_default_velocities=bool(self._value('publish_default_velocities', False)),
            publish_default_efforts=bool(self._value('publish_default_efforts', False)),
        )
        for warning in self._table.warnings:
            self.get_logger().warning(warning)

    def _on_description(self, message: std_msgs.String) -> None:
        try:
            model = RobotModel.from_string(message.data, source='robot_description')
        except UrdfError as error:
            self.get_logger().warning(f'Invalid robot_description given, ignoring: {error}')
            return
        self._configure(model)

    def _on_source(self, message: sensor_msgs.JointState) -> None:
        self._table.apply_source(message.name, message.position, message.velocity, message.effort)

    def _on_timer(self) -> None:
        if self._delta > 0:
            self._table.update(self._delta)
        fields = self._table.message_fields()
        if fields is None:
            return
        stamp = self.get_clock().now().to_msg()
        self._pub.publish(joint_state_message(sensor_msgs.JointState, stamp, fields))


def joint_state_message(
    joint_state_type: type[sensor_msgs.JointState],
    stamp: builtin_interfaces.Time,
    fields: tuple[list[str], list[float], list[float], list[float]],
) -> sensor_msgs.JointState:
    """
    Build the world's ``sensor_msgs/JointState`` from :meth:`JointStateTable.message_fields`.

    Field types are what rclpy's generated setters require (``str`` names, ``float`` values,
    a ``builtin_interfaces/Time`` stamp of the same world), so the message also passes with
    ``ROS_PYTHON_CHECK_FIELDS=1``.
    """
    names, position, velocity, effort = fields
    message = joint_state_type()
    message.header.stamp = stamp
    message.name = [str(name) for name in names]
    message.position = [float(value) for value in position]
    message.velocity = [float(value) for value in velocity]
    message.effort = [float(value) for value in effort]
    return message


def _urdf_file_argument(args: Sequence[str]) -> str | None:
    plain = non_ros_arguments(args)
    if len(plain) > 1:
        msg = f'joint_state_publisher: unrecognized arguments: {" ".join(plain[1:])}'
        raise SystemExit(msg)
    return plain[0] if plain else None


def main(args: Sequence[str] | None = None) -> int:
    """Run joint_state_publisher [urdf_file]; return the process exit code."""
    argv = list(sys.argv if args is None else args)  # argv[0] is the program
    urdf_file = _urdf_file_argument(argv[1:])
    return int(run_node(lambda: JointStatePublisher(urdf_file), argv))


if __name__ == '__main__':
    sys.exit(main())
