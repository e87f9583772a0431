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

No ``from __future__ import annotations``: cyclonedds reads the annotations at class creation.
"""

import argparse
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path
import statistics
import sys
import time
import timeit

from cyclonedds.idl import IdlStruct
from cyclonedds.idl.annotations import final
import cyclonedds.idl.types as idl

sys.path.insert(0, str(Path(__file__).resolve().parent.parent))  # tf_demo from this checkout

from tf_demo.msgs import cdr
from tf_demo.msgs.convert import fill_transform_stamped
from tf_demo.msgs.geometry_msgs import TransformStamped
from tf_demo.msgs.tf2_msgs import TFMessage


@dataclass
@final
class Time_(IdlStruct, typename='builtin_interfaces::msg::dds_::Time_'):  # noqa: N801
    sec: idl.int32
    nanosec: idl.uint32


@dataclass
@final
class Header_(IdlStruct, typename='std_msgs::msg::dds_::Header_'):  # noqa: N801
    stamp: Time_
    frame_id: str


@dataclass
@final
class Vector3_(IdlStruct, typename='geometry_msgs::msg::dds_::Vector3_'):  # noqa: N801
    x: idl.float64
    y: idl.float64
    z: idl.float64


@dataclass
@final
class Quaternion_(IdlStruct, typename='geometry_msgs::msg::dds_::Quaternion_'):  # noqa: N801
    x: idl.float64
    y: idl.float64
    z: idl.float64
    w: idl.float64


@dataclass
@final
class Transform_(IdlStruct, typename='geometry_msgs::msg::dds_::Transform_'):  # noqa: N801
    translation: Vector3_
    rotation: Quaternion_


@dataclass
@final
class TransformStamped_(IdlStruct, typename='geometry_msgs::msg::dds_::TransformStamped_'):  # noqa: N801
    header: Header_
    child_frame_id: str
    transform: Transform_


@dataclass
@final
class TFMessage_(IdlStruct, typename='tf2_msgs::msg::dds_::TFMessage_'):  # noqa: N801
    transforms: idl.sequence[TransformStamped_]


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
    theirs = TFMessage_(
        [
            TransformStamped_(
                Header_(Time_(t.header.stamp.sec, t.header.stamp.nanosec), t.header.frame_id),
                t.child_frame_id,
                Transform_(
                    Vector3_(
                        t.transform.translation.x,
                        t.transform.translation.y,
                        t.transform.translation.z,
                    ),
                    Quaternion_(
                        t.transform.rotation.x,
                        t.transform.rotation.y,
                        t.transform.rotation.z,
                        t.transform.rotation.w,
                    ),
                ),
            )
            for t in ours.transforms
        ]
    )
    return ours, theirs


def times_us(function: Callable[[], object], number: int, repeat: int) -> tuple[float, float]:
    """Return the (minimum, median) per-call CPU time in microseconds over ``repeat`` runs."""
    runs = sorted(timeit.repeat(function, number=number, repeat=repeat, timer=time.process_time))
    return runs[0] / number * 1e6, statistics.median(runs) / number * 1e6


def main() -> int:
    """Run the benchmark and print a table."""
    parser = argparse.ArgumentParser(description=__doc__.split('\n\n')[0])
    parser.add_argument('--repeat', type=int, default=25, help='timed runs per case (default 25)')
    repeat = parser.parse_args().repeat
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
        encode = times_us(lambda ours=ours: cdr.serialize(ours), number, repeat)
        decode = times_us(lambda data=data: cdr.deserialize(TFMessage, data), number, repeat)
        fast = times_us(lambda data=data: cdr.decode_tf_message_transforms(data), number, repeat)
        both = times_us(
            lambda ours=ours: cdr.deserialize(TFMessage, cdr.serialize(ours)), number, repeat
        )
        idl_encode = times_us(
            lambda theirs=theirs: theirs.serialize(use_version_2=False), number // 4 or 1, repeat
        )
        idl_decode = times_us(
            lambda data=data: TFMessage_.deserialize(data, has_header=True),
            number // 4 or 1,
            repeat,
        )
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
