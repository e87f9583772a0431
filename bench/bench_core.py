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
Benchmark ``tf_demo.core.BufferCore`` against tf2's C++ core (``tf2_py``) in one run.

Printed, never asserted.  Usage (from the repository root)::

    .venv/bin/python bench/bench_core.py [--rounds 5] [--repeat 3] [--json]

Both halves run the same workloads with the same timing method (``time.perf_counter`` around a
loop of calls, the median over ``--repeat`` repetitions), in alternating rounds of one process
each: ours under the virtual environment's Python, tf2's in a ``/usr/bin/python3`` subprocess
running this same file with ``--half tf2``
(Debian's ``python3-tf2``, the ROS 1 Noetic build of tf2's C++ core).  Inputs are prepared
outside the timed loops on both sides (tf2's ``TransformStamped`` messages and ``rospy.Time``
stamps, our plain tuples and ints).  Memory is the resident-set growth of a fresh process
(``--memory ours|tf2``) after caching 100 frames x 10 s x 100 Hz.  This file must stay
importable by ``/usr/bin/python3`` without the package: it imports ``tf_demo`` and numpy
only inside our half.
"""

import argparse
from collections.abc import Callable
from collections.abc import Iterator
import gc
import json
import math
import os
import random
import statistics
import subprocess
import sys
import time
from typing import Any
from typing import NamedTuple

from _flow import build_line

Vec3 = tuple[float, float, float]
Quat = tuple[float, float, float, float]
#: parent, child, stamp_ns, translation, rotation, is_static
Insert = tuple[str, str, int, Vec3, Quat, bool]

SECOND = 1_000_000_000
T0 = 1_000 * SECOND  # first stamp of every history
SYSTEM_PYTHON = '/usr/bin/python3'
HERE = os.path.dirname(os.path.abspath(__file__))
REPO_ROOT = os.path.dirname(HERE)

REP105_STATIC = [
    ('base_footprint', 'base_link', (0.0, 0.0, 0.1), (0.0, 0.0, 0.0, 1.0)),
    (
        'base_link',
        'lidar_link',
        (0.2, 0.0, 0.3),
        (0.0, 0.0, 0.3826834323650898, 0.9238795325112867),
    ),
    ('lidar_link', 'camera_link', (0.05, 0.02, -0.1), (0.5, -0.5, 0.5, -0.5)),
]
REP105_DYNAMIC = [('map', 'odom'), ('odom', 'base_footprint')]
CHAIN_LINKS = 30
CALLS = 2000
BATCH_STAMPS = 10_000
MEMORY_FRAMES, MEMORY_SECONDS, MEMORY_RATE = 100, 10, 100


def _pose(index: int, k: int) -> tuple[Vec3, Quat]:
    """Return a deterministic, slowly varying (translation, rotation) for sample k of a link."""
    angle = 0.01 * k + 0.1 * index
    half = angle / 2.0
    return (
        (0.1 * k + index, 0.05 * k, 0.01 * index),
        (0.0, 0.0, math.sin(half), math.cos(half)),
    )


def rep105_inserts() -> list[Insert]:
    """Return the REP-105 inserts: (parent, child, stamp_ns, t, q, is_static)."""
    out = [(p, c, 0, t, q, True) for p, c, t, q in REP105_STATIC]
    for index, (parent, child) in enumerate(REP105_DYNAMIC):
        for k in range(101):  # 10 Hz for 10 s
            t, q = _pose(index, k)
            out.append((parent, child, T0 + k * SECOND // 10, t, q, False))
    return out


def chain_inserts() -> list[Insert]:
    """Return a 30-link chain l0 -> l1 -> ... -> l30, every link dynamic at 10 Hz for 10 s."""
    out = []
    for index in range(CHAIN_LINKS):
        for k in range(101):
            t, q = _pose(index, k)
            out.append((f'l{index}', f'l{index + 1}', T0 + k * SECOND // 10, t, q, False))
    return out


def interior_stamps(count: int, seed: int) -> list[int]:
    """Return ``count`` distinct-ish stamps strictly inside the 10 s history."""
    rng = random.Random(seed)
    return [T0 + rng.randint(1, 10 * SECOND - 1) for _ in range(count)]


def insert_stream(count: int) -> list[Insert]:
    """Return ``count`` dynamic inserts of one link at 100 Hz (the insert benchmark)."""
    return [
        ('odom', 'base_footprint', T0 + k * SECOND // 100, *_pose(0, k), False)
        for k in range(count)
    ]


def _median_per_call(run: Callable[[], None], calls: int, repeat: int) -> float:
    """Run ``run()`` (which makes ``calls`` calls) ``repeat`` times; median seconds per call."""
    samples = []
    for _ in range(repeat):
        gc.collect()
        start = time.perf_counter()
        run()
        samples.append((time.perf_counter() - start) / calls)
    return statistics.median(samples)


def _rss_bytes() -> int:
    """Return this process's resident set size from /proc."""
    with open('/proc/self/statm') as statm:
        return int(statm.read().split()[1]) * os.sysconf('SC_PAGE_SIZE')


def _rss_growth(insert_all: Callable[[], None]) -> int:
    """Return the RSS growth in bytes while ``insert_all()`` fills an already created buffer."""
    gc.collect()
    before = _rss_bytes()
    insert_all()
    gc.collect()
    return _rss_bytes() - before


def _memory_inserts() -> Iterator[tuple[str, str, int, Vec3, Quat]]:
    """Yield 100 frames x 10 s x 100 Hz of samples (a star around ``world``), time-ordered."""
    for k in range(MEMORY_SECONDS * MEMORY_RATE):
        stamp = T0 + k * SECOND // MEMORY_RATE
        for index in range(MEMORY_FRAMES):
            yield ('world', f'f{index}', stamp, *_pose(index, k))


class Core(NamedTuple):
    """How one half drives its core: the same workloads through each core's own API."""

    #: Returns a buffer filled with the inserts.
    buffer: Callable[[list[Insert]], Any]
    #: Names of the can-transform and lookup methods (tf2_py's ``*_core`` or ours).
    can_transform: str
    lookup_transform: str
    #: Converts nanoseconds to the core's time argument (prepared outside the timed loops).
    stamp: Callable[[int], Any]
    #: ``batch(buffer, stamps_ns)`` returns the run that looks up all the stamps.
    batch: Callable[[Any, list[int]], Callable[[], None]]


def time_workloads(core: Core, repeat: int) -> dict[str, float]:
    """Time the lookup workloads on ``core``; return seconds per call by workload name."""
    rep105 = core.buffer(rep105_inserts())
    stamps = [core.stamp(ns) for ns in interior_stamps(CALLS, 1)]
    zero = core.stamp(0)

    def can_run() -> None:
        can = getattr(rep105, core.can_transform)
        for stamp in stamps:
            can('map', 'camera_link', stamp)

    def lookup_run() -> None:
        lookup = getattr(rep105, core.lookup_transform)
        for stamp in stamps:
            lookup('map', 'camera_link', stamp)

    def latest_run() -> None:
        lookup = getattr(rep105, core.lookup_transform)
        for _ in range(CALLS):
            lookup('map', 'camera_link', zero)

    chain = core.buffer(chain_inserts())
    chain_stamps = [core.stamp(ns) for ns in interior_stamps(CALLS, 2)]

    def chain_run() -> None:
        lookup = getattr(chain, core.lookup_transform)
        for stamp in chain_stamps:
            lookup('l0', f'l{CHAIN_LINKS}', stamp)

    batch_run = core.batch(rep105, interior_stamps(BATCH_STAMPS, 3))
    return {
        'can_transform': _median_per_call(can_run, CALLS, repeat),
        'rep105_lookup': _median_per_call(lookup_run, CALLS, repeat),
        'rep105_lookup_latest': _median_per_call(latest_run, CALLS, repeat),
        'chain30_lookup': _median_per_call(chain_run, CALLS, repeat),
        'batch_10000': _median_per_call(batch_run, 1, repeat),
    }


# ----------------------------------------------------------------------------------------------
# tf2 half (runs under /usr/bin/python3)


def _tf2_message(parent: str, child: str, stamp_ns: int, t: Vec3, q: Quat) -> Any:
    """Build a ROS 1 ``TransformStamped``."""
    from geometry_msgs.msg import TransformStamped
    import rospy  # type: ignore[import-not-found]

    msg = TransformStamped()
    msg.header.frame_id = parent
    msg.child_frame_id = child
    msg.header.stamp = rospy.Time(stamp_ns // SECOND, stamp_ns % SECOND)
    tr, rot = msg.transform.translation, msg.transform.rotation
    tr.x, tr.y, tr.z = t
    rot.x, rot.y, rot.z, rot.w = q
    return msg


def _tf2_buffer(inserts: list[Insert]) -> Any:
    """Return a tf2 ``BufferCore`` (10 s cache) filled with ``inserts``."""
    import rospy
    import tf2_py

    buffer = tf2_py.BufferCore(rospy.Duration(10))
    for parent, child, stamp, t, q, is_static in inserts:
        msg = _tf2_message(parent, child, stamp, t, q)
        if is_static:
            buffer.set_transform_static(msg, 'bench')
        else:
            buffer.set_transform(msg, 'bench')
    return buffer


def tf2_half(repeat: int) -> dict[str, float]:
    """Time every workload on tf2's C++ core; return seconds per call by workload name."""
    import rospy

    def stamp(ns: int) -> Any:
        return rospy.Time(ns // SECOND, ns % SECOND)

    stream = [_tf2_message(p, c, s, t, q) for p, c, s, t, q, _ in insert_stream(CALLS)]

    def insert_run() -> None:
        set_transform = _tf2_buffer([]).set_transform
        for msg in stream:
            set_transform(msg, 'bench')

    def batch_run(buffer: Any, stamps_ns: list[int]) -> Callable[[], None]:
        stamps = [stamp(ns) for ns in stamps_ns]

        def run() -> None:  # tf2 has no batch lookup: one call per stamp
            lookup = buffer.lookup_transform_core
            for one in stamps:
                lookup('map', 'camera_link', one)

        return run

    results = {'insert': _median_per_call(insert_run, CALLS, repeat)}
    core = Core(_tf2_buffer, 'can_transform_core', 'lookup_transform_core', stamp, batch_run)
    return {**results, **time_workloads(core, repeat)}


def tf2_memory() -> int:
    """Return the RSS growth in bytes of caching the memory workload in tf2's core."""
    import rospy
    import tf2_py

    buffer = tf2_py.BufferCore(rospy.Duration(MEMORY_SECONDS + 1))

    def insert_all() -> None:
        for parent, child, stamp, t, q in _memory_inserts():
            buffer.set_transform(_tf2_message(parent, child, stamp, t, q), 'bench')

    return _rss_growth(insert_all)


# ----------------------------------------------------------------------------------------------
# Our half


def _our_buffer(inserts: list[Insert]) -> Any:
    """Return a ``tf_demo`` ``BufferCore`` (10 s cache) filled with ``inserts``."""
    from tf_demo.core import BufferCore

    buffer = BufferCore(10 * SECOND, log=lambda level, text: None)
    for parent, child, stamp, t, q, is_static in inserts:
        buffer.set_transform(parent, child, stamp, t, q, 'bench', is_static)
    return buffer


def ours_half(repeat: int) -> dict[str, float]:
    """Time every workload on ``tf_demo.core``; return seconds per call by workload name."""
    import numpy as np

    stream = insert_stream(CALLS)

    def insert_run() -> None:
        set_transform = _our_buffer([]).set_transform
        for parent, child, stamp, t, q, _ in stream:
            set_transform(parent, child, stamp, t, q, 'bench')

    def batch_run(buffer: Any, stamps_ns: list[int]) -> Callable[[], None]:
        stamps = np.array(stamps_ns, dtype=np.int64)
        return lambda: buffer.lookup_transforms('map', 'camera_link', stamps)

    results = {'insert': _median_per_call(insert_run, CALLS, repeat)}
    core = Core(_our_buffer, 'can_transform', 'lookup_transform', int, batch_run)
    return {**results, **time_workloads(core, repeat)}


def ours_memory() -> int:
    """Return the RSS growth in bytes of caching the memory workload in ``tf_demo.core``."""
    from tf_demo.core import BufferCore

    buffer = BufferCore((MEMORY_SECONDS + 1) * SECOND, log=lambda level, text: None)

    def insert_all() -> None:
        for parent, child, stamp, t, q in _memory_inserts():
            buffer.set_transform(parent, child, stamp, t, q, 'bench')

    return _rss_growth(insert_all)


# ----------------------------------------------------------------------------------------------
# Driver


def _run_json(python: str, *args: str) -> Any:
    """Run this file under ``python`` with ``args``; return its JSON output."""
    env = dict(os.environ)
    env['PYTHONPATH'] = os.pathsep.join(p for p in (REPO_ROOT, env.get('PYTHONPATH', '')) if p)
    done = subprocess.run(
        [python, os.path.abspath(__file__), *args],
        capture_output=True,
        text=True,
        timeout=900,
        check=True,
        env=env,
    )
    return json.loads(done.stdout.strip().splitlines()[-1])


def _tf2_available() -> bool:
    """Tell whether ``/usr/bin/python3`` can import ``tf2_py``."""
    try:
        subprocess.run(
            [SYSTEM_PYTHON, '-c', 'import tf2_py, rospy'],
            capture_output=True,
            timeout=60,
            check=True,
        )
    except (OSError, subprocess.SubprocessError):
        return False
    return True


ROWS = [
    # key, label, target (issue 22, the compiled build: ours/tf2 ratio bound)
    ('insert', 'insert one dynamic transform', '<= 0.5x'),
    ('can_transform', 'can_transform map<-camera_link, interior stamp', '<= 0.5x'),
    ('rep105_lookup', 'REP-105 lookup map<-camera_link, new interior stamp per call', '<= 0.5x'),
    ('rep105_lookup_latest', 'REP-105 lookup map<-camera_link at time 0', '<= 0.4x'),
    ('chain30_lookup', '30-link all-dynamic chain lookup, interior stamp', '<= 1.0x'),
    ('batch_10000', '10,000 stamps: one lookup_transforms vs 10,000 tf2 calls', '>= 50x faster'),
]


def main(argv: list[str] | None = None) -> int:
    """Run the benchmark, or one half of it (``--half``, ``--memory``) for the driver."""
    parser = argparse.ArgumentParser(description=__doc__.split('\n\n')[1])
    parser.add_argument('--rounds', type=int, default=5, help='alternating ours/tf2 rounds')
    parser.add_argument('--repeat', type=int, default=3, help='repetitions inside each round')
    parser.add_argument('--half', choices=('ours', 'tf2'), help=argparse.SUPPRESS)
    parser.add_argument('--memory', choices=('ours', 'tf2'), help=argparse.SUPPRESS)
    parser.add_argument('--json', action='store_true', help='also print the raw numbers as JSON')
    args = parser.parse_args(argv)
    if args.half:
        print(json.dumps((ours_half if args.half == 'ours' else tf2_half)(args.repeat)))
        return 0
    if args.memory:
        print(json.dumps((ours_memory if args.memory == 'ours' else tf2_memory)()))
        return 0

    # Rounds alternate between the two halves so that a change in the machine's load hits both;
    # each round is one process per half (median of --repeat inside), ratios are taken per round.
    have_tf2 = _tf2_available()
    rounds = []
    for _ in range(args.rounds):
        ours = _run_json(sys.executable, '--half', 'ours', '--repeat', str(args.repeat))
        theirs = (
            _run_json(SYSTEM_PYTHON, '--half', 'tf2', '--repeat', str(args.repeat))
            if have_tf2
            else {}
        )
        rounds.append((ours, theirs))
    ours_mem = _run_json(sys.executable, '--memory', 'ours')
    theirs_mem = _run_json(SYSTEM_PYTHON, '--memory', 'tf2') if have_tf2 else None

    print(f'tf_demo build: {build_line()}')
    print(
        f'tf_demo.core vs tf2 C++ core (tf2_py): {args.rounds} alternating rounds x median of '
        f'{args.repeat}; medians shown, ratio = median of per-round ratios'
    )
    print(f'{"workload":64} {"ours":>11} {"tf2":>11} {"ours/tf2":>9}  target')
    summary = {}
    for key, label, target in ROWS:
        mine = statistics.median(r[0][key] for r in rounds)
        other = statistics.median(r[1][key] for r in rounds) if have_tf2 else None
        ratio = statistics.median(r[0][key] / r[1][key] for r in rounds) if have_tf2 else None
        summary[key] = {'ours': mine, 'tf2': other, 'ratio': ratio}
        unit = 'ms' if key == 'batch_10000' else 'us'
        scale = 1e3 if unit == 'ms' else 1e6
        ratio_text = f'{ratio:8.2f}x' if ratio else '      n/a'
        other_text = f'{other * scale:8.2f} {unit}' if other else '        n/a'
        note = target or ''
        if key == 'batch_10000' and ratio:
            note += f'  (speed-up {1 / ratio:.1f}x)'
        print(f'{label:64} {mine * scale:8.2f} {unit} {other_text} {ratio_text}  {note}')
    mem_ratio = f'{ours_mem / theirs_mem:8.2f}x' if theirs_mem else '      n/a'
    theirs_mem_text = f'{theirs_mem / 2**20:8.2f} MB' if theirs_mem is not None else '        n/a'
    label = f'memory: RSS growth, {MEMORY_FRAMES} frames x {MEMORY_SECONDS} s x {MEMORY_RATE} Hz'
    samples = MEMORY_FRAMES * MEMORY_SECONDS * MEMORY_RATE
    per_sample = f'{ours_mem / samples:.0f} B/sample'
    if theirs_mem is not None:
        per_sample += f' vs {theirs_mem / samples:.0f}'
    print(
        f'{label:64} {ours_mem / 2**20:8.2f} MB {theirs_mem_text} {mem_ratio}  '
        f'<= 150 B/sample ({per_sample})'
    )
    if args.json:
        print(json.dumps({'workloads': summary, 'memory_bytes': [ours_mem, theirs_mem]}))
    return 0


if __name__ == '__main__':
    sys.exit(main())
