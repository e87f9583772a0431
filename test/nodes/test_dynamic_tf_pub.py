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

"""Pure logic of dynamic_tf_pub: the circle of the course."""

from __future__ import annotations

import math

from tf_demo.nodes.dynamic_tf_pub import circle_transform


def test_circle_transform_matches_the_course_formula() -> None:
    """x = r cos t, y = r sin t, rotation (0, 0, sin(t/2), cos(t/2)) with t the stamp in s."""
    translation, rotation = circle_transform(2.0, 1_500_000_000)
    assert translation == (2.0 * math.cos(1.5), 2.0 * math.sin(1.5), 0.0)
    assert rotation == (0.0, 0.0, math.sin(0.75), math.cos(0.75))
