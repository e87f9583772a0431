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

"""joint_state_publisher's joint table: defaults, limits, mimic chains, delta, source values."""

from __future__ import annotations

import math

import pytest
from tf_demo.nodes.joint_state_publisher import Dependent
from tf_demo.nodes.joint_state_publisher import dependent_joints_from_parameters
from tf_demo.nodes.joint_state_publisher import JointStateTable
from tf_demo.urdf import RobotModel

ROBOT = """<robot name="jsp">
  <link name="base"/><link name="a"/><link name="b"/><link name="c"/><link name="d"/>
  <link name="e"/><link name="f"/><link name="g"/>
  <joint name="shoulder" type="revolute">
    <parent link="base"/><child link="a"/>
    <limit lower="-1" upper="2" effort="1" velocity="1"/>
  </joint>
  <joint name="elbow" type="revolute">
    <parent link="a"/><child link="b"/>
    <limit lower="-3" upper="-1" effort="1" velocity="1"/>
  </joint>
  <joint name="torso" type="prismatic">
    <parent link="base"/><child link="c"/>
    <limit lower="0" upper="0.4" effort="1" velocity="1"/>
    <safety_controller soft_lower_limit="0.1" soft_upper_limit="0.3" k_velocity="1"/>
  </joint>
  <joint name="wheel" type="continuous"><parent link="base"/><child link="d"/></joint>
  <joint name="finger" type="prismatic">
    <parent link="b"/><child link="e"/><mimic joint="shoulder" multiplier="2" offset="0.5"/>
    <limit lower="0" upper="1" effort="1" velocity="1"/>
  </joint>
  <joint name="fingertip" type="continuous">
    <parent link="e"/><child link="f"/><mimic joint="finger" multiplier="-1" offset="0.25"/>
  </joint>
  <joint name="camera" type="fixed"><parent link="base"/><child link="g"/></joint>
</robot>
"""


def table(**options: object) -> JointStateTable:
    return JointStateTable.from_model(RobotModel.from_string(ROBOT), **options)  # type: ignore[arg-type]


def test_free_joints_start_at_zero_or_mid_limits_and_mimics_are_dependent() -> None:
    """0 when inside the limits, the middle otherwise (after safety narrowing); mimics follow."""
    fields = table().message_fields()
    assert fields is not None
    names, positions, velocities, efforts = fields
    assert names == ['shoulder', 'elbow', 'torso', 'wheel', 'finger', 'fingertip']
    assert positions == pytest.approx([0.0, -2.0, 0.2, 0.0, 0.5, -0.25])
    assert velocities == []
    assert efforts == []


def test_zeros_parameter_sets_the_start_position() -> None:
    """zeros.<joint> replaces the computed centre, and mimics follow it."""
    fields = table(zeros={'shoulder': 0.25, 'elbow': -1.5}).message_fields()
    assert fields is not None
    assert fields[1][:2] == [0.25, -1.5]
    assert fields[1][4] == pytest.approx(1.0)
    assert fields[1][5] == pytest.approx(-0.75)


def test_continuous_joints_get_minus_pi_to_pi_and_soft_limits_narrow() -> None:
    """A continuous joint's range is [-pi, pi]; the safety controller narrows when asked."""
    narrowed = table()
    assert (narrowed.free_joints['wheel'].minimum, narrowed.free_joints['wheel'].maximum) == (
        -math.pi,
        math.pi,
    )
    assert (narrowed.free_joints['torso'].minimum, narrowed.free_joints['torso'].maximum) == (
        0.1,
        0.3,
    )
    wide = table(use_smallest_joint_limits=False)
    assert (wide.free_joints['torso'].minimum, wide.free_joints['torso'].maximum) == (0.0, 0.4)
    assert wide.free_joints['torso'].zero == 0.0


def test_without_mimic_tags_every_movable_joint_is_free() -> None:
    """use_mimic_tags=False makes mimic joints ordinary free joints."""
    free = table(use_mimic_tags=False)
    assert set(free.free_joints) == {'shoulder', 'elbow', 'torso', 'wheel', 'finger', 'fingertip'}
    assert free.dependent_joints == {}


def test_default_velocities_and_efforts_when_requested() -> None:
    """publish_default_velocities/efforts add zero arrays; dependent velocity scales."""
    state = table(publish_default_velocities=True, publish_default_efforts=True)
    state.apply_source(['shoulder'], [0.1], [2.0], [3.0])
    fields = state.message_fields()
    assert fields is not None
    _, _, velocities, efforts = fields
    assert velocities[0] == 2.0
    assert velocities[4] == 4.0
    assert velocities[5] == -4.0
    assert efforts[4] == 3.0


def test_delta_bounces_between_limits_and_wraps_continuous() -> None:
    """Each tick moves by delta; bounded joints turn around, continuous joints wrap to -pi."""
    state = table()
    for _ in range(40):
        state.update(0.1)
    shoulder = state.free_joints['shoulder']
    # 0 -> 2.0 in 20 ticks (clamped, turns), then 20 ticks back down to 0
    assert shoulder.forward is False
    assert shoulder.position == pytest.approx(0.0, abs=1e-9)
    state.free_joints['wheel'].position = math.pi - 0.05
    state.update(0.1)
    assert state.free_joints['wheel'].position == -math.pi


def test_delta_turns_at_the_upper_limit() -> None:
    """A bounded joint reaching its maximum is clamped there and then moves back."""
    state = table()
    joint = state.free_joints['shoulder']
    joint.position = 1.95
    state.update(0.1)
    assert joint.position == 2.0
    assert joint.forward is False
    state.update(0.1)
    assert joint.position == pytest.approx(1.9)


def test_source_values_only_touch_free_joints() -> None:
    """source_list messages set free joints; unknown and mimic names are ignored."""
    state = table()
    state.apply_source(['wheel', 'finger', 'nobody'], [1.5, 9.0, 9.0], [], [])
    fields = state.message_fields()
    assert fields is not None
    assert fields[1][3] == 1.5
    assert fields[1][4] == pytest.approx(0.5)


def test_dependent_joints_parameters_parse_with_upstream_errors() -> None:
    """dependent_joints.<j>.parent/factor/offset parse; malformed names use upstream texts."""
    assert dependent_joints_from_parameters(
        {'head.parent': 'neck', 'head.factor': 2.0, 'tail.parent': 'hip'}
    ) == {'head': Dependent('neck', 2.0, 0.0), 'tail': Dependent('hip', 1.0, 0.0)}
    with pytest.raises(ValueError, match=r"Invalid dependent_joint name 'a\.b\.c'"):
        dependent_joints_from_parameters({'a.b.c': 1})
    with pytest.raises(ValueError, match="Invalid dependent_joint name 'scale'"):
        dependent_joints_from_parameters({'a.scale': 1})
    with pytest.raises(ValueError, match='All dependent_joints must at least have a parent'):
        dependent_joints_from_parameters({'a.factor': 1.0})


def test_dependent_joint_parameter_makes_a_joint_follow_another() -> None:
    """A joint named in dependent_joints is computed from its parent instead of being free."""
    state = table(
        dependent_joints={'wheel': Dependent('shoulder', 3.0, 0.1)}, zeros={'shoulder': 1}
    )
    fields = state.message_fields()
    assert fields is not None
    assert 'wheel' not in state.free_joints
    assert fields[1][3] == pytest.approx(3.1)


def test_mimic_of_a_fixed_joint_is_left_out_with_a_warning() -> None:
    """Upstream crashes on a mimic whose source is not free; here it is reported and skipped."""
    xml = ROBOT.replace('<mimic joint="shoulder"', '<mimic joint="camera"')
    state = JointStateTable.from_model(RobotModel.from_string(xml))
    assert 'finger' not in state.joint_list
    assert 'fingertip' not in state.joint_list
    assert any("'finger' mimics 'camera'" in w for w in state.warnings)


def test_robot_without_movable_joints_publishes_nothing() -> None:
    """Only non-empty messages are published."""
    model = RobotModel.from_string('<robot name="r"><link name="a"/></robot>')
    assert JointStateTable.from_model(model).message_fields() is None
