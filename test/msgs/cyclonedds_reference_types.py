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
cyclonedds-python ``IdlStruct`` twins of the ROS types the codec tests and benchmark compare with.

Final structs with the ROS DDS type names, as rmw_cyclonedds declares them, declared here by hand
(not from tf_demo's schema table, so that they check it), and the conversions of our messages
into them. No ``from __future__ import annotations``: cyclonedds reads the annotations at class
creation.
"""

from dataclasses import dataclass
from typing import TYPE_CHECKING

from cyclonedds.idl import IdlStruct
from cyclonedds.idl.annotations import final
import cyclonedds.idl.types as idl
from tf_demo.msgs.sensor_msgs import JointState
from tf_demo.msgs.std_msgs import Header
from tf_demo.msgs.tf2_msgs import TFMessage

if TYPE_CHECKING:
    # sequence[T] is Annotated[Sequence[T], ...] at run time; the checker sees the Sequence.
    from collections.abc import Sequence as sequence  # noqa: N813
else:
    from cyclonedds.idl.types import sequence


@dataclass
@final
class Time_(IdlStruct, typename='builtin_interfaces::msg::dds_::Time_'):  # noqa: N801
    sec: idl.int32
    nanosec: idl.uint32


@dataclass
@final
class Header_(IdlStruct, typename='std_msgs::msg::dds_::Header_'):  # noqa: N801
    stamp: Time_
    frame_id: str


@dataclass
@final
class Vector3_(IdlStruct, typename='geometry_msgs::msg::dds_::Vector3_'):  # noqa: N801
    x: idl.float64
    y: idl.float64
    z: idl.float64


@dataclass
@final
class Quaternion_(IdlStruct, typename='geometry_msgs::msg::dds_::Quaternion_'):  # noqa: N801
    x: idl.float64
    y: idl.float64
    z: idl.float64
    w: idl.float64


@dataclass
@final
class Transform_(IdlStruct, typename='geometry_msgs::msg::dds_::Transform_'):  # noqa: N801
    translation: Vector3_
    rotation: Quaternion_


@dataclass
@final
class TransformStamped_(IdlStruct, typename='geometry_msgs::msg::dds_::TransformStamped_'):  # noqa: N801
    header: Header_
    child_frame_id: str
    transform: Transform_


@dataclass
@final
class TFMessage_(IdlStruct, typename='tf2_msgs::msg::dds_::TFMessage_'):  # noqa: N801
    transforms: sequence[TransformStamped_]


@dataclass
@final
class JointState_(IdlStruct, typename='sensor_msgs::msg::dds_::JointState_'):  # noqa: N801
    header: Header_
    name: sequence[str]
    position: sequence[idl.float64]
    velocity: sequence[idl.float64]
    effort: sequence[idl.float64]


def idl_header(header: Header) -> Header_:
    """Return the twin of our Header."""
    return Header_(Time_(header.stamp.sec, header.stamp.nanosec), header.frame_id)


def idl_tf_message(message: TFMessage) -> TFMessage_:
    """Return the twin of our TFMessage."""
    return TFMessage_(
        [
            TransformStamped_(
                idl_header(t.header),
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


def idl_joint_state(message: JointState) -> JointState_:
    """Return the twin of our JointState."""
    return JointState_(
        idl_header(message.header),
        list(message.name),
        list(message.position),
        list(message.velocity),
        list(message.effort),
    )
