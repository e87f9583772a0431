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

"""A node's create_publisher/create_subscription refuse options they cannot honour."""

from __future__ import annotations

from conftest import STANDALONE_ONLY
import pytest

pytest.importorskip('cyclonedds', reason=STANDALONE_ONLY)

from tf_demo.msgs import std_msgs
from tf_demo.transport import dds_backend


@pytest.mark.dds
def test_endpoint_options_the_backend_cannot_honour_are_refused(dds_world):
    """event_callbacks / qos_overriding_options raise instead of being ignored; typos TypeError."""
    node = dds_backend.DdsNode('options')
    with pytest.raises(NotImplementedError, match='qos_overriding_options'):
        node.create_publisher(std_msgs.String, 'x', 10, qos_overriding_options=object())
    with pytest.raises(NotImplementedError, match='event_callbacks'):
        node.create_subscription(std_msgs.String, 'x', print, 10, event_callbacks=object())
    with pytest.raises(TypeError):
        node.create_publisher(std_msgs.String, 'x', 10, callback_grup=None)  # type: ignore[call-arg]
    assert node.publishers == []
    assert node.subscriptions == []
