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

"""Differential check of our codec against cyclonedds-python's own IdlStruct serialisation.

No ``from __future__ import annotations`` here: cyclonedds reads the annotations at class creation.
"""

from typing import Any

from conftest import STANDALONE_ONLY
import pytest

pytest.importorskip('cyclonedds', reason=STANDALONE_ONLY)

from cyclonedds_reference_types import Header_
from cyclonedds_reference_types import JointState_
from cyclonedds_reference_types import Quaternion_
from cyclonedds_reference_types import TFMessage_
from cyclonedds_reference_types import Time_
from cyclonedds_reference_types import Transform_
from cyclonedds_reference_types import TransformStamped_
from cyclonedds_reference_types import Vector3_
from hypothesis import given
from hypothesis import settings
from msgs_strategies import message_strategy
from tf_demo.msgs import cdr
from tf_demo.msgs.sensor_msgs import JointState
from tf_demo.msgs.tf2_msgs import TFMessage


def _header(header: Any) -> Header_:
    """Convert our Header."""
    return Header_(Time_(header.stamp.sec, header.stamp.nanosec), header.frame_id)


def _tf_message(message: Any) -> TFMessage_:
    """Convert our TFMessage to the IdlStruct."""
    return TFMessage_(
        [
            TransformStamped_(
                _header(t.header),
                t.child_frame_id,
                Transform_(
                    Vector3_(
                        t.transform.translation.x,
                        t.transform.translation.y,
                        t.transform.translation.z,
                    ),
                    Quaternion_(
                        t.transform.rotation.x,
                        t.transform.rotation.y,
                        t.transform.rotation.z,
                        t.transform.rotation.w,
                    ),
                ),
            )
            for t in message.transforms
        ]
    )


def _joint_state(message: Any) -> JointState_:
    """Convert our JointState to the IdlStruct."""
    return JointState_(
        _header(message.header),
        list(message.name),
        list(message.position),
        list(message.velocity),
        list(message.effort),
    )


def _unpadded(data: bytes, length: int) -> bytes:
    """Drop the zero padding to 4 that cyclonedds may append; check it is only padding."""
    assert data[length:] == bytes(len(data) - length)
    assert len(data) - length < 4
    return data[:length]


@pytest.mark.differential
@pytest.mark.property
@settings(max_examples=60, deadline=None)
@given(message=message_strategy('tf2_msgs/msg/TFMessage'))
def test_tf_message_bytes_equal_cyclonedds(message: Any) -> None:
    """TFMessage: our bytes equal cyclonedds' XCDR1 bytes, and each decodes the other's."""
    ours = cdr.serialize(message)
    theirs = _tf_message(message).serialize(use_version_2=False)
    assert _unpadded(theirs, len(ours)) == ours
    assert cdr.deserialize(TFMessage, theirs) == message
    assert TFMessage_.deserialize(ours, has_header=True) == _tf_message(message)


@pytest.mark.differential
@pytest.mark.property
@settings(max_examples=60, deadline=None)
@given(message=message_strategy('sensor_msgs/msg/JointState'))
def test_joint_state_bytes_equal_cyclonedds(message: Any) -> None:
    """JointState: our bytes equal cyclonedds' XCDR1 bytes, and each decodes the other's."""
    ours = cdr.serialize(message)
    theirs = _joint_state(message).serialize(use_version_2=False)
    assert _unpadded(theirs, len(ours)) == ours
    assert cdr.deserialize(JointState, theirs) == message
    assert JointState_.deserialize(ours, has_header=True) == _joint_state(message)
