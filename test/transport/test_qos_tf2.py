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

"""tf2's QoS profiles (tf2_ros/qos.hpp), built by tf_demo.transport.qos in both worlds."""

from tf_demo.transport.qos import DurabilityPolicy
from tf_demo.transport.qos import DynamicBroadcasterQoS
from tf_demo.transport.qos import DynamicListenerQoS
from tf_demo.transport.qos import HistoryPolicy
from tf_demo.transport.qos import ReliabilityPolicy
from tf_demo.transport.qos import StaticBroadcasterQoS
from tf_demo.transport.qos import StaticListenerQoS


def test_tf2_profiles_match_tf2_ros_qos_hpp() -> None:
    """/tf is KEEP_LAST 100 RELIABLE VOLATILE; /tf_static TRANSIENT_LOCAL depth 1 / 100."""
    for profile in (DynamicBroadcasterQoS(), DynamicListenerQoS()):
        assert (profile.history, profile.depth) == (HistoryPolicy.KEEP_LAST, 100)
        assert profile.reliability is ReliabilityPolicy.RELIABLE
        assert profile.durability is DurabilityPolicy.VOLATILE
    assert StaticBroadcasterQoS().depth == 1
    assert StaticListenerQoS().depth == 100
    for profile in (StaticBroadcasterQoS(), StaticListenerQoS()):
        assert profile.reliability is ReliabilityPolicy.RELIABLE
        assert profile.durability is DurabilityPolicy.TRANSIENT_LOCAL
    assert DynamicListenerQoS(10).depth == 10
    assert DynamicBroadcasterQoS() is not DynamicBroadcasterQoS()
