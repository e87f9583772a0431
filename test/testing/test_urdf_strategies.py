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

"""Tests of the shipped robot-description strategies (``tf_demo.testing.urdf_strategies``)."""

from __future__ import annotations

import math
import random

from hypothesis import given
from hypothesis import settings
import pytest
from tf_demo.core.math3d import Vec3
from tf_demo.testing.urdf_strategies import axes
from tf_demo.testing.urdf_strategies import GeneratedRobot
from tf_demo.testing.urdf_strategies import random_positions
from tf_demo.testing.urdf_strategies import robots
from tf_demo.urdf import RobotModel

pytestmark = pytest.mark.property


@settings(max_examples=100, deadline=None)
@given(robots())
def test_drawn_robots_are_valid_urdf_with_a_position_for_every_free_joint(
    robot: GeneratedRobot,
) -> None:
    """The URDF loads; free joints have positions within their limits, mimic joints none."""
    model = RobotModel.from_string(robot.xml)
    assert {joint.name: joint.type for joint in model.joints} == robot.joint_types
    assert sorted(robot.positions) == sorted(model.movable_joints)
    for name, position in robot.positions.items():
        limit = model.joint(name).limit
        if limit is not None and model.joint(name).type != 'continuous':
            assert limit.lower <= position <= limit.upper


@settings(max_examples=200, deadline=None)
@given(axes())
def test_axes_are_never_shorter_than_a_tenth(axis: Vec3) -> None:
    """Every drawn axis has length at least 0.1, so a joint's direction is well defined."""
    assert math.sqrt(sum(c * c for c in axis)) >= 0.1 - 1e-12


def test_random_positions_are_seeded_and_within_the_limits() -> None:
    """Positions lie within each joint's limits ([-pi, pi] for continuous), the same per seed."""
    model = RobotModel.from_string(
        '<robot name="r"><link name="a"/><link name="b"/><link name="c"/>'
        '<joint name="j1" type="revolute"><parent link="a"/><child link="b"/>'
        '<limit lower="-0.5" upper="0.25" effort="1" velocity="1"/></joint>'
        '<joint name="j2" type="continuous"><parent link="b"/><child link="c"/></joint>'
        '</robot>'
    )
    first = random_positions(model, random.Random(7))
    assert first == random_positions(model, random.Random(7))
    assert sorted(first) == ['j1', 'j2']
    assert -0.5 <= first['j1'] <= 0.25
    assert -math.pi <= first['j2'] <= math.pi
