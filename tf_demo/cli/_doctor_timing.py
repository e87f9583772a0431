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
tf_doctor's timing checks of the frames on /tf: stamps, rates, stopped streams, fixed mounts.

A stamp far ahead of or behind the listener's clock (a clock or use_sim_time mismatch), data too
sparse for lookups at now(), a stream that stopped, and a fixed mount sent again and again on
/tf instead of once on /tf_static.
"""

from __future__ import annotations

from collections.abc import Sequence
import itertools
import statistics

from tf_demo.cli._doctor_model import distinct_values
from tf_demo.cli._doctor_model import Finding
from tf_demo.cli._doctor_model import FrameStats
from tf_demo.cli._doctor_model import NS_PER_S
from tf_demo.cli._doctor_model import seconds
from tf_demo.cli._doctor_model import Thresholds
from tf_demo.cli._doctor_tree import LINK_PUBLISHERS
from tf_demo.cli._observations import TF_TOPIC
from tf_demo.core.math3d import Quat
from tf_demo.core.math3d import Vec3

# Links that move by nature even when a robot stands still during the recording.
_DYNAMIC_BY_NATURE = frozenset(
    (parent, child) for parent, child in (link.split('→') for link in LINK_PUBLISHERS)
) - {('earth', 'map')}


def timing(
    stats: dict[str, FrameStats],
    listen_ns: int,
    limits: Thresholds,
    moving: set[str] | frozenset[str] = frozenset(),
) -> list[Finding]:
    """
    Stamp, rate and constancy findings for the frames on /tf.

    :param moving: children of the robot's moving joints (never called fixed mounts).
    """
    findings = []
    for child in sorted(stats):
        samples = stats[child].dynamic
        if not samples:
            continue
        parent = stats[child].latest_parent
        offsets = [receive - stamp for receive, stamp, _, _ in samples]
        median_offset = statistics.median(offsets)
        if all(stamp == 0 for _, stamp, _, _ in samples):
            findings.append(
                Finding(
                    'zero_stamps',
                    'error',
                    (child,),
                    f'Transforms {parent}→{child} on {TF_TOPIC} carry stamp 0. Time-based '
                    'lookups need real stamps; with 0 every lookup at a real time is an '
                    'extrapolation error.',
                    'Stamp each transform with the node clock (node.get_clock().now()), or '
                    'publish it on /tf_static if it never moves.',
                    samples[0][0],
                )
            )
            continue
        if -median_offset > limits.future_tolerance_s * NS_PER_S:
            findings.append(
                Finding(
                    'future_stamps',
                    'error',
                    (child,),
                    f'Transforms {parent}→{child} are stamped {seconds(-median_offset)} in the '
                    "future of this listener's clock. Lookups at 'now' miss them and old data is "
                    'dropped as they arrive.',
                    'The publisher and listeners use different clocks: check use_sim_time (all '
                    'nodes true with a /clock source, or all false) and synchronize machine '
                    'clocks (chrony/NTP).',
                    samples[0][0],
                )
            )
        elif median_offset > limits.old_tolerance_s * NS_PER_S:
            sim_hint = ''
            if samples[-1][1] < 10**9 * 10**6 <= samples[-1][0]:
                sim_hint = (
                    ' The stamps look like simulation time (seconds since start) while this '
                    'listener runs on the wall clock.'
                )
            findings.append(
                Finding(
                    'old_stamps',
                    'error',
                    (child,),
                    f'Transforms {parent}→{child} are already {seconds(median_offset)} old when '
                    f'they arrive (the buffer keeps 10 s), so lookups at now() fail with '
                    f'extrapolation into the future.{sim_hint}',
                    'Check use_sim_time: a publisher on sim time and a listener on wall time (or '
                    'the reverse) disagree by years; otherwise synchronize clocks or fix the '
                    "publisher's stamping.",
                    samples[0][0],
                )
            )
        stamps = sorted({stamp for _, stamp, _, _ in samples})
        window = listen_ns or (samples[-1][0] - samples[0][0])
        gaps = [b - a for a, b in itertools.pairwise(stamps)]
        sparse = (len(stamps) == 1 and window >= NS_PER_S) or bool(
            gaps and statistics.median(gaps) > limits.max_gap_s * NS_PER_S
        )
        fixed = _fixed_mount_on_tf(
            parent, child, samples, sparse=sparse, limits=limits, moving=moving
        )
        if fixed is not None:
            findings.append(fixed)
            continue  # "publish faster" is not the fix for a transform that never changes
        if len(stamps) == 1 and window >= NS_PER_S:
            findings.append(
                Finding(
                    'sparse_data',
                    'warning',
                    (child,),
                    f'Only one stamp of {parent}→{child} arrived in {seconds(window)}. Lookups '
                    'at any other time fail with extrapolation errors.',
                    'Publish moving frames continuously (10 Hz or more), or publish a fixed '
                    'transform once on /tf_static.',
                    samples[0][0],
                )
            )
            continue
        if gaps and statistics.median(gaps) > limits.max_gap_s * NS_PER_S:
            rate = (len(stamps) - 1) / ((stamps[-1] - stamps[0]) / NS_PER_S)
            widest = stamps[max(range(len(gaps)), key=gaps.__getitem__)]
            gap_at = next(receive for receive, stamp, _, _ in samples if stamp == widest)
            findings.append(
                Finding(
                    'sparse_data',
                    'warning',
                    (child,),
                    f'{parent}→{child} arrives at {rate:.3g} Hz, with gaps up to '
                    f'{seconds(max(gaps))}. Lookups at now() need data newer than the request '
                    'and will extrapolate into the future for up to that long.',
                    'Publish faster, look up at time 0 (latest available) or with a timeout, or '
                    'interpolate at the stamp of the data you transform.',
                    gap_at,
                )
            )
    return findings


def _fixed_mount_on_tf(
    parent: str,
    child: str,
    samples: Sequence[tuple[int, int, Vec3, Quat]],
    *,
    sparse: bool,
    limits: Thresholds,
    moving: set[str] | frozenset[str],
) -> Finding | None:
    """Report a transform sent again and again on /tf with one value (a fixed mount)."""
    if len(samples) < 3 or child in moving or (parent, child) in _DYNAMIC_BY_NATURE:
        return None
    values = [(translation, rotation) for _, _, translation, rotation in samples]
    if len(distinct_values(values, limits.value_tolerance)) != 1:
        return None
    consequence = (
        'Between its messages tf2 can only extrapolate, so lookups at now() fail'
        if sparse
        else 'It works, but listeners only find it at the stamps sent (and 10 s back)'
    )
    return Finding(
        'fixed_mount_on_tf',
        'warning' if sparse else 'info',
        (child,),
        f'{parent}→{child} arrived {len(samples)} times on {TF_TOPIC} with the same value every '
        f'time: it looks like a fixed mount. {consequence}.',
        'Publish a fixed mount once on /tf_static instead (static_transform_publisher, a '
        'StaticTransformBroadcaster, or a fixed joint in the URDF): lookups then succeed at any '
        'time. If this frame really moves and only stood still, ignore this.',
        samples[0][0],
    )


def stopped(stats: dict[str, FrameStats], end_ns: int) -> list[Finding]:
    """Dynamic frames whose messages stopped well before the end of the recording."""
    findings = []
    for child in sorted(stats):
        samples = stats[child].dynamic
        if len(samples) < 3:
            continue
        receives = [receive for receive, _, _, _ in samples]
        period = statistics.median(b - a for a, b in itertools.pairwise(receives))
        silence = end_ns - receives[-1]
        if silence > max(2 * NS_PER_S, 5 * period):
            findings.append(
                Finding(
                    'stopped',
                    'warning',
                    (child,),
                    f'{stats[child].latest_parent}→{child} stopped arriving '
                    f'{seconds(silence)} before the end of the recording (it came every '
                    f'{seconds(period)} before). Lookups at later times will fail with '
                    'extrapolation errors.',
                    'Check that its publisher is still running and not blocked.',
                    receives[-1],
                )
            )
    return findings


def stamps_went_back(stats: dict[str, FrameStats], limits: Thresholds) -> list[Finding]:
    """
    Frames whose stamps went backwards once or twice (three times or more: fighting publishers).

    A step back of more than ``limits.clock_jump_s`` is a clock jump (a simulation restarted,
    ``/clock`` reset, a bag played again); a smaller one a stamp regression. Each finding
    carries the time of the largest step.
    """
    findings = []
    for child in sorted(stats):
        samples = stats[child].dynamic
        steps = [(a[1] - b[1], b[0]) for a, b in itertools.pairwise(samples) if b[1] < a[1]]
        if not steps or len(steps) >= 3:
            continue
        back, at_ns = max(steps, key=lambda step: step[0])  # the first of the largest
        parent = stats[child].latest_parent
        if back > limits.clock_jump_s * NS_PER_S:
            findings.append(
                Finding(
                    'clock_jump',
                    'warning',
                    (child,),
                    f'The stamps of {parent}→{child} jumped back by {seconds(back)}: its '
                    "publisher's clock was reset (a simulation restarted, /clock started over, "
                    'a bag played again). Listeners whose own clock jumped back cleared their '
                    'buffers; others keep the newer data and extrapolate until time catches up.',
                    'Restart the nodes after resetting a simulation, or give every node the same '
                    'clock (use_sim_time true everywhere with one /clock source).',
                    at_ns,
                )
            )
        else:
            findings.append(
                Finding(
                    'stamp_regression',
                    'warning',
                    (child,),
                    f'The stamps of {parent}→{child} went backwards {len(steps)} time'
                    f'{"s" if len(steps) > 1 else ""} (by up to {seconds(back)}): a message was '
                    'stamped earlier than the one before it.',
                    'Stamp with a monotonic source (the node clock at publication), and do not '
                    'reorder or re-send old transforms.',
                    at_ns,
                )
            )
    return findings
