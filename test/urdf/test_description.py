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

"""Every way a robot description can be broken gives a UrdfError naming source, element, reason."""

from __future__ import annotations

import re

import pytest
from tf_demo.urdf import RobotModel
from tf_demo.urdf import UrdfBrokenRefError
from tf_demo.urdf import UrdfError
from tf_demo.urdf import UrdfMalformedError
from tf_demo.urdf import UrdfUnsupportedError

LINKS = '<link name="a"/><link name="b"/><link name="c"/>'


def robot(body: str, name: str = 'r') -> str:
    return f'<robot name="{name}">\n{body}\n</robot>\n'


def joint(
    name: str,
    parent: str,
    child: str,
    joint_type: str = 'fixed',
    extra: str = '',
) -> str:
    return (
        f'<joint name="{name}" type="{joint_type}"><parent link="{parent}"/>'
        f'<child link="{child}"/>{extra}</joint>'
    )


def fixed_joints(*joints: str) -> str:
    """Fixed joints, each written ``'name parent child'``."""
    return ''.join(joint(*written.split()) for written in joints)


LIMIT = '<limit lower="-1" upper="1" effort="1" velocity="1"/>'

# id: (the robot description, the error class, a pattern its message matches)
CASES: dict[str, tuple[str, type[UrdfError], str]] = {
    'unclosed-element': (
        '<robot name="r"><link name="a"></robot>',
        UrdfMalformedError,
        r'^bad\.urdf:1: XML: malformed XML: .*link',
    ),
    'empty': ('', UrdfMalformedError, r'^bad\.urdf:.*XML: malformed XML'),
    'truncated': (
        '<robot name="r"><link name="a"/>',
        UrdfMalformedError,
        r'^bad\.urdf:1: XML: malformed XML',
    ),
    'not-robot': (
        '<sdf version="1.6"><model name="m"/></sdf>',
        UrdfMalformedError,
        r"^bad\.urdf:1: <sdf>: Could not find the 'robot' element",
    ),
    'robot-without-name': (
        '<robot><link name="a"/></robot>',
        UrdfMalformedError,
        r'^bad\.urdf:1: <robot>: No name given for the robot\.$',
    ),
    'no-links': (robot(''), UrdfMalformedError, r'<robot>: No link elements found in urdf file'),
    'unknown-joint-type': (
        robot(LINKS + joint('j', 'a', 'b', 'ball')),
        UrdfUnsupportedError,
        r"^bad\.urdf:2: joint 'j': Joint \[j\] has no known type \[ball\]",
    ),
    'joint-without-type': (
        robot(LINKS + '<joint name="j"><parent link="a"/><child link="b"/></joint>'),
        UrdfMalformedError,
        r"joint 'j': joint has no type attribute",
    ),
    'missing-child-link': (
        robot(LINKS + fixed_joints('j a ghost', 'k a c')),
        UrdfBrokenRefError,
        r"^bad\.urdf:2: joint 'j': child link \[ghost\] of joint \[j\] not found$",
    ),
    'missing-parent-link': (
        robot(LINKS + fixed_joints('j ghost b', 'k a c')),
        UrdfBrokenRefError,
        r"joint 'j': parent link \[ghost\] of joint \[j\] not found\. Every link",
    ),
    'joint-without-parent': (
        robot(LINKS + '<joint name="j" type="fixed"><child link="b"/></joint>'),
        UrdfMalformedError,
        r"joint 'j': Joint \[j\] is missing a parent and/or child link specification",
    ),
    'link-with-two-parents': (
        robot(LINKS + fixed_joints('j a b', 'k c b')),
        UrdfMalformedError,
        r"joint 'k': link 'b' is the child of two joints \('j' at line 2 and 'k'\)",
    ),
    'two-roots': (
        robot(LINKS + joint('j', 'a', 'b')),
        UrdfMalformedError,
        r'<robot>: Failed to find root link: 2 root links found: \[a\] and \[c\]',
    ),
    'pure-cycle-no-root': (
        robot('<link name="a"/><link name="b"/>' + fixed_joints('j a b', 'k b a')),
        UrdfMalformedError,
        r'<robot>: No root link found\. The robot xml is not a valid tree: links form a cycle '
        r'(a -> b -> a|b -> a -> b)',
    ),
    'cycle-with-two-parents': (
        robot(LINKS + '<link name="d"/>' + fixed_joints('j a b', 'k b c', 'l c d', 'm d c')),
        UrdfMalformedError,
        r'link .c. is the child of two joints',
    ),
    'cycle-beside-a-root': (
        robot(LINKS + '<link name="d"/>' + fixed_joints('j a b', 'k d c', 'l c d')),
        UrdfMalformedError,
        r"joint '(k|l)': links form a cycle (c -> d -> c|d -> c -> d); they are not connected "
        r'to the root link \[a\]',
    ),
    'zero-axis': (
        robot(LINKS + joint('j', 'a', 'b', 'revolute', LIMIT + '<axis xyz="0 0 0"/>')),
        UrdfMalformedError,
        r"joint 'j' <axis>: axis 0 0 0 has no direction",
    ),
    'axis-without-xyz': (
        robot(LINKS + joint('j', 'a', 'b', 'prismatic', LIMIT + '<axis/>')),
        UrdfMalformedError,
        r"joint 'j' <axis>: axis 0 0 0 has no direction",
    ),
    'revolute-without-limit': (
        robot(LINKS + joint('j', 'a', 'b', 'revolute')),
        UrdfMalformedError,
        r"joint 'j': a revolute joint needs a <limit> element",
    ),
    'prismatic-without-limit': (
        robot(LINKS + joint('j', 'a', 'b', 'prismatic')),
        UrdfMalformedError,
        r"joint 'j': a prismatic joint needs a <limit> element",
    ),
    'limit-without-effort': (
        robot(LINKS + joint('j', 'a', 'b', 'revolute', '<limit lower="0" upper="1"/>')),
        UrdfMalformedError,
        r"joint 'j' <limit>: <limit> has no effort attribute",
    ),
    'non-numeric-origin': (
        robot(LINKS + joint('j', 'a', 'b', extra='<origin xyz="1 two 3"/>')),
        UrdfMalformedError,
        r"^bad\.urdf:2: joint 'j' <origin>: attribute xyz=\"1 two 3\": two is not a number$",
    ),
    'two-component-rpy': (
        robot(LINKS + joint('j', 'a', 'b', extra='<origin rpy="0 0"/>')),
        UrdfMalformedError,
        r'attribute rpy="0 0" is not three numbers',
    ),
    'non-numeric-limit': (
        robot(
            LINKS
            + joint(
                'j',
                'a',
                'b',
                'revolute',
                '<limit lower="-1" upper="1_0" effort="1" velocity="1"/>',
            )
        ),
        UrdfMalformedError,
        r"joint 'j' <limit>: attribute upper=\"1_0\" is not a number",
    ),
    'non-numeric-mimic': (
        robot(LINKS + joint('j', 'a', 'b', 'continuous', '<mimic joint="k" multiplier="x"/>')),
        UrdfMalformedError,
        r"joint 'j' <mimic>: attribute multiplier=\"x\" is not a number",
    ),
    'duplicate-link': (
        robot('<link name="a"/>\n<link name="a"/>'),
        UrdfMalformedError,
        r"^bad\.urdf:3: link 'a': link 'a' is not unique \(first defined at line 2\)",
    ),
    'duplicate-joint': (
        robot(LINKS + joint('j', 'a', 'b') + '\n' + joint('j', 'a', 'c')),
        UrdfMalformedError,
        r"^bad\.urdf:3: joint 'j': joint 'j' is not unique \(first defined at line 2\)",
    ),
    'mimic-cycle': (
        robot(
            LINKS
            + joint('j', 'a', 'b', 'continuous', '<mimic joint="k"/>')
            + joint('k', 'b', 'c', 'continuous', '<mimic joint="j"/>')
        ),
        UrdfMalformedError,
        r"joint 'j' <mimic>: mimic joints form a cycle: j -> k -> j",
    ),
    'mimic-of-itself': (
        robot(
            LINKS + joint('j', 'a', 'b', 'continuous', '<mimic joint="j"/>') + joint('k', 'b', 'c')
        ),
        UrdfMalformedError,
        r'mimic joints form a cycle: j -> j',
    ),
    'unsupported-version': (
        '<robot name="r" version="2.0"><link name="a"/></robot>',
        UrdfUnsupportedError,
        r'<robot>: unsupported URDF version "2\.0"',
    ),
}


@pytest.mark.parametrize(('xml', 'error', 'pattern'), CASES.values(), ids=CASES.keys())
def test_invalid_description_is_rejected_with_a_clear_message(
    xml: str, error: type[UrdfError], pattern: str
) -> None:
    """The error class and message name the source, the element and the reason."""
    with pytest.raises(error) as caught:
        RobotModel.from_string(xml, source='bad.urdf')
    assert re.search(pattern, str(caught.value)), str(caught.value)
    assert isinstance(caught.value, ValueError)


def test_malformed_xml_is_never_repaired(tmp_path) -> None:
    """A file whose XML is broken half-way fails instead of loading what precedes the break."""
    path = tmp_path / 'half.urdf'
    path.write_text(robot('<link name="a"/>\n<link name="b">\n' + joint('j', 'a', 'b')))
    with pytest.raises(UrdfMalformedError, match=rf'^{re.escape(str(path))}:\d+: XML: malformed'):
        RobotModel.from_file(path)


def test_missing_file_is_a_broken_reference(tmp_path) -> None:
    """A path that does not exist is reported with that path."""
    missing = tmp_path / 'nope.urdf'
    with pytest.raises(UrdfBrokenRefError, match=rf'^{re.escape(str(missing))}: file: no such'):
        RobotModel.from_file(missing)


def test_unknown_elements_and_link_contents_are_accepted() -> None:
    """Like urdfdom, extra elements (gazebo, transmission, visuals) do not make a robot invalid."""
    xml = robot(
        '<link name="a"><visual><geometry><mesh filename="package://x/y.dae"/></geometry>'
        '</visual></link><link name="b"/><gazebo reference="a"/><transmission name="t"/>'
        + joint('j', 'a', 'b', 'continuous')
    )
    model = RobotModel.from_string(xml)
    assert model.movable_joints == ['j']
    assert model.joint('j').axis == (1.0, 0.0, 0.0)


def test_limit_bounds_default_to_zero_and_continuous_needs_no_limit() -> None:
    """urdfdom defaults: lower/upper 0 when absent; a continuous joint needs no <limit>."""
    xml = robot(
        LINKS
        + joint('j', 'a', 'b', 'revolute', '<limit effort="1" velocity="2"/>')
        + joint('k', 'b', 'c', 'continuous')
    )
    model = RobotModel.from_string(xml)
    limit = model.joint('j').limit
    assert limit is not None
    assert (limit.lower, limit.upper, limit.effort, limit.velocity) == (0.0, 0.0, 1.0, 2.0)
    assert model.joint('k').limit is None


def test_visuals_are_kept_with_their_origin_shape_and_colour():
    """Visuals in document order; inline and named materials; collisions are not visuals."""
    model = RobotModel.from_string(
        robot(
            '<material name="blue"><color rgba="0 0 1 1"/></material>'
            '<link name="a"><visual><origin xyz="1 2 3" rpy="0 0 1.5"/>'
            '<geometry><box size="0.1 0.2 0.3"/></geometry><material name="blue"/></visual>'
            '<collision><geometry><sphere radius="9"/></geometry></collision></link>'
            '<link name="b"><visual><geometry><cylinder radius="0.5" length="2"/></geometry>'
            '<material name="red"><color rgba="1 0 0 0.5"/></material></visual>'
            '<visual><geometry><mesh filename="package://p/m.stl"/></geometry></visual></link>'
            + joint('j', 'a', 'b')
        )
    )
    first, second, third = model.description.visuals
    assert (first.link, first.xyz, first.rpy, first.shape, first.size, first.rgba) == (
        'a',
        (1.0, 2.0, 3.0),
        (0.0, 0.0, 1.5),
        'box',
        (0.1, 0.2, 0.3),
        (0.0, 0.0, 1.0, 1.0),
    )
    assert (second.shape, second.size, second.rgba) == ('cylinder', (0.5, 2.0), (1, 0, 0, 0.5))
    assert (third.shape, third.size, third.filename, third.rgba) == (
        'mesh',
        (1.0, 1.0, 1.0),
        'package://p/m.stl',
        None,
    )
