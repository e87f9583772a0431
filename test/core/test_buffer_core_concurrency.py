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

"""Several threads inserting and looking up at once: only tf2 errors, never a torn result."""

from __future__ import annotations

import sys
import threading

import numpy as np
import pytest
from tf_demo.core import BufferCore
from tf_demo.core import TransformException
from tf_demo.core.math3d import Vec3

S = 1_000_000_000
IDENTITY = (0.0, 0.0, 0.0, 1.0)
ROUNDS = 400


@pytest.fixture
def fast_switching():
    """Switch threads often so that the interleavings are many."""
    old = sys.getswitchinterval()
    sys.setswitchinterval(1e-6)
    yield
    sys.setswitchinterval(old)


def _writer(core: BufferCore, chain: int, errors: list[Exception]) -> None:
    try:
        for k in range(1, ROUNDS + 1):
            stamp = k * S // 100
            # Both links of a chain carry the same k at the same stamp: a lookup across them
            # sees x = 2y and z = 3y unless it mixed two different inserts.
            core.set_transform(
                f'root{chain}', f'mid{chain}', stamp, (k, 2.0 * k, 3.0 * k), IDENTITY
            )
            core.set_transform(f'mid{chain}', f'tip{chain}', stamp, (k, -1.0 * k, 0.0), IDENTITY)
            if k % 97 == 0:
                core.clear()
    except Exception as error:
        errors.append(error)


def _reader(core: BufferCore, chain: int, errors: list[Exception], results: list[Vec3]) -> None:
    for k in range(ROUNDS * 3):
        try:
            if k % 3 == 0:
                result = core.lookup_transform(f'root{chain}', f'tip{chain}', 0)
                results.append(result.translation)
            elif k % 3 == 1:
                stamp = (k % ROUNDS + 1) * S // 100 + S // 300
                result = core.lookup_transform(f'root{chain}', f'tip{chain}', stamp)
                results.append(result.translation)
                core.can_transform(f'tip{chain}', f'root{chain}', stamp)
            else:
                translations, _ = core.lookup_transforms(
                    f'root{chain}', f'tip{chain}', np.array([0, S // 10, S // 5])
                )
                results.extend(map(tuple, translations.tolist()))
                core.all_frames_as_yaml()
        except TransformException:
            continue
        except Exception as error:
            errors.append(error)


@pytest.mark.usefixtures('fast_switching')
def test_concurrent_inserts_and_lookups_are_consistent():
    """Writers and readers on shared frames raise only tf2 errors and see whole inserts."""
    core = BufferCore()
    errors: list[Exception] = []
    results: list[Vec3] = []
    threads = [threading.Thread(target=_writer, args=(core, chain, errors)) for chain in range(2)]
    threads += [
        threading.Thread(target=_reader, args=(core, chain % 2, errors, results))
        for chain in range(4)
    ]
    for thread in threads:
        thread.start()
    for thread in threads:
        thread.join(timeout=120)
    assert not any(thread.is_alive() for thread in threads)
    assert errors == []
    assert len(results) > 100
    for x, y, z in results:
        assert x == pytest.approx(2.0 * y, abs=1e-9)
        assert z == pytest.approx(3.0 * y, abs=1e-9)


@pytest.mark.usefixtures('fast_switching')
def test_insert_callbacks_from_many_threads():
    """Insert callbacks run once per successful insert, outside the lock (they may look up)."""
    core = BufferCore()
    seen = []
    lock = threading.Lock()

    def callback():
        core.can_transform('a0', 'b0', 0)
        with lock:
            seen.append(1)

    core.add_insert_callback(callback)

    def insert(index):
        for k in range(1, 201):
            core.set_transform(f'a{index}', f'b{index}', k, (0.0, 0.0, 0.0), IDENTITY)

    threads = [threading.Thread(target=insert, args=(index,)) for index in range(4)]
    for thread in threads:
        thread.start()
    for thread in threads:
        thread.join(timeout=60)
    assert len(seen) == 800
