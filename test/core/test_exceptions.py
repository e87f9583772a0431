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

"""tf2's exact message texts not covered elsewhere: argument labels and log formats."""

from __future__ import annotations

import logging
import math

import pytest
from tf_demo.core import BufferCore
from tf_demo.core import ConnectivityException
from tf_demo.core import InvalidArgumentException
from tf_demo.core import LookupException

S = 1_000_000_000
IDENTITY = (0.0, 0.0, 0.0, 1.0)


def _core() -> BufferCore:
    core = BufferCore()
    core.set_transform('a', 'b', S, (0, 0, 0), IDENTITY)
    core.set_transform('c', 'd', S, (0, 0, 0), IDENTITY)
    return core


@pytest.mark.parametrize(
    ('target', 'source', 'error', 'text'),
    [
        (
            '',
            'a',
            InvalidArgumentException,
            'Invalid argument "" passed to get_latest_common_time - in tf2 frame_ids cannot be '
            'empty',
        ),
        (
            'a',
            '/b',
            InvalidArgumentException,
            'Invalid argument "/b" passed to get_latest_common_time - in tf2 frame_ids cannot '
            "start with a '/'",
        ),
        ('a', 'zz', LookupException, '"zz" passed to get_latest_common_time does not exist. '),
        (
            'a',
            'd',
            ConnectivityException,
            "Could not find a connection between 'a' and 'd' because they are not part of the "
            'same tree.Tf has two or more unconnected trees.',
        ),
    ],
)
def test_latest_common_time_errors(target, source, error, text):
    """get_latest_common_time uses tf2_py's label and the core's texts."""
    with pytest.raises(error) as info:
        _core().get_latest_common_time(target, source)
    assert str(info.value) == text


def test_full_lookup_labels_in_order():
    """The fixed-frame lookup validates target, source, then fixed with tf2's labels."""
    core = _core()
    with pytest.raises(InvalidArgumentException) as info:
        core.lookup_transform_full('a', 0, 'b', 0, '/x')
    assert str(info.value) == (
        'Invalid argument "/x" passed to lookupTransform argument fixed_frame - in tf2 '
        "frame_ids cannot start with a '/'"
    )
    with pytest.raises(LookupException) as lookup_info:
        core.lookup_transform_full('q', 0, 'r', 0, 's')
    assert (
        str(lookup_info.value)
        == '"q" passed to lookupTransform argument target_frame does not exist. '
    )
    assert not core.can_transform_full('a', 0, 'b', 0, '')
    assert core.transform_error_full('a', 0, 'b', 0, '') == (
        'Invalid frame ID "" passed to canTransform argument fixed_frame - in tf2 frame_ids '
        'cannot be empty'
    )


def test_full_lookup_has_no_same_frame_shortcut():
    """Unlike the simple lookup, the fixed-frame lookup validates even equal names."""
    with pytest.raises(LookupException):
        _core().lookup_transform_full('zz', 0, 'zz', 0, 'zz')


def test_nan_input_log_prints_c_style_values():
    """TF_NAN_INPUT prints values with %f: inf stays 'inf', NaN prints 'nan'."""
    lines = []
    core = BufferCore(log=lambda level, text: lines.append((level, text)))
    assert not core.set_transform('p', 'c', S, (math.inf, math.nan, -math.inf), IDENTITY, 'au')
    assert lines == [
        (
            logging.ERROR,
            'TF_NAN_INPUT: Ignoring transform for child_frame_id "c" from authority "au" because '
            'of a nan value in the transform (inf nan -inf) (0.000000 0.000000 0.000000 '
            '1.000000)',
        )
    ]


def test_inf_minus_inf_translation_is_not_a_nan():
    """Opposite infinities in the translation are accepted like any other inf (no NaN)."""
    lines = []
    core = BufferCore(log=lambda level, text: lines.append(text))
    assert core.set_transform('p', 'c', S, (math.inf, -math.inf, 0.0), IDENTITY)
    assert lines == []


class _Collect(logging.Handler):
    def __init__(self) -> None:
        super().__init__(logging.ERROR)
        self.records: list[logging.LogRecord] = []

    def emit(self, record: logging.LogRecord) -> None:
        self.records.append(record)


def test_default_log_goes_to_stdlib_logger():
    """Without a log function the texts go to the 'tf_demo.core' logger."""
    # A handler on the logger itself: inside ROS 2, launch's logging setup stops propagation
    # to the root logger that pytest's caplog listens on.
    core = BufferCore()
    logger = logging.getLogger('tf_demo.core')
    collect = _Collect()
    logger.addHandler(collect)
    try:
        core.set_transform('x', 'x', S, (0, 0, 0), IDENTITY, 'me')
    finally:
        logger.removeHandler(collect)
    assert collect.records[0].name == 'tf_demo.core'
    assert collect.records[0].getMessage().startswith('TF_SELF_TRANSFORM: Ignoring transform')
