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

"""PerWriterThrottle: the first bad sample of a writer in full, then a count per period."""

from __future__ import annotations

from tf_demo.msgs.log_throttle import PerWriterThrottle
from tf_demo.msgs.log_throttle import writer_name

S = 1_000_000_000
GID = bytes(range(16))


class FakeClock:
    """A monotonic clock the test moves by hand."""

    def __init__(self) -> None:
        self.now_ns = 0

    def __call__(self) -> int:
        return self.now_ns


def test_first_sample_is_logged_verbatim_then_counted_once_per_period() -> None:
    """Thousands of bad samples in one period give one full line; the next period one count."""
    clock = FakeClock()
    throttle = PerWriterThrottle('malformed samples', period_ns=5 * S, clock_ns=clock)
    assert throttle.line(GID, 'first error') == 'first error'
    lines = [throttle.line(GID, f'error {index}') for index in range(3000)]
    assert lines == [None] * 3000
    clock.now_ns = 5 * S
    assert throttle.line(GID, 'error 3000') == (
        '3001 more malformed samples from writer 00.01.02.03.04.05.06.07.08.09.0a.0b.0c.0d.0e.0f'
        ' in the last 5.0 s; the latest: error 3000'
    )
    assert throttle.line(GID, 'error 3001') is None
    assert throttle.pending() == [
        '1 more malformed samples from writer 00.01.02.03.04.05.06.07.08.09.0a.0b.0c.0d.0e.0f'
        ' in the last 0.0 s; the latest: error 3001'
    ]
    assert throttle.pending() == []


def test_each_writer_and_kind_gets_its_own_first_line() -> None:
    """A second writer's (or a second kind's) first bad sample is not hidden by the first's."""
    throttle = PerWriterThrottle('rejected transforms', clock_ns=FakeClock())
    assert throttle.line('a', 'TF_NAN_INPUT: x', 'TF_NAN_INPUT') == 'TF_NAN_INPUT: x'
    assert throttle.line('b', 'TF_NAN_INPUT: y', 'TF_NAN_INPUT') == 'TF_NAN_INPUT: y'
    assert throttle.line('a', 'TF_SELF_TRANSFORM: z', 'TF_SELF_TRANSFORM') is not None
    assert throttle.line('a', 'TF_NAN_INPUT: x', 'TF_NAN_INPUT') is None
    assert throttle.pending() == [
        '1 more rejected transforms (TF_NAN_INPUT) from a in the last 0.0 s; the latest: '
        'TF_NAN_INPUT: x'
    ]


def test_memory_is_bounded_by_the_number_of_writers_remembered() -> None:
    """Many writers make the oldest forgotten, never an unbounded table; quotes are cut."""
    throttle = PerWriterThrottle('malformed samples', clock_ns=FakeClock(), max_writers=8)
    for index in range(1000):
        assert throttle.line(f'w{index}', 'x') == 'x'
    assert len(throttle._counts) == 8
    throttle.line('w999', 'y' * 10_000)
    (line,) = throttle.pending()
    assert len(line) < 500
    assert line.endswith('y...')


def test_writer_names() -> None:
    """A GUID is printed as ros2cli prints gids; a description is used as it is."""
    assert writer_name(GID).startswith('writer 00.01.02.')
    assert writer_name(b'') == 'writer (no gid)'
    assert writer_name("a writer on '/tf'") == "a writer on '/tf'"
