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

"""Forward kinematics of RobotModel against pinocchio, and robot_state_publisher's joint rules."""

from __future__ import annotations

import math
from pathlib import Path
import random

from hypothesis import given
from hypothesis import HealthCheck
from hypothesis import settings
import pytest
from tf_demo.core.math3d import matrix_from_quat
from tf_demo.core.math3d import quat_from_axis_angle
from tf_demo.core.math3d import quat_from_rpy
from tf_demo.core.math3d import quat_multiply
from tf_demo.testing.urdf_strategies import GeneratedRobot
from tf_demo.testing.urdf_strategies import pinocchio_link_poses
from tf_demo.testing.urdf_strategies import random_positions
from tf_demo.testing.urdf_strategies import robots
from tf_demo.urdf import kdl_quaternion
from tf_demo.urdf import RobotModel

pytest.importorskip(
    'pinocchio', reason='pinocchio (PyPI pin), the kinematics oracle, is not installed'
)

SAMPLES = Path(__file__).resolve().parents[2] / 'urdf'


def assert_poses_match_pinocchio(model: RobotModel, positions: dict[str, float]) -> int:
    """Compare every link pose RobotModel reaches with pinocchio's; return how many."""
    ours = model.link_poses(positions)
    theirs = pinocchio_link_poses(model, positions)
    for link, (translation, rotation) in ours.items():
        pin_translation, pin_rotation = theirs[link]
        for a, b in zip(translation, pin_translation, strict=True):
            assert a == pytest.approx(b, abs=1e-9), link
        for row, pin_row in zip(matrix_from_quat(rotation), pin_rotation, strict=True):
            for a, b in zip(row, pin_row, strict=True):
                assert a == pytest.approx(b, abs=1e-9), link
    return len(ours)


@pytest.mark.differential
@pytest.mark.parametrize(
    ('path', 'mappings'),
    [
        ('example_fixed.urdf', None),
        ('example_revolute.urdf', None),
        ('mobile_robot.urdf.xacro', None),
        ('mobile_robot.urdf.xacro', {'prefix': 'r2_', 'wheel_radius': '0.1'}),
    ],
)
def test_sample_robots_match_pinocchio_in_random_configurations(
    path: str, mappings: dict[str, str] | None
) -> None:
    """Every link of the sample robots sits where pinocchio puts it, for 30 configurations."""
    model = RobotModel.from_file(SAMPLES / path, mappings)
    rng = random.Random(path)
    for _ in range(30):
        reached = assert_poses_match_pinocchio(model, random_positions(model, rng))
        assert reached == len(model.links)


@pytest.mark.property
@pytest.mark.differential
@settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(robots())
def test_generated_robots_match_pinocchio(robot: GeneratedRobot) -> None:
    """Random trees of every joint type, mimic chains and odd axes agree with pinocchio."""
    model = RobotModel.from_string(robot.xml)
    assert_poses_match_pinocchio(model, robot.positions)


@pytest.mark.property
@settings(max_examples=40, deadline=None)
@given(robots())
def test_generated_robots_publish_every_joint_but_floating(robot: GeneratedRobot) -> None:
    """Fixed and planar joints are static, moving ones follow positions, floating ones vanish."""
    model = RobotModel.from_string(robot.xml)
    static = {child for _, child, _, _ in model.static_transforms()}
    moving = {child for _, child, _, _ in model.joint_transforms(robot.positions)}
    for joint in model.joints:
        if joint.type in {'fixed', 'planar'}:
            assert joint.child in static
        elif joint.type == 'floating':
            assert joint.child not in static | moving
        else:
            assert joint.child in moving
    assert set(model.movable_joints) == set(robot.positions)


def test_generated_robots_cover_every_joint_type_and_mimic_chains() -> None:
    """The strategy really draws all joint types, mimic-of-mimic chains and unaligned axes."""
    seen_types: set[str] = set()
    seen = {'chain': False, 'unaligned': False, 'non_unit': False}

    @settings(max_examples=200, deadline=None, database=None)
    @given(robots())
    def collect(robot: GeneratedRobot) -> None:
        model = RobotModel.from_string(robot.xml)
        seen_types.update(robot.joint_types.values())
        mimics = model.mimic_joints
        if any(source in mimics for source, _, _ in mimics.values()):
            seen['chain'] = True
        for joint in model.joints:
            if joint.type in {'revolute', 'continuous', 'prismatic'}:
                nonzero = sum(1 for c in joint.axis if c != 0.0)
                norm = math.sqrt(sum(c * c for c in joint.axis))
                seen['unaligned'] |= nonzero > 1
                seen['non_unit'] |= abs(norm - 1.0) > 1e-3

    collect()
    assert seen_types == {'fixed', 'revolute', 'continuous', 'prismatic', 'planar', 'floating'}
    assert seen == {'chain': True, 'unaligned': True, 'non_unit': True}


ARM = """<robot name="arm">
  <link name="base"/><link name="a"/><link name="b"/><link name="c"/><link name="d"/>
  <link name="e"/><link name="f"/>
  <joint name="j_rev" type="revolute">
    <parent link="base"/><child link="a"/><origin xyz="1 2 3" rpy="0.1 0.2 0.3"/>
    <axis xyz="0 0 2"/><limit lower="-1" upper="1" effort="1" velocity="1"/>
  </joint>
  <joint name="j_pri" type="prismatic">
    <parent link="a"/><child link="b"/><origin xyz="0 0 1" rpy="0 0 1.5707963267948966"/>
    <axis xyz="0 0 2"/><limit lower="-1" upper="1" effort="1" velocity="1"/>
  </joint>
  <joint name="m_first" type="continuous">
    <parent link="b"/><child link="c"/><mimic joint="j_rev" multiplier="2" offset="0.5"/>
  </joint>
  <joint name="a_chained" type="continuous">
    <parent link="c"/><child link="d"/><mimic joint="m_first" multiplier="-1"/>
  </joint>
  <joint name="j_float" type="floating"><parent link="base"/><child link="e"/></joint>
  <joint name="j_planar" type="planar">
    <parent link="base"/><child link="f"/><origin xyz="0 0 5"/><axis xyz="0 0 1"/>
  </joint>
</robot>
"""


def test_revolute_rotates_about_normalised_axis_after_origin() -> None:
    """A revolute joint keeps its origin translation and rotates R_o * R(axis/|axis|, q)."""
    model = RobotModel.from_string(ARM)
    transforms = {t[1]: t for t in model.joint_transforms({'j_rev': 0.7})}
    parent, child, translation, rotation = transforms['a']
    assert (parent, child, translation) == ('base', 'a', (1.0, 2.0, 3.0))

    expected = quat_multiply(quat_from_rpy(0.1, 0.2, 0.3), quat_from_axis_angle((0, 0, 1), 0.7))
    assert rotation == pytest.approx(kdl_quaternion(*expected), abs=1e-15)


def test_prismatic_moves_along_normalised_axis() -> None:
    """An axis of (0 0 2) and q = 0.5 moves 0.5 m (KDL and pinocchio), not 1 m (yourdfpy)."""
    model = RobotModel.from_string(ARM)
    [(_, child, translation, rotation)] = model.joint_transforms({'j_pri': 0.5})
    assert child == 'b'
    assert translation == pytest.approx((0.0, 0.0, 1.5), abs=1e-15)
    assert rotation == pytest.approx((0.0, 0.0, math.sqrt(0.5), math.sqrt(0.5)), abs=1e-15)


def test_mimic_chain_resolves_regardless_of_name_order() -> None:
    """A mimic of a mimic gets m*(m*q+o)+o even when its name sorts before its source's."""
    model = RobotModel.from_string(ARM)
    values = model.resolve_positions({'j_rev': 0.25})
    assert values['m_first'] == pytest.approx(2 * 0.25 + 0.5)
    assert values['a_chained'] == pytest.approx(-(2 * 0.25 + 0.5))
    children = [child for _, child, _, _ in model.joint_transforms({'j_rev': 0.25})]
    assert children == ['d', 'a', 'c']  # ordered by joint name: a_chained, j_rev, m_first


def test_explicit_mimic_position_wins_over_computed_one() -> None:
    """As in robot_state_publisher, a position given for a mimic joint is used as is."""
    model = RobotModel.from_string(ARM)
    values = model.resolve_positions({'j_rev': 0.25, 'm_first': 3.0})
    assert values['m_first'] == 3.0
    assert values['a_chained'] == -3.0


def test_floating_skipped_planar_static_and_unknown_names_ignored() -> None:
    """Floating joints publish nothing, planar ones sit at their origin, strangers are ignored."""
    model = RobotModel.from_string(ARM)
    assert model.static_transforms() == [('base', 'f', (0.0, 0.0, 5.0), (0.0, 0.0, 0.0, 1.0))]
    assert model.joint_transforms({'j_float': 1.0, 'j_planar': 2.0, 'nobody': 3.0}) == []
    assert model.movable_joints == ['j_rev', 'j_pri']
    assert model.root == 'base'
    assert any("'j_float'" in w for w in model.warnings)


@pytest.mark.parametrize(
    'q_xyzw',
    [(0.1, 0.2, 0.3, -0.9), (0.9, 0.1, -0.2, 0.1), (-0.1, 0.9, 0.2, 0.3), (0.1, -0.3, -0.9, 0.2)],
)
def test_quaternion_sign_follows_kdl_matrix_conversion(q_xyzw: tuple[float, ...]) -> None:
    """The published sign is the one KDL's GetQuaternion reads back from the rotation matrix."""
    norm = math.sqrt(sum(c * c for c in q_xyzw))
    x, y, z, w = (c / norm for c in q_xyzw)
    m = matrix_from_quat((x, y, z, w))
    trace = m[0][0] + m[1][1] + m[2][2]
    result = kdl_quaternion(x, y, z, w)
    if trace > 1e-12:
        assert result[3] > 0
    else:
        diagonal = [m[0][0], m[1][1], m[2][2]]
        assert result[diagonal.index(max(diagonal))] > 0
    assert abs(sum(a * b for a, b in zip(result, (x, y, z, w), strict=True))) == pytest.approx(1.0)


def test_root_link_inertia_gets_kdl_warning() -> None:
    """A root link with <inertial> keeps working but carries kdl_parser's warning."""
    xml = (
        '<robot name="r"><link name="base"><inertial><mass value="1"/></inertial></link>'
        '<link name="a"/><joint name="j" type="fixed"><parent link="base"/><child link="a"/>'
        '</joint></robot>'
    )
    model = RobotModel.from_string(xml)
    assert model.warnings == [
        'The root link base has an inertia specified in the URDF, but KDL does not support a '
        'root link with an inertia.  As a workaround, you can add an extra dummy link to your '
        'URDF.'
    ]
    assert (
        RobotModel.from_string(
            xml.replace('base"><inertial>', 'base"><visual>').replace('</inertial>', '</visual>')
        ).warnings
        == []
    )
