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
``static_tf_pub``: publish static transforms once, latched on ``/tf_static``.

By default base_link -> camera_link at (0.5, 0, 0.2) without rotation, as in the course.
Parameters (``--ros-args -p name:=value``):

- ``parent_frame`` (``base_link``), ``child_frame`` (``camera_link``);
- ``translation`` ([0.5, 0.0, 0.2]) in metres;
- ``rotation`` ([0.0, 0.0, 0.0]): [roll, pitch, yaw] in radians or a quaternion [x, y, z, w];
- ``transforms_file`` (''): a YAML file with a whole set of static transforms (see
  ``config/rep105_static_transforms.yaml``); when set, it replaces the single transform above.
"""

from __future__ import annotations

from dataclasses import dataclass
import sys

from tf_demo.core.files import InputFileError
from tf_demo.core.files import read_text_file
from tf_demo.core.math3d import Quat
from tf_demo.core.math3d import Vec3
from tf_demo.nodes.helpers import as_frame
from tf_demo.nodes.helpers import as_vector3
from tf_demo.nodes.helpers import declare_flexible
from tf_demo.nodes.helpers import make_transform_stamped
from tf_demo.nodes.helpers import NodeConfigError
from tf_demo.nodes.helpers import now_ns
from tf_demo.nodes.helpers import rotation_from_values
from tf_demo.ros.static_transform_broadcaster import StaticTransformBroadcaster
from tf_demo.transport import run_node
from tf_demo.transport.node import Node
import yaml

NODE_NAME = 'static_tf_pub'
DEFAULT_PARENT = 'base_link'
DEFAULT_CHILD = 'camera_link'
DEFAULT_TRANSLATION = (0.5, 0.0, 0.2)
DEFAULT_ROTATION = (0.0, 0.0, 0.0)
#: Lists and mappings in a transforms file nested deeper than this are refused.
MAX_YAML_DEPTH = 32


@dataclass(frozen=True)
class StaticTransformSpec:
    """One static transform: parent_T_child."""

    parent: str
    child: str
    translation: Vec3
    rotation: Quat


def spec_from_values(
    parent: object,
    child: object,
    translation: object,
    rotation: object,
    where: str = 'parameter',
) -> StaticTransformSpec:
    """
    Validate raw values into a :class:`StaticTransformSpec`.

    :param where: prefix naming the source in error messages.
    :raises NodeConfigError: naming the bad field.
    """
    parent_frame = as_frame(f'{where} parent_frame', parent)
    child_frame = as_frame(f'{where} child_frame', child)
    if parent_frame == child_frame:
        msg = f'{where}: parent and child frame are both {parent_frame!r}'
        raise NodeConfigError(msg)
    return StaticTransformSpec(
        parent_frame,
        child_frame,
        as_vector3(f'{where} translation', translation),
        rotation_from_values(f'{where} rotation', rotation),
    )


def _check_nesting(text: str, source: str) -> None:
    """Refuse YAML nested deeper than MAX_YAML_DEPTH before PyYAML's recursive composer runs."""
    depth = 0
    for event in yaml.parse(text, Loader=yaml.SafeLoader):
        if isinstance(event, yaml.CollectionStartEvent):
            depth += 1
            if depth > MAX_YAML_DEPTH:
                mark = event.start_mark
                line = f' line {mark.line + 1}' if mark is not None else ''
                msg = f'{source}:{line} lists or mappings nested deeper than {MAX_YAML_DEPTH}'
                raise NodeConfigError(msg)
        elif isinstance(event, yaml.CollectionEndEvent):
            depth -= 1


def specs_from_yaml(text: str, source: str = '<yaml>') -> list[StaticTransformSpec]:
    """
    Parse a static-transform set: ``transforms: [{parent, child, translation, rotation}, ...]``.

    ``rotation`` may be omitted (identity). Child frames must be unique.

    :raises NodeConfigError: one line naming the file, entry and field.
    """
    try:
        _check_nesting(text, source)
        document = yaml.safe_load(text)
    except yaml.YAMLError as error:
        mark = getattr(error, 'problem_mark', None)
        line = f' line {mark.line + 1}' if mark is not None else ''
        msg = f'{source}:{line} is not valid YAML ({getattr(error, "problem", error)})'
        raise NodeConfigError(msg) from None
    except (ValueError, OverflowError) as error:
        # A scalar YAML types but Python cannot build: a 5,000-digit integer, a 13th month.
        reason = str(error).split(':', 1)[0]
        msg = f'{source}: a value cannot be converted ({reason})'
        raise NodeConfigError(msg) from None
    if not isinstance(document, dict) or not isinstance(document.get('transforms'), list):
        msg = f"{source}: expected a mapping with a 'transforms' list"
        raise NodeConfigError(msg)
    specs: list[StaticTransformSpec] = []
    seen: set[str] = set()
    for index, entry in enumerate(document['transforms']):
        where = f'{source}: transforms[{index}]'
        if not isinstance(entry, dict):
            msg = f'{where} must be a mapping with parent, child, translation, rotation'
            raise NodeConfigError(msg)
        unknown = sorted(set(entry) - {'parent', 'child', 'translation', 'rotation'})
        if unknown:
            msg = f'{where} has unknown key(s) {", ".join(map(str, unknown))}'
            raise NodeConfigError(msg)
        for key in ('parent', 'child', 'translation'):
            if key not in entry:
                msg = f'{where} is missing {key!r}'
                raise NodeConfigError(msg)
        spec = spec_from_values(
            entry['parent'],
            entry['child'],
            entry['translation'],
            entry.get('rotation', [0.0, 0.0, 0.0]),
            where,
        )
        if spec.child in seen:
            msg = f'{where}: child frame {spec.child!r} appears twice'
            raise NodeConfigError(msg)
        seen.add(spec.child)
        specs.append(spec)
    if not specs:
        msg = f'{source}: the transforms list is empty'
        raise NodeConfigError(msg)
    return specs


def load_specs_file(path: str) -> list[StaticTransformSpec]:
    """Read (bounded, regular files only) and parse a static-transform YAML file."""
    try:
        text = read_text_file(path)
    except InputFileError as error:
        msg = f'transforms_file {error}'
        raise NodeConfigError(msg) from None
    return specs_from_yaml(text, path)


def format_published(specs: list[StaticTransformSpec]) -> str:
    """Log text listing the published static transforms, one per line."""
    lines = [f'Publishing {len(specs)} static transform(s) on /tf_static:']
    for spec in specs:
        t, q = spec.translation, spec.rotation
        lines.append(
            f'  {spec.parent} -> {spec.child}: translation ({t[0]:g}, {t[1]:g}, {t[2]:g}), '
            f'rotation ({q[0]:g}, {q[1]:g}, {q[2]:g}, {q[3]:g})'
        )
    return '\n'.join(lines)


class StaticTfPublisher(Node):
    """Publishes the configured static transforms once (latched)."""

    def __init__(self) -> None:
        """Read the parameters, publish, and keep the latched publisher alive."""
        super().__init__(NODE_NAME)
        transforms_file = declare_flexible(self, 'transforms_file', '')
        parent = declare_flexible(self, 'parent_frame', DEFAULT_PARENT)
        child = declare_flexible(self, 'child_frame', DEFAULT_CHILD)
        translation = declare_flexible(self, 'translation', list(DEFAULT_TRANSLATION))
        rotation = declare_flexible(self, 'rotation', list(DEFAULT_ROTATION))
        if transforms_file:
            if not isinstance(transforms_file, str):
                msg = f'parameter transforms_file must be a path, got {transforms_file!r}'
                raise NodeConfigError(msg)
            self.specs = load_specs_file(transforms_file)
        else:
            self.specs = [spec_from_values(parent, child, translation, rotation)]
        self.broadcaster = StaticTransformBroadcaster(self)
        stamp_ns = now_ns(self)
        self.broadcaster.send_transform(
            [
                make_transform_stamped(s.parent, s.child, stamp_ns, s.translation, s.rotation)
                for s in self.specs
            ]
        )
        self.get_logger().info(format_published(self.specs))


def main(args: list[str] | None = None) -> int:
    """Run the node until Ctrl-C; exit 1 with a one-line error on bad parameters."""
    return run_node(StaticTfPublisher, args)


if __name__ == '__main__':
    sys.exit(main())
