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

"""Pure logic of tf_listener: what it prints."""

from __future__ import annotations

from tf_demo.nodes.helpers import make_transform_stamped
from tf_demo.nodes.tf_listener import format_failure
from tf_demo.nodes.tf_listener import format_translation


def test_listener_formatters() -> None:
    """The listener logs the translation, or the course's warning with the reason."""
    t = make_transform_stamped(
        'odom', 'camera_link', 1_250_000_000, (1.0, -2.0, 0.25), (0, 0, 0, 1)
    )
    assert format_translation('odom', 'camera_link', t) == (
        'Transform odom <- camera_link at 1.250000: translation x=1.000, y=-2.000, z=0.250'
    )
    assert format_failure('odom', 'camera_link', 'no frame') == (
        'Could not transform odom to camera_link: no frame'
    )
