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

"""new_transform_stamped and transform_stamped_args in the rclpy world: rclpy's own slots."""

from __future__ import annotations

import os
import subprocess
import sys
from typing import Any

import pytest
from tf_demo.core.buffer_core import TransformResult

pytestmark = pytest.mark.rclpy_world

Case = tuple[str, str, int, tuple[float, float, float], tuple[float, float, float, float]]
CASES: list[Case] = [
    ('map', 'base_link', 1_700_000_000_123_456_789, (1.0, -2.5, 3e-9), (0.0, 0.0, 0.6, 0.8)),
    ('', 'ç/名前', 0, (0, 0, 0), (0, 0, 0, 1)),  # ints become floats, as the setters want
    ('a', 'b', -1, (float('inf'), -0.0, 1e308), (1.0, 0.0, 0.0, 0.0)),
    ('odom', 'x' * 300, 2**31 * 10**9 - 1, (0.1, 0.2, 0.3), (0.5, 0.5, 0.5, 0.5)),
]


def _reference(parent: str, child: str, stamp_ns: int, t: tuple[float, ...], q: tuple[float, ...]):
    """The same message made the ordinary way: rclpy's constructors and property setters."""
    from geometry_msgs.msg import TransformStamped
    from tf_demo.msgs.convert import fill_transform_stamped

    return fill_transform_stamped(TransformStamped(), parent, child, stamp_ns, t, q)


def _slots(message: Any) -> object:  # an rclpy message (no stubs) or a leaf value
    """Every slot of a message tree, with the Python type of each leaf."""
    if not hasattr(type(message), '_fields_and_field_types'):
        return (type(message).__name__, message)
    return {slot: _slots(getattr(message, slot)) for slot in type(message).__slots__}


@pytest.mark.parametrize('case', CASES, ids=range(len(CASES)))
def test_the_fast_message_is_rclpys_own_slot_for_slot(case: Case) -> None:
    from geometry_msgs.msg import TransformStamped
    from rclpy.serialization import serialize_message
    from tf_demo.transport.messages import new_transform_stamped

    target, source, stamp_ns, translation, rotation = case
    built = new_transform_stamped(target, source, TransformResult(translation, rotation, stamp_ns))
    reference = _reference(*case)
    assert type(built) is TransformStamped
    assert built == reference
    assert _slots(built) == _slots(reference)
    assert serialize_message(built) == serialize_message(reference)


def test_a_stamp_out_of_range_is_refused_as_the_standalone_world_refuses_it() -> None:
    from tf_demo.transport.messages import new_transform_stamped

    with pytest.raises(ValueError, match='out of the range of builtin_interfaces/Time'):
        new_transform_stamped('a', 'b', TransformResult((0, 0, 0), (0, 0, 0, 1), 2**31 * 10**9))


def test_with_field_checks_on_the_message_checks_later_assignments() -> None:
    """ROS_PYTHON_CHECK_FIELDS=1: the built objects check fields as constructed ones do."""
    code = (
        'from tf_demo.transport.messages import new_transform_stamped\n'
        'from tf_demo.core.buffer_core import TransformResult\n'
        'm = new_transform_stamped("a", "b", TransformResult((1, 2, 3), (0, 0, 0, 1), 5))\n'
        'assert m._check_fields and m.header.stamp._check_fields\n'
        'assert m.transform.rotation._check_fields\n'
        'try:\n'
        '    m.transform.translation.x = "not a float"\n'
        'except AssertionError as error:\n'
        '    print("refused:", error)\n'
    )
    env = dict(os.environ, ROS_PYTHON_CHECK_FIELDS='1')
    result = subprocess.run(
        [sys.executable, '-c', code],
        check=False,
        env=env,
        capture_output=True,
        text=True,
        timeout=60,
    )
    assert result.returncode == 0, result.stderr
    assert "refused: The 'x' field must be of type 'float'" in result.stdout


@pytest.mark.parametrize('case', CASES, ids=range(len(CASES)))
def test_reading_through_the_slots_gives_what_the_properties_give(case: Case) -> None:
    from tf_demo.msgs import convert
    from tf_demo.transport.messages import transform_stamped_args

    message = _reference(*case)
    assert transform_stamped_args(message) == convert.transform_stamped_args(message)
    parent, child, stamp_ns, translation, rotation = transform_stamped_args(message)
    assert (parent, child, stamp_ns) == case[:3]
    assert translation == tuple(float(v) for v in case[3])
    assert rotation == tuple(float(v) for v in case[4])


def test_a_foreign_object_in_a_field_is_read_through_its_attributes() -> None:
    """With field checks off rclpy accepts any object in a field: the slots then do not apply."""
    from types import SimpleNamespace

    from tf_demo.transport.messages import transform_stamped_args

    message = _reference(*CASES[0])
    message.transform.translation = SimpleNamespace(x=7.0, y=8.0, z=9.0)
    assert transform_stamped_args(message)[3] == (7.0, 8.0, 9.0)
    plain = SimpleNamespace(header=message.header, child_frame_id='c', transform=message.transform)
    assert transform_stamped_args(plain)[:2] == ('map', 'c')
