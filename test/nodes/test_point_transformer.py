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

"""Pure logic of point_transformer: what it prints."""

from __future__ import annotations

from tf_demo.msgs import geometry_msgs
from tf_demo.nodes.point_transformer import format_point


def test_point_formatter() -> None:
    """The point transformer logs the point in both frames."""
    a = geometry_msgs.PointStamped()
    a.point.x = 1.0
    b = geometry_msgs.PointStamped()
    b.point.x, b.point.y = 2.0, 3.5
    assert format_point('base_link', 'map', a, b) == (
        'Point (1.000, 0.000, 0.000) in base_link is (2.000, 3.500, 0.000) in map'
    )
