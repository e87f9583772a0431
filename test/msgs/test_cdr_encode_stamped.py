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

"""TfMessageEncoder.encode_stamped (tf_relay's path): each transform's stamp, renamed frames."""

from __future__ import annotations

import random

import pytest
from tf_demo.msgs import cdr
from tf_demo.msgs import geometry_msgs
from tf_demo.msgs import tf2_msgs
from tf_demo.msgs.cdr import TfMessageEncoder
from tf_demo.msgs.convert import fill_transform_stamped

SECOND = 1_000_000_000


def random_transforms(rng: random.Random, count: int) -> list[cdr.TransformTuple]:
    return [
        (
            'p' * rng.randint(1, 11),
            'c' * rng.randint(1, 13),
            rng.randint(-(2**31), 2**31 - 1) * SECOND + rng.randint(0, SECOND - 1),
            (rng.uniform(-5, 5), rng.uniform(-5, 5), rng.uniform(-5, 5)),
            (rng.random(), rng.random(), rng.random(), rng.random()),
        )
        for _ in range(count)
    ]


def test_encode_stamped_agrees_with_serialize_and_decodes_back() -> None:
    """Random names, stamps and counts: serialize's bytes, renamed; decoding gives them back."""
    rng = random.Random(5)
    encoder = TfMessageEncoder(rename=lambda frame: 'r1/' + frame)
    for count in (0, 1, 2, 5, 5, 40):
        transforms = random_transforms(rng, count)
        renamed = [('r1/' + p, 'r1/' + c, s, t, q) for p, c, s, t, q in transforms]
        expected = cdr.serialize(
            tf2_msgs.TFMessage(
                transforms=[
                    fill_transform_stamped(geometry_msgs.TransformStamped(), p, c, s, t, q)
                    for p, c, s, t, q in renamed
                ]
            )
        )
        encoded = encoder.encode_stamped(transforms)
        assert encoded == expected
        assert cdr.decode_tf_message_transforms(encoded) == renamed


def test_a_stamp_time_cannot_hold_is_an_overflow_error() -> None:
    pose = ((0.0, 0.0, 0.0), (0.0, 0.0, 0.0, 1.0))
    with pytest.raises(OverflowError, match='does not fit'):
        TfMessageEncoder().encode_stamped([('a', 'b', 2**31 * SECOND, *pose)])
