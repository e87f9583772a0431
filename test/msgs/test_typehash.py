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

"""RIHS01 type hashes against the values ROS 2 Jazzy publishes."""

from __future__ import annotations

import pytest
from tf_demo.msgs.geometry_msgs import Point
from tf_demo.msgs.tf2_msgs import TFMessage
from tf_demo.msgs.typehash import JsonValue
from tf_demo.msgs.typehash import type_description
from tf_demo.msgs.typehash import type_hash

# Values from ../shared/spec/ros2_dds_wire.md section 4. TFMessage was read from `ros2 topic
# info -v` against a real Jazzy node; String..TransformStamped match a third-party table;
# JointState, ParticipantEntitiesInfo and Gid were computed by an independent implementation.
# Point and Vector3 are the EXPECTED_HASH constants in rosidl_generator_c's generated
# *__description.c files of Jazzy builds.
KNOWN_HASHES = {
    'tf2_msgs/msg/TFMessage': 'e369d0f05a23ae52508854b66f6aa0437f3449d652e8cbf22d5abe85d020f087',
    'geometry_msgs/msg/TransformStamped': (
        '0a241f87d04668d94099cbb5ba11691d5ad32c2f29682e4eb5653424bd275206'
    ),
    'std_msgs/msg/Header': 'f49fb3ae2cf070f793645ff749683ac6b06203e41c891e17701b1cb597ce6a01',
    'builtin_interfaces/msg/Time': (
        'b106235e25a4c5ed35098aa0a61a3ee9c9b18d197f398b0e4206cea9acf9c197'
    ),
    'sensor_msgs/msg/JointState': (
        'a13ee3a330e346c9d87b5aa18d24e11690752bd33a0350f11c5882bc9179260e'
    ),
    'rmw_dds_common/msg/ParticipantEntitiesInfo': (
        '91a0593bacdcc50ea9bdcf849a938b128412cc1ea821245c663bcd26f83c295e'
    ),
    'rmw_dds_common/msg/Gid': 'ab6f21cfbb0a6dbb837161e1110c2051a2850ed9f9c53944d7115d9bcebedf71',
    'geometry_msgs/msg/Point': '6963084842a9b04494d6b2941d11444708d892da2f4b09843b9c43f42a7f6881',
}


@pytest.mark.parametrize(('msgtype', 'digest'), KNOWN_HASHES.items(), ids=list(KNOWN_HASHES))
def test_type_hash_matches_ros(msgtype: str, digest: str) -> None:
    """The computed RIHS01 hash equals the one ROS 2 Jazzy uses."""
    assert type_hash(msgtype) == f'RIHS01_{digest}'


def test_classes_carry_their_hash() -> None:
    """The class attribute is the computed hash (what USER_DATA typehash= needs)."""
    assert TFMessage.__typehash__ == f'RIHS01_{KNOWN_HASHES["tf2_msgs/msg/TFMessage"]}'
    assert Point.__typehash__ == f'RIHS01_{KNOWN_HASHES["geometry_msgs/msg/Point"]}'


def _object(value: JsonValue) -> dict[str, JsonValue]:
    """``value``, a JSON object here."""
    assert isinstance(value, dict)
    return value


def _array(value: JsonValue) -> list[JsonValue]:
    """``value``, a JSON array here."""
    assert isinstance(value, list)
    return value


def test_type_description_lists_referenced_types_sorted_without_defaults() -> None:
    """The hashed description has every nested type once, sorted, and no default values."""
    description = type_description('geometry_msgs/msg/TransformStamped')
    main = _object(description['type_description'])
    assert main['type_name'] == 'geometry_msgs/msg/TransformStamped'
    referenced = _array(description['referenced_type_descriptions'])
    names = [_object(item)['type_name'] for item in referenced]
    assert names == [
        'builtin_interfaces/msg/Time',
        'geometry_msgs/msg/Quaternion',
        'geometry_msgs/msg/Transform',
        'geometry_msgs/msg/Vector3',
        'std_msgs/msg/Header',
    ]
    quaternion = _object(referenced[1])
    assert _array(quaternion['fields'])[3] == {
        'name': 'w',
        'type': {'type_id': 11, 'capacity': 0, 'string_capacity': 0, 'nested_type_name': ''},
    }
