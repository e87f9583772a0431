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

"""Pure parts of TransformBroadcaster: what one send contains."""

from __future__ import annotations

import pytest
from tf_demo.nodes.helpers import make_transform_stamped
from tf_demo.ros.transform_broadcaster import as_transform_list
from tf_demo.transport.messages import geometry_msgs

TransformStamped = geometry_msgs.TransformStamped


def tf(child: str, x: float) -> TransformStamped:
    return make_transform_stamped('base', child, 0, (x, 0.0, 0.0), (0.0, 0.0, 0.0, 1.0))


def test_one_transform_or_any_iterable_of_them() -> None:
    """A single TransformStamped, a list, a tuple or a generator all become one list."""
    a, b = tf('a', 1.0), tf('b', 2.0)
    assert as_transform_list(a) == [a]
    assert as_transform_list([a, b]) == [a, b]
    assert as_transform_list((a, b)) == [a, b]
    assert as_transform_list(t for t in (a, b)) == [a, b]


def test_anything_else_is_a_type_error_naming_it() -> None:
    """Strings, numbers and lists of non-transforms are refused with the offending type."""
    with pytest.raises(TypeError, match='got str'):
        as_transform_list('base_link')
    with pytest.raises(TypeError, match='got int'):
        as_transform_list([tf('a', 1.0), 3])
