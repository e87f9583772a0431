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
Strict URDF parsing and validation into plain, immutable data.

This module is the functional core of loading: ``parse_robot(xml, source)`` either returns a
:class:`RobotDescription` whose links form one tree, or raises a :exc:`.UrdfError` subclass whose
message names the source, the element and the reason. It follows urdfdom's rules (what
robot_state_publisher accepts) and adds the checks urdfdom lacks: a link that is the child of two
joints, cycles, zero axes, duplicate names and mimic cycles. Every number goes through one
function that refuses what urdfdom refuses (not a decimal number, or not finite). A mimic of a
joint that does not exist is ignored with a warning, as urdfdom and robot_state_publisher load
such a robot.
Malformed XML is never repaired.
"""

from __future__ import annotations

from dataclasses import dataclass
from dataclasses import replace
import math
import re
from typing import NoReturn

from lxml import etree  # type: ignore[import-untyped]
from tf_demo.core.math3d import Vec3
from tf_demo.urdf.errors import UrdfBrokenRefError
from tf_demo.urdf.errors import UrdfMalformedError
from tf_demo.urdf.errors import UrdfUnsupportedError

__all__ = [
    'JOINT_TYPES',
    'JointDescription',
    'Limit',
    'Mimic',
    'RobotDescription',
    'parse_robot',
]

JOINT_TYPES = ('revolute', 'continuous', 'prismatic', 'fixed', 'floating', 'planar')
MOVABLE_TYPES = frozenset({'revolute', 'continuous', 'prismatic'})
_DYNAMICS = ('damping', 'friction')
_INERTIA = ('ixx', 'ixy', 'ixz', 'iyy', 'iyz', 'izz')
_SHAPE_NUMBERS: dict[str, tuple[tuple[str, int], ...]] = {
    'sphere': (('radius', 1),),
    'box': (('size', 3),),
    'cylinder': (('radius', 1), ('length', 1)),
    'mesh': (('scale', 3),),
}
_NUMBER = re.compile(r'[+-]?(?:\d+\.?\d*(?:[eE][+-]?\d+)?|\.\d+(?:[eE][+-]?\d+)?)')


@dataclass(frozen=True)
class Limit:
    """The ``<limit>`` of a joint (lower and upper default to 0 as in urdfdom)."""

    lower: float
    upper: float
    effort: float
    velocity: float


@dataclass(frozen=True)
class Mimic:
    """``<mimic joint multiplier offset>``: position = multiplier * source + offset."""

    joint: str
    multiplier: float = 1.0
    offset: float = 0.0


@dataclass(frozen=True)
class JointDescription:
    """One ``<joint>`` as written (axis not normalised); ``line`` is its line in the source."""

    name: str
    type: str
    parent: str
    child: str
    xyz: Vec3
    rpy: Vec3
    axis: Vec3
    limit: Limit | None
    mimic: Mimic | None
    soft_lower: float | None
    soft_upper: float | None
    line: int | None


@dataclass(frozen=True)
class Visual:
    """
    One ``<visual>`` of a link: its origin in the link, its shape and its colour.

    ``size`` is the shape's numbers: ``box`` (x, y, z), ``cylinder`` (radius, length),
    ``sphere`` (radius,), ``mesh`` its scale (1, 1, 1 by default). ``rgba`` is the inline or
    named material's colour (None when the URDF gives none).
    """

    link: str
    xyz: Vec3
    rpy: Vec3
    shape: str
    size: tuple[float, ...]
    filename: str | None = None
    rgba: tuple[float, float, float, float] | None = None


@dataclass(frozen=True)
class RobotDescription:
    """A validated robot: one tree of links joined by joints, in document order."""

    name: str
    source: str
    links: tuple[str, ...]
    joints: tuple[JointDescription, ...]
    root: str
    links_with_inertia: frozenset[str] = frozenset()
    warnings: tuple[str, ...] = ()
    """Problems upstream also tolerates (e.g. a mimic of a missing joint), one line each."""
    visuals: tuple[Visual, ...] = ()
    """The links' visual geometry in document order (what rviz2's RobotModel draws)."""


class _Reader:
    """Reads one document, raising errors that carry the source name and line numbers."""

    def __init__(self, source: str) -> None:
        self.source = source

    def malformed(self, element: str, reason: str, node: etree._Element | None) -> NoReturn:
        raise UrdfMalformedError(self.source, element, reason, _line(node))

    def number(
        self,
        text: str | None,
        element: str,
        attribute: str,
        node: etree._Element,
        whole: str | None = None,
    ) -> float:
        """
        Parse one double as urdfdom does; the one place every number of a URDF goes through.

        Anything that is not a decimal number (``inf``, ``nan``, hex, ``1_0``) is refused, and so
        is a number too large for a double (``1e400``), as urdfdom refuses them.
        """
        label = f'attribute {attribute}="{text}"'
        if whole is not None:  # one piece of a vector attribute
            label = f'attribute {attribute}="{whole}": {text}'
        if text is None or not _NUMBER.fullmatch(text.strip()):
            self.malformed(element, f'{label} is not a number', node)
        value = float(text.strip())
        if not math.isfinite(value):
            self.malformed(element, f'{label} is out of range (not a finite double)', node)
        return value

    def optional_number(
        self, node: etree._Element, attribute: str, element: str, default: float | None
    ) -> float | None:
        """Parse ``attribute`` of ``node`` when present, else return ``default``."""
        text = node.get(attribute)
        if text is None:
            return default
        return self.number(text, element, attribute, node)

    def numbers(
        self, node: etree._Element, attribute: str, element: str, count: int
    ) -> tuple[float, ...] | None:
        """Parse ``"a b c"``: exactly ``count`` space-separated numbers (None when absent)."""
        text = node.get(attribute)
        if text is None:
            return None
        pieces = text.split()
        if len(pieces) != count:
            words = {3: 'three', 4: 'four'}.get(count, str(count))
            self.malformed(
                element,
                f'attribute {attribute}="{text}" is not {words} numbers separated by spaces',
                node,
            )
        return tuple(self.number(piece, element, attribute, node, text) for piece in pieces)

    def vector(self, node: etree._Element, attribute: str, element: str, default: Vec3) -> Vec3:
        """Parse ``"x y z"``: exactly three space-separated finite numbers."""
        values = self.numbers(node, attribute, element, 3)
        if values is None:
            return default
        return (values[0], values[1], values[2])

    def origin(self, parent: etree._Element, element: str) -> tuple[Vec3, Vec3]:
        """Parse the first ``<origin xyz rpy>`` of ``parent`` (zeros when absent)."""
        zero: Vec3 = (0.0, 0.0, 0.0)
        node = parent.find('origin')
        if node is None:
            return zero, zero
        return (
            self.vector(node, 'xyz', f'{element} <origin>', zero),
            self.vector(node, 'rpy', f'{element} <origin>', zero),
        )


def _line(node: etree._Element | None) -> int | None:
    return None if node is None else node.sourceline


def _parse_xml(xml: str | bytes, source: str) -> etree._Element:
    data = xml.encode('utf-8') if isinstance(xml, str) else xml
    parser = etree.XMLParser(
        recover=False, resolve_entities=False, no_network=True, remove_comments=True
    )
    try:
        return etree.fromstring(data, parser)
    except etree.XMLSyntaxError as error:
        reason = error.msg or 'document is empty'
        line = error.lineno if error.lineno else None
        raise UrdfMalformedError(source, 'XML', f'malformed XML: {reason}', line) from None


def _parse_joint(reader: _Reader, node: etree._Element) -> JointDescription:
    name = node.get('name')
    if not name:
        reader.malformed('<joint>', 'joint has no name attribute', node)
    element = f"joint '{name}'"
    joint_type = node.get('type')
    if joint_type is None:
        reader.malformed(element, 'joint has no type attribute', node)
    if joint_type not in JOINT_TYPES:
        raise UrdfUnsupportedError(
            reader.source,
            element,
            f'Joint [{name}] has no known type [{joint_type}] '
            f'(expected one of {", ".join(JOINT_TYPES)})',
            _line(node),
        )

    links: dict[str, str] = {}
    for role in ('parent', 'child'):
        role_nodes = node.findall(role)
        if len(role_nodes) != 1 or not role_nodes[0].get('link'):
            reader.malformed(
                element,
                f'Joint [{name}] is missing a parent and/or child link specification '
                f'(needs exactly one <{role} link="..."/>)',
                node,
            )
        links[role] = role_nodes[0].get('link', '')

    xyz, rpy = reader.origin(node, element)

    axis: Vec3 = (1.0, 0.0, 0.0)
    axis_node = node.find('axis')
    if axis_node is not None:
        axis = reader.vector(axis_node, 'xyz', f'{element} <axis>', (0.0, 0.0, 0.0))
    if joint_type in MOVABLE_TYPES:
        norm = math.sqrt(axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2])
        if not norm > 0.0 or math.isinf(norm):
            reader.malformed(
                f'{element} <axis>',
                f'axis {axis[0]:g} {axis[1]:g} {axis[2]:g} has no direction '
                '(zero or not finite length)',
                axis_node if axis_node is not None else node,
            )

    limit: Limit | None = None
    limit_node = node.find('limit')
    if limit_node is not None:
        limit_element = f'{element} <limit>'
        values: dict[str, float] = {}
        for attribute in ('effort', 'velocity'):
            value = reader.optional_number(limit_node, attribute, limit_element, None)
            if value is None and joint_type in {'revolute', 'prismatic'}:
                reader.malformed(
                    limit_element, f'<limit> has no {attribute} attribute', limit_node
                )
            values[attribute] = 0.0 if value is None else value
        lower = reader.number(limit_node.get('lower', '0'), limit_element, 'lower', limit_node)
        upper = reader.number(limit_node.get('upper', '0'), limit_element, 'upper', limit_node)
        limit = Limit(lower, upper, values['effort'], values['velocity'])
    elif joint_type in {'revolute', 'prismatic'}:
        reader.malformed(
            element, f'a {joint_type} joint needs a <limit> element (none found)', node
        )

    mimic: Mimic | None = None
    mimic_node = node.find('mimic')
    if mimic_node is not None:
        mimic_element = f'{element} <mimic>'
        source_joint = mimic_node.get('joint')
        if not source_joint:
            reader.malformed(mimic_element, '<mimic> has no joint attribute', mimic_node)
        multiplier = reader.number(
            mimic_node.get('multiplier', '1.0'), mimic_element, 'multiplier', mimic_node
        )
        offset = reader.number(
            mimic_node.get('offset', '0.0'), mimic_element, 'offset', mimic_node
        )
        mimic = Mimic(source_joint, multiplier, offset)

    soft_lower: float | None = None
    soft_upper: float | None = None
    safety = node.find('safety_controller')
    if safety is not None:
        safety_element = f'{element} <safety_controller>'
        soft_lower = reader.optional_number(safety, 'soft_lower_limit', safety_element, None)
        soft_upper = reader.optional_number(safety, 'soft_upper_limit', safety_element, None)
        reader.optional_number(safety, 'k_position', safety_element, None)
        reader.optional_number(safety, 'k_velocity', safety_element, None)
    for tag, attributes in (('calibration', ('rising', 'falling')), ('dynamics', _DYNAMICS)):
        extra = node.find(tag)
        for attribute in attributes if extra is not None else ():
            reader.optional_number(extra, attribute, f'{element} <{tag}>', None)

    return JointDescription(
        name=name,
        type=joint_type,
        parent=links['parent'],
        child=links['child'],
        xyz=xyz,
        rpy=rpy,
        axis=axis,
        limit=limit,
        mimic=mimic,
        soft_lower=soft_lower,
        soft_upper=soft_upper,
        line=_line(node),
    )


def _read_link_geometry(
    reader: _Reader,
    node: etree._Element,
    name: str,
    materials: dict[str, tuple[float, float, float, float]],
) -> list[Visual]:
    """Check the numbers urdfdom reads in a link (inertial, visual, collision); return visuals."""
    element = f"link '{name}'"
    inertial = node.find('inertial')
    if inertial is not None:
        where = f'{element} <inertial>'
        reader.origin(inertial, where)
        for tag, attributes in (('mass', ('value',)), ('inertia', _INERTIA)):
            part = inertial.find(tag)
            for attribute in attributes if part is not None else ():
                reader.optional_number(part, attribute, f'{where} <{tag}>', None)
    visuals: list[Visual] = []
    for tag in ('visual', 'collision'):
        for part in node.iterchildren(tag):
            where = f'{element} <{tag}>'
            xyz, rpy = reader.origin(part, where)
            geometry = part.find('geometry')
            shape = (
                next((c for c in geometry if isinstance(c.tag, str)), None)
                if (geometry is not None)
                else None
            )
            if shape is None:
                continue
            size: list[float] = []
            for attribute, count in _SHAPE_NUMBERS.get(shape.tag, ()):
                shape_element = f'{where} <{shape.tag}>'
                if count == 1:
                    size.append(
                        reader.optional_number(shape, attribute, shape_element, 0.0) or 0.0
                    )
                else:
                    size.extend(
                        reader.numbers(shape, attribute, shape_element, count) or (1.0,) * 3
                    )
            if tag == 'visual' and shape.tag in _SHAPE_NUMBERS:
                rgba = _material_colour(reader, part.find('material'), where, materials)
                filename = shape.get('filename') if shape.tag == 'mesh' else None
                visuals.append(Visual(name, xyz, rpy, shape.tag, tuple(size), filename, rgba))
    return visuals


def _material_colour(
    reader: _Reader,
    material: etree._Element | None,
    where: str,
    materials: dict[str, tuple[float, float, float, float]],
) -> tuple[float, float, float, float] | None:
    """Return a ``<material>``'s ``<color rgba>``, inline or by name (None without one)."""
    if material is None:
        return None
    color = material.find('color')
    if color is not None:
        rgba = reader.numbers(color, 'rgba', f'{where} <material> <color>', 4)
        if rgba is not None:
            return (rgba[0], rgba[1], rgba[2], rgba[3])
    return materials.get(material.get('name') or '')


def _global_materials(
    reader: _Reader, root: etree._Element
) -> dict[str, tuple[float, float, float, float]]:
    """Return the colours of the robot's named top-level ``<material>`` elements."""
    materials: dict[str, tuple[float, float, float, float]] = {}
    for material in root.iterchildren('material'):
        name = material.get('name')
        rgba = _material_colour(reader, material, f"material '{name}'", {})
        if name and rgba is not None:
            materials[name] = rgba
    return materials


def parse_robot(xml: str | bytes, source: str = '<string>') -> RobotDescription:
    """
    Parse and validate a URDF document.

    :param xml: the URDF text (already expanded if it was xacro).
    :param source: how to name the document in error messages (usually its file path).
    :return: the validated description.
    :raises UrdfError: (a subclass) naming the source, the element and the reason.
    """
    reader = _Reader(source)
    root = _parse_xml(xml, source)
    if root.tag != 'robot':
        raise UrdfMalformedError(
            source,
            f'<{root.tag}>' if isinstance(root.tag, str) else 'document',
            "Could not find the 'robot' element in the xml file (the root element must be "
            '<robot>)',
            _line(root),
        )
    robot_name = root.get('name')
    if not robot_name:
        reader.malformed('<robot>', 'No name given for the robot.', root)
    version = root.get('version')
    if version is not None and version.strip() != '1.0':
        raise UrdfUnsupportedError(
            source, '<robot>', f'unsupported URDF version "{version}" (only 1.0)', _line(root)
        )

    links: list[str] = []
    visuals: list[Visual] = []
    materials = _global_materials(reader, root)
    link_lines: dict[str, int | None] = {}
    inertial_links: set[str] = set()
    for node in root.iterchildren('link'):
        link_name = node.get('name')
        if not link_name:
            reader.malformed('<link>', 'link has no name attribute', node)
        if link_name in link_lines:
            reader.malformed(
                f"link '{link_name}'",
                f"link '{link_name}' is not unique (first defined at line "
                f'{link_lines[link_name]})',
                node,
            )
        link_lines[link_name] = _line(node)
        visuals.extend(_read_link_geometry(reader, node, link_name, materials))
        if node.find('inertial') is not None:
            inertial_links.add(link_name)
        links.append(link_name)
    if not links:
        reader.malformed('<robot>', 'No link elements found in urdf file', root)

    joints: list[JointDescription] = []
    joint_lines: dict[str, int | None] = {}
    for node in root.iterchildren('joint'):
        joint = _parse_joint(reader, node)
        if joint.name in joint_lines:
            reader.malformed(
                f"joint '{joint.name}'",
                f"joint '{joint.name}' is not unique (first defined at line "
                f'{joint_lines[joint.name]})',
                node,
            )
        joint_lines[joint.name] = joint.line
        joints.append(joint)

    parent_joint: dict[str, JointDescription] = {}
    for joint in joints:
        element = f"joint '{joint.name}'"
        if joint.parent not in link_lines:
            raise UrdfBrokenRefError(
                source,
                element,
                f'parent link [{joint.parent}] of joint [{joint.name}] not found. Every link '
                'you refer to from a joint needs to be explicitly defined in the robot '
                'description.',
                joint.line,
            )
        if joint.child not in link_lines:
            raise UrdfBrokenRefError(
                source,
                element,
                f'child link [{joint.child}] of joint [{joint.name}] not found',
                joint.line,
            )
        if joint.child in parent_joint:
            other = parent_joint[joint.child]
            reader_line = joint.line
            raise UrdfMalformedError(
                source,
                element,
                f"link '{joint.child}' is the child of two joints ('{other.name}' at line "
                f"{other.line} and '{joint.name}'); a link has at most one parent",
                reader_line,
            )
        parent_joint[joint.child] = joint

    roots = [link for link in links if link not in parent_joint]
    if len(roots) > 1:
        first, second = sorted(roots)[:2]
        raise UrdfMalformedError(
            source,
            '<robot>',
            f'Failed to find root link: {len(roots)} root links found: [{first}] and '
            f'[{second}]{" and more" if len(roots) > 2 else ""} (a robot is one tree)',
            _line(root),
        )
    if not roots:
        cycle = _cycle_from(links[0], parent_joint)
        raise UrdfMalformedError(
            source,
            '<robot>',
            'No root link found. The robot xml is not a valid tree: links form a cycle '
            f'{" -> ".join(cycle)}',
            _line(root),
        )
    _check_reachable(source, roots[0], links, parent_joint)
    joints, warnings = _resolve_mimics(source, joints)
    _check_mimics(source, joints)
    return RobotDescription(
        robot_name,
        source,
        tuple(links),
        tuple(joints),
        roots[0],
        frozenset(inertial_links),
        tuple(warnings),
        tuple(visuals),
    )


def _cycle_from(start: str, parent_joint: dict[str, JointDescription]) -> list[str]:
    """Follow parent pointers from ``start`` until a link repeats; return that cycle."""
    order: list[str] = []
    seen: dict[str, int] = {}
    link: str | None = start
    while link is not None and link not in seen:
        seen[link] = len(order)
        order.append(link)
        joint = parent_joint.get(link)
        link = joint.parent if joint is not None else None
    if link is None:
        return order
    cycle = order[seen[link] :]
    cycle.reverse()
    return [*cycle, cycle[0]]


def _check_reachable(
    source: str, root: str, links: list[str], parent_joint: dict[str, JointDescription]
) -> None:
    """With one parent per link, a link not under the root lies on (or hangs off) a cycle."""
    children: dict[str, list[str]] = {}
    for child, joint in parent_joint.items():
        children.setdefault(joint.parent, []).append(child)
    reached = {root}
    stack = [root]
    while stack:
        for child in children.get(stack.pop(), ()):
            if child not in reached:
                reached.add(child)
                stack.append(child)
    for link in links:
        if link not in reached:
            cycle = _cycle_from(link, parent_joint)
            joint = parent_joint[cycle[0]]
            raise UrdfMalformedError(
                source,
                f"joint '{joint.name}'",
                f'links form a cycle {" -> ".join(cycle)}; they are not connected to the '
                f'root link [{root}]',
                joint.line,
            )


def _resolve_mimics(
    source: str, joints: list[JointDescription]
) -> tuple[list[JointDescription], list[str]]:
    """
    Drop each ``<mimic>`` of a joint that does not exist, with a warning naming both joints.

    urdfdom and robot_state_publisher load such a robot and ignore the mimic; the joint is then
    an ordinary joint.
    """
    names = {joint.name for joint in joints}
    warnings: list[str] = []
    resolved: list[JointDescription] = []
    for joint in joints:
        if joint.mimic is not None and joint.mimic.joint not in names:
            location = source if joint.line is None else f'{source}:{joint.line}'
            warnings.append(
                f"{location}: joint '{joint.name}' <mimic>: joint '{joint.name}' mimics joint "
                f"'{joint.mimic.joint}', which does not exist; the <mimic> is ignored and "
                f"'{joint.name}' is an ordinary joint"
            )
            resolved.append(replace(joint, mimic=None))
        else:
            resolved.append(joint)
    return resolved, warnings


def _check_mimics(source: str, joints: list[JointDescription]) -> None:
    """Refuse mimic cycles; each joint is visited once (every mimic names an existing joint)."""
    by_name = {joint.name: joint for joint in joints}
    done: set[str] = set()
    for joint in joints:
        path: list[str] = []
        on_path: set[str] = set()
        current: JointDescription | None = joint
        while current is not None and current.name not in done:
            if current.name in on_path:
                cycle = [*path[path.index(current.name) :], current.name]
                first = by_name[cycle[0]]
                raise UrdfMalformedError(
                    source,
                    f"joint '{first.name}' <mimic>",
                    f'mimic joints form a cycle: {" -> ".join(cycle)}',
                    first.line,
                )
            path.append(current.name)
            on_path.add(current.name)
            current = None if current.mimic is None else by_name[current.mimic.joint]
        done.update(path)
