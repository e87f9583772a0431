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

"""The schema table's parser: .msg fields, constants, defaults and the names rclpy gives them."""

from __future__ import annotations

import pytest
from tf_demo.msgs._schema import DEFINITIONS
from tf_demo.msgs._schema import parse_definition
from tf_demo.msgs._schema import rclpy_field_type
from tf_demo.msgs._schema import SchemaError
from tf_demo.msgs._schema import spec_for
from tf_demo.msgs._schema import SPECS


def test_fields_constants_and_defaults_are_parsed_as_written() -> None:
    """Kinds, bounds, defaults and nested types (relative ones in the same package)."""
    spec = parse_definition(
        'demo_msgs/msg/Sample',
        'uint8 LEVEL=10; string NAME="x"; float64 w 1.0; string<=8 label; int32[3] fixed; '
        'Header[] headers; std_msgs/Header[<=2] few',
    )
    assert (spec.package, spec.name, spec.interface) == ('demo_msgs', 'Sample', 'msg')
    assert spec.dds_typename == 'demo_msgs::msg::dds_::Sample_'
    assert [(c.name, c.base, c.value) for c in spec.constants] == [
        ('LEVEL', 'uint8', 10),
        ('NAME', 'string', 'x'),
    ]
    fields = {field.name: field for field in spec.fields}
    assert list(fields) == ['w', 'label', 'fixed', 'headers', 'few']
    assert (fields['w'].base, fields['w'].default) == ('float64', 1.0)
    assert fields['label'].string_bound == 8
    assert (fields['fixed'].kind, fields['fixed'].size) == ('array', 3)
    assert (fields['headers'].base, fields['headers'].kind) == ('demo_msgs/msg/Header', 'sequence')
    assert (fields['few'].base, fields['few'].size) == ('std_msgs/msg/Header', 2)
    assert [rclpy_field_type(field) for field in spec.fields] == [
        'double',
        'string<8>',
        'int32[3]',
        'sequence<demo_msgs/Header>',
        'sequence<std_msgs/Header, 2>',
    ]


@pytest.mark.parametrize(
    ('text', 'message'),
    [
        ('float64 X', 'cannot parse field definition'),
        ('wstring name', "field type 'wstring' is not supported"),
        ('int32<=4 count', 'only strings take a <=N bound'),
        ('byte B=1', "constants of type 'byte' are not supported"),
        ('int32 N=1.5', 'cannot parse constant definition'),
    ],
)
def test_malformed_definitions_are_refused_naming_the_line(text: str, message: str) -> None:
    """Each malformed line raises SchemaError saying what is wrong with it."""
    with pytest.raises(SchemaError, match=message):
        parse_definition('demo_msgs/msg/Bad', text)


def test_the_table_is_parsed_once_and_looked_up_by_either_name() -> None:
    """SPECS holds every type of the table; pkg/Name and pkg/msg/Name find the same spec."""
    assert set(SPECS) == set(DEFINITIONS)
    assert spec_for('geometry_msgs/Vector3') is spec_for('geometry_msgs/msg/Vector3')
    assert [field.name for field in spec_for('geometry_msgs/Vector3').fields] == ['x', 'y', 'z']
    with pytest.raises(KeyError, match="unknown message type 'nope_msgs/msg/Nope'"):
        spec_for('nope_msgs/Nope')
