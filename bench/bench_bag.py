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
Reading recorded TF: transforms per second from a rosbag2 into a BufferCore.

Writes a bag (MCAP, then SQLite3) of ``--messages`` TFMessages × ``--transforms`` each (a
REP-105-like set of frames at 100 Hz) with rosbags' writer, then times, in the same run:
``tf_demo.bag.load_buffer`` (container by rosbags, payloads by our CDR decoder, straight into the
core) and, as the reference, rosbags' own ``deserialize_cdr`` of the same payloads with nothing
inserted. Target (issue 22): at least 1,000,000 transforms/s into the core.

Bounded memory: MCAP bags of ``--stream-mb`` sizes (default 64 and 256 MB; ``--stream-mb 1024``
for the 1 GB of the issue) are streamed with ``TfBag.records()`` in a fresh process each, which
prints its peak resident memory; the peak must not grow with the bag.

Run: ``.venv/bin/python bench/bench_bag.py``.
"""

from __future__ import annotations

import argparse
import math
from pathlib import Path
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, str(Path(__file__).resolve().parent.parent))

from _flow import build_line

TARGET = 1_000_000
SECOND = 1_000_000_000
T0 = 1_700_000_000 * SECOND


def write(path: Path, storage: str, messages: int, transforms: int) -> None:
    from rosbags.rosbag2 import StoragePlugin
    from rosbags.rosbag2 import Writer
    from rosbags.typesys import get_typestore
    from rosbags.typesys import Stores
    from tf_demo.msgs.cdr import TfMessageEncoder

    plugin = StoragePlugin.MCAP if storage == 'mcap' else StoragePlugin.SQLITE3
    encoder = TfMessageEncoder()
    store = get_typestore(Stores.ROS2_JAZZY)
    with Writer(path, version=9, storage_plugin=plugin) as writer:
        connection = writer.add_connection('/tf', 'tf2_msgs/msg/TFMessage', typestore=store)
        for k in range(messages):
            stamp = T0 + k * SECOND // 100
            angle = k / 100
            batch = [
                (f'f{i}' if i else 'odom', f'f{i + 1}', (0.1 * i, math.cos(angle), 0.0),
                 (0.0, 0.0, math.sin(angle / 2), math.cos(angle / 2)))
                for i in range(transforms)
            ]  # fmt: skip
            sec, nanosec = divmod(stamp, SECOND)
            writer.write(connection, stamp, encoder.encode(batch, sec, nanosec))


#: Streams a bag in a fresh process and prints: records, transforms, peak RSS (KiB).
_STREAM = """
import resource, sys
from tf_demo.bag import open_tf_bag
records = transforms = 0
with open_tf_bag(sys.argv[1]) as bag:
    for record in bag.records():
        records += 1
        transforms += len(record.transforms)
print(records, transforms, resource.getrusage(resource.RUSAGE_SELF).ru_maxrss)
"""


def streamed_peak(path: Path) -> tuple[int, int, int, float]:
    """Stream ``path`` in a new process: records, transforms, peak RSS (KiB), seconds."""
    start = time.perf_counter()
    completed = subprocess.run(
        [sys.executable, '-c', _STREAM, str(path)],
        capture_output=True, text=True, check=True,
        cwd=Path(__file__).resolve().parent.parent,
    )  # fmt: skip
    records, transforms, peak = (int(v) for v in completed.stdout.split())
    return records, transforms, peak, time.perf_counter() - start


def bounded_memory(folder: Path, sizes_mb: list[int], transforms: int) -> None:
    """Print the peak memory of streaming MCAP bags of ``sizes_mb``."""
    bytes_per_message = 4 + transforms * 88  # the encoder's CDR for these frame names
    print('streaming TfBag.records() (fresh process each):')
    peaks = []
    for size in sizes_mb:
        path = folder / f'stream_{size}'
        messages = size * 1024 * 1024 // bytes_per_message
        write(path, 'mcap', messages, transforms)
        on_disk = sum(f.stat().st_size for f in path.iterdir()) / 2**20
        records, count, peak, seconds = streamed_peak(path)
        peaks.append(peak)
        print(
            f'  {on_disk:7.0f} MiB bag, {records:,} messages, {count:,} transforms: peak RSS '
            f'{peak / 1024:6.1f} MiB, {count / seconds:,.0f} transforms/s'
        )
    growth = peaks[-1] / peaks[0]
    print(f'  peak RSS largest/smallest bag: {growth:.2f} (bounded: about 1)')


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.strip().splitlines()[0])
    parser.add_argument('--messages', type=int, default=4000)
    parser.add_argument('--transforms', type=int, default=50)
    parser.add_argument('--stream-mb', type=int, nargs='*', default=[64, 256])
    options = parser.parse_args(argv)
    print(f'tf_demo build: {build_line()}')
    from rosbags.rosbag2 import Reader
    from rosbags.typesys import get_typestore
    from rosbags.typesys import Stores
    from tf_demo.bag import load_buffer

    store = get_typestore(Stores.ROS2_JAZZY)
    total = options.messages * options.transforms
    print(f'{options.messages} TFMessages x {options.transforms} transforms = {total} transforms')
    with tempfile.TemporaryDirectory() as folder:
        for storage in ('mcap', 'sqlite3'):
            path = Path(folder) / storage
            write(path, storage, options.messages, options.transforms)
            start = time.perf_counter()
            core = load_buffer(path)
            ours = time.perf_counter() - start
            assert core.frame_exists(f'f{options.transforms}')
            start = time.perf_counter()
            with Reader(path) as reader:
                for connection, _, data in reader.messages():
                    store.deserialize_cdr(data, connection.msgtype)
            theirs = time.perf_counter() - start
            rate = total / ours
            print(
                f'  {storage:8s} load_buffer {rate:10,.0f} transforms/s '
                f'(target >= {TARGET:,}: {"ok" if rate >= TARGET else "MISSED"}); '
                f"rosbags' deserialize_cdr alone {total / theirs:10,.0f}/s; "
                f'ours/theirs time {ours / theirs:.2f}'
            )
        if options.stream_mb:
            bounded_memory(Path(folder), sorted(options.stream_mb), options.transforms)
    return 0


if __name__ == '__main__':
    sys.exit(main())
