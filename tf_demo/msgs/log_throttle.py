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
Throttled reports of bad samples: the first of each writer in full, then a count per period.

A node that logs one line per malformed or rejected sample can be made to write thousands of
lines a second by any writer on the network. :class:`PerWriterThrottle` decides what to log:
the first bad sample of a writer (and kind) is logged with its full text, the following ones
are counted, and once ``period_ns`` has passed since the last line the next bad sample logs
``<n> more <what> from <writer> in the last <s> s; the latest: <text>``.
:meth:`PerWriterThrottle.pending` gives the counts not yet logged (for a final line at
shutdown). Decoding (transport) and the tf listener and buffer (ros) share it, which is why it
lives here, below both.
"""

from __future__ import annotations

from collections.abc import Callable
import threading
import time

#: How often a writer that keeps sending bad samples gets a count line.
THROTTLE_PERIOD_NS = 5_000_000_000
#: Writers remembered at most (then the oldest is forgotten: its next sample is logged in full).
MAX_WRITERS = 256
#: The latest text quoted in a count line is cut to this many characters.
MAX_QUOTED = 300
_GID_SIZE = 16

#: What a writer is known by: its 16-byte DDS GUID (rmw's gid), or a description.
Writer = bytes | str


def writer_name(writer: Writer) -> str:
    """Return how to name ``writer``: a GUID as ``ros2 topic info -v`` prints gids."""
    if isinstance(writer, bytes):
        if len(writer) == _GID_SIZE:
            return 'writer ' + '.'.join(f'{byte:02x}' for byte in writer)
        return 'writer ' + (writer.hex() or '(no gid)')
    return writer


class _Count:
    """Bad samples of one (writer, kind) since its last logged line."""

    __slots__ = ('count', 'latest', 'since_ns')

    def __init__(self, since_ns: int) -> None:
        self.since_ns = since_ns
        self.count = 0
        self.latest = ''


def _quoted(text: str) -> str:
    return text if len(text) <= MAX_QUOTED else text[:MAX_QUOTED] + '...'


class PerWriterThrottle:
    """Decide which bad-sample lines to log: thread-safe, bounded, with an injectable clock."""

    def __init__(
        self,
        what: str,
        *,
        period_ns: int = THROTTLE_PERIOD_NS,
        clock_ns: Callable[[], int] = time.monotonic_ns,
        max_writers: int = MAX_WRITERS,
    ) -> None:
        """
        Create an empty throttle.

        :param what: what a count line counts, e.g. ``'malformed samples'``.
        :param period_ns: at most one count line per writer and kind in this time.
        :param clock_ns: a monotonic clock in nanoseconds.
        :param max_writers: how many (writer, kind) pairs to remember.
        """
        self.what = what
        self.period_ns = period_ns
        self._clock_ns = clock_ns
        self._max_writers = max_writers
        self._counts: dict[tuple[Writer, str], _Count] = {}
        self._lock = threading.Lock()

    def line(self, writer: Writer, text: str, kind: str = '') -> str | None:
        """
        Record one bad sample from ``writer`` and return the line to log now, or None.

        :param writer: who sent it (a GUID or a description).
        :param text: the full report of this sample; returned as it is for the first one.
        :param kind: a finer key (e.g. tf2's ``TF_NAN_INPUT``): each kind's first is logged.
        """
        key = (writer, kind)
        now_ns = self._clock_ns()
        with self._lock:
            entry = self._counts.get(key)
            if entry is None:
                if len(self._counts) >= self._max_writers:
                    del self._counts[next(iter(self._counts))]
                self._counts[key] = _Count(now_ns)
                return text
            entry.count += 1
            entry.latest = text
            if now_ns - entry.since_ns < self.period_ns:
                return None
            summary = self._summary(key, entry, now_ns)
            entry.count = 0
            entry.since_ns = now_ns
            return summary

    def pending(self) -> list[str]:
        """Return the count lines of bad samples not reported yet, and forget them."""
        now_ns = self._clock_ns()
        with self._lock:
            lines = [
                self._summary(key, entry, now_ns)
                for key, entry in self._counts.items()
                if entry.count
            ]
            for entry in self._counts.values():
                entry.count = 0
                entry.since_ns = now_ns
        return lines

    def _summary(self, key: tuple[Writer, str], entry: _Count, now_ns: int) -> str:
        writer, kind = key
        what = f'{self.what} ({kind})' if kind else self.what
        seconds = (now_ns - entry.since_ns) / 1e9
        return (
            f'{entry.count} more {what} from {writer_name(writer)} in the last '
            f'{seconds:.1f} s; the latest: {_quoted(entry.latest)}'
        )
