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

"""Pure parts of StaticTransformBroadcaster: how static sets merge."""

from __future__ import annotations

from test_transform_broadcaster import tf
from tf_demo.ros.static_transform_broadcaster import merge_static_transforms


def test_static_merge_replaces_in_place_and_appends_new_children() -> None:
    """C++ semantics: a known child is replaced where it was; new children go at the end."""
    first = merge_static_transforms({}, [tf('a', 1.0), tf('b', 2.0)])
    merged = merge_static_transforms(first, [tf('c', 3.0), tf('a', 9.0)])
    assert list(merged) == ['a', 'b', 'c']
    assert merged['a'].transform.translation.x == 9.0
    assert first['a'].transform.translation.x == 1.0
