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

"""Hand-made observations for tf_doctor's tests: static links, streams, a healthy tree."""

from __future__ import annotations

from collections.abc import Iterable
from collections.abc import Sequence

from tf_demo.cli._doctor_model import Finding
from tf_demo.cli._doctor_robot import RobotJoint
from tf_demo.cli._observations import Observation
from tf_demo.cli._observations import ObservedTransform
from tf_demo.cli._observations import TF_STATIC_TOPIC
from tf_demo.cli._observations import TF_TOPIC
from tf_demo.core.math3d import Vec3

S = 1_000_000_000
T0 = 1_700_000_000 * S


def static(parent: str, child: str, t: Vec3 = (0.0, 0.0, 0.0), publisher: str = '') -> Observation:
    return Observation(TF_STATIC_TOPIC, T0, (ObservedTransform(parent, child, T0, t),), publisher)


def stream(
    parent: str,
    child: str,
    *,
    rate_hz: float = 20.0,
    seconds: float = 2.0,
    delay_ns: int = 1_000_000,
    values: Sequence[Vec3] | None = None,
    pub: str = '',
) -> list[Observation]:
    count = int(rate_hz * seconds)
    result = []
    for i in range(count):
        stamp = T0 + int(i * S / rate_hz)
        t = values[i % len(values)] if values else (i * 0.01, 0.0, 0.0)
        transform = ObservedTransform(parent, child, stamp, t)
        result.append(Observation(TF_TOPIC, stamp + delay_ns, (transform,), pub))
    return result


def later(observations: Iterable[Observation], seconds: int) -> list[Observation]:
    """The same messages, received and stamped ``seconds`` later."""
    shift = seconds * S
    return [
        Observation(
            o.topic,
            o.receive_ns + shift,
            tuple(
                ObservedTransform(t.parent, t.child, t.stamp_ns + shift, t.translation)
                for t in o.transforms
            ),
            o.publisher,
        )
        for o in observations
    ]


def healthy() -> list[Observation]:
    return [
        static('map', 'odom'),
        *stream('odom', 'base_link'),
        static('base_link', 'laser'),
        static('base_link', 'camera'),
    ]


def kinds(findings: Iterable[Finding]) -> list[str]:
    return sorted(f.kind for f in findings)


REVOLUTE_ROBOT = (
    RobotJoint('world_to_frame_1', 'fixed', 'world', 'frame_1'),
    RobotJoint('frame_1_to_frame_2', 'revolute', 'frame_1', 'frame_2'),
    RobotJoint('frame_2_to_tool', 'fixed', 'frame_2', 'tool'),
    RobotJoint('follower', 'revolute', 'frame_2', 'finger', mimic='frame_1_to_frame_2'),
)
