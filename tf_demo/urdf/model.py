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
The robot model robot_state_publisher needs, with KDL's semantics.

It knows which joints are static, which move, and the transform of each joint at a position.

Per joint, ``parent_T_child = T_origin * motion(q)``: rotation about the normalised axis for
revolute and continuous joints, translation along the normalised axis for prismatic joints,
the origin alone for fixed and planar joints (as robot_state_publisher does), nothing for floating
joints. Mimic joints take ``multiplier * q_source + offset``, along chains of mimics too.
Everything that does not depend on ``q`` is computed once, so a joint costs a sine, a cosine and a
dozen multiplications per message; quaternions follow KDL's sign choice, so published values match
robot_state_publisher's to rounding.
"""

from __future__ import annotations

from collections.abc import Mapping
from collections.abc import Sequence
import math
from pathlib import Path

from tf_demo.core.math3d import compose
from tf_demo.core.math3d import Quat
from tf_demo.core.math3d import quat_from_rpy
from tf_demo.core.math3d import rotate_vector
from tf_demo.core.math3d import Vec3
from tf_demo.urdf.description import JointDescription
from tf_demo.urdf.description import parse_robot
from tf_demo.urdf.description import RobotDescription
from tf_demo.urdf.loading import read_description

__all__ = ['JointPositionError', 'JointTransform', 'RobotModel']

JointTransform = tuple[str, str, Vec3, Quat]
"""``(parent_link, child_link, translation, rotation_xyzw)``: the pose of child in parent."""


def kdl_quaternion(x: float, y: float, z: float, w: float) -> Quat:
    """
    Return the sign of ``q`` / ``-q`` that KDL's ``Rotation::GetQuaternion`` produces.

    KDL reads the quaternion back from the rotation matrix: when its trace exceeds 1e-12 the result
    has ``w > 0``; otherwise the component of the largest diagonal element is positive.
    """
    if 4.0 * w * w - 1.0 > 1e-12:
        negative = w < 0.0
    else:
        xx, yy, zz = x * x, y * y, z * z
        if xx > yy and xx > zz:
            negative = x < 0.0
        elif yy > zz:
            negative = y < 0.0
        else:
            negative = z < 0.0
    if negative:
        return (-x, -y, -z, -w)
    return (x, y, z, w)


# One moving joint, precomputed: (name, is_revolute, parent, child, origin translation,
# origin quaternion x y z w, u x y z, d, KDL-signed origin quaternion). For a revolute joint
# q_origin * (axis sin(a/2), cos(a/2)) = (q_v cos(a/2) + u sin(a/2), w cos(a/2) - d sin(a/2))
# with u = w axis + q_v x axis and d = q_v . axis; for a prismatic joint u = R_origin axis.
_MovingJoint = tuple[
    str, bool, str, str, Vec3, float, float, float, float, float, float, float, float, Quat
]


def _moving_joint(joint: JointDescription) -> _MovingJoint:
    ax, ay, az = joint.axis
    norm = math.sqrt(ax * ax + ay * ay + az * az)
    ax, ay, az = ax / norm, ay / norm, az / norm
    qx, qy, qz, qw = quat_from_rpy(*joint.rpy)
    if joint.type == 'prismatic':
        ux, uy, uz = rotate_vector((qx, qy, qz, qw), (ax, ay, az))
        d = 0.0
    else:
        ux = qw * ax + qy * az - qz * ay
        uy = qw * ay + qz * ax - qx * az
        uz = qw * az + qx * ay - qy * ax
        d = qx * ax + qy * ay + qz * az
    names = (joint.name, joint.type != 'prismatic', joint.parent, joint.child)
    return (*names, joint.xyz, qx, qy, qz, qw, ux, uy, uz, d, kdl_quaternion(qx, qy, qz, qw))


class JointPositionError(ValueError):
    """A joint position that is not a finite number: given, or computed for a mimic joint."""

    def __init__(self, joint: str, position: float, computed: bool = False) -> None:
        self.joint = joint
        self.position = position
        how = ' (computed from the joint it mimics)' if computed else ''
        super().__init__(f"joint '{joint}': position {position!r}{how} is not a finite number")


class RobotModel:
    """
    A validated robot description with KDL-semantics kinematics.

    Build it with :meth:`from_file` or :meth:`from_string`; both validate strictly and raise a
    :class:`~tf_demo.urdf.errors.UrdfError` subclass on any problem.
    """

    def __init__(self, description: RobotDescription, xml: str) -> None:
        self.description = description
        self.xml = xml
        joints = description.joints
        self._joints = {joint.name: joint for joint in joints}
        self._movable = [
            j.name for j in joints if j.type in {'revolute', 'continuous', 'prismatic'}
        ]
        self._moving_sorted = sorted(_moving_joint(self._joints[name]) for name in self._movable)
        self._mimics = _mimics_in_dependency_order(joints)
        self._static: list[JointTransform] = []
        self.warnings: list[str] = []
        if description.root in description.links_with_inertia:
            self.warnings.append(
                f'The root link {description.root} has an inertia specified in the URDF, but KDL '
                'does not support a root link with an inertia.  As a workaround, you can add an '
                'extra dummy link to your URDF.'
            )
        for joint in sorted(joints, key=lambda j: j.name):
            if joint.type in {'fixed', 'planar'}:
                x, y, z, w = quat_from_rpy(*joint.rpy)
                self._static.append(
                    (joint.parent, joint.child, joint.xyz, kdl_quaternion(x, y, z, w))
                )
            if joint.type in {'planar', 'floating'}:
                self.warnings.append(
                    f"Converting unknown joint type of joint '{joint.name}' into a fixed joint"
                    + (' (published as static at its origin)' if joint.type == 'planar' else '')
                )

    @classmethod
    def from_string(cls, xml: str, *, source: str = '<string>') -> RobotModel:
        """
        Parse and validate URDF text.

        :param xml: the URDF document.
        :param source: the name used in error messages.
        """
        return cls(parse_robot(xml, source), xml)

    @classmethod
    def from_file(
        cls,
        path: str | Path,
        mappings: dict[str, str] | None = None,
        *,
        package_paths: Sequence[str | Path] | None = None,
    ) -> RobotModel:
        """
        Load a URDF file, or a ``.xacro`` file expanded with ``mappings`` as its arguments.

        :param path: the file.
        :param mappings: xacro arguments (``name -> value``), ignored for plain URDF.
        :param package_paths: directories searched first for ``$(find pkg)`` / ``package://``.
        """
        xml = read_description(path, mappings, package_paths)
        return cls(parse_robot(xml, str(path)), xml)

    @property
    def name(self) -> str:
        """The robot's name."""
        return self.description.name

    @property
    def root(self) -> str:
        """The root link (the one link that is nobody's child)."""
        return self.description.root

    @property
    def links(self) -> list[str]:
        """All link names in document order."""
        return list(self.description.links)

    @property
    def joints(self) -> list[JointDescription]:
        """All joints as parsed, in document order."""
        return list(self.description.joints)

    @property
    def movable_joints(self) -> list[str]:
        """Revolute, continuous and prismatic joints that are not mimics, in document order."""
        return [name for name in self._movable if self._joints[name].mimic is None]

    @property
    def mimic_joints(self) -> dict[str, tuple[str, float, float]]:
        """``joint -> (source joint, multiplier, offset)`` for every joint with ``<mimic>``."""
        return {
            j.name: (j.mimic.joint, j.mimic.multiplier, j.mimic.offset)
            for j in self.description.joints
            if j.mimic is not None
        }

    def joint(self, name: str) -> JointDescription:
        """Return the description of joint ``name`` (``KeyError`` if there is none)."""
        return self._joints[name]

    def static_transforms(self) -> list[JointTransform]:
        """Return fixed and planar joints' transforms (planar at its origin), by joint name."""
        return list(self._static)

    def resolve_positions(self, positions: Mapping[str, float]) -> dict[str, float]:
        """
        Add the positions of mimic joints to ``positions``.

        A mimic joint gets ``multiplier * source + offset`` when its source is known (also when
        the source is itself a mimic) and it has no explicit value of its own: an explicit value
        wins, as in robot_state_publisher.
        """
        values = dict(positions)
        for name, source, multiplier, offset in self._mimics:
            if name not in values and source in values:
                values[name] = multiplier * values[source] + offset
        return values

    def joint_transforms(self, positions: Mapping[str, float]) -> list[JointTransform]:
        """
        Return the transforms of moving joints with a known position, ordered by joint name.

        :param positions: joint name -> position (rad or m); unknown, fixed and floating names are
            ignored, mimic joints are filled in from their sources.
        :raises JointPositionError: when a used position (or a mimic's result) is inf or nan.
        """
        values = self.resolve_positions(positions) if self._mimics else positions
        transforms: list[JointTransform] = []
        append = transforms.append
        sin = math.sin
        cos = math.cos
        kdl_sign = kdl_quaternion
        for name, rev, parent, child, t, qx, qy, qz, qw, ux, uy, uz, d, q0 in self._moving_sorted:
            position = values.get(name)
            if position is None:
                continue
            if position - position != 0.0:  # inf or nan (math.sin(inf) raises ValueError)
                raise JointPositionError(name, position, name not in positions)
            if not rev:
                append(
                    (
                        parent,
                        child,
                        (t[0] + position * ux, t[1] + position * uy, t[2] + position * uz),
                        q0,
                    )
                )
                continue
            s = sin(0.5 * position)
            c = cos(0.5 * position)
            x = qx * c + ux * s
            y = qy * c + uy * s
            z = qz * c + uz * s
            append((parent, child, t, kdl_sign(x, y, z, qw * c - d * s)))
        return transforms

    def link_poses(self, positions: Mapping[str, float]) -> dict[str, tuple[Vec3, Quat]]:
        """
        Return the pose in the root frame of every link the published transforms reach.

        Links below a floating joint or a moving joint without a position are left out, as a tf
        listener would not reach them either.
        """
        edges: dict[str, tuple[str, Vec3, Quat]] = {}
        for parent, child, t, q in self.static_transforms() + self.joint_transforms(positions):
            edges[child] = (parent, t, q)
        poses: dict[str, tuple[Vec3, Quat]] = {self.root: ((0.0, 0.0, 0.0), (0.0, 0.0, 0.0, 1.0))}
        unreachable: set[str] = set()
        for link in self.description.links:
            # walk up to a link whose pose is known (or cannot be), then compose downwards
            chain: list[str] = []
            current = link
            while current not in poses and current not in unreachable and current in edges:
                chain.append(current)
                current = edges[current][0]
            if current not in poses:
                unreachable.update(chain)
                unreachable.add(current)
                continue
            for child in reversed(chain):
                parent, translation, rotation = edges[child]
                parent_pose = poses[parent]
                t, q = compose(parent_pose[0], parent_pose[1], translation, rotation)
                poses[child] = ((t[0], t[1], t[2]), (q[0], q[1], q[2], q[3]))
        return poses


def _mimics_in_dependency_order(
    joints: Sequence[JointDescription],
) -> list[tuple[str, str, float, float]]:
    """Mimic joints ordered so that a mimic of a mimic comes after its source (else by name)."""
    by_name = {joint.name: joint for joint in joints}
    ordered: list[tuple[str, str, float, float]] = []
    placed: set[str] = set()
    for joint in sorted(joints, key=lambda j: j.name):
        # walk up to the first source already placed (or not a mimic), then place downwards
        chain: list[tuple[str, str, float, float]] = []
        current: JointDescription | None = joint
        while current is not None and current.mimic is not None and current.name not in placed:
            mimic = current.mimic
            chain.append((current.name, mimic.joint, mimic.multiplier, mimic.offset))
            placed.add(current.name)  # parse_robot refuses mimic cycles: no joint comes twice
            current = by_name.get(mimic.joint)
        ordered.extend(reversed(chain))
    return ordered
