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

"""Differential check of our codec against cyclonedds-python's own IdlStruct serialisation."""

from __future__ import annotations

from collections.abc import Callable

from conftest import STANDALONE_ONLY
from hypothesis import given
from hypothesis import settings
from hypothesis import strategies as st
import pytest

pytest.importorskip('cyclonedds', reason=STANDALONE_ONLY)

from cyclonedds.idl import IdlStruct
from cyclonedds_reference_types import idl_joint_state
from cyclonedds_reference_types import idl_tf_message
from cyclonedds_reference_types import JointState_
from cyclonedds_reference_types import TFMessage_
from msgs_strategies import message_strategy
from tf_demo.msgs import cdr
from tf_demo.msgs._message import Message

#: Message type -> (its IdlStruct twin, the conversion of our message into the twin).
TWINS: dict[str, tuple[type[IdlStruct], Callable[..., IdlStruct]]] = {
    'tf2_msgs/msg/TFMessage': (TFMessage_, idl_tf_message),
    'sensor_msgs/msg/JointState': (JointState_, idl_joint_state),
}


def _unpadded(data: bytes, length: int) -> bytes:
    """Drop the zero padding to 4 that cyclonedds may append; check it is only padding."""
    assert data[length:] == bytes(len(data) - length)
    assert len(data) - length < 4
    return data[:length]


@pytest.mark.differential
@pytest.mark.property
@pytest.mark.parametrize('msgtype', sorted(TWINS))
@settings(max_examples=60, deadline=None)
@given(data=st.data())
def test_bytes_equal_cyclonedds(msgtype: str, data: st.DataObject) -> None:
    """TFMessage, JointState: our bytes equal cyclonedds' XCDR1 bytes; each decodes the other's."""
    twin, convert = TWINS[msgtype]
    message: Message = data.draw(message_strategy(msgtype))
    ours = cdr.serialize(message)
    theirs = convert(message).serialize(use_version_2=False)
    assert _unpadded(theirs, len(ours)) == ours
    assert cdr.deserialize(msgtype, theirs) == message
    assert twin.deserialize(ours, has_header=True) == convert(message)
