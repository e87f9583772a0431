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


LIMIT = '<limit lower="-1" upper="1" effort="1" velocity="1"/>'

CASES = [
    pytest.param(
        '<robot name="r"><link name="a"></robot>',
        UrdfMalformedError,
        r'^bad\.urdf:1: XML: malformed XML: .*link',
        id='unclosed-element',
    ),
    pytest.param('', UrdfMalformedError, r'^bad\.urdf:.*XML: malformed XML', id='empty'),
    pytest.param(
        '<robot name="r"><link name="a"/>',
        UrdfMalformedError,
        r'^bad\.urdf:1: XML: malformed XML',
        id='truncated',
    ),
    pytest.param(
        '<sdf version="1.6"><model name="m"/></sdf>',
        UrdfMalformedError,
        r"^bad\.urdf:1: <sdf>: Could not find the 'robot' element",
        id='not-robot',
    ),
    pytest.param(
        '<robot><link name="a"/></robot>',
        UrdfMalformedError,
        r'^bad\.urdf:1: <robot>: No name given for the robot\.$',
        id='robot-without-name',
    ),
    pytest.param(
        robot(''),
        UrdfMalformedError,
        r'<robot>: No link elements found in urdf file',
        id='no-links',
    ),
    pytest.param(
        robot(LINKS + joint('j', 'a', 'b', 'ball')),
        UrdfUnsupportedError,
        r"^bad\.urdf:2: joint 'j': Joint \[j\] has no known type \[ball\]",
        id='unknown-joint-type',
    ),
    pytest.param(
        robot(LINKS + '<joint name="j"><parent link="a"/><child link="b"/></joint>'),
        UrdfMalformedError,
        r"joint 'j': joint has no type attribute",
        id='joint-without-type',
    ),
    pytest.param(
        robot(LINKS + joint('j', 'a', 'ghost') + joint('k', 'a', 'c')),
        UrdfBrokenRefError,
        r"^bad\.urdf:2: joint 'j': child link \[ghost\] of joint \[j\] not found$",
        id='missing-child-link',
    ),
    pytest.param(
        robot(LINKS + joint('j', 'ghost', 'b') + joint('k', 'a', 'c')),
        UrdfBrokenRefError,
        r"joint 'j': parent link \[ghost\] of joint \[j\] not found\. Every link",
        id='missing-parent-link',
    ),
    pytest.param(
        robot(LINKS + '<joint name="j" type="fixed"><child link="b"/></joint>'),
        UrdfMalformedError,
        r"joint 'j': Joint \[j\] is missing a parent and/or child link specification",
        id='joint-without-parent',
    ),
    pytest.param(
        robot(LINKS + joint('j', 'a', 'b') + joint('k', 'c', 'b')),
        UrdfMalformedError,
        r"joint 'k': link 'b' is the child of two joints \('j' at line 2 and 'k'\)",
        id='link-with-two-parents',
    ),
    pytest.param(
        robot(LINKS + joint('j', 'a', 'b')),
        UrdfMalformedError,
        r'<robot>: Failed to find root link: 2 root links found: \[a\] and \[c\]',
        id='two-roots',
    ),
    pytest.param(
        robot('<link name="a"/><link name="b"/>' + joint('j', 'a', 'b') + joint('k', 'b', 'a')),
        UrdfMalformedError,
        r'<robot>: No root link found\. The robot xml is not a valid tree: links form a cycle '
        r'(a -> b -> a|b -> a -> b)',
        id='pure-cycle-no-root',
    ),
    pytest.param(
        robot(
            LINKS
            + '<link name="d"/>'
            + joint('j', 'a', 'b')
            + joint('k', 'b', 'c')
            + joint('l', 'c', 'd')
            + joint('m', 'd', 'c')
        ),
        UrdfMalformedError,
        r'link .c. is the child of two joints',
        id='cycle-with-two-parents',
    ),
    pytest.param(
        robot(
            LINKS
            + '<link name="d"/>'
            + joint('j', 'a', 'b')
            + joint('k', 'd', 'c')
            + joint('l', 'c', 'd')
        ),
        UrdfMalformedError,
        r"joint '(k|l)': links form a cycle (c -> d -> c|d -> c -> d); they are not connected "
        r'to the root link \[a\]',
        id='cycle-beside-a-root',
    ),
    pytest.param(
        robot(LINKS + joint('j', 'a', 'b', 'revolute', LIMIT + '<axis xyz="0 0 0"/>')),
        UrdfMalformedError,
        r"joint 'j' <axis>: axis 0 0 0 has no direction",
        id='zero-axis',
    ),
    pytest.param(
        robot(LINKS + joint('j', 'a', 'b', 'prismatic', LIMIT + '<axis/>')),
        UrdfMalformedError,
        r"joint 'j' <axis>: axis 0 0 0 has no direction",
        id='axis-without-xyz',
    ),
    pytest.param(
        robot(LINKS + joint('j', 'a', 'b', 'revolute')),
        UrdfMalformedError,
        r"joint 'j': a revolute joint needs a <limit> element",
        id='revolute-without-limit',
    ),
    pytest.param(
        robot(LINKS + joint('j', 'a', 'b', 'prismatic')),
        UrdfMalformedError,
        r"joint 'j': a prismatic joint needs a <limit> element",
        id='prismatic-without-limit',
    ),
    pytest.param(
        robot(LINKS + joint('j', 'a', 'b', 'revolute', '<limit lower="0" upper="1"/>')),
        UrdfMalformedError,
        r"joint 'j' <limit>: <limit> has no effort attribute",
        id='limit-without-effort',
    ),
    pytest.param(
        robot(LINKS + joint('j', 'a', 'b', extra='<origin xyz="1 two 3"/>')),
        UrdfMalformedError,
        r"^bad\.urdf:2: joint 'j' <origin>: attribute xyz=\"1 two 3\": two is not a number$",
        id='non-numeric-origin',
    ),
    pytest.param(
        robot(LINKS + joint('j', 'a', 'b', extra='<origin rpy="0 0"/>')),
        UrdfMalformedError,
        r'attribute rpy="0 0" is not three numbers',
        id='two-component-rpy',
    ),
    pytest.param(
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
        id='non-numeric-limit',
    ),
    pytest.param(
        robot(LINKS + joint('j', 'a', 'b', 'continuous', '<mimic joint="k" multiplier="x"/>')),
        UrdfMalformedError,
        r"joint 'j' <mimic>: attribute multiplier=\"x\" is not a number",
        id='non-numeric-mimic',
    ),
    pytest.param(
        robot('<link name="a"/>\n<link name="a"/>'),
        UrdfMalformedError,
        r"^bad\.urdf:3: link 'a': link 'a' is not unique \(first defined at line 2\)",
        id='duplicate-link',
    ),
    pytest.param(
        robot(LINKS + joint('j', 'a', 'b') + '\n' + joint('j', 'a', 'c')),
        UrdfMalformedError,
        r"^bad\.urdf:3: joint 'j': joint 'j' is not unique \(first defined at line 2\)",
        id='duplicate-joint',
    ),
    pytest.param(
        robot(
            LINKS
            + joint('j', 'a', 'b', 'continuous', '<mimic joint="k"/>')
            + joint('k', 'b', 'c', 'continuous', '<mimic joint="j"/>')
        ),
        UrdfMalformedError,
        r"joint 'j' <mimic>: mimic joints form a cycle: j -> k -> j",
        id='mimic-cycle',
    ),
    pytest.param(
        robot(
            LINKS + joint('j', 'a', 'b', 'continuous', '<mimic joint="j"/>') + joint('k', 'b', 'c')
        ),
        UrdfMalformedError,
        r'mimic joints form a cycle: j -> j',
        id='mimic-of-itself',
    ),
    pytest.param(
        '<robot name="r" version="2.0"><link name="a"/></robot>',
        UrdfUnsupportedError,
        r'<robot>: unsupported URDF version "2\.0"',
        id='unsupported-version',
    ),
]


@pytest.mark.parametrize(('xml', 'error', 'pattern'), CASES)
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
