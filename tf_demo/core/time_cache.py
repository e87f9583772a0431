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
Per-frame transform history: tf2's ``TimeCache`` and ``StaticCache``.

A cache belongs to the *child* frame of a link and stores, per sample, the stamp, the
translation, the rotation and the parent frame id (the parent may change over time).

Storage is compact (``array`` of int64 stamps, float64 values and int32 parent ids) and kept in
ascending stamp order; among equal stamps the most recently inserted sample comes last.  This is
tf2's newest-first ``std::list`` read backwards, so every tie-breaking rule of tf2 carries over:

* lookup at the newest stamp returns the newest-inserted sample of that stamp;
* lookup at the oldest stamp returns the first-inserted sample of that stamp;
* interior lookups interpolate between the newest-inserted sample at or before the time and the
  first sample after it.

Pruning works as in tf2: on insert, samples older than ``newest - max_storage`` (the newest stamp
*before* the insert) are dropped, so pruning lags one insert.  Pruned samples are dropped lazily
by advancing a start index; the arrays are compacted when more than half of them is dead.

A sample read from a cache is a flat tuple ``(tx, ty, tz, qx, qy, qz, qw, parent_id)``.
"""

from __future__ import annotations

from array import array
from bisect import bisect_left
from bisect import bisect_right
import math
from typing import NamedTuple

__all__ = [
    'DEFAULT_CACHE_TIME_NS',
    'ERROR_BACKWARD_EXTRAPOLATION',
    'ERROR_CONNECTIVITY',
    'ERROR_EXTRAPOLATION',
    'ERROR_FORWARD_EXTRAPOLATION',
    'ERROR_LOOKUP',
    'ERROR_NO_DATA_FOR_EXTRAPOLATION',
    'Sample',
    'StaticCache',
    'TimeCache',
    'TransformStorage',
    'display_time_point',
    'duration_to_sec',
]

DEFAULT_CACHE_TIME_NS = 10_000_000_000

# tf2's TF2Error codes (the subset the core produces).
ERROR_LOOKUP = 1
ERROR_CONNECTIVITY = 2
ERROR_EXTRAPOLATION = 3
ERROR_BACKWARD_EXTRAPOLATION = 7
ERROR_FORWARD_EXTRAPOLATION = 8
ERROR_NO_DATA_FOR_EXTRAPOLATION = 9

Sample = tuple[float, float, float, float, float, float, float, int]

_NS_PER_S = 1_000_000_000
_NOT_FOUND = -(1 << 62)  # _bracket's failure value (single matches are encoded as ~index)


class TransformStorage(NamedTuple):
    """One stored sample, in tf2's terms (used for inspection, not on the hot path)."""

    stamp_ns: int
    translation: tuple[float, float, float]
    rotation: tuple[float, float, float, float]
    parent_id: int
    child_id: int


def duration_to_sec(duration_ns: int) -> float:
    """Convert nanoseconds to seconds as tf2's ``durationToSec`` (whole and fractional parts)."""
    sec = abs(duration_ns) // _NS_PER_S
    if duration_ns < 0:
        sec = -sec
    nsec = duration_ns - sec * _NS_PER_S
    return float(sec) + 1e-9 * float(nsec)


def display_time_point(stamp_ns: int) -> str:
    """Format a time as tf2's ``displayTimePoint``: seconds with six decimals."""
    return f'{duration_to_sec(stamp_ns):.6f}'


class TimeCache:
    """History of one dynamic link, with tf2's ordering, pruning and interpolation."""

    is_static = False

    __slots__ = ('_data', '_max_storage_ns', '_parents', '_stamps', '_start', 'child_id')

    def __init__(self, max_storage_ns: int = DEFAULT_CACHE_TIME_NS, child_id: int = 0) -> None:
        self._max_storage_ns = max_storage_ns
        self.child_id = child_id
        self._stamps: array[int] = array('q')
        self._data: array[float] = array('d')
        self._parents: array[int] = array('i')
        self._start = 0

    # --- insertion -----------------------------------------------------------------------

    def insert(self, stamp_ns: int, values: tuple[float, ...], parent_id: int) -> bool:
        """
        Insert ``values`` = ``(tx, ty, tz, qx, qy, qz, qw)`` at ``stamp_ns`` (tf2 insertData).

        :returns: False when the stamp is older than ``newest - max_storage`` (tf2's TF_OLD_DATA
            case); True otherwise, including for a silently dropped exact duplicate.
        """
        stamps = self._stamps
        start = self._start
        end = len(stamps)
        if start < end:
            latest = stamps[end - 1]
            oldest_kept = latest - self._max_storage_ns
            if stamps[start] < oldest_kept:
                start = self._start = bisect_left(stamps, oldest_kept, start, end)
            if stamp_ns < oldest_kept:
                self._compact_if_sparse()
                return False
            if stamp_ns >= latest:
                position = end
                if stamp_ns == latest and self._has_duplicate(
                    bisect_left(stamps, stamp_ns, start, end), end, values, parent_id
                ):
                    return True
            else:
                position = bisect_right(stamps, stamp_ns, start, end)
                first_same = bisect_left(stamps, stamp_ns, start, position)
                if first_same < position and self._has_duplicate(
                    first_same, position, values, parent_id
                ):
                    return True
        else:
            position = end
        if position == end:
            stamps.append(stamp_ns)
            self._data.extend(values)
            self._parents.append(parent_id)
        else:
            stamps.insert(position, stamp_ns)
            self._data[7 * position : 7 * position] = array('d', values)
            self._parents.insert(position, parent_id)
        self._compact_if_sparse()
        return True

    def _has_duplicate(
        self, first: int, end: int, values: tuple[float, ...], parent_id: int
    ) -> bool:
        data = self._data
        parents = self._parents
        for index in range(first, end):
            base = 7 * index
            if parents[index] == parent_id and tuple(data[base : base + 7]) == tuple(values):
                return True
        return False

    def _compact_if_sparse(self) -> None:
        start = self._start
        if start > 32 and 2 * start > len(self._stamps):
            del self._stamps[:start]
            del self._data[: 7 * start]
            del self._parents[:start]
            self._start = 0

    def clear(self) -> None:
        """Drop every sample (tf2 clearList)."""
        self._stamps = array('q')
        self._data = array('d')
        self._parents = array('i')
        self._start = 0

    # --- queries -------------------------------------------------------------------------

    def _sample(self, index: int) -> Sample:
        data = self._data
        base = 7 * index
        return (
            data[base],
            data[base + 1],
            data[base + 2],
            data[base + 3],
            data[base + 4],
            data[base + 5],
            data[base + 6],
            self._parents[index],
        )

    def _bracket(self, time_ns: int) -> int:
        """
        Locate ``time_ns`` as tf2's ``findClosest`` does.

        :returns: ``_NOT_FOUND`` on failure, ``~i`` for a single matching sample ``i``, or
            ``i`` for the older neighbour of an interior time (the newer one is ``i + 1``).
        """
        stamps = self._stamps
        start = self._start
        end = len(stamps)
        if start == end:
            return _NOT_FOUND
        if time_ns == 0:
            return ~(end - 1)
        if end - start == 1:
            return ~start if stamps[start] == time_ns else _NOT_FOUND
        latest = stamps[end - 1]
        if time_ns == latest:
            return ~(end - 1)
        earliest = stamps[start]
        if time_ns == earliest:
            return ~start
        if time_ns > latest or time_ns < earliest:
            return _NOT_FOUND
        return bisect_right(stamps, time_ns, start, end) - 1

    def get_data(self, time_ns: int) -> Sample | None:
        """
        Return the (possibly interpolated) sample at ``time_ns`` (0 = newest), or None.

        Interpolation is linear in translation and tf2's slerp in rotation; it never crosses a
        parent change (the older sample is returned instead).  Use :meth:`explain_failure` for
        tf2's error text when None is returned.
        """
        found = self._bracket(time_ns)
        if found < 0:
            if found == _NOT_FOUND:
                return None
            return self._sample(~found)
        parents = self._parents
        parent = parents[found]
        if parents[found + 1] != parent:
            return self._sample(found)
        stamps = self._stamps
        one_stamp = stamps[found]
        two_stamp = stamps[found + 1]
        data = self._data
        base = 7 * found
        if two_stamp == one_stamp:
            return self._sample(found + 1)
        ratio = float(time_ns - one_stamp) / float(two_stamp - one_stamp)
        keep = 1.0 - ratio
        x0, y0, z0, w0 = data[base + 3], data[base + 4], data[base + 5], data[base + 6]
        x1, y1, z1, w1 = data[base + 10], data[base + 11], data[base + 12], data[base + 13]
        dot = x0 * x1 + y0 * y1 + z0 * z1 + w0 * w1
        cosine = (-dot if dot < 0 else dot) / math.sqrt(
            (x0 * x0 + y0 * y0 + z0 * z0 + w0 * w0) * (x1 * x1 + y1 * y1 + z1 * z1 + w1 * w1)
        )
        theta = math.acos(1.0 if cosine > 1.0 else cosine) * 2.0 / 2.0
        if theta != 0.0:
            d = 1.0 / math.sin(theta)
            s0 = math.sin(keep * theta)
            s1 = math.sin(ratio * theta)
            if dot < 0:
                s1 = -s1
            x0 = (x0 * s0 + x1 * s1) * d
            y0 = (y0 * s0 + y1 * s1) * d
            z0 = (z0 * s0 + z1 * s1) * d
            w0 = (w0 * s0 + w1 * s1) * d
        return (
            keep * data[base] + ratio * data[base + 7],
            keep * data[base + 1] + ratio * data[base + 8],
            keep * data[base + 2] + ratio * data[base + 9],
            x0,
            y0,
            z0,
            w0,
            parent,
        )

    def get_parent(self, time_ns: int) -> int:
        """Return the parent id at ``time_ns`` (older neighbour's parent), or 0 on failure."""
        found = self._bracket(time_ns)
        if found == _NOT_FOUND:
            return 0
        return self._parents[~found if found < 0 else found]

    def explain_failure(self, time_ns: int) -> tuple[int, str]:
        """
        Return tf2's ``(error code, message)`` for a failed lookup at ``time_ns``.

        An empty cache gives NO_DATA with an empty message, as tf2 Jazzy does.
        """
        stamps = self._stamps
        start = self._start
        end = len(stamps)
        if start == end:
            return ERROR_NO_DATA_FOR_EXTRAPOLATION, ''
        if end - start == 1:
            return (
                ERROR_NO_DATA_FOR_EXTRAPOLATION,
                f'Lookup would require extrapolation at time {display_time_point(time_ns)}, '
                f'but only time {display_time_point(stamps[start])} is in the buffer',
            )
        latest = stamps[end - 1]
        if time_ns > latest:
            return (
                ERROR_FORWARD_EXTRAPOLATION,
                'Lookup would require extrapolation into the future.  Requested time '
                f'{display_time_point(time_ns)} but the latest data is at time '
                f'{display_time_point(latest)}',
            )
        return (
            ERROR_BACKWARD_EXTRAPOLATION,
            'Lookup would require extrapolation into the past.  Requested time '
            f'{display_time_point(time_ns)} but the earliest data is at time '
            f'{display_time_point(stamps[start])}',
        )

    def latest_time_and_parent(self) -> tuple[int, int]:
        """Return ``(newest stamp, its parent id)``, or ``(0, 0)`` when empty."""
        end = len(self._stamps)
        if self._start == end:
            return 0, 0
        return self._stamps[end - 1], self._parents[end - 1]

    @property
    def latest_stamp_ns(self) -> int:
        """Newest stamp, 0 when empty."""
        return self._stamps[-1] if self._start < len(self._stamps) else 0

    @property
    def oldest_stamp_ns(self) -> int:
        """Oldest stamp still held, 0 when empty."""
        return self._stamps[self._start] if self._start < len(self._stamps) else 0

    def __len__(self) -> int:
        return len(self._stamps) - self._start

    def items(self) -> list[TransformStorage]:
        """Return every held sample, newest first (tf2's list order)."""
        out = []
        for index in range(len(self._stamps) - 1, self._start - 1, -1):
            sample = self._sample(index)
            out.append(
                TransformStorage(
                    self._stamps[index],
                    (sample[0], sample[1], sample[2]),
                    (sample[3], sample[4], sample[5], sample[6]),
                    sample[7],
                    self.child_id,
                )
            )
        return out

    def arrays(self) -> tuple[array[int], array[float], array[int]]:
        """Return copies of the live ``(stamps, values, parents)`` arrays (ascending order)."""
        start = self._start
        return (self._stamps[start:], self._data[7 * start :], self._parents[start:])


class StaticCache:
    """A static link: one sample, valid at every time (tf2 StaticCache)."""

    is_static = True

    __slots__ = ('_sample', 'child_id')

    def __init__(self, child_id: int = 0) -> None:
        self.child_id = child_id
        self._sample: Sample = (0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0)

    def insert(self, stamp_ns: int, values: tuple[float, ...], parent_id: int) -> bool:
        """Overwrite the stored sample (the stamp is ignored); always succeeds."""
        del stamp_ns
        self._sample = (
            values[0],
            values[1],
            values[2],
            values[3],
            values[4],
            values[5],
            values[6],
            parent_id,
        )
        return True

    def clear(self) -> None:
        """Do nothing: tf2 keeps static transforms across ``clear()``."""

    def get_data(self, time_ns: int) -> Sample:
        """Return the stored sample, whatever the time."""
        del time_ns
        return self._sample

    def get_parent(self, time_ns: int) -> int:
        """Return the stored parent id."""
        del time_ns
        return self._sample[7]

    def explain_failure(self, time_ns: int) -> tuple[int, str]:
        """Never called in practice: a static cache never fails."""
        del time_ns
        return 0, ''

    def latest_time_and_parent(self) -> tuple[int, int]:
        """Return ``(0, parent)``: static links impose no time constraint."""
        return 0, self._sample[7]

    @property
    def latest_stamp_ns(self) -> int:
        """Always 0."""
        return 0

    @property
    def oldest_stamp_ns(self) -> int:
        """Always 0."""
        return 0

    def __len__(self) -> int:
        return 1

    def items(self) -> list[TransformStorage]:
        """Return the stored sample with stamp 0."""
        s = self._sample
        return [
            TransformStorage(0, (s[0], s[1], s[2]), (s[3], s[4], s[5], s[6]), s[7], self.child_id)
        ]
