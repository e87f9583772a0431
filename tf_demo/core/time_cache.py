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

Storage is compact, one typed array per field in ascending stamp order: int64 stamps, seven
doubles per sample (translation, then the rotation *as inserted*) and int64 parent ids, plus a
list that memoises each sample as tf2 stores it (:data:`Sample`, rotation normalised and
sign-canonicalised bit for bit by :func:`~tf_demo.core.math3d.canonical_quat`), made the first
time a lookup reads it.  Most samples of a busy ``/tf`` are never read: they cost 80 bytes and no
canonicalisation.  Among equal stamps the most recently inserted sample comes last.  This is
tf2's newest-first ``std::list`` read backwards, so every tie-breaking rule of tf2 carries over:

* lookup at the newest stamp returns the newest-inserted sample of that stamp;
* lookup at the oldest stamp returns the first-inserted sample of that stamp;
* interior lookups interpolate between the newest-inserted sample at or before the time and the
  first sample after it.

Pruning works as in tf2: on insert, samples older than ``newest - max_storage`` (the newest stamp
*before* the insert) are dropped, so pruning lags one insert.  Pruned samples are dropped lazily
by advancing a start index; the arrays are compacted when more than a quarter of them is dead.

A sample read from a cache is a flat tuple ``(tx, ty, tz, qx, qy, qz, qw, parent_id)``.
"""

from __future__ import annotations

from array import array
from bisect import bisect_left
from bisect import bisect_right
import math
from struct import Struct
from typing import ClassVar
from typing import Literal
from typing import NamedTuple
from typing import TYPE_CHECKING

from tf_demo.core.lazy_import import lazy_module
from tf_demo.core.math3d import canonical_quat
from tf_demo.core.math3d import canonical_quat_batch
from tf_demo.core.math3d import lerp
from tf_demo.core.math3d import slerp

if TYPE_CHECKING:
    from collections.abc import Sequence

    import numpy as np
    import numpy.typing as npt
else:
    np = lazy_module('numpy')

__all__ = [
    'DEFAULT_CACHE_TIME_NS',
    'ERROR_BACKWARD_EXTRAPOLATION',
    'ERROR_CONNECTIVITY',
    'ERROR_EXTRAPOLATION',
    'ERROR_FORWARD_EXTRAPOLATION',
    'ERROR_LOOKUP',
    'ERROR_NO_DATA_FOR_EXTRAPOLATION',
    'INTERVAL_COLUMNS',
    'CacheArrays',
    'CacheView',
    'Sample',
    'StaticCache',
    'TimeCache',
    'TransformStorage',
    'display_time_point',
    'duration_to_sec',
    'pack_values',
    'unpack_values',
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
#: The interpolation constants of one interval between samples: :meth:`TimeCache.interval_at`.
Interval = tuple[float, float, float, float, float, float, float, float]
#: :meth:`TimeCache.view`: earliest, latest, scale, start, last, stamps, samples (None: not read
#: yet, see :meth:`TimeCache.sample_at`), intervals (None: not made yet, see
#: :meth:`TimeCache.interval_at`).
CacheView = tuple[
    int, int, float, int, int, 'array[int]', list[Sample | None], list[Interval | None]
]

_NS_PER_S = 1_000_000_000
_acos = math.acos
_sin = math.sin
_cos = math.cos
_VALUES = Struct('7d')
#: :meth:`TimeCache.interval_at` of an interval across a parent change (no interpolation).
_PARENT_CHANGE: Interval = (-1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0)
#: ``pack_values(tx, ty, tz, qx, qy, qz, qw)``: one sample's seven doubles, as a cache stores them.
pack_values = _VALUES.pack
#: The inverse of :data:`pack_values`.
unpack_values = _VALUES.unpack


class TransformStorage(NamedTuple):
    """One stored sample, in tf2's terms (used for inspection, not on the hot path)."""

    stamp_ns: int
    translation: tuple[float, float, float]
    rotation: tuple[float, float, float, float]
    parent_id: int
    child_id: int


#: Rows of :attr:`CacheArrays.intervals`, one column per interval between samples k and k + 1:
#: older translation (3), newer minus older translation (3), older rotation (4), newer rotation
#: with the slerp sign applied (4), slerp angle, ``1 / sin(angle)`` (0 for a zero angle), the
#: interval length in ns as a float, ``cos(angle) / sin(angle)`` (0 for a zero angle), and
#: ``newer / sin(angle) - older * cot(angle)`` (4; the sine coefficient of the slerp).
INTERVAL_COLUMNS = 22


class CacheArrays(NamedTuple):
    """A :class:`TimeCache`'s live samples as numpy arrays, with per-interval constants."""

    #: ``(K,)`` ascending stamps.
    stamps: npt.NDArray[np.int64]
    #: ``(7, K)``: one contiguous row per component (tx, ty, tz, qx, qy, qz, qw).
    values: npt.NDArray[np.float64]
    #: ``(K,)`` parent ids.
    parents: npt.NDArray[np.int64]
    #: ``(INTERVAL_COLUMNS, K - 1)`` lerp / slerp constants, one contiguous row each.
    intervals: npt.NDArray[np.float64]
    #: Some interval has a zero slerp angle (its rotation is the older one, as tf2).
    any_still: bool
    #: Some interval changes parent (no interpolation across it).
    any_parent_change: bool
    #: Largest slerp angle of any interval (0 when there is none).
    max_theta: float


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


def _stored_sample(values: Sequence[float], parent_id: int) -> Sample:
    """Return seven inserted values as the sample tf2 stores (rotation canonicalised)."""
    tx, ty, tz, x, y, z, w = values
    qx, qy, qz, qw = canonical_quat((x, y, z, w))
    return (tx, ty, tz, qx, qy, qz, qw, parent_id)


def _older_index(  # noqa: PLR0917 (hot path: positional arguments are fastest)
    stamps: array[int], time_ns: int, start: int, end: int, earliest: int, latest: int
) -> int:
    """
    Return the last index in ``[start, end)`` whose stamp is <= ``time_ns`` (interior times).

    Streams are usually evenly spaced, so a linear guess lands on the answer or next to it;
    bisection only narrows what the guess missed.
    """
    guess = start + (time_ns - earliest) * (end - 1 - start) // (latest - earliest)
    if stamps[guess] <= time_ns:
        if stamps[guess + 1] > time_ns:
            return guess
        return bisect_right(stamps, time_ns, guess + 1, end) - 1
    return bisect_right(stamps, time_ns, start, guess) - 1


class TimeCache:
    """History of one dynamic link, with tf2's ordering, pruning and interpolation."""

    is_static: ClassVar[Literal[False]] = False

    __slots__ = (
        '_arrays',
        '_intervals',
        '_max_storage_ns',
        '_parents',
        '_samples',
        '_stamps',
        '_start',
        '_values',
        '_view',
        'child_id',
        'latest',
    )

    def __init__(self, max_storage_ns: int = DEFAULT_CACHE_TIME_NS, child_id: int = 0) -> None:
        self._max_storage_ns = max_storage_ns
        self.child_id = child_id
        self._stamps: array[int] = array('q')
        #: Seven doubles per sample: translation, rotation as inserted.
        self._values: array[float] = array('d')
        self._parents: array[int] = array('q')
        #: Each sample as tf2 stores it, None until first read (:meth:`sample_at`).  This list
        #: and the next may be shorter than the stamps: what is past their end is None too
        #: (an insert at the end does not touch them; :meth:`view` extends them).
        self._samples: list[Sample | None] = []
        #: Per interval to the next sample, its interpolation constants (:meth:`interval_at`),
        #: or None.
        self._intervals: list[Interval | None] = []
        self._start = 0
        self._view: CacheView | None = None
        #: ``(newest stamp, its parent id)``, ``(0, 0)`` when empty (tf2 getLatestTimeAndParent).
        self.latest: tuple[int, int] = (0, 0)
        self._arrays: CacheArrays | None = None

    # --- insertion -----------------------------------------------------------------------

    def insert(self, stamp_ns: int, sample: Sample) -> bool:
        """
        Insert ``sample`` = ``(tx, ty, tz, qx, qy, qz, qw, parent_id)`` at ``stamp_ns``, as is.

        The sample is stored as given (its rotation already as tf2 stores it); see
        :meth:`insert_raw` for the rules.
        """
        return self.insert_raw(stamp_ns, pack_values(*sample[:7]), sample[7], sample)

    def insert_raw(
        self, stamp_ns: int, values: bytes, parent_id: int, sample: Sample | None = None
    ) -> bool:
        """
        Insert one sample given as :func:`pack_values` bytes with an inserted (raw) rotation.

        This is tf2's ``insertData``: prune first (relative to the newest stamp before the
        insert), reject data older than ``newest - max_storage``, drop exact duplicates (equal
        as tf2 stores them).  The rotation is canonicalised when the sample is first read;
        ``sample``, when given, is that canonical form already.

        :returns: False when the stamp is too old (tf2's TF_OLD_DATA case); True otherwise,
            including for a silently dropped exact duplicate.
        """
        self._view = self._arrays = None
        stamps = self._stamps
        start = self._start
        end = len(stamps)
        if start < end:
            latest = stamps[end - 1]
            oldest_kept = latest - self._max_storage_ns
            if stamps[start] < oldest_kept:
                start += 1  # a steady stream drops one sample per insert
                if start < end and stamps[start] < oldest_kept:
                    start = bisect_left(stamps, oldest_kept, start, end)
                self._start = start
                if start > 32 and 4 * start > end:
                    del stamps[:start]
                    del self._values[: 7 * start]
                    del self._parents[:start]
                    del self._samples[:start]
                    del self._intervals[:start]
                    end -= start
                    start = self._start = 0
            position = end
            if stamp_ns <= latest:
                if stamp_ns < oldest_kept:
                    return False
                if stamp_ns < latest:
                    position = bisect_right(stamps, stamp_ns, start, end)
                index = position - 1
                if index >= start and stamps[index] == stamp_ns:
                    if sample is None:
                        sample = _stored_sample(unpack_values(values), parent_id)
                    while index >= start and stamps[index] == stamp_ns:
                        if self.sample_at(index) == sample:
                            return True
                        index -= 1
        else:
            position = end
        if position == end:
            stamps.append(stamp_ns)
            self._values.frombytes(values)
            self._parents.append(parent_id)
            self.latest = (stamp_ns, parent_id)
            if sample is not None:
                self._memos_up_to(position)
                self._samples[position] = sample
            return True
        stamps.insert(position, stamp_ns)
        self._values[7 * position : 7 * position] = array('d', values)
        self._parents.insert(position, parent_id)
        samples = self._samples
        if position < len(samples) or sample is not None:
            self._memos_up_to(position - 1)
            samples.insert(position, sample)
            intervals = self._intervals
            intervals.insert(position, None)
            if position:
                intervals[position - 1] = None  # that interval now ends at the new sample
        return True

    def _memos_up_to(self, index: int) -> None:
        """Make the memo lists reach ``index`` (and the stamps' end, at most)."""
        size = min(index + 1, len(self._stamps))
        for memos in (self._samples, self._intervals):
            if len(memos) < size:
                memos.extend([None] * (size - len(memos)))

    def clear(self) -> None:
        """Drop every sample (tf2 clearList)."""
        self._stamps = array('q')
        self._values = array('d')
        self._parents = array('q')
        self._samples = []
        self._intervals = []
        self._start = 0
        self._view = self._arrays = None
        self.latest = (0, 0)

    # --- queries -------------------------------------------------------------------------

    @property
    def mixed(self) -> bool:
        """Whether the held samples have more than one parent (a scan: for planning only)."""
        parents = self._parents
        start = self._start
        return parents[start:].count(parents[-1]) != len(parents) - start if parents else False

    def sample_at(self, index: int) -> Sample:
        """Return the sample at ``index`` of the storage as tf2 stores it (made once)."""
        samples = self._samples
        if index >= len(samples):
            self._memos_up_to(index)
        sample = samples[index]
        if sample is None:
            offset = 7 * index
            sample = samples[index] = _stored_sample(
                self._values[offset : offset + 7], self._parents[index]
            )
        return sample

    def interval_at(self, index: int) -> Interval:
        """
        Return the constants of tf2's interpolation from sample ``index`` to the next (made once).

        ``(theta, dx, dy, dz, bx, by, bz, bw)``: tf2's ``slerp`` angle (``acos`` of the clamped
        absolute dot product, its shortest path), the newer minus the older translation, and
        the sine coefficient ``b = newer / sin(theta) - older * cot(theta)`` (the newer rotation
        negated when the dot product is negative; 0 for a zero angle), so that at ``ratio``
        the translation is ``older + ratio * d`` and the rotation ``older * cos(ratio * theta)
        + b * sin(ratio * theta)``, tf2's slerp by the sine of a difference.  The same
        constants as :attr:`CacheArrays.intervals`.  A negative ``theta`` marks a parent change:
        no interpolation, the older sample as it is.
        """
        tx0, ty0, tz0, px, py, pz, pw, parent = self.sample_at(index)
        tx1, ty1, tz1, x1, y1, z1, w1, parent1 = self.sample_at(index + 1)
        if parent1 != parent:
            interval = _PARENT_CHANGE
        else:
            dot = px * x1 + py * y1 + pz * z1 + pw * w1
            magnitude = -dot if dot < 0 else dot
            theta = _acos(magnitude if magnitude < 1.0 else 1.0)
            if theta != 0.0:
                d = 1.0 / _sin(theta)
                d1 = -d if dot < 0 else d
                cot = _cos(theta) * d
                b = (
                    x1 * d1 - px * cot,
                    y1 * d1 - py * cot,
                    z1 * d1 - pz * cot,
                    w1 * d1 - pw * cot,
                )
            else:
                b = (0.0, 0.0, 0.0, 0.0)
            interval = (theta, tx1 - tx0, ty1 - ty0, tz1 - tz0, *b)
        self._intervals[index] = interval
        return interval

    def view(self) -> CacheView:
        """
        Return (and keep until the next insert or clear) the walk's snapshot of this cache.

        ``(earliest, latest, scale, start, last, stamps, samples, intervals)``: the oldest and
        newest stamps (``1, 0`` when empty, so that no time is inside), ``(last - start) /
        (latest - earliest)`` for a first guess of the interval, and the live index range
        ``[start, last]`` of the stamp array, the sample list (an entry not read yet is None:
        :meth:`sample_at` makes it) and the interval list (likewise, :meth:`interval_at`).
        """
        view = self._view
        if view is None:
            stamps = self._stamps
            start = self._start
            last = len(stamps) - 1
            self._memos_up_to(last)
            samples = self._samples
            if start > last:
                view = (1, 0, 0.0, start, last, stamps, samples, self._intervals)
            else:
                earliest = stamps[start]
                latest = stamps[last]
                scale = (last - start) / (latest - earliest) if latest != earliest else 0.0
                view = (earliest, latest, scale, start, last, stamps, samples, self._intervals)
            self._view = view
        return view

    def get_data(self, time_ns: int) -> Sample | None:
        """
        Return the (possibly interpolated) sample at ``time_ns`` (0 = newest), or None.

        This is tf2's ``findClosest`` plus ``interpolate``: :func:`~tf_demo.core.math3d.lerp` of
        the translation, :func:`~tf_demo.core.math3d.slerp` of the rotation, never across a
        parent change (the older sample is returned instead).  The lookup walk inlines the same
        step (``links.accumulate_links``).  Use :meth:`explain_failure` for tf2's error
        text when None is returned.
        """
        stamps = self._stamps
        end = len(stamps)
        start = self._start
        if start == end:
            return None
        if time_ns == 0:
            return self.sample_at(end - 1)
        latest = stamps[end - 1]
        if time_ns >= latest:
            return self.sample_at(end - 1) if time_ns == latest else None
        earliest = stamps[start]
        if time_ns <= earliest:
            return self.sample_at(start) if time_ns == earliest else None
        index = _older_index(stamps, time_ns, start, end, earliest, latest)
        one = self.sample_at(index)
        two = self.sample_at(index + 1)
        tx0, ty0, tz0, x0, y0, z0, w0, parent = one
        tx1, ty1, tz1, x1, y1, z1, w1, parent1 = two
        if parent1 != parent:
            return one
        one_stamp = stamps[index]
        ratio = float(time_ns - one_stamp) / float(stamps[index + 1] - one_stamp)
        tx, ty, tz = lerp((tx0, ty0, tz0), (tx1, ty1, tz1), ratio)
        x, y, z, w = slerp((x0, y0, z0, w0), (x1, y1, z1, w1), ratio)
        return (tx, ty, tz, x, y, z, w, parent)

    def get_parent(self, time_ns: int) -> int:
        """Return the parent id at ``time_ns`` (older neighbour's parent), or 0 on failure."""
        stamps = self._stamps
        end = len(stamps)
        start = self._start
        if start == end:
            return 0
        if time_ns == 0:
            return self._parents[end - 1]
        latest = stamps[end - 1]
        if time_ns >= latest:
            return self._parents[end - 1] if time_ns == latest else 0
        earliest = stamps[start]
        if time_ns <= earliest:
            return self._parents[start] if time_ns == earliest else 0
        return self._parents[_older_index(stamps, time_ns, start, end, earliest, latest)]

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
        return self.latest

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
        return [
            TransformStorage(
                self._stamps[index],
                (s[0], s[1], s[2]),
                (s[3], s[4], s[5], s[6]),
                s[7],
                self.child_id,
            )
            for index in range(len(self._stamps) - 1, self._start - 1, -1)
            for s in (self.sample_at(index),)
        ]

    def arrays(self) -> CacheArrays:
        """
        Return the live samples as numpy arrays, ascending by stamp (for the batch walk).

        Kept until the next change (insert, prune, clear); treat them as read-only.  The
        interval constants are the batch walk's slerp, pinned to :func:`math3d.slerp
        <tf_demo.core.math3d.slerp>` by ``test/core/test_math3d_inlined.py``.
        """
        cached = self._arrays
        if cached is not None:
            return cached
        start = self._start
        stamps = np.array(self._stamps[start:], dtype=np.int64)
        table = np.array(self._values[7 * start :], dtype=np.float64).reshape(-1, 7)
        canonical_quat_batch(table[:, 3:], out=table[:, 3:])
        for row, sample in enumerate(self._samples[start:]):
            if sample is not None:  # stored as given (insert), or read already: the same bits
                table[row] = sample[:7]
        values = np.ascontiguousarray(table.T)
        parents = np.array(self._parents[start:], dtype=np.int64)
        count = stamps.shape[0]
        intervals = np.empty((INTERVAL_COLUMNS, max(count - 1, 0)))
        q0 = values[3:, :-1]
        q1 = values[3:, 1:]
        dot = np.einsum('ij,ij->j', q0, q1)
        theta = np.arccos(np.minimum(np.abs(dot), 1.0))
        intervals[0:3] = values[:3, :-1]
        intervals[3:6] = values[:3, 1:] - values[:3, :-1]
        intervals[6:10] = q0
        intervals[10:14] = q1 * np.where(dot < 0, -1.0, 1.0)
        intervals[14] = theta
        with np.errstate(divide='ignore'):
            intervals[15] = np.where(theta != 0.0, 1.0 / np.sin(theta), 0.0)
        intervals[16] = np.diff(stamps).astype(np.float64)
        intervals[17] = np.cos(theta) * intervals[15]
        intervals[18:22] = intervals[10:14] * intervals[15] - q0 * intervals[17]
        arrays = CacheArrays(
            stamps,
            values,
            parents,
            intervals,
            bool((theta == 0.0).any()),
            bool((parents[1:] != parents[:-1]).any()),
            float(theta.max()) if theta.size else 0.0,
        )
        self._arrays = arrays
        return arrays


class StaticCache:
    """A static link: one sample, valid at every time (tf2 StaticCache)."""

    is_static: ClassVar[Literal[True]] = True

    __slots__ = ('_sample', 'child_id', 'latest')

    def __init__(self, child_id: int = 0) -> None:
        self.child_id = child_id
        self._sample: Sample = (0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0)
        #: ``(0, parent id)``: static links impose no time constraint.
        self.latest: tuple[int, int] = (0, 0)

    def insert(self, stamp_ns: int, sample: Sample) -> bool:
        """Overwrite the stored sample (the stamp is ignored); always succeeds."""
        del stamp_ns
        self._sample = sample
        self.latest = (0, sample[7])
        return True

    def insert_raw(
        self, stamp_ns: int, values: bytes, parent_id: int, sample: Sample | None = None
    ) -> bool:
        """Overwrite the stored sample with :func:`pack_values` bytes (rotation canonicalised)."""
        return self.insert(stamp_ns, sample or _stored_sample(unpack_values(values), parent_id))

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
        return self.latest

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
