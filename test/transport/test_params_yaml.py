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

"""``-p`` values read from the YAML event stream and typed as rcl types them."""

import pytest
from tf_demo.transport.params_yaml import parse_param_value


@pytest.mark.parametrize(
    ('text', 'expected'),
    [
        ('true', True),
        ('False', False),
        ('42', 42),
        ('-3', -3),
        ('1.5', 1.5),
        ('hello', 'hello'),
        ("'42'", '42'),
        ('[1, 2, 3]', [1, 2, 3]),
        ('[1.0, 2.5]', [1.0, 2.5]),
        ('[a, b]', ['a', 'b']),
        ('[true, false]', [True, False]),
        ('2020-01-01', '2020-01-01'),
        ('/robot/base', '/robot/base'),
    ],
)
def test_param_values_are_yaml_typed(text: str, expected: object) -> None:
    """-p values get YAML types as rcl gives them (dates stay strings)."""
    value = parse_param_value(text)
    assert value == expected
    assert type(value) is type(expected)
