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

"""QoS profiles follow rclpy's construction rules and presets, in both worlds."""

import pytest
from tf_demo.transport.clock import Duration
from tf_demo.transport.qos import DurabilityPolicy
from tf_demo.transport.qos import HistoryPolicy
from tf_demo.transport.qos import InvalidQoSProfileException
from tf_demo.transport.qos import LivelinessPolicy
from tf_demo.transport.qos import qos_profile_sensor_data
from tf_demo.transport.qos import qos_profile_system_default
from tf_demo.transport.qos import QoSPresetProfiles
from tf_demo.transport.qos import QoSProfile
from tf_demo.transport.qos import ReliabilityPolicy


def test_policy_values_match_rmw() -> None:
    """The enum values are rmw/types.h's, so they map one to one onto the wire mapping."""
    assert [HistoryPolicy.SYSTEM_DEFAULT, HistoryPolicy.KEEP_LAST, HistoryPolicy.KEEP_ALL] == [
        0,
        1,
        2,
    ]
    # As lists, like the history policies: mypy takes an IntEnum member and an int literal
    # compared alone for two literal types that can never be equal.
    reliability = [
        ReliabilityPolicy.RELIABLE,
        ReliabilityPolicy.BEST_EFFORT,
        ReliabilityPolicy.BEST_AVAILABLE,
    ]
    assert reliability == [1, 2, 4]
    assert [DurabilityPolicy.TRANSIENT_LOCAL, DurabilityPolicy.VOLATILE] == [1, 2]
    assert [LivelinessPolicy.AUTOMATIC, LivelinessPolicy.MANUAL_BY_TOPIC] == [1, 3]
    assert ReliabilityPolicy.get_from_short_key('best_effort') == 2
    assert DurabilityPolicy.TRANSIENT_LOCAL.short_key == 'transient_local'


def test_depth_alone_means_keep_last_with_rmw_defaults() -> None:
    """QoSProfile(depth=n) is KEEP_LAST n, RELIABLE, VOLATILE, durations unspecified."""
    profile = QoSProfile(depth=7)
    assert profile.history is HistoryPolicy.KEEP_LAST
    assert profile.depth == 7
    assert profile.reliability is ReliabilityPolicy.RELIABLE
    assert profile.durability is DurabilityPolicy.VOLATILE
    assert profile.deadline == Duration()
    assert profile.lifespan == Duration()
    assert profile.liveliness is LivelinessPolicy.SYSTEM_DEFAULT
    assert profile.avoid_ros_namespace_conventions is False


def test_history_or_depth_is_required() -> None:
    """Without history and depth, or KEEP_LAST without depth, construction fails as in rclpy."""
    with pytest.raises(InvalidQoSProfileException, match='History and/or depth'):
        QoSProfile()
    with pytest.raises(InvalidQoSProfileException, match='KEEP_LAST without a depth'):
        QoSProfile(history=HistoryPolicy.KEEP_LAST)
    assert QoSProfile(history=HistoryPolicy.KEEP_ALL).history is HistoryPolicy.KEEP_ALL


def test_bad_fields_are_rejected_with_their_name() -> None:
    """Unknown keywords and wrong types fail as rclpy's asserts; bad policies name the value."""
    with pytest.raises(AssertionError, match='Invalid arguments passed to constructor'):
        QoSProfile(depth=1, reliabilty=ReliabilityPolicy.RELIABLE)  # type: ignore[call-arg]
    with pytest.raises(AssertionError):  # rclpy asserts the type
        QoSProfile(depth=1, deadline=1.0)  # type: ignore[arg-type]
    assert QoSProfile(depth=-1).depth == -1  # rclpy keeps it; rmw refuses it at creation
    with pytest.raises(ValueError):
        QoSProfile(depth=1, reliability=9)


def test_int_policies_become_enums_and_profiles_compare_by_value() -> None:
    """Ints are accepted where rclpy accepts them; equal settings compare equal."""
    profile = QoSProfile(depth=1, reliability=2, durability=1)
    assert profile.reliability is ReliabilityPolicy.BEST_EFFORT
    assert profile.durability is DurabilityPolicy.TRANSIENT_LOCAL
    same = QoSProfile(
        depth=1,
        reliability=ReliabilityPolicy.BEST_EFFORT,
        durability=DurabilityPolicy.TRANSIENT_LOCAL,
    )
    assert profile == same
    assert profile != QoSProfile(depth=2)


def test_int_depth_is_accepted_where_rclpy_accepts_it() -> None:
    """An int stands for QoSProfile(depth=n) on a standalone node; else rclpy's TypeError."""
    from tf_demo.transport.dds.qos import QoSProfile
    from tf_demo.transport.dds.qos import validate_qos_or_depth

    assert validate_qos_or_depth(5) == QoSProfile(depth=5)
    profile = QoSProfile(depth=3)
    assert validate_qos_or_depth(profile) is profile
    with pytest.raises(TypeError, match='Expected QoSProfile or int'):
        validate_qos_or_depth('10')  # type: ignore[arg-type]
    with pytest.raises(ValueError, match='greater than or equal to zero'):
        validate_qos_or_depth(-1)


def test_presets_have_rmw_values() -> None:
    """sensor_data is KEEP_LAST 5 BEST_EFFORT VOLATILE; system_default is all SYSTEM_DEFAULT."""
    assert qos_profile_sensor_data.depth == 5
    assert qos_profile_sensor_data.reliability is ReliabilityPolicy.BEST_EFFORT
    assert qos_profile_system_default.history is HistoryPolicy.SYSTEM_DEFAULT
    assert qos_profile_system_default.reliability is ReliabilityPolicy.SYSTEM_DEFAULT
    assert QoSPresetProfiles.get_from_short_key('sensor_data') is qos_profile_sensor_data
    assert QoSPresetProfiles.PARAMETERS.value.depth == 1000
