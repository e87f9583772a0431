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
What the listening tools record: each tf message received, with its topic and reception time.

A :class:`TfRecorder <tf_demo.cli._live.TfRecorder>` records every message on ``/tf`` and
``/tf_static`` as an :class:`Observation`; a tf_saver snapshot reads back as observations too
(:func:`observations_from_snapshot`). :func:`buffer_from_observations` replays them into a
``BufferCore`` for the tools that look transforms up (view_frames, tf_saver, tf_monitor,
tf_doctor).
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING

from tf_demo.cli._snapshot import Snapshot
from tf_demo.core.buffer_core import BufferCore
from tf_demo.core.math3d import Quat
from tf_demo.core.math3d import Vec3

TF_TOPIC = '/tf'
TF_STATIC_TOPIC = '/tf_static'
RECORDER_AUTHORITY = 'default_authority'

if TYPE_CHECKING:
    from tf_demo.bag import BagError


@dataclass(frozen=True)
class ObservedTransform:
    """One transform of a received message."""

    parent: str
    child: str
    stamp_ns: int
    translation: Vec3 = (0.0, 0.0, 0.0)
    rotation: Quat = (0.0, 0.0, 0.0, 1.0)


@dataclass(frozen=True)
class Observation:
    """One received tf message: topic, reception time (listener clock) and its transforms."""

    topic: str
    receive_ns: int
    transforms: tuple[ObservedTransform, ...]
    publisher: str = ''


def observations_from_snapshot(snapshot: Snapshot) -> list[Observation]:
    """Turn a saved snapshot into observations (one message per transform, no timing)."""
    return [
        Observation(
            TF_STATIC_TOPIC if entry.is_static else TF_TOPIC,
            entry.stamp_ns or 0,
            (
                ObservedTransform(
                    entry.parent,
                    entry.child,
                    entry.stamp_ns or 0,
                    entry.translation,
                    entry.rotation,
                ),
            ),
        )
        for entry in snapshot.transforms
    ]


@dataclass(frozen=True)
class BagObservations:
    """A bag's TF messages as observations, up to its end or to the damage that stopped them."""

    observations: list[Observation]
    start_ns: int
    end_ns: int
    """The bag's end, or the last message read before the damage."""
    damage: BagError | None


def observations_from_bag(
    path: str, tf_topic: str = TF_TOPIC, static_topic: str = TF_STATIC_TOPIC
) -> BagObservations:
    """
    Read a rosbag2's TF messages as observations received at their bag times.

    The topics are named ``/tf`` and ``/tf_static`` whatever they were recorded as. A damaged
    bag gives what came before the damage, and the damage.

    :raises tf_demo.bag.BagError: for a bag that cannot be opened (one line naming it).
    """
    from tf_demo.bag import BagRecord
    from tf_demo.bag import open_tf_bag

    observations: list[Observation] = []

    def observe(record: BagRecord) -> None:
        topic = TF_STATIC_TOPIC if record.is_static else TF_TOPIC
        transforms = tuple(ObservedTransform(*t) for t in record.transforms)
        observations.append(Observation(topic, record.bag_time_ns, transforms))

    with open_tf_bag(path, tf_topic, static_topic) as bag:
        end_ns, damage = bag.read(observe)
        return BagObservations(observations, bag.start_ns, end_ns, damage)


def add_observation(
    core: BufferCore, observation: Observation, authority: str = RECORDER_AUTHORITY
) -> None:
    """Set every transform of ``observation`` in ``core`` (static when it came on /tf_static)."""
    is_static = observation.topic == TF_STATIC_TOPIC
    for transform in observation.transforms:
        core.set_transform(
            transform.parent,
            transform.child,
            transform.stamp_ns,
            transform.translation,
            transform.rotation,
            authority,
            is_static,
        )


def quiet_log(level: int, text: str) -> None:
    """Drop ``BufferCore``'s log lines (the tools report what matters themselves)."""
    del level, text


def buffer_from_observations(
    observations: Sequence[Observation],
    cache_time_ns: int = 10**10,
    authority: str = RECORDER_AUTHORITY,
) -> BufferCore:
    """Replay ``observations`` into a new ``BufferCore`` (rejected transforms are skipped)."""
    core = BufferCore(cache_time_ns, log=quiet_log)
    for observation in sorted(observations, key=lambda o: o.receive_ns):
        add_observation(core, observation, authority)
    return core
