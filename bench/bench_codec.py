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
Benchmark the CDR codec against cyclonedds-python's IdlStruct on TFMessages of 1 and 50 transforms.

Run: ``.venv/bin/python bench/bench_codec.py [--repeat N]``. Prints CPU microseconds per message
of this process (minimum and median over N runs, for a shared, loaded machine) and the speed-up
over IdlStruct (minimum against minimum). The issue's target: encode plus decode of a 50-transform
TFMessage within 100 us ("encode + decode" times one ``deserialize(serialize(m))`` per call).
"""

import argparse
from collections.abc import Callable
from pathlib import Path
import statistics
import sys
import time
import timeit

sys.path.insert(0, str(Path(__file__).resolve().parent.parent))  # tf_demo from this checkout
# The cyclonedds IdlStruct twins of the ROS types, shared with test/msgs.
sys.path.insert(0, str(Path(__file__).resolve().parent.parent / 'test' / 'msgs'))

from _flow import build_line
from cyclonedds_reference_types import idl_tf_message
from cyclonedds_reference_types import TFMessage_
from tf_demo.msgs import cdr
from tf_demo.msgs.convert import fill_transform_stamped
from tf_demo.msgs.geometry_msgs import TransformStamped
from tf_demo.msgs.tf2_msgs import TFMessage


def make_messages(count: int) -> tuple[TFMessage, TFMessage_]:
    """Return the same TFMessage of ``count`` transforms in both worlds."""
    ours = TFMessage(
        transforms=[
            fill_transform_stamped(
                TransformStamped(),
                f'link_{i}',
                f'link_{i + 1}',
                1_700_000_000_123_456_789 + i,
                (0.1 * i, -0.2, 0.3),
                (0.0, 0.0, 0.38268343236508984, 0.9238795325112867),
            )
            for i in range(count)
        ]
    )
    return ours, idl_tf_message(ours)


def times_us(function: Callable[[], object], number: int, repeat: int) -> tuple[float, float]:
    """Return the (minimum, median) per-call CPU time in microseconds over ``repeat`` runs."""
    runs = sorted(timeit.repeat(function, number=number, repeat=repeat, timer=time.process_time))
    return runs[0] / number * 1e6, statistics.median(runs) / number * 1e6


def main() -> int:
    """Run the benchmark and print a table."""
    parser = argparse.ArgumentParser(description=__doc__.split('\n\n')[0])
    parser.add_argument('--repeat', type=int, default=25, help='timed runs per case (default 25)')
    repeat = parser.parse_args().repeat
    print(f'tf_demo build: {build_line()}')
    print(f'Python {sys.version.split()[0]}; CPU microseconds per message over {repeat} runs')
    print(
        f'{"case":34s} {"ours min":>9s} {"median":>8s} {"IdlStruct min":>14s} {"median":>8s}'
        f' {"speed-up":>9s}'
    )
    for count in (1, 10, 50):
        ours, theirs = make_messages(count)
        data = cdr.serialize(ours)
        assert theirs.serialize(use_version_2=False)[: len(data)] == data
        assert cdr.deserialize(TFMessage, data) == ours
        number = max(20, 20_000 // (count * 10))

        # The timed calls, each with its message bound as a default (as a lambda would bind it).
        def encode_ours(ours: TFMessage = ours) -> bytes:
            return cdr.serialize(ours)

        def decode_ours(data: bytes = data) -> TFMessage:
            return cdr.deserialize(TFMessage, data)

        def decode_fast(data: bytes = data) -> list[cdr.TransformTuple]:
            return cdr.decode_tf_message_transforms(data)

        def round_trip(ours: TFMessage = ours) -> TFMessage:
            return cdr.deserialize(TFMessage, cdr.serialize(ours))

        def encode_theirs(theirs: TFMessage_ = theirs) -> bytes:
            return theirs.serialize(use_version_2=False)

        def decode_theirs(data: bytes = data) -> TFMessage_:
            return TFMessage_.deserialize(data, has_header=True)

        encode = times_us(encode_ours, number, repeat)
        decode = times_us(decode_ours, number, repeat)
        fast = times_us(decode_fast, number, repeat)
        both = times_us(round_trip, number, repeat)
        idl_encode = times_us(encode_theirs, number // 4 or 1, repeat)
        idl_decode = times_us(decode_theirs, number // 4 or 1, repeat)
        idl_both = (idl_encode[0] + idl_decode[0], idl_encode[1] + idl_decode[1])
        rows = [
            (f'{count} tf: encode', encode, idl_encode),
            (f'{count} tf: decode to messages', decode, idl_decode),
            (f'{count} tf: decode tf fast path', fast, idl_decode),
            (f'{count} tf: encode + decode', both, idl_both),
        ]
        for label, (mine, mine_median), (other, other_median) in rows:
            print(
                f'{label:34s} {mine:9.1f} {mine_median:8.1f} {other:14.1f} {other_median:8.1f}'
                f' {other / mine:8.1f}x'
            )
    return 0


if __name__ == '__main__':
    sys.exit(main())
