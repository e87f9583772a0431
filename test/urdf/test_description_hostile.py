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

"""Hostile and odd robot descriptions: numbers, huge trees, mimics, the samples as -p values."""

from __future__ import annotations

import math
from pathlib import Path
import re
import shutil
import subprocess

import pytest
from tf_demo.urdf import JointPositionError
from tf_demo.urdf import RobotModel
from tf_demo.urdf import UrdfError
from tf_demo.urdf import UrdfMalformedError

SAMPLES = Path(__file__).resolve().parents[2] / 'urdf'
LIMIT = '<limit lower="-1" upper="1" effort="1" velocity="1"/>'

# -- every number goes through one parser -----------------------------------------------------

# (element named in the error, attribute, the URDF line holding it with {v} for the value)
SAFETY = "joint 'j' <safety_controller>"
VISUAL = '<visual><geometry>{}</geometry></visual>'
COLLISION = '<collision><geometry>{}</geometry></collision>'
NUMBER_SITES = [
    ("joint 'j' <origin>", 'xyz', '<origin xyz="{v} 0 0"/>'),
    ("joint 'j' <origin>", 'rpy', '<origin rpy="0 {v} 0"/>'),
    ("joint 'j' <axis>", 'xyz', '<axis xyz="1 0 {v}"/>'),
    ("joint 'j' <limit>", 'lower', '<limit lower="{v}" upper="1" effort="1" velocity="1"/>'),
    ("joint 'j' <limit>", 'upper', '<limit lower="0" upper="{v}" effort="1" velocity="1"/>'),
    ("joint 'j' <limit>", 'effort', '<limit effort="{v}" velocity="1"/>'),
    ("joint 'j' <limit>", 'velocity', '<limit effort="1" velocity="{v}"/>'),
    (SAFETY, 'soft_lower_limit', '<safety_controller soft_lower_limit="{v}"/>'),
    (SAFETY, 'k_velocity', '<safety_controller k_velocity="{v}"/>'),
    (SAFETY, 'k_position', '<safety_controller k_position="{v}"/>'),
    ("joint 'j' <calibration>", 'rising', '<calibration rising="{v}"/>'),
    ("joint 'j' <dynamics>", 'damping', '<dynamics damping="{v}"/>'),
    ("joint 'j' <dynamics>", 'friction', '<dynamics friction="{v}"/>'),
    ("joint 'j' <mimic>", 'multiplier', '<mimic joint="k" multiplier="{v}"/>'),
    ("joint 'j' <mimic>", 'offset', '<mimic joint="k" offset="{v}"/>'),
    ("link 'a' <inertial> <origin>", 'xyz', '<inertial><origin xyz="{v} 0 0"/></inertial>'),
    ("link 'a' <inertial> <mass>", 'value', '<inertial><mass value="{v}"/></inertial>'),
    ("link 'a' <inertial> <inertia>", 'iyz', '<inertial><inertia iyz="{v}"/></inertial>'),
    ("link 'a' <visual> <origin>", 'rpy', '<visual><origin rpy="{v} 0 0"/></visual>'),
    ("link 'a' <collision> <origin>", 'xyz', '<collision><origin xyz="0 {v} 0"/></collision>'),
    ("link 'a' <visual> <box>", 'size', VISUAL.format('<box size="1 {v} 1"/>')),
    ("link 'a' <collision> <cylinder>", 'length', COLLISION.format('<cylinder length="{v}"/>')),
    ("link 'a' <visual> <sphere>", 'radius', VISUAL.format('<sphere radius="{v}"/>')),
    ("link 'a' <visual> <mesh>", 'scale', VISUAL.format('<mesh filename="m" scale="{v} 1 1"/>')),
]
NON_FINITE = ['1e400', '-1e400', '1E+309', 'inf', '-inf', 'nan', 'NaN', 'Infinity']


def site_robot(line: str) -> str:
    """A robot with ``line`` inside link a (line 3) or joint j (line 4; mimic source k)."""
    if line.startswith(('<inertial', '<visual', '<collision')):
        return (
            f'<robot name="r">\n<link name="a">\n{line}\n</link><link name="b"/>\n'
            '<joint name="j" type="fixed"><parent link="a"/><child link="b"/></joint></robot>\n'
        )
    return (
        '<robot name="r">\n<link name="a"/><link name="b"/><link name="c"/>\n'
        '<joint name="j" type="revolute"><parent link="a"/><child link="b"/>\n'
        f'{line}\n'
        f'{LIMIT if "<limit" not in line else ""}</joint>\n'
        '<joint name="k" type="continuous"><parent link="b"/><child link="c"/></joint>\n'
        '</robot>\n'
    )


@pytest.mark.parametrize('value', NON_FINITE)
@pytest.mark.parametrize(('element', 'attribute', 'line'), NUMBER_SITES)
def test_non_finite_numbers_are_refused_with_file_line_and_element(
    element: str, attribute: str, line: str, value: str
) -> None:
    """Every number of a URDF: too large for a double, inf or nan is refused as urdfdom does."""
    xml = site_robot(line.format(v=value))
    with pytest.raises(UrdfMalformedError) as caught:
        RobotModel.from_string(xml, source='bad.urdf')
    text = str(caught.value)
    line_number = 3 if 'link' in element else 4
    prefix = f'bad.urdf:{line_number}: {element}: attribute {attribute}="'
    assert text.startswith(prefix), text
    assert re.search(r'is (out of range \(not a finite double\)|not a number)$', text), text
    assert isinstance(caught.value, ValueError)


@pytest.mark.parametrize('value', ['1e-400', '+1', '.5', '1.', '-0', '1E5'])
@pytest.mark.parametrize(('element', 'attribute', 'line'), NUMBER_SITES[:3])
def test_numbers_urdfdom_accepts_are_accepted(
    element: str, attribute: str, line: str, value: str
) -> None:
    """Underflow to zero, a sign, a bare point and an exponent load, as urdfdom loads them."""
    del element, attribute
    model = RobotModel.from_string(site_robot(line.format(v=value)))
    assert model.root == 'a'


@pytest.mark.differential
@pytest.mark.parametrize(
    ('value', 'loads'),
    [('1e400', False), ('inf', False), ('nan', False), ('1e-400', True), ('.5', True)],
)
@pytest.mark.parametrize('line', [site[2] for site in (*NUMBER_SITES[:3], NUMBER_SITES[13])])
def test_number_rules_agree_with_urdfdom_check_urdf(
    tmp_path: Path, line: str, value: str, loads: bool
) -> None:
    """urdfdom's own check_urdf (Jazzy) loads exactly what tf_demo loads."""
    check_urdf = shutil.which('check_urdf')
    if check_urdf is None:
        pytest.skip('check_urdf (urdfdom, ROS 2 Jazzy) is not on PATH')
    path = tmp_path / 'robot.urdf'
    path.write_text(site_robot(line.format(v=value)), encoding='utf-8')
    completed = subprocess.run(
        [check_urdf, str(path)], capture_output=True, text=True, timeout=60, check=False
    )
    upstream_loads = 'Successfully Parsed XML' in completed.stdout
    assert upstream_loads is loads, completed.stdout + completed.stderr
    try:
        RobotModel.from_file(path)
    except UrdfError:
        assert not loads
    else:
        assert loads


# -- mimic of a joint that does not exist ----------------------------------------------------

GHOST_MIMIC = (
    '<robot name="r">\n<link name="a"/><link name="b"/>\n'
    '<joint name="j" type="continuous"><parent link="a"/><child link="b"/>\n'
    '<mimic joint="ghost" multiplier="2"/></joint>\n</robot>\n'
)


def test_a_mimic_of_a_missing_joint_is_ignored_with_one_warning() -> None:
    """The robot loads (as urdfdom); the joint is an ordinary joint; one warning names both."""
    model = RobotModel.from_string(GHOST_MIMIC, source='robot.urdf')
    assert model.description.warnings == (
        "robot.urdf:3: joint 'j' <mimic>: joint 'j' mimics joint 'ghost', which does not exist; "
        "the <mimic> is ignored and 'j' is an ordinary joint",
    )
    assert model.movable_joints == ['j']
    assert model.mimic_joints == {}
    [(parent, child, _, rotation)] = model.joint_transforms({'j': math.pi / 2, 'ghost': 1.0})
    assert (parent, child) == ('a', 'b')
    assert rotation == pytest.approx((math.sqrt(0.5), 0.0, 0.0, math.sqrt(0.5)))


@pytest.mark.differential
def test_urdfdom_loads_a_mimic_of_a_missing_joint_too(tmp_path: Path) -> None:
    """check_urdf (urdfdom) accepts the same robot: tf_demo refuses only what upstream cannot."""
    check_urdf = shutil.which('check_urdf')
    if check_urdf is None:
        pytest.skip('check_urdf (urdfdom, ROS 2 Jazzy) is not on PATH')
    path = tmp_path / 'robot.urdf'
    path.write_text(GHOST_MIMIC, encoding='utf-8')
    completed = subprocess.run(
        [check_urdf, str(path)], capture_output=True, text=True, timeout=60, check=False
    )
    assert 'Successfully Parsed XML' in completed.stdout, completed.stdout + completed.stderr


def test_a_mimic_whose_value_overflows_is_a_joint_position_error() -> None:
    """A finite source times a large multiplier is inf: a JointPositionError, not math's error."""
    xml = (
        '<robot name="r"><link name="a"/><link name="b"/><link name="c"/>'
        '<joint name="s" type="continuous"><parent link="a"/><child link="b"/></joint>'
        '<joint name="m" type="continuous"><parent link="b"/><child link="c"/>'
        '<mimic joint="s" multiplier="1e300"/></joint></robot>'
    )
    model = RobotModel.from_string(xml)
    with pytest.raises(JointPositionError, match=r"^joint 'm': position inf \(computed from"):
        model.joint_transforms({'s': 1e10})
    for bad in (math.inf, -math.inf, math.nan):
        with pytest.raises(JointPositionError, match=r"^joint '[sm]': position -?(inf|nan)"):
            model.joint_transforms({'s': bad})
    assert len(model.joint_transforms({'s': 0.5, 'unknown': math.nan})) == 2


# -- size: long chains, long mimic chains, deep XML -------------------------------------------


def chain_robot(count: int, joint_type: str = 'fixed', mimics: bool = False) -> str:
    """Links l0..l<count> in a chain, listed in reverse (children before parents)."""
    links = [f'<link name="l{i}"/>' for i in reversed(range(count + 1))]
    joints = []
    for i in reversed(range(count)):
        extra = '<origin xyz="0.001 0 0"/>'
        if mimics and i > 0:
            extra += f'<mimic joint="j{i - 1}" offset="0.001"/>'
        joints.append(
            f'<joint name="j{i}" type="{joint_type}"><parent link="l{i}"/>'
            f'<child link="l{i + 1}"/>{extra}</joint>'
        )
    return '<robot name="chain">' + ''.join(links + joints) + '</robot>'


def test_a_1500_link_chain_listed_in_reverse_loads_and_walks() -> None:
    """No RecursionError: the root, the statics and the pose of the last link are right."""
    model = RobotModel.from_string(chain_robot(1500))
    assert model.root == 'l0'
    assert len(model.static_transforms()) == 1500
    translation, _ = model.link_poses({})['l1500']
    assert translation == pytest.approx((1.5, 0.0, 0.0))


def test_a_1200_mimic_chain_resolves_every_joint() -> None:
    """j_k mimics j_(k-1) with offset 0.001: j_1199 = j_0 + 1.199, all published."""
    model = RobotModel.from_string(chain_robot(1200, 'continuous', mimics=True))
    assert model.movable_joints == ['j0']
    values = model.resolve_positions({'j0': 0.5})
    assert values['j1199'] == pytest.approx(0.5 + 1.199)
    assert len(model.joint_transforms({'j0': 0.5})) == 1200
    assert len(model.link_poses({'j0': 0.5})) == 1201


def test_a_3000_joint_mimic_cycle_is_found() -> None:
    """A cycle closing a 3,000-joint mimic chain is refused, naming the cycle's first joint."""
    xml = chain_robot(3000, 'continuous', mimics=True).replace(
        '<joint name="j0" type="continuous"><parent link="l0"/><child link="l1"/>'
        '<origin xyz="0.001 0 0"/>',
        '<joint name="j0" type="continuous"><parent link="l0"/><child link="l1"/>'
        '<origin xyz="0.001 0 0"/><mimic joint="j2999"/>',
    )
    with pytest.raises(UrdfMalformedError, match=r'mimic joints form a cycle: j\d+ -> .* -> j\d+'):
        RobotModel.from_string(xml)


def test_deeply_nested_xml_is_refused_by_the_parser() -> None:
    """10,000 nested elements: a clear XML error from libxml2's depth limit, no RecursionError."""
    xml = '<robot name="r"><link name="a">' + '<x>' * 10_000 + '</x>' * 10_000 + '</link></robot>'
    with pytest.raises(UrdfMalformedError, match=r'^bad\.urdf:1: XML: malformed XML: .*depth'):
        RobotModel.from_string(xml, source='bad.urdf')


# -- the sample robot on the command line -----------------------------------------------------


@pytest.mark.parametrize('sample', sorted(p.name for p in SAMPLES.iterdir()))
def test_every_sample_is_a_valid_command_line_parameter_value(sample: str) -> None:
    """-p robot_description:="$(xacro <sample>)": libyaml (rcl's parser) reads one string."""
    yaml = pytest.importorskip('yaml')
    loader = getattr(yaml, 'CSafeLoader', None)
    if loader is None:
        pytest.skip('PyYAML without libyaml (rcl parses -p values with libyaml)')
    text = RobotModel.from_file(SAMPLES / sample).xml
    assert isinstance(yaml.load(text, Loader=loader), str)
    assert 'Arguments: ' not in text
