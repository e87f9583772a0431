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
Hypothesis strategies for tf2 data: quaternions, transforms, stamps, frame names, trees.

The strategies draw every choice through hypothesis (no external random generator), so failures
shrink and replay.  Two settings profiles are registered: ``ci`` (derandomised, a fixed number of
examples, no deadline) and ``nightly`` (random, many more examples); pick one with
:func:`profile_settings`, whose default comes from ``TF_DEMO_HYPOTHESIS_PROFILE`` (``ci``).

The differential test against tf2's C++ core also needs whole *scenarios* (a tree, an insert
sequence, queries).  They are built by :func:`build_scenario` from a small :class:`Chooser`
interface, so the same generator runs under hypothesis (:func:`scenarios`, shrinkable) and under a
seeded ``random.Random`` for bulk runs of thousands of scenarios.
"""

from __future__ import annotations

from collections.abc import Sequence
import math
import os
import random
import sys
from typing import Any
from typing import Protocol
from typing import TypedDict
from typing import TypeVar

from hypothesis import HealthCheck
from hypothesis import settings
from hypothesis import strategies as st
from tf_demo.core import math3d
from tf_demo.core.math3d import Quat
from tf_demo.core.math3d import Vec3

#: One operation of a scenario; see :func:`build_scenario` (JSON-compatible lists).
Op = list[Any]
T = TypeVar('T')

#: Characters frame names are drawn from: no ``/``, no spaces, nothing that needs quoting.
FRAME_ALPHABET = 'abcxyz_019'
#: Quaternion draws whose norm is below this are rejected before normalisation.
MIN_QUATERNION_NORM = 1e-3

settings.register_profile(
    'ci',
    derandomize=True,
    max_examples=100,
    deadline=None,
    print_blob=True,
    suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large],
)
#: The other Pythons' runs (tools/other_pythons.sh): CI's profile with a tenth of its examples.
settings.register_profile('matrix', settings.get_profile('ci'), max_examples=10)
settings.register_profile(
    'nightly',
    max_examples=2000,
    deadline=None,
    suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large],
)


def profile_settings(max_examples: int | None = None) -> settings:
    """
    Return the settings of the selected profile, optionally with another example count.

    :param max_examples: overrides the profile's count (scaled up 20x for ``nightly``, down 10x
        for ``matrix``: the other Pythons' runs, which look for what an interpreter breaks).
    """
    name = os.environ.get('TF_DEMO_HYPOTHESIS_PROFILE', 'ci')
    base = settings.get_profile(name)
    if max_examples is None:
        return base
    scale = {'nightly': 20.0, 'matrix': 0.1}.get(name, 1.0)
    return settings(base, max_examples=max(1, int(max_examples * scale)))


def frame_names(max_size: int = 6) -> st.SearchStrategy[str]:
    """Draw a valid tf2 frame name (non-empty, no leading ``/``) from :data:`FRAME_ALPHABET`."""
    return st.text(alphabet=FRAME_ALPHABET, min_size=1, max_size=max_size)


def stamps_ns(min_ns: int = 0, max_ns: int = 4_000_000_000_000_000_000) -> st.SearchStrategy[int]:
    """Draw an integer time stamp in nanoseconds (0 means "latest" in lookups)."""
    return st.integers(min_value=min_ns, max_value=max_ns)


def translations(bound: float = 100.0) -> st.SearchStrategy[Vec3]:
    """Draw a finite translation with every component in ``[-bound, bound]``."""
    component = st.floats(min_value=-bound, max_value=bound, allow_nan=False)
    return st.tuples(component, component, component)


def _normalised(q: Quat) -> Quat:
    """Scale ``q`` to unit norm (the caller has filtered out tiny norms)."""
    norm = math.sqrt(sum(c * c for c in q))
    return (q[0] / norm, q[1] / norm, q[2] / norm, q[3] / norm)


def _norm_is_usable(q: Quat) -> bool:
    """Tell whether ``q`` is far enough from zero to be normalised reliably."""
    return math.sqrt(sum(c * c for c in q)) > MIN_QUATERNION_NORM


def raw_quaternions() -> st.SearchStrategy[Quat]:
    """Draw a quaternion with components in ``[-1, 1]`` and a usable, not necessarily unit norm."""
    component = st.floats(min_value=-1.0, max_value=1.0, allow_nan=False)
    return st.tuples(component, component, component, component).filter(_norm_is_usable)


def unit_quaternions() -> st.SearchStrategy[Quat]:
    """Draw a unit quaternion ``(x, y, z, w)``; both signs of ``w`` occur."""
    return raw_quaternions().map(_normalised)


def transforms(bound: float = 100.0) -> st.SearchStrategy[tuple[Vec3, Quat]]:
    """Draw a rigid transform ``(translation, unit rotation)``."""
    return st.tuples(translations(bound), unit_quaternions())


def rpy_angles() -> st.SearchStrategy[Vec3]:
    """Draw ``(roll, pitch, yaw)``: roll and yaw in ``(-pi, pi]``, pitch in ``[-pi/2, pi/2]``."""
    half_turn = st.floats(min_value=-math.pi, max_value=math.pi, allow_nan=False).filter(
        lambda a: a != -math.pi
    )
    pitch = st.floats(min_value=-math.pi / 2, max_value=math.pi / 2, allow_nan=False)
    return st.tuples(half_turn, pitch, half_turn)


@st.composite
def parent_lists(draw: st.DrawFn, min_frames: int = 2, max_frames: int = 8) -> list[int]:
    """
    Draw a forest as a parent list: ``parents[i]`` is ``-1`` (a root) or an index ``< i``.

    Frame 0 is always a root; every later frame attaches to an earlier one unless it is drawn as a
    root of its own, which makes disconnected trees.
    """
    count = draw(st.integers(min_value=min_frames, max_value=max_frames))
    return [-1] + [
        draw(st.integers(min_value=-1, max_value=index - 1)) for index in range(1, count)
    ]


@st.composite
def chains(draw: st.DrawFn, min_links: int = 1, max_links: int = 8) -> list[str]:
    """Draw distinct frame names for a chain ``names[0] -> names[1] -> ...`` (root first)."""
    count = draw(st.integers(min_value=min_links + 1, max_value=max_links + 1))
    return draw(st.lists(frame_names(), min_size=count, max_size=count, unique=True))


# --------------------------------------------------------------------------------------------
# Scenarios for the differential test


class Chooser(Protocol):
    """The source of every choice :func:`build_scenario` makes."""

    def integer(self, low: int, high: int) -> int:
        """Return an integer in ``[low, high]``."""
        ...

    def real(self, low: float, high: float) -> float:
        """Return a finite float in ``[low, high]``."""
        ...


class SeededChooser(random.Random):
    """A seeded :class:`Chooser` for bulk runs: ``SeededChooser(seed)`` (the same every run)."""

    def integer(self, low: int, high: int) -> int:
        """Return an integer in ``[low, high]``."""
        return self.randint(low, high)

    def real(self, low: float, high: float) -> float:
        """Return a float in ``[low, high]``."""
        return self.uniform(low, high)


class HypothesisChooser:
    """A :class:`Chooser` that draws through hypothesis (shrinkable, replayable)."""

    def __init__(self, draw: st.DrawFn) -> None:
        """Wrap the ``draw`` function of a composite strategy."""
        self._draw = draw

    def integer(self, low: int, high: int) -> int:
        """Return an integer in ``[low, high]``."""
        return self._draw(st.integers(min_value=low, max_value=high))

    def real(self, low: float, high: float) -> float:
        """Return a finite float in ``[low, high]``."""
        return self._draw(st.floats(min_value=low, max_value=high, allow_nan=False))


def _chance(choose: Chooser, percent: int) -> bool:
    """Return True with roughly ``percent`` % probability."""
    return choose.integer(0, 99) < percent


def _pick(choose: Chooser, items: Sequence[T]) -> T:
    """Return one element of a non-empty sequence."""
    return items[choose.integer(0, len(items) - 1)]


def _shuffled(choose: Chooser, items: Sequence[T]) -> list[T]:
    """Return a permutation of ``items`` (Fisher-Yates driven by ``choose``)."""
    result = list(items)
    for index in range(len(result) - 1, 0, -1):
        other = choose.integer(0, index)
        result[index], result[other] = result[other], result[index]
    return result


def _name_pool() -> list[str]:
    """Return the frame names scenarios pick from: one and two characters of the alphabet."""
    letters = FRAME_ALPHABET
    singles = list(letters)
    doubles = [a + b for a in letters for b in letters]
    return singles + doubles


_NAME_POOL = _name_pool()


_SPECIAL_QUATERNIONS = (
    ((0.0, 0.0, 0.0, 1.0), (0.0, 0.0, 0.0, -1.0)),
    ((0.0, 0.0, 0.0, 1.0), (0.0, 0.0, 1.0, 0.0), (1.0, 0.0, 0.0, 0.0)),
)


def _quaternion(choose: Chooser, special_set: int = 0) -> Quat:
    """
    Return a unit quaternion; exact special values from ``_SPECIAL_QUATERNIONS[special_set]``.

    A link uses one special set: ``(0, 0, 0, -1)`` (stored as given by ROS 1, as ``(0, 0, 0, 1)``
    by Jazzy: spec Appendix, "quaternion sign") never meets a half turn on the same link, because
    slerp between exactly opposite rotations (dot product 0) picks its arc from the signs. For
    the same reason the other quaternions come with the sign Jazzy stores (its matrix route):
    exact values such as ``(-0, -0, -1, 0)`` next to ``(0, 0, 0, 1)`` would otherwise interpolate
    along opposite arcs in ROS 1 and in Jazzy (checked against the real Jazzy's tf2_py).
    """
    if _chance(choose, 10):
        return _pick(choose, _SPECIAL_QUATERNIONS[special_set])
    while True:
        q = (
            choose.real(-1.0, 1.0),
            choose.real(-1.0, 1.0),
            choose.real(-1.0, 1.0),
            choose.real(-1.0, 1.0),
        )
        if _norm_is_usable(q):
            # A subnormal component keeps its sign in ROS 1's store and loses it in Jazzy's
            # matrix route: next to a rotation at a right angle, that sign picks the arc.
            x, y, z, w = (c if abs(c) >= sys.float_info.min else 0.0 for c in _normalised(q))
            unit = (x, y, z, w)
            stored = math3d.canonical_quat(unit)
            if sum(a * b for a, b in zip(unit, stored, strict=True)) < 0:
                return (-unit[0], -unit[1], -unit[2], -unit[3])
            return unit


def _translation(choose: Chooser) -> list[float]:
    """Return a translation with components in ``[-10, 10]``."""
    return [choose.real(-10.0, 10.0) for _ in range(3)]


class Scenario(TypedDict):
    """A differential-test scenario: the buffer's cache time and its operations."""

    cache_time_ns: int
    ops: list[Op]


def build_scenario(choose: Chooser, *, ros1: bool = True) -> Scenario:
    """
    Build one random scenario: a forest, an insert sequence and queries, as JSON-ready data.

    ``ros1=False`` is for Jazzy's own core as the oracle: it lifts the avoidances below (a
    second sample with the same stamp and other data, non-unit quaternions, a dynamic link
    made static, frame-chain queries, stamps of today's epoch), adds velocity queries (ROS
    1's binding has none) and leaves pruning as Jazzy does it (no re-sent samples).

    ``{"cache_time_ns": int, "ops": [...]}`` with the operations of ``test/core/tf2_oracle.py``.
    What is generated, and what is deliberately avoided because Debian's ROS 1 oracle differs
    from Jazzy (``spec/tf2.md`` Appendix):

    * two to eight (sometimes twenty) frames in one or several trees; a link is static or
      dynamic for the whole scenario (the oracle never switches a cache's kind, Jazzy does);
    * static links are sometimes overwritten, also with a new parent; dynamic links get one to
      five (sometimes up to twenty-one) samples on a stamp grid (distinct stamps per link: the
      oracle drops a second sample with the same stamp), sometimes stamp 0, sometimes a new
      parent from some stamp on (re-parenting, possibly a loop); inserts are shuffled (out of
      order), some are repeated exactly, some are written with a leading ``/``; invalid inserts
      (self transform, empty names); a short cache time so that old data is rejected and
      pruned; ``clear()``;
    * queries at time 0, at exact sample stamps, between samples, outside the data, for unknown,
      empty and ``/``-prefixed names, fixed-frame lookups, ``can_transform``, latest common time,
      the frame names, ``all_frames_as_string``, ``all_frames_as_yaml`` and the DOT dump.  No
      frame-chain queries: Noetic's ``_chainAsVector`` is an older algorithm than Jazzy's
      (``spec/tf2.md`` §3.8 lists Jazzy's verified chains).
    """
    step = _pick(choose, [1, 1000, 100_000_000, 1_000_000_000, 123_456_789])
    # Stamps stay below 1e6 s: the oracle's Python binding passes times to C++ as double seconds
    # (``rospy.Time.to_sec``), which keeps every nanosecond only for small epochs.
    bases = [0, 0, 1_000_000_000_000, 123_456_789_000_000]
    if not ros1:  # Jazzy's binding passes sec and nanosec: today's epoch times are exact
        bases.append(1_764_000_000_123_456_789)
    base = _pick(choose, bases)
    cache_time_ns = _pick(choose, [10_000_000_000, 10_000_000_000, 3 * step, 6 * step])
    frame_count = choose.integer(2, 20) if _chance(choose, 10) else choose.integer(2, 8)
    names = _shuffled(choose, _NAME_POOL)[:frame_count]
    parents = [-1] + [
        -1 if _chance(choose, 12) else choose.integer(0, index - 1)
        for index in range(1, len(names))
    ]

    inserts: list[Op] = []
    dynamic_stamps: list[int] = []
    for index, child in enumerate(names):
        if parents[index] < 0:
            continue
        parent = names[parents[index]]
        authority = _pick(choose, ['auth_a', 'auth_b'])
        special_set = choose.integer(0, 1)
        if _chance(choose, 30):
            for repeat in range(choose.integer(1, 2)):
                stamp = base + step * choose.integer(0, 20)
                if repeat and _chance(choose, 30):  # a static overwrite with a new parent
                    parent = _pick(choose, [n for n in names if n != child])
                inserts.append(
                    [
                        'set',
                        parent,
                        child,
                        stamp,
                        _translation(choose),
                        list(_quaternion(choose, special_set)),
                        authority,
                        True,
                    ]
                )
            continue
        sample_count = choose.integer(6, 21) if _chance(choose, 10) else choose.integer(1, 5)
        grid = sorted({choose.integer(0, 20) for _ in range(sample_count)})
        new_parent_from = None
        if len(grid) >= 2 and _chance(choose, 15):
            new_parent_from = grid[choose.integer(1, len(grid) - 1)]
            other_parent = _pick(choose, [n for n in names if n != child])
        for point in grid:
            stamp = base + step * point
            if stamp == 0 and not _chance(choose, 30):
                stamp = base + step * 21
            link_parent = parent
            if new_parent_from is not None and point >= new_parent_from:
                link_parent = other_parent
            inserts.append(
                [
                    'set',
                    link_parent,
                    child,
                    stamp,
                    _translation(choose),
                    list(_quaternion(choose, special_set)),
                    authority,
                    False,
                ]
            )
            dynamic_stamps.append(stamp)
            if not ros1 and _chance(choose, 8):  # the same stamp again, with other data
                inserts.append(
                    ['set', link_parent, child, stamp, _translation(choose), *inserts[-1][5:]]
                )
        if not ros1 and _chance(choose, 8):  # the dynamic link becomes static
            inserts.append(
                ['set', parent, child, 0, _translation(choose), [0.0, 0.0, 0.0, 1.0], 'x', True]
            )
    if not inserts:
        inserts.append(
            [
                'set',
                names[0],
                names[1],
                base + step,
                _translation(choose),
                list(_quaternion(choose)),
                'auth_a',
                False,
            ]
        )
        dynamic_stamps.append(base + step)

    if _chance(choose, 70):
        inserts = _shuffled(choose, inserts)
    else:
        inserts.sort(key=lambda op: int(op[3]))
    for _ in range(choose.integer(0, 2)):
        if _chance(choose, 50):
            duplicate = list(_pick(choose, inserts))
            inserts.insert(choose.integer(0, len(inserts)), duplicate)
    for position, op in enumerate(inserts):
        if _chance(choose, 8):
            inserts[position] = ['set', '/' + str(op[1]), '/' + str(op[2]), *op[3:]]
        if not ros1 and _chance(choose, 10):  # not unit length: Jazzy normalises it
            scale = _pick(choose, [0.5, 2.0, 1.0 + 1e-3])
            inserts[position] = [*op[:5], [c * scale for c in op[5]], *op[6:]]
    if _chance(choose, 10):
        bad_name = _pick(choose, names)
        bad = _pick(
            choose,
            [[bad_name, bad_name], ['', bad_name], [bad_name, ''], ['', '']],
        )
        inserts.insert(
            choose.integer(0, len(inserts)),
            [
                'set',
                bad[0],
                bad[1],
                base + step,
                [1.0, 2.0, 3.0],
                [0.0, 0.0, 0.0, 1.0],
                'bad',
                False,
            ],
        )

    odd_frames = ['unknown', '', '/' + names[0]]

    def query_frame() -> str:
        return _pick(choose, odd_frames) if _chance(choose, 6) else _pick(choose, names)

    query_times = [0, 0, *dynamic_stamps, base + step * 25]
    if step > 1:
        query_times += [s + step // 2 for s in dynamic_stamps] + [
            s - step // 3 for s in dynamic_stamps
        ]
    query_times += [s + 1 for s in dynamic_stamps] + [s - 1 for s in dynamic_stamps]  # boundaries
    query_times = [t for t in query_times if t >= 0]

    def query() -> Op:
        roll = choose.integer(0, 99)
        target = query_frame()
        source = query_frame()
        time_ns = _pick(choose, query_times)
        if roll < 50:
            return ['lookup', target, source, time_ns]
        if roll < 63:
            return ['can', target, source, time_ns]
        if roll < 73:
            return [
                'lookup_full',
                target,
                time_ns,
                source,
                _pick(choose, query_times),
                query_frame(),
            ]
        if roll < 78:
            return ['can_full', target, time_ns, source, _pick(choose, query_times), query_frame()]
        if roll < 93:
            return ['lct', target, source]
        if not ros1 and roll < 95:
            if _chance(choose, 50):
                averaging = _pick(choose, [step, 2 * step, 10_000_000, 1_000_000_000])
                return ['velocity', target, source, time_ns, averaging]
            return ['chain', target, time_ns, source, _pick(choose, query_times), query_frame()]
        if roll < 95:
            return ['string']
        if roll < 96:
            return ['frames']
        if roll < 98:
            return ['yaml']
        return ['dot', _pick(choose, [0, time_ns])]

    ops: list[Op] = list(inserts)
    if _chance(choose, 25):
        cut = choose.integer(0, len(ops))
        ops[cut:cut] = [query() for _ in range(choose.integer(1, 3))]
    if _chance(choose, 12):
        cut = choose.integer(0, len(ops))
        ops.insert(cut, ['clear'])
    ops += [query() for _ in range(choose.integer(3, 12))]
    if ros1:
        ops = with_prune_flushes(ops, cache_time_ns)
    return {'cache_time_ns': cache_time_ns, 'ops': ops}


def with_prune_flushes(ops: list[Op], cache_time_ns: int) -> list[Op]:
    """
    Re-send the newest sample of a dynamic link before queries when pruning could differ.

    tf2 Jazzy prunes a ``TimeCache`` with the newest stamp from *before* each insert
    (``spec/tf2.md`` §2.1: pruning lags one insert); ROS 1 Noetic, the differential oracle,
    prunes after inserting, with the new newest stamp.  An exact duplicate of the newest sample
    changes nothing in either buffer except that it makes Jazzy prune up to the same point, so
    both hold the same samples when the queries run.  The pruning lag itself is checked by a
    dedicated test.
    """
    latest: dict[str, int] = {}
    newest_op: dict[str, Op] = {}
    lagging: set[str] = set()
    static: set[str] = set()
    result: list[Op] = []
    for op in ops:
        kind = op[0]
        if kind == 'clear':
            latest.clear()
            newest_op.clear()
            lagging.clear()
        elif kind == 'set':
            parent = str(op[1]).removeprefix('/')
            child = str(op[2]).removeprefix('/')
            stamp = int(op[3])
            if not parent or not child or parent == child:
                result.append(op)
                continue
            if op[7]:
                static.add(child)
            elif child not in static:
                before = latest.get(child)
                if before is None or stamp > before:
                    latest[child] = stamp
                    newest_op[child] = op
                if before is not None and before < latest[child]:
                    lagging.add(child)
                elif before is not None:
                    lagging.discard(child)
        elif lagging:
            result.extend(list(newest_op[child]) for child in sorted(lagging))
            lagging.clear()
        result.append(op)
    return result


@st.composite
def scenarios(draw: st.DrawFn, *, ros1: bool = True) -> Scenario:
    """Draw one differential-test scenario (see :func:`build_scenario`)."""
    return build_scenario(HypothesisChooser(draw), ros1=ros1)
