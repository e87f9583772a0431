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

"""Conversions between messages and the core's nanoseconds and tuples."""

from __future__ import annotations

from hypothesis import given
from hypothesis import strategies as st
import pytest
from tf_demo.msgs import cdr
from tf_demo.msgs.builtin_interfaces import Time
from tf_demo.msgs.convert import fill_transform_stamped
from tf_demo.msgs.convert import ns_from_stamp
from tf_demo.msgs.convert import stamp_fields_from_ns
from tf_demo.msgs.convert import transform_stamped_args
from tf_demo.msgs.geometry_msgs import TransformStamped
from tf_demo.msgs.tf2_msgs import TFMessage


@pytest.mark.property
@given(st.integers(-(2**31) * 10**9, (2**31 - 1) * 10**9 + 999_999_999))
def test_nanoseconds_round_trip_through_stamp_fields(ns: int) -> None:
    """Any int32-seconds time splits into (sec, 0 <= nanosec < 1e9) and back."""
    sec, nanosec = stamp_fields_from_ns(ns)
    assert 0 <= nanosec < 10**9
    assert ns_from_stamp(Time(sec=sec, nanosec=nanosec)) == ns


def test_negative_time_borrows_a_second_like_rclpy() -> None:
    """-1.7 s is sec=-2, nanosec=3e8 (builtin_interfaces/Time's documented convention)."""
    assert stamp_fields_from_ns(-1_700_000_000) == (-2, 300_000_000)


def test_out_of_range_time_is_a_clear_error() -> None:
    """Seconds beyond int32 raise ValueError instead of wrapping on the wire."""
    with pytest.raises(ValueError, match='out of the range of builtin_interfaces/Time'):
        stamp_fields_from_ns(2**31 * 10**9)


def test_fill_and_read_transform_stamped_agree() -> None:
    """fill_transform_stamped then transform_stamped_args gives back the same values."""
    message = fill_transform_stamped(
        TransformStamped(), 'odom', 'base_link', 5_000_000_007, (1, 2, 3), (0.0, 0.0, 0.6, 0.8)
    )
    assert message.header.stamp.sec == 5
    assert message.header.stamp.nanosec == 7
    assert isinstance(message.transform.translation.x, float)
    assert transform_stamped_args(message) == (
        'odom',
        'base_link',
        5_000_000_007,
        (1.0, 2.0, 3.0),
        (0.0, 0.0, 0.6, 0.8),
    )


def test_transform_stamped_args_match_the_tf_fast_path() -> None:
    """The listener's fast decode and convert on decoded messages give identical tuples."""
    message = TFMessage(
        transforms=[
            fill_transform_stamped(
                TransformStamped(), 'map', f'f{i}', i * 10**8, (i, 0, 0), (0, 0, 0, 1)
            )
            for i in range(5)
        ]
    )
    data = cdr.serialize(message)
    decoded = cdr.deserialize(TFMessage, data)
    assert cdr.decode_tf_message_transforms(data) == [
        transform_stamped_args(t) for t in decoded.transforms
    ]


def test_fill_rejects_wrong_vector_lengths() -> None:
    """A 3-element rotation is a ValueError naming both lengths."""
    with pytest.raises(ValueError, match='got 3 and 3'):
        fill_transform_stamped(TransformStamped(), 'a', 'b', 0, (0, 0, 0), (0, 0, 1))
