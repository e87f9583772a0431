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

"""lookup_transforms (vectorised) against N single lookups on random trees."""

from __future__ import annotations

import random

import numpy as np
import pytest
from tf_demo.core import BufferCore
from tf_demo.core import math3d
from tf_demo.core import TransformException
from tf_demo.core.buffer_core import TransformResult

S = 1_000_000_000
FRAMES = ['f0', 'f1', 'f2', 'f3', 'f4', 'f5', 'f6']


def _random_buffer(rng: random.Random) -> BufferCore:
    core = BufferCore(3 * S, log=lambda level, text: None)
    for _ in range(rng.randint(5, 40)):
        child_index = rng.randint(1, len(FRAMES) - 1)
        parent = FRAMES[rng.randint(0, child_index - 1)]  # parents have lower index: no loops
        q = math3d.quat_from_rpy(rng.uniform(-3, 3), rng.uniform(-1.5, 1.5), rng.uniform(-3, 3))
        t = (rng.uniform(-2, 2), rng.uniform(-2, 2), rng.uniform(-2, 2))
        is_static = rng.random() < 0.2
        stamp = 0 if is_static else rng.randint(0, 8) * S // 2 + rng.choice((0, 0, 1, 7))
        core.set_transform(parent, FRAMES[child_index], stamp, t, q, 'r', is_static)
        if rng.random() < 0.03:
            core.clear()
    return core


def _first_failure(
    core: BufferCore, target: str, source: str, times: list[int]
) -> tuple[TransformException | None, list[TransformResult] | None]:
    singles: list[TransformResult] = []
    for stamp in times:
        try:
            singles.append(core.lookup_transform(target, source, stamp))
        except TransformException as error:
            return error, None
    return None, singles


@pytest.mark.parametrize('seed', range(40))
def test_batch_equals_single_lookups_on_random_trees(seed):
    """Every batch equals the single lookups, or raises the first single failure's error."""
    rng = random.Random(seed)
    core = _random_buffer(rng)
    known = core.frame_ids()
    for _ in range(8):
        target, source = rng.choice(known), rng.choice(known)
        times = [
            rng.choice((0, rng.randint(0, 9 * S // 2), rng.randint(0, 8) * S // 2))
            for _ in range(12)
        ]
        error, singles = _first_failure(core, target, source, times)
        if error is not None:
            with pytest.raises(type(error)) as info:
                core.lookup_transforms(target, source, np.array(times, dtype=np.int64))
            assert str(info.value) == str(error)
            continue
        translations, rotations = core.lookup_transforms(target, source, np.array(times))
        assert singles is not None  # no failure: every single lookup answered
        for row, single in enumerate(singles):
            assert translations[row] == pytest.approx(single.translation, abs=1e-9)
            assert rotations[row] == pytest.approx(single.rotation, abs=1e-9)


def test_batch_of_interior_stamps_with_reparenting():
    """A parent change inside the history is handled lane by lane."""
    core = BufferCore()
    core.set_transform('world', 'a', 0, (1.0, 0.0, 0.0), (0.0, 0.0, 0.0, 1.0), '', True)
    core.set_transform('world', 'b', 0, (0.0, 1.0, 0.0), (0.0, 0.0, 0.0, 1.0), '', True)
    for k in range(10):
        parent = 'a' if k < 5 else 'b'
        core.set_transform(
            parent, 'c', k * S, (0.1 * k, 0.0, 0.0), math3d.quat_from_rpy(0, 0, 0.1 * k)
        )
    times = np.arange(0, 9 * S, S // 7, dtype=np.int64)[1:]
    translations, rotations = core.lookup_transforms('world', 'c', times)
    for row, stamp in enumerate(times.tolist()):
        single = core.lookup_transform('world', 'c', stamp)
        assert translations[row] == pytest.approx(single.translation, abs=1e-12)
        assert rotations[row] == pytest.approx(single.rotation, abs=1e-12)


@pytest.mark.parametrize('step', [0.0, 0.05, 0.9, 2.5])
def test_batch_along_a_smooth_chain_equals_single_lookups(step):
    """Stamps inside every history (one pass per link): equal to single lookups, any angle."""
    core = BufferCore(20 * S, log=lambda level, text: None)
    core.set_transform('c', 'd', 0, (0.1, 0.2, 0.3), math3d.quat_from_rpy(0.3, 0.2, 0.1), '', True)
    core.set_transform('d', 'e', 0, (0.0, 0.0, 0.5), math3d.quat_from_rpy(0.0, 1.2, 0.0), '', True)
    for k in range(60):
        for index, (parent, child) in enumerate((('w', 'a'), ('a', 'b'), ('b', 'c'))):
            angle = step * k + 0.1 * index
            q = math3d.quat_from_rpy(0.5 * angle, -0.25 * angle, angle)
            t = (0.3 * k + index, 0.1 * k, -0.05 * k)
            core.set_transform(parent, child, 10 * S + k * S // 10 + 7 * index, t, q)
    rng = random.Random(int(step * 100))
    times = np.array([10 * S + 1_000 + rng.randint(0, 58 * S // 10) for _ in range(4200)])
    for target, source in (('w', 'e'), ('e', 'w'), ('a', 'd')):
        translations, rotations = core.lookup_transforms(target, source, times)
        for row, stamp in enumerate(times.tolist()):
            single = core.lookup_transform(target, source, stamp)
            assert translations[row] == pytest.approx(single.translation, abs=1e-9)
            assert rotations[row] == pytest.approx(single.rotation, abs=1e-9)
