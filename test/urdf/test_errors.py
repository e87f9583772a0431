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

"""The robot-description errors: one line naming the source, the line, the element, the reason."""

from __future__ import annotations

import pytest
from tf_demo.urdf import UrdfBrokenRefError
from tf_demo.urdf import UrdfError
from tf_demo.urdf import UrdfMalformedError
from tf_demo.urdf import UrdfUnsupportedError


@pytest.mark.parametrize('error', [UrdfMalformedError, UrdfUnsupportedError, UrdfBrokenRefError])
def test_every_error_is_a_value_error_whose_message_names_where_and_what(
    error: type[UrdfError],
) -> None:
    """``<source>:<line>: <element>: <reason>``, the parts kept as attributes."""
    caught = error('robot.urdf', "joint 'j'", 'child link [c] of joint [j] not found', 7)
    assert isinstance(caught, UrdfError)
    assert isinstance(caught, ValueError)
    assert str(caught) == "robot.urdf:7: joint 'j': child link [c] of joint [j] not found"
    assert (caught.source, caught.element, caught.line) == ('robot.urdf', "joint 'j'", 7)
    assert caught.reason == 'child link [c] of joint [j] not found'


def test_without_a_line_the_message_names_the_source_alone() -> None:
    """A problem of the whole file (it cannot be read) has no line number."""
    assert str(UrdfBrokenRefError('nope.urdf', 'file', 'no such file')) == (
        'nope.urdf: file: no such file'
    )
