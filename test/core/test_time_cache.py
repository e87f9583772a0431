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

"""TimeCache and StaticCache, reproducing tf2's cache_unittest and spec/tf2.md §2."""

from __future__ import annotations

import math
import random

import pytest
from tf_demo.core import _batch
from tf_demo.core import math3d
from tf_demo.core.time_cache import display_time_point
from tf_demo.core.time_cache import ERROR_BACKWARD_EXTRAPOLATION
from tf_demo.core.time_cache import ERROR_FORWARD_EXTRAPOLATION
from tf_demo.core.time_cache import ERROR_NO_DATA_FOR_EXTRAPOLATION
from tf_demo.core.time_cache import pack_values
from tf_demo.core.time_cache import Sample
from tf_demo.core.time_cache import StaticCache
from tf_demo.core.time_cache import TimeCache

S = 1_000_000_000
IDENTITY = (0.0, 0.0, 0.0, 1.0)


def _values(
    x: float = 0.0,
    y: float = 0.0,
    z: float = 0.0,
    q: tuple[float, float, float, float] = IDENTITY,
    parent: int = 1,
) -> Sample:
    qx, qy, qz, qw = q
    return (float(x), float(y), float(z), qx, qy, qz, qw, parent)


def _data(cache: TimeCache | StaticCache, time_ns: int) -> Sample:
    """The cache's sample at ``time_ns`` (the tests that call this expect one)."""
    sample = cache.get_data(time_ns)
    assert sample is not None
    return sample


def _stamps(cache: TimeCache | StaticCache) -> list[int]:
    return [item.stamp_ns for item in cache.items()]


def test_repeatability_in_and_reverse_order():
    """Every inserted sample comes back exactly at its own stamp, whatever the insert order."""
    for order in (range(1, 101), range(100, 0, -1)):
        cache = TimeCache(10 * S)
        for i in order:
            cache.insert(i, _values(i, parent=i))
        for i in range(1, 101):
            sample = _data(cache, i)
            assert sample is not None
            assert sample[0] == i
            assert sample[7] == i
        assert len(cache) == 100


def test_time_zero_returns_newest():
    """Time 0 means the newest sample."""
    cache = TimeCache(10 * S)
    for i in (5, 9, 2):
        cache.insert(i, _values(i, parent=1))
    assert _data(cache, 0)[0] == 9


def test_get_all_items_order_and_pruning():
    """tf2's GetAllItems: newest first, ties reverse-inserted, then pruning and rejection."""
    cache = TimeCache(10)
    labels = {}
    for stamp, label in ((0, 0), (10, 10), (5, 5), (3, 3), (8, 81), (8, 82), (8, 83)):
        assert cache.insert(stamp, _values(label, parent=1))
        labels[label] = stamp
    order = [int(item.translation[0]) for item in cache.items()]
    assert order == [10, 83, 82, 81, 5, 3, 0]
    for stamp, label in ((0, 0), (10, 10), (5, 5), (3, 3), (8, 81), (8, 82), (8, 83)):
        assert cache.insert(stamp, _values(label, parent=1))
    assert [int(item.translation[0]) for item in cache.items()] == order
    assert cache.insert(15, _values(15, parent=1))
    assert not cache.insert(0, _values(1000, parent=1))
    assert cache.insert(5, _values(55, parent=1))
    order = [int(item.translation[0]) for item in cache.items()]
    assert order == [15, 10, 83, 82, 81, 55, 5]


def test_pruning_lags_one_insert():
    """Cache 2 s, stamps 0..10 inserted in order: 7, 8, 9 and 10 remain."""
    cache = TimeCache(2 * S)
    for second in range(11):
        assert cache.insert(second * S, _values(second, parent=1))
    assert _stamps(cache) == [10 * S, 9 * S, 8 * S, 7 * S]
    assert cache.oldest_stamp_ns == 7 * S


def test_rejection_threshold_is_strict():
    """Exactly newest - cache_time is accepted; one nanosecond older is rejected."""
    cache = TimeCache(2 * S)
    cache.insert(10 * S, _values(parent=1))
    assert cache.insert(8 * S, _values(1, parent=1))
    assert not cache.insert(8 * S - 1, _values(2, parent=1))


def test_exact_duplicate_dropped_same_stamp_different_data_kept():
    """Exact duplicates are dropped silently (still True); different data at a stamp is kept."""
    cache = TimeCache(10 * S)
    assert cache.insert(S, _values(1, parent=1))
    assert cache.insert(S, _values(1, parent=1))
    assert len(cache) == 1
    assert cache.insert(S, _values(2, parent=1))
    assert cache.insert(S, _values(1, parent=2))
    assert len(cache) == 3


def test_tie_breaking_latest_oldest_interior():
    """Newest stamp -> newest-inserted, oldest -> first-inserted, interior uses newest-inserted."""
    cache = TimeCache(10 * S)
    cache.insert(S, _values(1, parent=1))
    cache.insert(S, _values(2, parent=1))
    cache.insert(2 * S, _values(3, parent=1))
    cache.insert(2 * S, _values(4, parent=1))
    cache.insert(3 * S, _values(5, parent=1))
    cache.insert(3 * S, _values(6, parent=1))
    assert _data(cache, 3 * S)[0] == 6
    assert _data(cache, S)[0] == 1
    # Interior: older neighbour is the newest-inserted at 2 s, so ratio 0 gives 4.
    assert _data(cache, 2 * S)[0] == 4
    # Between 2 s and 3 s: from the newest-inserted at 2 s (4) to the first-inserted at 3 s (5).
    assert _data(cache, 2 * S + S // 2)[0] == pytest.approx(4.5)


def test_cartesian_interpolation():
    """Translation is interpolated linearly between the neighbours."""
    rng = random.Random(1)
    for _ in range(50):
        cache = TimeCache(10 * S)
        a = [rng.uniform(-10, 10) for _ in range(3)]
        b = [rng.uniform(-10, 10) for _ in range(3)]
        cache.insert(S, _values(a[0], a[1], a[2], parent=1))
        cache.insert(2 * S, _values(b[0], b[1], b[2], parent=1))
        for step in range(11):
            t = S + step * S // 10
            sample = _data(cache, t)
            ratio = step / 10
            for axis in range(3):
                expected = (1 - ratio) * a[axis] + ratio * b[axis]
                assert sample[axis] == pytest.approx(expected, abs=1e-9)


def test_angular_interpolation_is_slerp():
    """Rotation is tf2's slerp between the neighbours."""
    cache = TimeCache(10 * S)
    q0 = math3d.quat_from_rpy(0.1, 0.2, 0.3)
    q1 = math3d.quat_from_rpy(-0.5, 0.4, 2.0)
    cache.insert(0 + 10, _values(q=q0, parent=1))
    cache.insert(10 + S, _values(q=q1, parent=1))
    sample = _data(cache, 10 + S // 4)
    assert sample[3:7] == pytest.approx(math3d.slerp(q0, q1, 0.25), abs=1e-12)


def test_no_interpolation_across_parent_change():
    """tf2's ReparentingInterpolationProtection: the older sample is returned unchanged."""
    cache = TimeCache(10 * S)
    cache.insert(S, _values(1, parent=1))
    cache.insert(2 * S, _values(2, parent=2))
    sample = _data(cache, S + S // 2)
    assert sample[0] == 1.0
    assert sample[7] == 1
    assert cache.get_parent(S + S // 2) == 1
    assert cache.get_parent(2 * S) == 2


def test_failure_messages_and_codes():
    """Empty, single-sample, future and past failures give tf2's codes and texts."""
    cache = TimeCache(10 * S)

    def failure(time_ns: int) -> tuple[int, str]:
        """Return tf2's ``(code, text)`` at ``time_ns``, where the cache has no sample."""
        assert cache.get_data(time_ns) is None
        return cache.explain_failure(time_ns)

    assert failure(S) == (ERROR_NO_DATA_FOR_EXTRAPOLATION, '')
    cache.insert(2 * S, _values(parent=1))
    assert failure(4 * S) == (
        ERROR_NO_DATA_FOR_EXTRAPOLATION,
        'Lookup would require extrapolation at time 4.000000, but only time 2.000000 is in the '
        'buffer',
    )
    cache.insert(3 * S, _values(parent=1))
    assert failure(4 * S) == (
        ERROR_FORWARD_EXTRAPOLATION,
        'Lookup would require extrapolation into the future.  Requested time 4.000000 but the '
        'latest data is at time 3.000000',
    )
    assert failure(1 * S) == (
        ERROR_BACKWARD_EXTRAPOLATION,
        'Lookup would require extrapolation into the past.  Requested time 1.000000 but the '
        'earliest data is at time 2.000000',
    )
    assert cache.get_parent(4 * S) == 0


def test_latest_time_and_parent_and_clear():
    """latest_time_and_parent gives the front entry, (0, 0) when empty; clear empties."""
    cache = TimeCache(10 * S)
    assert cache.latest_time_and_parent() == (0, 0)
    cache.insert(S, _values(parent=4))
    cache.insert(3 * S, _values(parent=5))
    assert cache.latest_time_and_parent() == (3 * S, 5)
    assert (cache.latest_stamp_ns, cache.oldest_stamp_ns) == (3 * S, S)
    cache.clear()
    assert len(cache) == 0
    assert cache.latest_time_and_parent() == (0, 0)


def test_lazy_pruning_compacts_and_stays_correct():
    """A long stream keeps only the window and still answers every retained stamp exactly."""
    cache = TimeCache(S)
    for i in range(5000):
        cache.insert(i * S // 100, _values(i, parent=1))
    assert len(cache) == 102
    for i in range(4900, 5000):
        assert _data(cache, i * S // 100)[0] == i


def test_static_cache_answers_any_time():
    """StaticCache returns its single sample at any time and survives clear()."""
    cache = StaticCache()
    cache.insert(123, _values(1, parent=7))
    cache.insert(5, _values(2, parent=8))
    assert _data(cache, 999 * S)[0] == 2
    assert cache.get_parent(1) == 8
    assert cache.latest_time_and_parent() == (0, 8)
    assert len(cache) == 1
    cache.clear()
    assert _data(cache, 0)[0] == 2


def test_display_time_point():
    """displayTimePoint prints six decimals: 1 ns -> 0.000000, -1 ns -> -0.000000."""
    assert display_time_point(1) == '0.000000'
    assert display_time_point(-1) == '-0.000000'
    assert display_time_point(1_500_000_000) == '1.500000'
    assert display_time_point(1_700_000_000_123_456_789) == '1700000000.123457'
    assert math.isclose(float(display_time_point(-2_500_000_000)), -2.5)


def test_interior_search_matches_linear_scan_on_irregular_stamps():
    """The guessed-then-bisected search finds tf2's older neighbour for any spacing and ties."""
    rng = random.Random(23)
    for _ in range(30):
        cache = TimeCache(10**12)
        stamps = sorted(rng.choice((rng.randint(0, 10**6), rng.randint(0, 50))) for _ in range(40))
        for order, stamp in enumerate(stamps):
            cache.insert(stamp, _values(order, parent=1 + order % 3))
        ascending = sorted((stamp, order) for order, stamp in enumerate(stamps))
        for time_ns in (rng.randint(stamps[0] + 1, stamps[-1] - 1) for _ in range(50)):
            if time_ns in stamps:
                continue
            older = max(order for stamp, order in ascending if stamp <= time_ns)
            assert cache.get_parent(time_ns) == 1 + older % 3
            sample = _data(cache, time_ns)
            newer = min((stamp, order) for stamp, order in ascending if stamp > time_ns)[1]
            if 1 + older % 3 != 1 + newer % 3:
                assert sample[0] == older
            else:
                assert min(older, newer) <= sample[0] <= max(older, newer)


def _raw_quaternions(count: int, seed: int) -> list[tuple[float, float, float, float]]:
    """Return ``count`` quaternions of assorted norms (none of them normalised)."""
    rng = random.Random(seed)
    return [
        (rng.gauss(0, 1), rng.gauss(0, 1), rng.gauss(0, 1), rng.gauss(0, 1)) for _ in range(count)
    ]


def test_a_raw_sample_reads_back_as_tf2_stores_it_bit_for_bit():
    """insert_raw keeps the rotation as given; every read canonicalises it exactly once."""
    cache = TimeCache(1000 * S)
    quaternions = _raw_quaternions(200, 5)
    for k, q in enumerate(quaternions):
        assert cache.insert_raw((k + 1) * S, pack_values(float(k), 0.0, -1.0, *q), 3)
    for k, q in enumerate(quaternions):
        expected = (float(k), 0.0, -1.0, *math3d.canonical_quat(q), 3)
        sample = cache.sample_at(k)
        assert [v.hex() for v in sample[:7]] == [v.hex() for v in expected[:7]]
        assert sample[7] == 3
        assert cache.sample_at(k) == sample  # made once
    assert cache.get_data(200 * S) == cache.sample_at(199)  # the newest, as read
    arrays = _batch.cache_arrays(cache)
    for k, q in enumerate(quaternions):
        assert [v.hex() for v in arrays.values[3:, k].tolist()] == [
            v.hex() for v in math3d.canonical_quat(q)
        ]


def test_arrays_of_raw_and_given_samples_hold_what_a_read_returns():
    """arrays() canonicalises the raw samples and keeps the given (canonical) ones as given."""
    cache = TimeCache(100 * S)
    quaternions = _raw_quaternions(50, 6)
    for k, q in enumerate(quaternions):
        if k % 3:
            cache.insert_raw((k + 1) * S, pack_values(0.0, float(k), 0.0, *q), 1)
        else:  # a canonical sample whose second canonicalisation could change its bits
            cache.insert((k + 1) * S, (0.0, float(k), 0.0, *math3d.canonical_quat(q), 1))
    cache.get_data(20 * S)  # reads (memoises) samples 18 and 19
    table = _batch.cache_arrays(cache).values
    for k in range(len(quaternions)):
        assert table[:, k].tolist() == list(cache.sample_at(k)[:7])


def test_equal_stamps_are_duplicates_when_tf2_would_store_them_equal():
    """The duplicate check compares samples as tf2 stores them, not as they were sent."""
    cache = TimeCache(10 * S)
    q = (0.0, 0.0, 0.6, 0.8)
    assert cache.insert_raw(S, pack_values(1.0, 2.0, 3.0, *q), 1)
    assert cache.insert_raw(S, pack_values(1.0, 2.0, 3.0, *q), 1)  # dropped: the same sample
    assert len(cache) == 1
    assert cache.insert_raw(S, pack_values(1.0, 2.0, 3.5, *q), 1)  # kept: other data
    assert len(cache) == 2
    assert _data(cache, S)[2] == 3.5  # the newest-inserted of the stamp


def test_pruning_and_out_of_order_inserts_keep_every_field_aligned():
    """Stamps, values, parents and read samples stay in step through pruning and inserts."""
    cache = TimeCache(5 * S)
    for k in range(0, 400, 2):  # prunes and compacts on the way
        cache.insert_raw(k * S // 10, pack_values(float(k), 0.0, 0.0, 0.0, 0.0, 0.0, 1.0), k + 1)
        if k % 7 == 0:
            cache.get_data(k * S // 10)  # some samples read (memoised) before they move
    for k in range(351, 399, 4):  # out of order, between the held samples
        cache.insert_raw(k * S // 10, pack_values(float(k), 0.0, 0.0, 0.0, 0.0, 0.0, 1.0), k + 1)
    for index in range(cache._start, len(cache._stamps)):
        k = cache._stamps[index] * 10 // S
        assert cache.sample_at(index) == (float(k), 0.0, 0.0, 0.0, 0.0, 0.0, 1.0, k + 1)
        assert cache._parents[index] == k + 1


def test_the_newest_sample_is_known_after_every_insert_compaction_included():
    """``latest`` follows every in-order insert, also the ones that compact the storage."""
    cache = TimeCache(S)
    for i in range(1, 3000):
        cache.insert_raw(i * S // 100, pack_values(float(i), 0.0, 0.0, 0.0, 0.0, 0.0, 1.0), 2)
        assert cache.latest == (i * S // 100, 2)
        assert cache.get_data(0) == (float(i), 0.0, 0.0, 0.0, 0.0, 0.0, 1.0, 2)
