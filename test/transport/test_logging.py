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

"""Log lines in rcutils' console format, levels, and rclpy's once/skip_first/throttle options."""

import os
from pathlib import Path
import re
import subprocess
import sys

import pytest
from tf_demo.transport.logging import format_log_line
from tf_demo.transport.logging import get_logger
from tf_demo.transport.logging import get_logging_severity_from_string
from tf_demo.transport.logging import LoggingSeverity

REPO_ROOT = Path(__file__).resolve().parents[2]
LINE = re.compile(r'^\[(DEBUG|INFO|WARN|ERROR|FATAL)\] \[(\d+)\.(\d{9})\] \[([^\]]+)\]: (.*)$')


def test_default_format_pads_nanoseconds_to_nine_digits() -> None:
    """The rcutils default line is [LEVEL] [sec.nnnnnnnnn] [name]: message."""
    line = format_log_line(LoggingSeverity.WARN, 'ns.talker', 'hello', 1_700_000_000_000_000_042)
    assert line == '[WARN] [1700000000.000000042] [ns.talker]: hello'


def test_custom_output_format_tokens() -> None:
    """RCUTILS_CONSOLE_OUTPUT_FORMAT tokens are substituted; unknown ones are kept."""
    line = format_log_line(
        LoggingSeverity.ERROR,
        'n',
        'm',
        5_000_000_123,
        output_format='{severity}|{time_as_nanoseconds}|{name}|{message}|{line_number}|{nope}',
        line_number=12,
    )
    assert line == 'ERROR|5000000123|n|m|12|{nope}'


def test_severity_names_parse_case_insensitively() -> None:
    """Level names are case-insensitive; 'warning' means WARN; unknown names raise."""
    assert get_logging_severity_from_string('Debug') is LoggingSeverity.DEBUG
    assert get_logging_severity_from_string('WARNING') is LoggingSeverity.WARN
    with pytest.raises(ValueError, match="Unknown log severity 'verbose'"):
        get_logging_severity_from_string('verbose')


def test_child_loggers_inherit_their_parents_level() -> None:
    """A.b takes A's level until it has its own; the default applies otherwise."""
    parent = get_logger('test_logging_parent')
    child = parent.get_child('child')
    assert child.name == 'test_logging_parent.child'
    parent.set_level(LoggingSeverity.ERROR)
    assert not child.is_enabled_for(LoggingSeverity.WARN)
    child.set_level(LoggingSeverity.DEBUG)
    assert child.is_enabled_for(LoggingSeverity.DEBUG)
    assert not parent.is_enabled_for(LoggingSeverity.DEBUG)


def test_options_once_skip_first_and_throttle(capfd: pytest.CaptureFixture[str]) -> None:
    """once prints the first call, skip_first all but the first, throttle the first in a window."""
    logger = get_logger('test_logging_options')
    printed = []
    for index in range(3):
        printed.append(logger.info(f'once {index}', once=True))
        printed.append(logger.info(f'skip {index}', skip_first=True))
        printed.append(logger.info(f'throttle {index}', throttle_duration_sec=3600.0))
    assert printed == [True, False, True, False, True, False, False, True, False]
    messages = [LINE.match(line).group(5) for line in capfd.readouterr().err.splitlines()]
    assert messages == ['once 0', 'throttle 0', 'skip 1', 'skip 2']
    with pytest.raises(TypeError, match='not one of the recognized logging options'):
        logger.info('x', every_n=3)


SCRIPT = """
import sys
from tf_demo.transport import init
from tf_demo.transport.logging import get_logger
init(sys.argv)
for name in ('talker', 'listener'):
    logger = get_logger(name)
    logger.debug('debug from ' + name)
    logger.info('info from ' + name)
    logger.warning('warn from ' + name)
    logger.error('error from ' + name)
    logger.fatal('fatal from ' + name)
"""


def run_logging_script(tmp_path: Path, *ros_args: str, **env: str) -> list[str]:
    script = tmp_path / 'log.py'
    script.write_text(SCRIPT, encoding='utf-8')
    environment = dict(os.environ, PYTHONPATH=str(REPO_ROOT), TF_DEMO_BACKEND='dds', **env)
    environment.pop('RCUTILS_CONSOLE_OUTPUT_FORMAT', None)
    environment.update(env)
    completed = subprocess.run(
        [sys.executable, str(script), '--ros-args', *ros_args],
        env=environment,
        capture_output=True,
        text=True,
        timeout=60,
        check=True,
    )
    assert completed.stdout == ''
    return completed.stderr.splitlines()


def test_process_logs_to_stderr_in_rcutils_format(tmp_path: Path) -> None:
    """A real process writes INFO and above to stderr, one line each, in rclpy's format."""
    lines = run_logging_script(tmp_path, RCUTILS_COLORIZED_OUTPUT='0')
    parsed = [LINE.match(line) for line in lines]
    assert all(parsed), lines
    assert [(m.group(1), m.group(4), m.group(5)) for m in parsed if m][:4] == [
        ('INFO', 'talker', 'info from talker'),
        ('WARN', 'talker', 'warn from talker'),
        ('ERROR', 'talker', 'error from talker'),
        ('FATAL', 'talker', 'fatal from talker'),
    ]
    assert len(lines) == 8


def test_log_level_argument_sets_default_and_per_logger_levels(tmp_path: Path) -> None:
    """--log-level error hides INFO/WARN; --log-level talker:=debug shows talker's DEBUG."""
    lines = run_logging_script(
        tmp_path,
        '--log-level',
        'error',
        '--log-level',
        'talker:=debug',
        RCUTILS_COLORIZED_OUTPUT='0',
    )
    seen = [(m.group(1), m.group(4)) for m in map(LINE.match, lines) if m]
    assert seen == [
        ('DEBUG', 'talker'),
        ('INFO', 'talker'),
        ('WARN', 'talker'),
        ('ERROR', 'talker'),
        ('FATAL', 'talker'),
        ('ERROR', 'listener'),
        ('FATAL', 'listener'),
    ]


def test_colorized_output_wraps_lines_in_rcutils_colors(tmp_path: Path) -> None:
    """RCUTILS_COLORIZED_OUTPUT=1 colours WARN yellow and resets at the end of the line."""
    lines = run_logging_script(tmp_path, RCUTILS_COLORIZED_OUTPUT='1')
    warn = next(line for line in lines if 'warn from talker' in line)
    assert warn.startswith('\x1b[33m[WARN] [')
    assert warn.endswith('\x1b[0m')


def test_filters_are_not_consumed_by_calls_below_the_level(
    capfd: pytest.CaptureFixture[str],
) -> None:
    """As in rclpy, once is only spent by a call that passes the level check."""
    logger = get_logger('test_logging_level_then_once')
    logger.set_level(LoggingSeverity.ERROR)
    results = []
    for level in (LoggingSeverity.ERROR, LoggingSeverity.INFO, LoggingSeverity.INFO):
        logger.set_level(level)
        results.append(logger.info('first allowed call', once=True))
    assert results == [False, True, False]
    assert capfd.readouterr().err.count('first allowed call') == 1


def test_name_option_logs_under_another_logger(capfd: pytest.CaptureFixture[str]) -> None:
    """The name= keyword logs under that logger name, as rclpy's RcutilsLogger.log does."""
    get_logger('test_logging_a').log('x', LoggingSeverity.WARN, name='test_logging_b')
    [line] = capfd.readouterr().err.splitlines()
    assert LINE.match(line).group(4) == 'test_logging_b'
