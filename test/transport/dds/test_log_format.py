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

"""rcutils' console line format (:func:`format_log_line`, standalone) and severity names.

The severity names are checked in both worlds (rclpy's ``get_logging_severity_from_string``
inside ROS 2); the formatter is the standalone world's own.
"""

import pytest
from tf_demo.transport.logging import format_log_line
from tf_demo.transport.logging import get_logging_severity_from_string
from tf_demo.transport.logging import LoggingSeverity


@pytest.mark.standalone
def test_default_format_pads_seconds_and_nanoseconds_as_rcutils() -> None:
    """The rcutils default line is [LEVEL] [ssssssssss.nnnnnnnnn] [name]: message."""
    line = format_log_line(LoggingSeverity.WARN, 'ns.talker', 'hello', 1_700_000_000_000_000_042)
    assert line == '[WARN] [1700000000.000000042] [ns.talker]: hello'
    # rcutils prints "%.10" PRId64 ".%.9" PRId64: at least ten digits of seconds
    line = format_log_line(LoggingSeverity.INFO, 'n', 'm', 5_000_000_123)
    assert line == '[INFO] [0000000005.000000123] [n]: m'


@pytest.mark.standalone
def test_custom_output_format_tokens() -> None:
    """Tokens are substituted as rcutils does; of an unknown one only the '{' is copied."""
    line = format_log_line(
        LoggingSeverity.ERROR,
        'n',
        'm',
        5_000_000_123,
        output_format='{severity}|{time_as_nanoseconds}|{name}|{message}|{line_number}|{nope}'
        '|{x{name}}',
        line_number=12,
    )
    assert line == 'ERROR|0000000005000000123|n|m|12|{nope}|{xn}'


def test_severity_names_parse_as_rcutils_parses_them() -> None:
    """Level names are ASCII case-insensitive; nothing else ('warning', spaces) is a level."""
    assert get_logging_severity_from_string('Debug') is LoggingSeverity.DEBUG
    assert get_logging_severity_from_string('WARN') is LoggingSeverity.WARN
    assert get_logging_severity_from_string('unset') is LoggingSeverity.UNSET
    for unknown in ('WARNING', 'verbose', ' info', ''):
        with pytest.raises(RuntimeError, match=r'^Failed to get severity name$'):
            get_logging_severity_from_string(unknown)
    with pytest.raises(TypeError, match='incompatible function arguments'):
        get_logging_severity_from_string(3)  # type: ignore[arg-type]
