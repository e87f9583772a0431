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

"""Parameter objects: rclpy's type inference and checks, and their messages, in both worlds.

The classes are those of ``tf_demo.transport.parameters`` (rclpy's inside ROS 2, the standalone
ones of :mod:`tf_demo.transport.dds.parameters` elsewhere).
"""

from array import array

import pytest
from tf_demo.transport.parameters import Parameter

Type = Parameter.Type


def test_parameter_type_is_inferred_as_rclpy_infers_it() -> None:
    """bool before int, homogeneous lists become arrays, an empty list is a BYTE_ARRAY."""
    assert Parameter('a', value=True).type_ is Type.BOOL
    assert Parameter('a', value=1).type_ is Type.INTEGER
    assert Parameter('a', value=1.0).type_ is Type.DOUBLE
    assert Parameter('a', value='x').type_ is Type.STRING
    assert Parameter('a', value=[1.0, 2.0]).type_ is Type.DOUBLE_ARRAY
    assert Parameter('a', value=['x']).type_ is Type.STRING_ARRAY
    assert Parameter('a', value=[]).type_ is Type.BYTE_ARRAY
    assert Parameter('a').type_ is Type.NOT_SET
    assert str(Type.DOUBLE) == 'Type.DOUBLE'
    with pytest.raises(TypeError, match='not a list of one of the allowed types'):
        Parameter('a', value=[1, 'x'])
    with pytest.raises(ValueError, match=r"Type 'Type\.DOUBLE' and value '1' do not agree"):
        Parameter('a', Type.DOUBLE, 1)
    assert repr(Type.DOUBLE) == '<Type.DOUBLE: 3>'


def test_explicit_types_check_values_as_rclpy_does() -> None:
    """rclpy's Type.check: a bool is an INTEGER, bytes items have length 1, few array.arrays."""
    assert Parameter('a', Type.INTEGER, True).value is True
    assert Parameter('a', Type.INTEGER_ARRAY, [1, False]).type_ is Type.INTEGER_ARRAY
    assert Parameter('a', Type.DOUBLE_ARRAY, array('d', [1.0])).type_ is Type.DOUBLE_ARRAY
    assert Parameter('a', Type.BYTE_ARRAY, [b'x']).type_ is Type.BYTE_ARRAY
    for type_, value in (
        (Type.BYTE_ARRAY, [b'xy']),
        (Type.BOOL_ARRAY, array('b', [1])),
        (Type.BOOL, 1),
        (Type.DOUBLE, 1),
        (Type.STRING_ARRAY, 'abc'),
    ):
        with pytest.raises(ValueError, match='do not agree'):
            Parameter('a', type_, value)
    with pytest.raises(TypeError, match="type must be an instance of '<enum 'Type'>'"):
        Parameter('a', 3, 1)  # type: ignore[arg-type]
    parameter = Parameter('a', value=1)
    assert parameter != Parameter('a', value=1)  # no value equality in rclpy: identity
    assert {parameter: 1}[parameter] == 1  # hashable


@pytest.mark.parametrize(
    ('value', 'field'),
    [
        ('camera_link', 'string_value'),
        (3, 'integer_value'),
        (0.5, 'double_value'),
        (True, 'bool_value'),
        ([1.0, 2.0], 'double_array_value'),
        (['a', 'b'], 'string_array_value'),
    ],
)
def test_parameter_value_messages_as_rclpy_gives_them(value: object, field: str) -> None:
    """``get_parameter_value().string_value`` and the message round trip (course code uses it)."""
    parameter = Parameter('p', value=value)
    message = parameter.get_parameter_value()
    got = getattr(message, field)
    assert (list(got) if isinstance(value, list) else got) == value
    assert message.type == parameter.type_.value
    back = Parameter.from_parameter_msg(parameter.to_parameter_msg())
    back_value = list(back.value) if isinstance(value, list) else back.value  # rclpy: array
    assert (back.name, back.type_, back_value) == ('p', parameter.type_, value)
