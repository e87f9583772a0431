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

"""tf_plot's model: a transform sampled over time, failures grouped by tf2's error."""

from __future__ import annotations

import math

import numpy as np
import pytest
from tf_demo.cli._plot_model import DEFAULT_MAX_SAMPLES
from tf_demo.cli._plot_model import first_sentence
from tf_demo.cli._plot_model import live_span
from tf_demo.cli._plot_model import MAX_SAMPLES
from tf_demo.cli._plot_model import old_stamps_hint
from tf_demo.cli._plot_model import sample_times
from tf_demo.cli._plot_model import sample_track
from tf_demo.core.buffer_core import BufferCore
from tf_demo.core.math3d import rpy_from_quat
from tf_demo.nodes.dynamic_tf_pub import circle_transform

SECOND = 1_000_000_000
T0 = 1_700_000_000 * SECOND
IDENTITY = (0.0, 0.0, 0.0, 1.0)


def circle_core(seconds: float = 5.0, rate_hz: int = 20) -> BufferCore:
    """The seed's circle (dynamic_tf_pub, odom -> base_link) under a static map -> odom."""
    core = BufferCore(100 * SECOND)
    core.set_transform('map', 'odom', T0, (1.0, 2.0, 0.0), IDENTITY, 'test', True)
    for k in range(round(seconds * rate_hz) + 1):
        stamp = T0 + k * SECOND // rate_hz
        translation, rotation = circle_transform(1.0, stamp)
        core.set_transform('odom', 'base_link', stamp, translation, rotation, 'test', False)
    return core


def test_the_circle_is_sampled_as_tf2_echo_reads_it() -> None:
    """At the recorded instants the track is the published circle, offset by map -> odom."""
    times = sample_times(T0, T0 + 5 * SECOND, 20.0)
    track = sample_track(circle_core(), 'map', 'base_link', times)
    assert track.failures == ()
    assert track.succeeded.all()
    assert len(track.times_ns) == 101
    for index, stamp in enumerate(track.times_ns.tolist()):
        (x, y, z), rotation = circle_transform(1.0, stamp)
        assert track.translations[index] == pytest.approx((x + 1.0, y + 2.0, z), abs=1e-9)
        assert track.rpy[index] == pytest.approx(rpy_from_quat(rotation), abs=1e-9)
    assert track.seconds[-1] == pytest.approx(5.0)


def test_a_publisher_that_stops_gives_one_extrapolation_span_to_the_end() -> None:
    times = sample_times(T0, T0 + 8 * SECOND, 10.0)
    track = sample_track(circle_core(seconds=5.0), 'map', 'base_link', times)
    (span,) = track.failures
    assert (span.start_ns, span.end_ns) == (T0 + 5_100_000_000, T0 + 8 * SECOND)
    assert span.kind == 'ExtrapolationException'
    assert (
        span.label == 'ExtrapolationException: Lookup would require extrapolation into the future'
    )
    assert 'Requested time 1700000005.100000' in span.error  # tf2's text, its first instant
    assert int((~track.succeeded).sum()) == 30
    assert np.isnan(track.translations[51:]).all()
    assert not np.isnan(track.translations[:51]).any()


def test_late_data_an_island_and_a_missing_frame_name_their_errors() -> None:
    """Data from 1 s on: into the past before; an island: Connectivity; no frame: Lookup."""
    core = BufferCore(100 * SECOND)
    for k in range(0, 21):
        stamp = T0 + k * SECOND // 10
        core.set_transform('map', 'base_link', stamp, (k, 0.0, 0.0), IDENTITY, 'test', False)
    core.set_transform('elsewhere', 'island', T0, (0.0, 0.0, 0.0), IDENTITY, 'test', True)
    track = sample_track(core, 'map', 'base_link', sample_times(T0, T0 + 2 * SECOND, 10.0))
    assert track.failures == ()
    late = BufferCore(100 * SECOND)
    for k in range(10, 21):
        stamp = T0 + k * SECOND // 10
        late.set_transform('map', 'base_link', stamp, (k, 0.0, 0.0), IDENTITY, 'test', False)
    track = sample_track(late, 'map', 'base_link', sample_times(T0, T0 + 2 * SECOND, 10.0))
    (span,) = track.failures
    assert span.kind == 'ExtrapolationException'  # base_link exists: data only from 1 s
    assert 'into the past' in span.label
    assert (span.start_ns, span.end_ns) == (T0, T0 + SECOND)
    island = sample_track(core, 'map', 'island', sample_times(T0, T0 + SECOND, 10.0))
    (span,) = island.failures
    assert span.kind == 'ConnectivityException'
    assert (span.start_ns, span.end_ns) == (T0, T0 + SECOND)
    missing = sample_track(core, 'map', 'nope', sample_times(T0, T0 + SECOND, 10.0))
    assert [s.kind for s in missing.failures] == ['LookupException']
    assert missing.failures[0].label == (
        'LookupException: "nope" passed to lookupTransform argument source_frame does not exist'
    )


def test_different_errors_in_a_row_are_different_spans() -> None:
    """Data from 1 s to 2 s: extrapolation into the past before, into the future after."""
    core = BufferCore(100 * SECOND)
    for k in range(10, 21):
        stamp = T0 + k * SECOND // 10
        core.set_transform('a', 'b', stamp, (0.0, 0.0, 0.0), IDENTITY, 'test', False)
    track = sample_track(core, 'a', 'b', sample_times(T0, T0 + 3 * SECOND, 10.0))
    assert [(s.start_ns - T0, s.end_ns - T0) for s in track.failures] == [
        (0, SECOND),
        (2_100_000_000, 3 * SECOND),
    ]
    assert ['past' in s.label for s in track.failures] == [True, False]


def test_sample_times_default_rate_is_capped_for_long_recordings() -> None:
    assert sample_times(0, SECOND, None) == range(0, SECOND + 1, SECOND // 50)
    hour = sample_times(0, 3600 * SECOND, None)
    assert len(hour) <= DEFAULT_MAX_SAMPLES
    assert hour[-1] > 3599 * SECOND
    assert sample_times(5, 5, 10.0) == range(5, 6, SECOND // 10)


@pytest.mark.parametrize('rate', [0.0, -1.0, math.nan, math.inf])
def test_sample_times_refuse_a_rate_that_is_not_positive(rate: float) -> None:
    with pytest.raises(ValueError, match='positive number of samples per second'):
        sample_times(0, SECOND, rate)


def test_sample_times_refuse_hostile_counts_and_reversed_spans() -> None:
    with pytest.raises(ValueError, match=f'more than {MAX_SAMPLES}: ask for a lower rate'):
        sample_times(0, 3600 * SECOND, 1e6)
    with pytest.raises(ValueError, match='is before the start'):
        sample_times(SECOND, 0, 10.0)


def test_first_sentence_drops_the_details() -> None:
    assert first_sentence('Lookup would fail.  Requested time 3.5 but ...') == 'Lookup would fail'
    assert first_sentence('"x" does not exist. ') == '"x" does not exist'
    assert first_sentence('no full stop') == 'no full stop'


def test_a_live_span_on_a_sim_clock_starts_at_its_first_message() -> None:
    """The clock read 0 at the start (no /clock yet): the span starts at the first message."""
    assert live_span(5, 9, [6, 7]) == (5, 9)
    assert live_span(0, 90, [0, 40, 30]) == (30, 90)
    assert live_span(0, 90, []) == (90, 90)


def test_only_all_future_extrapolations_get_the_old_stamps_hint() -> None:
    """Data older than every sample: the hint; a sample that worked, or another error: none."""
    core = BufferCore()
    core.set_transform('odom', 'base_link', 1_000, (0.0, 0.0, 0.0), (0.0, 0.0, 0.0, 1.0))
    core.set_transform('odom', 'base_link', 2_000, (0.0, 0.0, 0.0), (0.0, 0.0, 0.0, 1.0))
    future = sample_track(core, 'odom', 'base_link', range(10**9, 2 * 10**9, 10**8))
    hint = old_stamps_hint(future)
    assert hint is not None
    assert 'tf_play --clock' in hint
    partly = sample_track(core, 'odom', 'base_link', range(1_000, 10**9, 10**8))
    assert old_stamps_hint(partly) is None
    unknown = sample_track(core, 'map', 'base_link', range(10**9, 2 * 10**9, 10**8))
    assert old_stamps_hint(unknown) is None
