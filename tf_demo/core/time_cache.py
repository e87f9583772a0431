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

Storage is compact, in ascending stamp order: a list of stamps (which compiled code reads
without allocating), typed arrays of seven doubles per sample (translation, then the rotation *as
inserted*) and of int64 parent ids, plus a list that memoises each sample as tf2 stores it
(:data:`Sample`, rotation normalised and sign-canonicalised bit for bit by
:func:`~tf_demo.core.math3d.canonical_quat`), made the first time a lookup reads it.  Most
samples of a busy ``/tf`` are never read: they cost about 120 bytes and no canonicalisation.
Among equal stamps the most recently inserted sample comes last.  This is tf2's newest-first
``std::list`` read backwards, so every tie-breaking rule of tf2 carries over:

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
from struct import Struct
from typing import Final
from typing import final
from typing import NamedTuple
from typing import TYPE_CHECKING

from tf_demo.core.math3d import canonical_quat
from tf_demo.core.math3d import lerp
from tf_demo.core.math3d import slerp

if TYPE_CHECKING:
    from collections.abc import Sequence

__all__ = [
    'DEFAULT_CACHE_TIME_NS',
    'ERROR_BACKWARD_EXTRAPOLATION',
    'ERROR_CONNECTIVITY',
    'ERROR_EXTRAPOLATION',
    'ERROR_FORWARD_EXTRAPOLATION',
    'ERROR_LOOKUP',
    'ERROR_NO_DATA_FOR_EXTRAPOLATION',
    'Link',
    'Sample',
    'StaticCache',
    'StoredSample',
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

#: A sample as tf2 stores it: translation, rotation (normalised, canonical sign), parent id.
Sample = tuple[float, float, float, float, float, float, float, int]

_NS_PER_S: Final = 1_000_000_000
_VALUES: Final = Struct('7d')
#: ``pack_values(tx, ty, tz, qx, qy, qz, qw)``: one sample's seven doubles, as a cache stores them.
pack_values: Final = _VALUES.pack
#: The inverse of :data:`pack_values`.
unpack_values: Final = _VALUES.unpack


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


def _stored_sample(values: Sequence[float], parent_id: int) -> Sample:
    """Return seven inserted values as the sample tf2 stores (rotation canonicalised)."""
    tx, ty, tz, x, y, z, w = values
    qx, qy, qz, qw = canonical_quat((x, y, z, w))
    return (tx, ty, tz, qx, qy, qz, qw, parent_id)


@final
class StoredSample:
    """A :data:`Sample` kept by a cache once read: its fields are unboxed in the compiled build."""

    __slots__ = ('parent_id', 'qw', 'qx', 'qy', 'qz', 'tx', 'ty', 'tz')

    def __init__(self, sample: Sample) -> None:
        self.tx, self.ty, self.tz, self.qx, self.qy, self.qz, self.qw, self.parent_id = sample

    def as_tuple(self) -> Sample:
        """Return the sample as a tuple."""
        return (self.tx, self.ty, self.tz, self.qx, self.qy, self.qz, self.qw, self.parent_id)


def _interval(  # noqa: PLR0917 (hot path: positional arguments are fastest)
    stamps: list[int], time_ns: int, start: int, end: int, earliest: int, latest: int
) -> tuple[int, int, int]:
    """
    Return the interval of ``[start, end)`` that holds ``time_ns`` (an interior time).

    ``(index, older stamp, newer stamp)``: the last index whose stamp is <= ``time_ns``, its
    stamp and the next one.  Streams are usually evenly spaced, so a linear guess lands on the
    answer or next to it; bisection only narrows what the guess missed.  The guess is made in
    doubles: products of nanosecond stamps overflow the machine integers of compiled code.
    """
    guess = start + int(
        float(time_ns - earliest) * float(end - 1 - start) / float(latest - earliest)
    )
    guess = min(guess, end - 2)  # rounding, next to the newest stamp
    older = stamps[guess]
    if older <= time_ns:
        newer = stamps[guess + 1]
        if newer > time_ns:
            return guess, older, newer
        index = bisect_right(stamps, time_ns, guess + 1, end) - 1
    else:
        index = bisect_right(stamps, time_ns, start, guess) - 1
    return index, stamps[index], stamps[index + 1]


class Link:
    """
    What the walk asks of a link's history: :class:`TimeCache` (dynamic) or :class:`StaticCache`.

    :meth:`covers` says whether the link has data at a time and :meth:`sample_at_time` gives
    it; the walk (:mod:`~tf_demo.core.links`) composes what they return.
    """

    __slots__ = ('child_id', 'is_static', 'latest')

    def __init__(self, child_id: int, is_static: bool) -> None:
        self.child_id = child_id
        #: Whether the link is static (one sample, valid at every time).
        self.is_static = is_static
        #: ``(newest stamp, its parent id)``, ``(0, 0)`` when empty (tf2 getLatestTimeAndParent);
        #: static links: ``(0, parent id)``.
        self.latest: tuple[int, int] = (0, 0)

    def covers(self, time_ns: int) -> bool:
        """Return whether the link has data at ``time_ns`` (0: the newest)."""
        raise NotImplementedError

    def sample_at_time(self, time_ns: int) -> Sample:
        """Return the (possibly interpolated) sample at ``time_ns``, which :meth:`covers`."""
        raise NotImplementedError

    def get_data(self, time_ns: int) -> Sample | None:
        """Return the (possibly interpolated) sample at ``time_ns`` (0 = newest), or None."""
        return self.sample_at_time(time_ns) if self.covers(time_ns) else None


class TimeCache(Link):
    """History of one dynamic link, with tf2's ordering, pruning and interpolation."""

    __slots__ = (
        '_max_storage_ns',
        '_newest',
        '_oldest',
        '_parents',
        '_samples',
        '_stamps',
        '_start',
        '_values',
        'arrays_memo',
    )

    def __init__(self, max_storage_ns: int = DEFAULT_CACHE_TIME_NS, child_id: int = 0) -> None:
        super().__init__(child_id, False)
        self._max_storage_ns = max_storage_ns
        #: Ascending stamps: a list, whose reads compiled code takes without allocating.
        self._stamps: list[int] = []
        #: Seven doubles per sample: translation, rotation as inserted.
        self._values: array[float] = array('d')
        self._parents: array[int] = array('q')
        #: Each sample as tf2 stores it, None until first read (:meth:`sample_at`).  This list
        #: may be shorter than the stamps: what is past its end is None too (an insert at the
        #: end does not touch it).
        self._samples: list[StoredSample | None] = []
        self._start = 0
        #: The oldest and newest live stamps (``1, 0`` when empty: no time lies between them).
        self._oldest = 1
        self._newest = 0
        #: What the batch walk made of the live samples (numpy arrays), None after any change.
        self.arrays_memo: object = None

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
        self.arrays_memo = None
        stamps = self._stamps
        start = self._start
        end = len(stamps)
        if start < end:
            latest = self._newest
            oldest_kept = latest - self._max_storage_ns
            if self._oldest < oldest_kept:
                start += 1  # a steady stream drops one sample per insert
                if start < end and stamps[start] < oldest_kept:
                    start = bisect_left(stamps, oldest_kept, start, end)
                self._start = start
                if start < end:
                    self._oldest = stamps[start]
                if start > 32 and 4 * start > end:
                    del stamps[:start]
                    del self._values[: 7 * start]
                    del self._parents[:start]
                    del self._samples[:start]
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
                        if self._stored(index).as_tuple() == sample:
                            return True
                        index -= 1
        else:
            position = end
        if position == end:
            stamps.append(stamp_ns)
            self._values.frombytes(values)
            self._parents.append(parent_id)
            self.latest = (stamp_ns, parent_id)
            self._newest = stamp_ns
            if start == end:  # the only live sample (a prune may have dropped all others)
                self._oldest = stamp_ns
            if sample is not None:
                self._memos_up_to(position)
                self._samples[position] = StoredSample(sample)
            return True
        stamps.insert(position, stamp_ns)
        self._values[7 * position : 7 * position] = array('d', values)
        self._parents.insert(position, parent_id)
        if position == start:
            self._oldest = stamp_ns
        samples = self._samples
        if position < len(samples) or sample is not None:
            self._memos_up_to(position - 1)
            samples.insert(position, None if sample is None else StoredSample(sample))
        return True

    def _memos_up_to(self, index: int) -> None:
        """Make the sample memo list reach ``index`` (and the stamps' end, at most)."""
        samples = self._samples
        size = min(index + 1, len(self._stamps))
        if len(samples) < size:
            samples.extend([None] * (size - len(samples)))

    def clear(self) -> None:
        """Drop every sample (tf2 clearList)."""
        self._stamps = []
        self._values = array('d')
        self._parents = array('q')
        self._samples = []
        self._start = 0
        self._oldest = 1
        self._newest = 0
        self.arrays_memo = None
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
        return self._stored(index).as_tuple()

    def _stored(self, index: int) -> StoredSample:
        """Return the sample at ``index`` of the storage, made (canonicalised) on first read."""
        samples = self._samples
        if index >= len(samples):
            self._memos_up_to(index)
        stored = samples[index]
        if stored is None:
            offset = 7 * index
            stored = samples[index] = StoredSample(
                _stored_sample(self._values[offset : offset + 7], self._parents[index])
            )
        return stored

    def covers(self, time_ns: int) -> bool:
        """Return whether the cache has data at ``time_ns`` (0: the newest; tf2's findClosest)."""
        if self._start == len(self._stamps):
            return False
        return not time_ns or self._oldest <= time_ns <= self._newest

    def sample_at_time(self, time_ns: int) -> Sample:
        """
        Return the (possibly interpolated) sample at ``time_ns``, which :meth:`covers`.

        This is tf2's ``findClosest`` plus ``interpolate``: :func:`~tf_demo.core.math3d.lerp` of
        the translation, :func:`~tf_demo.core.math3d.slerp` of the rotation, never across a
        parent change (the older sample is returned instead).  Among equal stamps, the newest
        stamp gives the newest-inserted sample and the oldest the first-inserted (tf2's list).
        """
        stamps = self._stamps
        last = len(stamps) - 1
        latest = self._newest
        if time_ns == 0 or time_ns >= latest:
            return self.sample_at(last)
        start = self._start
        earliest = self._oldest
        if time_ns <= earliest:
            return self.sample_at(start)
        index, one_stamp, two_stamp = _interval(stamps, time_ns, start, last + 1, earliest, latest)
        one = self._stored(index)
        two = self._stored(index + 1)
        if two.parent_id != one.parent_id:
            return one.as_tuple()
        ratio = float(time_ns - one_stamp) / float(two_stamp - one_stamp)
        tx, ty, tz = lerp((one.tx, one.ty, one.tz), (two.tx, two.ty, two.tz), ratio)
        x, y, z, w = slerp(
            (one.qx, one.qy, one.qz, one.qw), (two.qx, two.qy, two.qz, two.qw), ratio
        )
        return (tx, ty, tz, x, y, z, w, one.parent_id)

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
        return self._parents[_interval(stamps, time_ns, start, end, earliest, latest)[0]]

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
        return self._newest if self._start < len(self._stamps) else 0

    @property
    def oldest_stamp_ns(self) -> int:
        """Oldest stamp still held, 0 when empty."""
        return self._oldest if self._start < len(self._stamps) else 0

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

    def live_storage(
        self,
    ) -> tuple[list[int], array[float], array[int], list[StoredSample | None]]:
        """
        Return copies of the live samples' storage: stamps, values, parents and memos.

        For the batch walk (:func:`tf_demo.core._batch.cache_arrays`), which keeps what it makes
        of them in :attr:`arrays_memo`.
        """
        start = self._start
        return (
            self._stamps[start:],
            self._values[7 * start :],
            self._parents[start:],
            self._samples[start:],
        )


class StaticCache(Link):
    """A static link: one sample, valid at every time (tf2 StaticCache)."""

    __slots__ = ('_sample',)

    def __init__(self, child_id: int = 0) -> None:
        super().__init__(child_id, True)
        self._sample: Sample = (0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0)

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

    def covers(self, time_ns: int) -> bool:
        """Return True: a static link has data at every time."""
        del time_ns
        return True

    def sample_at_time(self, time_ns: int) -> Sample:
        """Return the stored sample, whatever the time."""
        del time_ns
        return self._sample

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
