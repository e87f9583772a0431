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

"""
Callback groups behave as rclpy Jazzy's, in both worlds (written against the node API only).

Entities join the group they are created with or the node's mutually exclusive default group;
a mutually exclusive group lets one entity run at a time, a reentrant one any number.
"""

from __future__ import annotations

import pytest
from tf_demo import transport
from tf_demo.transport.callback_groups import MutuallyExclusiveCallbackGroup
from tf_demo.transport.callback_groups import ReentrantCallbackGroup
from tf_demo.transport.messages import std_msgs

pytestmark = pytest.mark.dds


def test_entities_join_their_callback_group_with_rclpy_methods(ros: None) -> None:
    """create_* put entities in the given group or the node's mutually exclusive default."""
    node = transport.create_node('grouped')
    reentrant = ReentrantCallbackGroup()
    subscription = node.create_subscription(
        std_msgs.String, 'grouped_topic', lambda _msg: None, 10, callback_group=reentrant
    )
    timer = node.create_timer(60.0, lambda: None)
    other_timer = node.create_timer(60.0, lambda: None)
    default = node.default_callback_group
    assert isinstance(default, MutuallyExclusiveCallbackGroup)
    assert subscription.callback_group is reentrant
    assert reentrant.has_entity(subscription)
    assert not default.has_entity(subscription)
    assert timer.callback_group is default
    assert default.has_entity(timer)
    assert default.has_entity(other_timer)

    assert default.can_execute(timer)
    assert default.beginning_execution(timer)
    assert not default.can_execute(other_timer)
    assert not default.beginning_execution(other_timer)
    default.ending_execution(timer)
    assert default.can_execute(other_timer)

    assert reentrant.beginning_execution(subscription)
    assert reentrant.beginning_execution(subscription)
    assert reentrant.can_execute(subscription)
    reentrant.ending_execution(subscription)
    reentrant.ending_execution(subscription)

    mine = MutuallyExclusiveCallbackGroup()
    late_timer = node.create_timer(60.0, lambda: None, callback_group=mine)
    assert mine.has_entity(late_timer)
    assert not default.has_entity(late_timer)
