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
The vocabulary of tf_doctor's checks: findings, thresholds and what each child frame did.

A check returns :class:`Finding` s; the timing checks use the :class:`Thresholds`; most checks
read the :class:`FrameStats` that :func:`gather` collects per child frame from the observations.
"""

from __future__ import annotations

from collections import Counter
from collections.abc import Iterable
from collections.abc import Sequence
from dataclasses import dataclass
from dataclasses import field

from tf_demo.cli._observations import Observation
from tf_demo.cli._observations import TF_STATIC_TOPIC
from tf_demo.core.math3d import Quat
from tf_demo.core.math3d import Vec3

NS_PER_S = 1_000_000_000


@dataclass(frozen=True)
class Thresholds:
    """Limits of the timing checks (seconds)."""

    future_tolerance_s: float = 0.5
    old_tolerance_s: float = 5.0
    max_gap_s: float = 0.5
    """A dynamic frame whose stamps are typically further apart is sparse (< 2 Hz)."""
    value_tolerance: float = 1e-9
    clock_jump_s: float = 1.0
    """Stamps stepping back further than this are a clock jump, not a stamp regression."""


@dataclass(frozen=True)
class Finding:
    """One problem: a short kind, severity ('error', 'warning' or 'info'), message and fix."""

    kind: str
    severity: str
    frames: tuple[str, ...]
    message: str
    fix: str
    at_ns: int | None = None
    """When it shows first (a reception time: bag time in a recording), if it has a time."""


@dataclass
class FrameStats:
    """What the observations say about one child frame: parents, topics, values, stamps."""

    parents: Counter[str] = field(default_factory=Counter)
    topics: Counter[str] = field(default_factory=Counter)
    publishers: set[str] = field(default_factory=set)
    dynamic_publishers: list[str] = field(default_factory=list)
    parent_by_topic: dict[str, set[str]] = field(default_factory=dict)
    static_values: list[tuple[Vec3, Quat]] = field(default_factory=list)
    dynamic: list[tuple[int, int, Vec3, Quat]] = field(default_factory=list)
    latest_parent: str = ''


def same_value(a: tuple[Vec3, Quat], b: tuple[Vec3, Quat], tolerance: float) -> bool:
    """Whether two (translation, rotation) values agree within ``tolerance``."""
    return all(abs(x - y) <= tolerance for x, y in zip(a[0] + a[1], b[0] + b[1], strict=True))


def distinct_values(
    values: Iterable[tuple[Vec3, Quat]], tolerance: float
) -> list[tuple[Vec3, Quat]]:
    """Return the values that differ from every earlier one, in order."""
    distinct: list[tuple[Vec3, Quat]] = []
    for value in values:
        if not any(same_value(value, seen, tolerance) for seen in distinct):
            distinct.append(value)
    return distinct


def gather(observations: Sequence[Observation]) -> dict[str, FrameStats]:
    """Gather the statistics of every child frame, in reception order."""
    stats: dict[str, FrameStats] = {}
    for observation in sorted(observations, key=lambda o: o.receive_ns):
        for transform in observation.transforms:
            entry = stats.setdefault(transform.child, FrameStats())
            entry.parents[transform.parent] += 1
            entry.topics[observation.topic] += 1
            entry.parent_by_topic.setdefault(observation.topic, set()).add(transform.parent)
            if observation.publisher:
                entry.publishers.add(observation.publisher)
            value = (transform.translation, transform.rotation)
            if observation.topic == TF_STATIC_TOPIC:
                entry.static_values.append(value)
            else:
                entry.dynamic.append(
                    (observation.receive_ns, transform.stamp_ns, value[0], value[1])
                )
                entry.dynamic_publishers.append(observation.publisher)
            entry.latest_parent = transform.parent
    return stats


def format_members(members: Sequence[str], limit: int = 8) -> str:
    """Return up to ``limit`` members joined by commas, with how many more there are."""
    shown = ', '.join(members[:limit])
    return shown + (f', … ({len(members) - limit} more)' if len(members) > limit else '')


def seconds(ns: float) -> str:
    """Return nanoseconds as seconds for a message (``1.500 s``)."""
    return f'{ns / NS_PER_S:.3f} s'
