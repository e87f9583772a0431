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
Fuzzing the URDF loader and the xacro entry point with hypothesis.

Whatever the input, the only exceptions are the documented ones (:class:`UrdfError` from
loading, :class:`JointPositionError` from a non-finite position), nothing hangs (xacro runs
under its time limit) and memory stays bounded (measured with tracemalloc for the loader; the
xacro child has an address-space limit). A model that loads never publishes a non-finite number
for finite positions.
"""

from __future__ import annotations

import math
from pathlib import Path
import re
import tempfile
import tracemalloc

from hypothesis import event
from hypothesis import given
from hypothesis import HealthCheck
from hypothesis import settings
from hypothesis import strategies as st
import pytest
from tf_demo.testing.urdf_strategies import robots
from tf_demo.urdf import expand_xacro
from tf_demo.urdf import JointPositionError
from tf_demo.urdf import RobotModel
from tf_demo.urdf import UrdfError

pytestmark = [pytest.mark.property, pytest.mark.timeout(300)]

#: Peak Python allocation allowed while loading one fuzzed document (all are < 64 KiB).
LOADER_MEMORY_BYTES = 32 * 1024 * 1024
HOSTILE_VALUES = [
    '1e400', '-1e400', 'inf', 'nan', '-0', '1e-400', '', ' ', '0x10', '1_0', '9' * 400,
    '1 2', '1 2 3 4', 'a', '&amp;', '${x}', '1e308', '-1e308', '1.', '.5', '+1', 'ghost',
    'revolute', 'continuous', 'prismatic', 'fixed', 'floating', 'planar', 'ball', '\t1\n2 3',
]  # fmt: skip
ATTRIBUTE = re.compile(r'="[^"]*"')


@st.composite
def mutated_robots(draw: st.DrawFn) -> str:
    """A valid generated robot, then a few hostile edits of its text."""
    lines = draw(robots(max_links=6)).xml.splitlines()
    for _ in range(draw(st.integers(1, 4))):
        kind = draw(st.sampled_from(('value', 'value', 'delete', 'duplicate', 'insert', 'cut')))
        index = draw(st.integers(0, len(lines) - 1))
        line = lines[index]
        if kind == 'value':
            spots = list(ATTRIBUTE.finditer(line))
            if spots:
                spot = spots[draw(st.integers(0, len(spots) - 1))]
                value = draw(st.one_of(st.sampled_from(HOSTILE_VALUES), st.text(max_size=8)))
                value = value.replace('"', '&quot;').replace('<', '&lt;')
                lines[index] = f'{line[: spot.start()]}="{value}"{line[spot.end() :]}'
        elif kind == 'delete' and len(lines) > 1:
            del lines[index]
        elif kind == 'duplicate':
            lines.insert(index, line)
        elif kind == 'insert':
            lines.insert(index, draw(st.sampled_from(EXTRA_ELEMENTS)))
        elif kind == 'cut':
            lines[index] = line[: draw(st.integers(0, len(line)))]
    return '\n'.join(lines)


EXTRA_ELEMENTS = [
    '<link name="link_a"/>',
    '<joint name="joint_x" type="fixed"><parent link="link_a"/><child link="link_a"/></joint>',
    '<joint name="joint_m" type="continuous"><parent link="link_a"/><child link="link_new"/>'
    '<mimic joint="joint_m"/></joint>',
    '<mimic joint="nobody" multiplier="1e308"/>',
    '<origin xyz="1e308 1e308 1e308" rpy="1e308 0 0"/>',
    '<axis xyz="0 0 0"/>',
    '<limit lower="1e308" upper="-1e308" effort="1" velocity="1"/>',
    '<inertial><mass value="nan"/></inertial>',
    '<visual><geometry><box size="1 1"/></geometry></visual>',
    '<robot name="nested"/>',
    '<!-- a comment: with a colon -->',
]

POSITIONS = st.floats(-1000.0, 1000.0, allow_nan=False, allow_infinity=False)


def check_model(model: RobotModel, positions: dict[str, float]) -> None:
    """Finite positions give finite transforms (or a JointPositionError for an overflow)."""
    for _, _, translation, rotation in model.static_transforms():
        assert all(math.isfinite(v) for v in (*translation, *rotation))
    try:
        transforms = model.joint_transforms(positions)
        poses = model.link_poses(positions)
    except JointPositionError:
        return  # a mimic multiplier large enough to overflow
    for _, _, translation, rotation in transforms:
        assert all(math.isfinite(v) for v in (*translation, *rotation))
    assert model.root in poses


def load_bounded(xml: str) -> RobotModel | None:
    """Load ``xml``; only a UrdfError may escape; the peak allocation stays bounded."""
    message = ''
    tracemalloc.start()
    try:
        model: RobotModel | None = RobotModel.from_string(xml, source='fuzz.urdf')
    except UrdfError as error:
        model, message = None, str(error)
    finally:
        _, peak = tracemalloc.get_traced_memory()
        tracemalloc.stop()
    assert peak < LOADER_MEMORY_BYTES
    assert model is not None or message.startswith('fuzz.urdf')
    event('loaded' if model is not None else 'UrdfError')
    return model


@settings(max_examples=300, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(xml=mutated_robots(), values=st.lists(POSITIONS, min_size=8, max_size=8))
def test_fuzzed_robots_load_or_fail_with_a_urdf_error(xml: str, values: list[float]) -> None:
    """Mutated robots: a model whose transforms are finite, or a UrdfError naming the source."""
    model = load_bounded(xml)
    if model is None:
        return
    positions = dict(zip(model.movable_joints, values, strict=False))
    check_model(model, positions)
    for bad in (math.inf, math.nan):
        for name in model.movable_joints[:1]:
            with pytest.raises(JointPositionError, match=r"^joint '[^']+': position"):
                model.joint_transforms({name: bad})


@settings(max_examples=200, deadline=None)
@given(text=st.one_of(st.text(max_size=300), st.binary(max_size=300).map(repr)))
def test_arbitrary_text_is_a_urdf_error(text: str) -> None:
    """Text that is no robot at all fails with a UrdfError (never another exception)."""
    assert load_bounded(text) is None or '<robot' in text


# -- xacro -----------------------------------------------------------------------------------

NAMES = ('p0', 'p1', 'p2')
MACROS = ('m0', 'm1')
FILES = ('main.xacro', 'part.xacro')


def expressions() -> st.SearchStrategy[str]:
    """Small Python expressions as xacro evaluates them (no huge powers: see the unit test)."""
    atom = st.one_of(
        st.integers(-20, 20).map(str),
        st.sampled_from(('0.5', '1e3', 'pi', "'s'", 'x', '[]', '{}', 'None', 'True', *NAMES)),
        st.sampled_from(('len([1, 2])', 'radians(90)', 'int("3")', 'float("nan")')),
    )
    operator = st.sampled_from(('+', '-', '*', '/', '//', '%', '==', ' and ', ' or ', '**'))
    return st.recursive(
        atom,
        lambda inner: st.tuples(inner, operator, inner).map(
            lambda t: f'({t[0]}{t[1]}{t[2]})' if t[1] != '**' else f'({t[0]}**2)'
        ),
        max_leaves=4,
    )


@st.composite
def xacro_elements(draw: st.DrawFn, depth: int = 0) -> str:
    """One xacro element: properties, args, macros (maybe recursive), includes, links."""
    expression = draw(expressions()).replace('"', '&quot;').replace('<', '&lt;')
    kinds = ['property', 'link', 'joint', 'call', 'include', 'if', 'arg', 'text']
    if depth == 0:
        kinds.append('macro')
    kind = draw(st.sampled_from(kinds))
    name = draw(st.sampled_from(NAMES))
    if kind == 'property':
        return f'<xacro:property name="{name}" value="${{{expression}}}"/>'
    if kind == 'link':
        return f'<link name="${{{expression}}}"/>'
    if kind == 'joint':
        parent, child = draw(st.sampled_from(('a', 'b', '${p0}'))), draw(st.sampled_from('bc'))
        return (
            f'<joint name="j{draw(st.integers(0, 3))}" type="fixed"><parent link="{parent}"/>'
            f'<child link="{child}"/><origin xyz="${{{expression}}} 0 0"/></joint>'
        )
    if kind == 'call':
        return f'<xacro:{draw(st.sampled_from(MACROS))} x="${{{expression}}}"/>'
    if kind == 'include':
        target = draw(st.sampled_from((*FILES, 'missing.xacro', '/dev/null')))
        return f'<xacro:include filename="{target}"/>'
    if kind == 'if':
        inner = draw(xacro_elements(depth + 1))
        return f'<xacro:if value="${{{expression}}}">{inner}</xacro:if>'
    if kind == 'arg':
        return f'<xacro:arg name="{name}" default="{expression}"/><link name="$(arg {name})"/>'
    if kind == 'text':
        return draw(st.sampled_from(('<link name="a"/>', '<link name="b"/>', '<bogus/>', '')))
    body = ''.join(draw(st.lists(xacro_elements(depth + 1), max_size=3)))
    return (
        f'<xacro:macro name="{draw(st.sampled_from(MACROS))}" params="x:=1">{body}</xacro:macro>'
    )


@st.composite
def xacro_projects(draw: st.DrawFn) -> tuple[dict[str, str], dict[str, str]]:
    """Two files that may include each other, and the arguments given on the command line."""
    files = {}
    for name in FILES:
        body = ''.join(draw(st.lists(xacro_elements(), max_size=6)))
        files[name] = (
            f'<robot name="fuzz" xmlns:xacro="http://www.ros.org/wiki/xacro">{body}</robot>'
        )
    arguments = draw(st.dictionaries(st.sampled_from(NAMES), st.text(max_size=6), max_size=2))
    return files, arguments


@settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(project=xacro_projects())
def test_fuzzed_xacro_expands_or_fails_with_a_urdf_error(
    project: tuple[dict[str, str], dict[str, str]],
) -> None:
    """Generated xacro code: URDF text (a model or a UrdfError), or a UrdfError; never a hang."""
    files, arguments = project
    with tempfile.TemporaryDirectory() as directory:
        for name, text in files.items():
            Path(directory, name).write_text(text, encoding='utf-8')
        main = Path(directory, 'main.xacro')
        try:
            xml, message = expand_xacro(main, arguments, timeout_s=20.0), ''
        except UrdfError as error:
            xml, message = '', str(error)
    if message:
        event('xacro: UrdfError')
        assert message.startswith(str(main))
        assert '\n' not in message
        return
    event('xacro: expanded')
    model = load_bounded(xml)
    if model is not None:
        check_model(model, dict.fromkeys(model.movable_joints, 0.5))
