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
Pure formatters for tf2's frame dumps: ``allFramesAsString``, ``allFramesAsYAML``, DOT.

They take snapshots of the buffer (:class:`FrameInfo` records in frame-id order) and return the
exact text tf2 Jazzy produces, odd spacing and the "recieved" typo included.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import NamedTuple

from tf_demo.core.time_cache import display_time_point
from tf_demo.core.time_cache import duration_to_sec

__all__ = [
    'NO_AUTHORITY',
    'FrameInfo',
    'all_frames_as_dot',
    'all_frames_as_string',
    'all_frames_as_yaml',
    'rate_hz',
]

NO_AUTHORITY = 'no recorded authority'
_MIN_RATE_WINDOW_NS = 100_000


class FrameInfo(NamedTuple):
    """
    What the buffer knows about one child frame (a frame that has a cache).

    ``parent`` is the parent of the newest sample, or None when the cache is empty (after
    ``clear()``).  Static frames report stamps 0 and one sample.
    """

    child: str
    parent: str | None
    authority: str
    is_static: bool
    oldest_ns: int
    newest_ns: int
    sample_count: int


def rate_hz(info: FrameInfo) -> float:
    """Return tf2's average publishing rate: samples per second over at least 100 us."""
    window = info.newest_ns - info.oldest_ns
    window = max(_MIN_RATE_WINDOW_NS, window)
    return (info.sample_count * 1e9) / float(window)


def all_frames_as_string(frames: Sequence[FrameInfo]) -> str:
    """Return ``Frame <child> exists with parent <parent>.`` lines (``NO_PARENT`` if empty)."""
    return ''.join(
        f'Frame {info.child} exists with parent {info.parent or "NO_PARENT"}.\n' for info in frames
    )


class _FrameNumbers(NamedTuple):
    """The numbers tf2's YAML and DOT dumps print about one frame, as both print them."""

    rate: str
    """Average publishing rate (Hz), see :func:`rate_hz`."""
    newest: str
    """Stamp of the newest sample (s)."""
    oldest: str
    """Stamp of the oldest sample (s)."""
    delay: str | None
    """Age of the newest sample at the current time (s); None without a current time."""
    length: str
    """Time between the oldest and the newest sample (s)."""


def _frame_numbers(info: FrameInfo, current_time_ns: int) -> _FrameNumbers:
    """Return ``info``'s numbers; ``current_time_ns`` 0 means no current time (no delay)."""
    delay = None
    if current_time_ns != 0:
        delay = f'{duration_to_sec(current_time_ns - info.newest_ns):.3f}'
    return _FrameNumbers(
        rate=f'{rate_hz(info):.3f}',
        newest=display_time_point(info.newest_ns),
        oldest=display_time_point(info.oldest_ns),
        delay=delay,
        length=f'{duration_to_sec(info.newest_ns - info.oldest_ns):.3f}',
    )


def all_frames_as_yaml(
    frames: Sequence[FrameInfo], *, any_frame_known: bool, current_time_ns: int = 0
) -> str:
    """
    Return tf2's YAML dump; ``[]`` when no frame is known, ``''`` when none holds data.

    :param frames: the child frames in frame-id order.
    :param any_frame_known: whether the buffer has interned any frame name at all.
    :param current_time_ns: when non-zero, a ``transform_delay`` line is added per frame.
    """
    parts = [] if any_frame_known else ['[]']
    for info in frames:
        if info.parent is None:
            continue
        numbers = _frame_numbers(info, current_time_ns)
        parts.append(
            f'{info.child}: \n'
            f"  parent: '{info.parent}'\n"
            f"  broadcaster: '{info.authority}'\n"
            f'  rate: {numbers.rate}\n'
            f'  most_recent_transform: {numbers.newest}\n'
            f'  oldest_transform: {numbers.oldest}\n'
        )
        if numbers.delay is not None:
            parts.append(f'  transform_delay: {numbers.delay}\n')
        parts.append(f'  buffer_length: {numbers.length}\n')
    return ''.join(parts)


def all_frames_as_dot(
    frames: Sequence[tuple[str, FrameInfo | None]], *, current_time_ns: int = 0
) -> str:
    """
    Return tf2's ``_allFramesAsDot`` graph.

    :param frames: every known frame in frame-id order, paired with its :class:`FrameInfo`, or
        None for frames without a cache (roots).
    :param current_time_ns: when non-zero, ages and a "Recorded at time" legend are added.
    """
    parts = ['digraph G {\n']
    if not frames:
        parts.append('"no tf data recieved"')
    for _, info in frames:
        if info is None or info.parent is None:
            continue
        numbers = _frame_numbers(info, current_time_ns)
        parts.append(
            f'"{info.parent}" -> "{info.child}"[label="Broadcaster: {info.authority}\\n'
            f'Average rate: {numbers.rate} Hz\\n'
            f'Most recent transform: {numbers.newest} '
        )
        if numbers.delay is not None:
            parts.append(f'( {numbers.delay} sec old)')
        parts.append(f'\\nBuffer length: {numbers.length} sec\\n"];\n')
    legend_head = (
        'edge [style=invis];\n'
        ' subgraph cluster_legend { style=bold; color=black; label ="view_frames Result";\n'
    )
    recorded = f'"Recorded at time: {display_time_point(current_time_ns)}"[ shape=plaintext ] ;\n '
    for name, info in frames:
        if info is None:
            if current_time_ns != 0:
                parts.append(f'{legend_head}{recorded}}}->"{name}";\n')
            continue
        if info.parent is None:
            parts.append(legend_head)
            if current_time_ns != 0:
                parts.append(recorded)
            parts.append(f'}}->"{name}";\n')
    parts.append('}')
    return ''.join(parts)
