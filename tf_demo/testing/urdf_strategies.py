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
Hypothesis strategies for robot descriptions, and a pinocchio forward-kinematics oracle.

:func:`robots` draws random URDF trees with every joint type, mimic chains (a mimic always follows
a joint earlier in the tree order, so chains never loop) and axes that are neither unit length
nor aligned with a coordinate axis, together with positions for the free joints.
:func:`pinocchio_link_poses` computes link poses with pinocchio (PyPI ``pin``), the independent
implementation the tests compare against; it follows the conventions of spec section 6
(``mimic=False`` with mimic values filled by hand, cos/sin for continuous joints, neutral
planar and floating joints, body frames looked up by type).
"""

from __future__ import annotations

from dataclasses import dataclass
import math
from typing import TYPE_CHECKING
from xml.sax.saxutils import quoteattr

from hypothesis import strategies as st
from tf_demo.core.math3d import Vec3

if TYPE_CHECKING:
    from collections.abc import Mapping
    import random

    from tf_demo.urdf import RobotModel

__all__ = ['GeneratedRobot', 'pinocchio_link_poses', 'random_positions', 'robots']

JOINT_TYPES = ('fixed', 'revolute', 'continuous', 'prismatic', 'planar', 'floating')
_MOVABLE = ('revolute', 'continuous', 'prismatic')
_NAME_ALPHABET = 'abcdefgh_'


@dataclass(frozen=True)
class GeneratedRobot:
    """A drawn robot: its URDF text and a position for every free (non-mimic) movable joint."""

    xml: str
    positions: dict[str, float]
    joint_types: dict[str, str]


def _finite(low: float, high: float) -> st.SearchStrategy[float]:
    return st.floats(low, high, allow_nan=False, allow_infinity=False)


@st.composite
def axes(draw: st.DrawFn) -> Vec3:
    """Draw a joint axis: any direction, any length from 0.1 to 3, often not axis-aligned."""
    kind = draw(st.sampled_from(('free', 'free', 'aligned')))
    if kind == 'aligned':
        index = draw(st.integers(0, 2))
        length = draw(_finite(0.1, 3.0)) * draw(st.sampled_from((1.0, -1.0)))
        axis = [0.0, 0.0, 0.0]
        axis[index] = length
        return (axis[0], axis[1], axis[2])
    vector = draw(st.tuples(_finite(-2.0, 2.0), _finite(-2.0, 2.0), _finite(-2.0, 2.0)))
    norm = math.sqrt(sum(c * c for c in vector))
    if norm < 0.1:
        return (0.3, -0.7, 1.1)
    return vector


def _vec(values: Vec3) -> str:
    return ' '.join(repr(v) for v in values)


@st.composite
def robots(draw: st.DrawFn, max_links: int = 8) -> GeneratedRobot:
    """
    Draw a random valid robot with its free joint positions.

    :param max_links: the largest number of links.
    """
    count = draw(st.integers(1, max_links))
    names = draw(
        st.lists(
            st.text(_NAME_ALPHABET, min_size=1, max_size=4),
            min_size=2 * count,
            max_size=2 * count,
            unique=True,
        )
    )
    link_names = [f'link_{n}' for n in names[:count]]
    joint_names = [f'joint_{n}' for n in names[count:]]
    lines = ['<robot name="generated">']
    order = draw(st.permutations(range(count)))  # document order of links
    lines += [f'  <link name={quoteattr(link_names[i])}/>' for i in order]
    positions: dict[str, float] = {}
    joint_types: dict[str, str] = {}
    movable: list[str] = []
    for child in range(1, count):
        parent = draw(st.integers(0, child - 1))
        name = joint_names[child]
        joint_type = draw(st.sampled_from(JOINT_TYPES))
        joint_types[name] = joint_type
        xyz = draw(st.tuples(_finite(-2.0, 2.0), _finite(-2.0, 2.0), _finite(-2.0, 2.0)))
        rpy = draw(st.tuples(_finite(-math.pi, math.pi), _finite(-3.0, 3.0), _finite(-4.0, 4.0)))
        body = [
            f'    <parent link={quoteattr(link_names[parent])}/>',
            f'    <child link={quoteattr(link_names[child])}/>',
        ]
        if draw(st.booleans()) or any(rpy) or any(xyz):
            body.append(f'    <origin xyz="{_vec(xyz)}" rpy="{_vec(rpy)}"/>')
        if joint_type in _MOVABLE:
            body.append(f'    <axis xyz="{_vec(draw(axes()))}"/>')
            lower = draw(_finite(-3.0, 3.0))
            upper = lower + draw(_finite(0.0, 3.0))
            if joint_type != 'continuous':
                body.append(
                    f'    <limit lower="{lower!r}" upper="{upper!r}" effort="1" velocity="1"/>'
                )
            if len(movable) > 0 and draw(st.booleans()):
                source = draw(st.sampled_from(movable))
                multiplier = draw(_finite(-2.0, 2.0))
                offset = draw(_finite(-1.0, 1.0))
                body.append(
                    f'    <mimic joint={quoteattr(source)} multiplier="{multiplier!r}" '
                    f'offset="{offset!r}"/>'
                )
            else:
                positions[name] = draw(_finite(lower, upper))
            movable.append(name)
        lines.append(f'  <joint name={quoteattr(name)} type="{joint_type}">')
        lines += body
        lines.append('  </joint>')
    lines.append('</robot>')
    return GeneratedRobot('\n'.join(lines) + '\n', positions, joint_types)


def pinocchio_link_poses(
    model: RobotModel, positions: Mapping[str, float]
) -> dict[str, tuple[Vec3, tuple[tuple[float, ...], ...]]]:
    """
    Return ``link -> (translation, 3x3 rotation)`` in the root frame, computed by pinocchio.

    Mimic joints get ``multiplier * source + offset`` (chains included) from
    :meth:`RobotModel.resolve_positions`; pinocchio builds the model with ``mimic=False``.
    """
    import pinocchio

    pin_model = pinocchio.buildModelFromXML(model.xml)
    data = pin_model.createData()
    values = model.resolve_positions(positions)
    q = pinocchio.neutral(pin_model)
    for index in range(1, pin_model.njoints):
        name = pin_model.names[index]
        joint = pin_model.joints[index]
        if name not in values or model.joint(name).type not in _MOVABLE:
            continue
        if joint.nq == 1:
            q[joint.idx_q] = values[name]
        elif joint.nq == 2:  # continuous: (cos, sin)
            q[joint.idx_q] = math.cos(values[name])
            q[joint.idx_q + 1] = math.sin(values[name])
    pinocchio.framesForwardKinematics(pin_model, data, q)
    poses: dict[str, tuple[Vec3, tuple[tuple[float, ...], ...]]] = {}
    for link in model.links:
        placement = data.oMf[pin_model.getFrameId(link, pinocchio.FrameType.BODY)]
        t = placement.translation
        poses[link] = (
            (float(t[0]), float(t[1]), float(t[2])),
            tuple(tuple(float(v) for v in row) for row in placement.rotation),
        )
    return poses


def random_positions(model: RobotModel, rng: random.Random) -> dict[str, float]:
    """Draw a position for every movable joint: within its limits, or in [-pi, pi] without."""
    positions = {}
    for name in model.movable_joints:
        joint = model.joint(name)
        if joint.type == 'continuous' or joint.limit is None:
            positions[name] = rng.uniform(-math.pi, math.pi)
        else:
            positions[name] = rng.uniform(joint.limit.lower, joint.limit.upper)
    return positions
