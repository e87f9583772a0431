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
What tf_plot draws: one transform looked up at evenly spaced times, and where the lookup failed.

:func:`sample_track` asks a :class:`~tf_demo.core.buffer_core.BufferCore` for ``target_T_source``
at every sample time, as ``tf_echo --bag`` does one instant at a time, and keeps the pose (x, y,
z and tf2_echo's roll, pitch, yaw) of each success and tf2's error of each failure. Consecutive
failures with the same error (tf2's exception and its first sentence: the times it quotes change
from sample to sample) become one :class:`FailureSpan`.
"""

from __future__ import annotations

from dataclasses import dataclass
import math

import numpy as np
import numpy.typing as npt
from tf_demo.core.buffer_core import BufferCore
from tf_demo.core.exceptions import ConnectivityException
from tf_demo.core.exceptions import ExtrapolationException
from tf_demo.core.exceptions import InvalidArgumentException
from tf_demo.core.exceptions import LookupException
from tf_demo.core.exceptions import TimeoutException
from tf_demo.core.exceptions import TransformException
from tf_demo.core.math3d import rpy_from_quat

#: Samples per second when none is asked for.
DEFAULT_RATE_HZ = 50.0
#: At most this many samples unless a rate is asked for (a long bag is sampled more coarsely).
DEFAULT_MAX_SAMPLES = 20_000
#: A track longer than this is refused (a hostile rate or an absurd time span).
MAX_SAMPLES = 2_000_000


@dataclass(frozen=True)
class FailureSpan:
    """Consecutive sample times at which the lookup failed with the same error."""

    start_ns: int
    end_ns: int
    error: str
    """tf2's message for the first failed sample of the span."""
    kind: str
    """tf2's exception (``ExtrapolationException``, ``LookupException`` ...)."""

    @property
    def label(self) -> str:
        """The exception and the first sentence of tf2's message (no sample-specific times)."""
        return f'{self.kind}: {first_sentence(self.error)}'


@dataclass(frozen=True)
class Track:
    """``target_T_source`` sampled every ``step_ns`` from ``start_ns`` (NaN where it failed)."""

    target: str
    source: str
    start_ns: int
    step_ns: int
    times_ns: npt.NDArray[np.int64]
    translations: npt.NDArray[np.float64]
    """(N, 3) metres."""
    rpy: npt.NDArray[np.float64]
    """(N, 3) roll, pitch, yaw in radians, as tf2_echo computes them."""
    failures: tuple[FailureSpan, ...]

    @property
    def succeeded(self) -> npt.NDArray[np.bool_]:
        """Which samples have a pose."""
        return ~np.isnan(self.translations[:, 0])

    @property
    def seconds(self) -> npt.NDArray[np.float64]:
        """The sample times in seconds since ``start_ns``."""
        return (self.times_ns - self.start_ns) / 1e9


#: tf2's exceptions (tf2_ros Python raises these; ours narrow extrapolation by direction).
TF2_EXCEPTIONS = (
    LookupException,
    ConnectivityException,
    ExtrapolationException,
    InvalidArgumentException,
    TimeoutException,
)


def tf2_exception_name(error: TransformException) -> str:
    """Return the name of the tf2 exception ``error`` is (``ExtrapolationException`` ...)."""
    return next(
        (kind.__name__ for kind in TF2_EXCEPTIONS if isinstance(error, kind)),
        type(error).__name__,
    )


def first_sentence(text: str) -> str:
    """Return ``text`` up to its first full stop (tf2 puts the details after it)."""
    head = text.split('. ', 1)[0].strip()
    return head.removesuffix('.')


def sample_times(
    start_ns: int, end_ns: int, rate_hz: float | None, max_samples: int = DEFAULT_MAX_SAMPLES
) -> range:
    """
    Return evenly spaced times from ``start_ns`` to ``end_ns`` (both included when they fit).

    ``rate_hz`` None: :data:`DEFAULT_RATE_HZ`, made coarser so that there are at most
    ``max_samples``.

    :raises ValueError: for a rate that is not a positive number, or more than
        :data:`MAX_SAMPLES` samples.
    """
    if end_ns < start_ns:
        msg = f'the end ({end_ns} ns) is before the start ({start_ns} ns)'
        raise ValueError(msg)
    span_ns = end_ns - start_ns
    if rate_hz is None:
        step_ns = max(round(1e9 / DEFAULT_RATE_HZ), -(-span_ns // max(1, max_samples - 1)))
    elif not (math.isfinite(rate_hz) and rate_hz > 0):
        msg = f'the rate must be a positive number of samples per second, not {rate_hz}'
        raise ValueError(msg)
    else:
        step_ns = max(1, round(1e9 / rate_hz))
    count = span_ns // step_ns + 1
    if count > MAX_SAMPLES:
        msg = (
            f'{count} samples ({span_ns / 1e9:g} s at {1e9 / step_ns:g} Hz) is more than '
            f'{MAX_SAMPLES}: ask for a lower rate'
        )
        raise ValueError(msg)
    return range(start_ns, end_ns + 1, step_ns)


def sample_track(core: BufferCore, target: str, source: str, times: range) -> Track:
    """Look ``target_T_source`` up at every time of ``times`` (see the module docstring)."""
    count = len(times)
    translations = np.full((count, 3), np.nan)
    rpy = np.full((count, 3), np.nan)
    failures: list[FailureSpan] = []
    open_span: tuple[int, str, str, str] | None = None  # start, key, error, kind
    for index, time_ns in enumerate(times):
        try:
            result = core.lookup_transform(target, source, time_ns)
        except TransformException as error:
            kind = tf2_exception_name(error)
            key = f'{kind}: {first_sentence(str(error))}'
            if open_span is not None and open_span[1] != key:
                failures.append(_closed(open_span, time_ns))
                open_span = None
            if open_span is None:
                open_span = (time_ns, key, str(error), kind)
            continue
        if open_span is not None:
            failures.append(_closed(open_span, time_ns))
            open_span = None
        translations[index] = result.translation
        rpy[index] = rpy_from_quat(result.rotation)
    if open_span is not None:
        failures.append(_closed(open_span, times[-1]))
    return Track(
        target,
        source,
        times.start,
        times.step,
        np.fromiter(times, dtype=np.int64, count=count),
        translations,
        rpy,
        tuple(failures),
    )


def _closed(span: tuple[int, str, str, str], end_ns: int) -> FailureSpan:
    """Return the failure span begun at ``span[0]`` and ending at ``end_ns``."""
    start_ns, _, error, kind = span
    return FailureSpan(start_ns, end_ns, error, kind)


def live_span(clock_start_ns: int, clock_end_ns: int, receive_ns: list[int]) -> tuple[int, int]:
    """
    Return the span of a live recording to sample, on the listener's clock.

    With ``use_sim_time`` the clock reads 0 until the first ``/clock`` message: the span then
    starts at the first message received on a running clock, not at time 0.
    """
    if clock_start_ns > 0:
        return clock_start_ns, clock_end_ns
    running = [stamp for stamp in receive_ns if stamp > 0]
    return (min(running) if running else clock_end_ns), clock_end_ns


#: What tf_plot says when every live sample asked for a time later than the newest data.
OLD_STAMPS_HINT = (
    'every lookup asked for a time later than the newest data: the transforms carry old stamps '
    '(a bag played without --clock?). Play it with `tf_play --clock` and run tf_plot with '
    '`--ros-args -p use_sim_time:=true`, or plot the bag itself with --bag'
)


def old_stamps_hint(track: Track) -> str | None:
    """Return :data:`OLD_STAMPS_HINT` when every sample failed by extrapolating into the future."""
    if track.succeeded.any() or not track.failures:
        return None
    if all('into the future' in span.error for span in track.failures):
        return OLD_STAMPS_HINT
    return None
