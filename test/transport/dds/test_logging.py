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

"""Loggers: levels, rclpy's once/skip_first/throttle options, and a process' log lines.

The tests run in both worlds on the world's loggers (``tf_demo.transport.logging`` names are
rclpy's inside ROS 2) and check what rclpy and rcutils do; the processes run in the test's world.
"""

from pathlib import Path
import re
import sys
from typing import Any

from conftest import run_captured
import pytest
from tf_demo.transport.clock import Clock
from tf_demo.transport.clock import ClockType
from tf_demo.transport.logging import get_logger
from tf_demo.transport.logging import LoggingSeverity

LINE = re.compile(r'^\[(DEBUG|INFO|WARN|ERROR|FATAL)\] \[(\d+)\.(\d{9})\] \[([^\]]+)\]: (.*)$')


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
    matches = [LINE.match(line) for line in capfd.readouterr().err.splitlines()]
    messages = [match.group(5) if match else None for match in matches]
    assert messages == ['once 0', 'throttle 0', 'skip 1', 'skip 2']
    with pytest.raises(TypeError, match='not one of the recognized logging options'):
        logger.info('x', every_n=3)
    logger.set_level(LoggingSeverity.WARN)
    assert logger.info('x', every_n=3) is False  # below the level the options are not checked


SCRIPT = """
import sys
from typing import Any
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


def run_logging_script(
    tmp_path: Path, world_env: dict[str, str], *ros_args: str, script: str = SCRIPT, **env: str
) -> list[str]:
    """Run ``script`` in this run's world with ``--ros-args ros_args``; return its stderr lines."""
    path = tmp_path / 'log.py'
    path.write_text(script, encoding='utf-8')
    environment = dict(world_env)  # PYTHONPATH: the source tree, then the world's own
    environment.pop('RCUTILS_CONSOLE_OUTPUT_FORMAT', None)
    environment.pop('RCUTILS_LOGGING_USE_STDOUT', None)
    environment.update(env)
    completed = run_captured([sys.executable, str(path), '--ros-args', *ros_args], environment)
    assert completed.returncode == 0, completed.stderr
    assert completed.stdout == ''
    return completed.stderr.splitlines()


def test_process_logs_to_stderr_in_rcutils_format(
    tmp_path: Path, world_env: dict[str, str]
) -> None:
    """A real process writes INFO and above to stderr, one line each, in rclpy's format."""
    lines = run_logging_script(tmp_path, world_env, RCUTILS_COLORIZED_OUTPUT='0')
    parsed = [LINE.match(line) for line in lines]
    assert all(parsed), lines
    assert [(m.group(1), m.group(4), m.group(5)) for m in parsed if m][:4] == [
        ('INFO', 'talker', 'info from talker'),
        ('WARN', 'talker', 'warn from talker'),
        ('ERROR', 'talker', 'error from talker'),
        ('FATAL', 'talker', 'fatal from talker'),
    ]
    assert len(lines) == 8


def test_log_level_argument_sets_default_and_per_logger_levels(
    tmp_path: Path, world_env: dict[str, str]
) -> None:
    """--log-level error hides INFO/WARN; --log-level talker:=debug shows talker's DEBUG."""
    lines = run_logging_script(
        tmp_path,
        world_env,
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


def test_colorized_output_wraps_lines_in_rcutils_colors(
    tmp_path: Path, world_env: dict[str, str]
) -> None:
    """RCUTILS_COLORIZED_OUTPUT=1 colours WARN yellow and resets at the end of the line."""
    lines = run_logging_script(tmp_path, world_env, RCUTILS_COLORIZED_OUTPUT='1')
    warn = next(line for line in lines if 'warn from talker' in line)
    assert warn.startswith('\x1b[33m[WARN] [')
    assert warn.endswith('\x1b[0m')


FORMAT_SCRIPT = """
import sys
from tf_demo.transport import init
from tf_demo.transport.logging import get_logger
init(sys.argv)
def emit():
    get_logger('fmt').warning('hello')
emit()
"""


def test_output_format_tokens_escapes_and_unknown_tokens(
    tmp_path: Path, world_env: dict[str, str]
) -> None:
    """RCUTILS_CONSOLE_OUTPUT_FORMAT: rcutils' tokens and escapes; of '{x' only '{' is kept."""
    fields = (
        '{severity}|{name}|{message}|{function_name}|{line_number}|{time}|{time_as_nanoseconds}'
        '|{nope}|{x{name}}|a\\tb\\x1bc'
    )  # (not an unknown escape such as \\q: rcutils copies garbage after one)
    [line] = run_logging_script(
        tmp_path,
        world_env,
        script=FORMAT_SCRIPT,
        RCUTILS_COLORIZED_OUTPUT='0',
        RCUTILS_CONSOLE_OUTPUT_FORMAT=fields,
    )
    severity, name, message, function, number, seconds, nanoseconds, *rest = line.split('|')
    assert (severity, name, message, function, number) == ('WARN', 'fmt', 'hello', 'emit', '7')
    assert re.fullmatch(r'\d{10}\.\d{9}', seconds), seconds
    assert re.fullmatch(r'\d{19}', nanoseconds), nanoseconds
    whole, fraction = divmod(int(nanoseconds), 1_000_000_000)
    assert seconds == f'{whole:010d}.{fraction:09d}'  # the same stamp, nanoseconds padded
    assert rest == ['{nope}', '{xfmt}', 'a\tb\x1bc']


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
    match = LINE.match(line)
    assert match is not None
    assert match.group(4) == 'test_logging_b'


def _log_at(logger: Any, severity: LoggingSeverity, text: str, **options: Any) -> bool:
    """One call site used with whatever severity and options the caller passes."""
    return bool(logger.log(text, severity, **options))


def test_a_call_site_keeps_its_first_severity_as_in_rclpy() -> None:
    """rclpy keys state by call site: another severity there raises ValueError (its text)."""
    logger = get_logger('test_logging_call_site_severity')
    assert _log_at(logger, LoggingSeverity.WARN, 'first')
    assert _log_at(logger, LoggingSeverity.WARN, 'same severity again')
    with pytest.raises(ValueError, match=r'^Logger severity cannot be changed between calls\.$'):
        _log_at(logger, LoggingSeverity.ERROR, 'other severity')

    def report(level: int) -> None:  # the pattern this rule breaks: one expression, two methods
        (logger.warning if level == 30 else logger.error)('x')

    report(30)
    with pytest.raises(ValueError, match='severity cannot be changed'):
        report(40)
    # a new logger object starts with fresh call-site state, as rclpy.logging.get_logger's do
    assert _log_at(get_logger('test_logging_call_site_severity'), LoggingSeverity.ERROR, 'ok')


def test_two_calls_on_one_line_are_two_call_sites() -> None:
    """Like rclpy's CallerId (which includes f_lasti), two calls on one line are distinct."""
    logger = get_logger('test_logging_one_line')
    assert logger.warning('a') and logger.error('b')  # noqa: PT018 - one line on purpose


def test_a_call_below_the_level_leaves_no_call_site_state() -> None:
    """rclpy checks the level first: a call below it neither fixes the call site nor checks."""
    logger = get_logger('test_logging_below_level')
    logger.set_level(LoggingSeverity.ERROR)
    assert not _log_at(logger, LoggingSeverity.DEBUG, 'hidden', once=True)
    assert _log_at(logger, LoggingSeverity.ERROR, 'shown')  # another severity and no once: fine
    assert not _log_at(logger, LoggingSeverity.DEBUG, 'hidden again', once=True)
    with pytest.raises(ValueError, match='severity cannot be changed'):
        _log_at(logger, LoggingSeverity.FATAL, 'shown')


def test_name_and_filter_options_are_fixed_per_call_site() -> None:
    """name=, the set of filters and their parameters cannot change at a call site."""
    logger = get_logger('test_logging_fixed_options')
    _log_at(logger, LoggingSeverity.INFO, 'x', name='test_logging_fixed_a')
    with pytest.raises(ValueError, match=r'^Logger name cannot be changed between calls\.$'):
        _log_at(logger, LoggingSeverity.INFO, 'x', name='test_logging_fixed_b')
    other = get_logger('test_logging_fixed_filters')
    _log_at(other, LoggingSeverity.INFO, 'x', throttle_duration_sec=10.0)
    with pytest.raises(ValueError, match=r'^Logging filter parameters cannot be changed'):
        _log_at(other, LoggingSeverity.INFO, 'x', throttle_duration_sec=5.0)
    with pytest.raises(ValueError, match=r'^Requested logging filters cannot be changed'):
        _log_at(other, LoggingSeverity.INFO, 'x', throttle_duration_sec=10.0, once=True)


def test_incomplete_or_unsupported_filter_options_are_refused_with_rclpys_texts() -> None:
    """A throttle without its duration is a TypeError; another time source a ValueError."""
    logger = get_logger('test_logging_filter_texts')
    with pytest.raises(TypeError, match='required parameter "throttle_duration_sec" not spec'):
        logger.info('x', throttle_time_source_type='RCUTILS_STEADY_TIME')
    with pytest.raises(ValueError, match='"RCUTILS_ROS_TIME" is not a clock instance'):
        logger.info('x', throttle_duration_sec=1.0, throttle_time_source_type='RCUTILS_ROS_TIME')


def test_throttle_measures_on_the_given_clock_and_logs_the_first_call() -> None:
    """rclpy Jazzy's throttle: system time by default (the first call logs), or a given Clock."""
    logger = get_logger('test_logging_throttle_clock')
    system = [logger.info('a', throttle_duration_sec=1e6) for _ in range(2)]
    steady = Clock(clock_type=ClockType.STEADY_TIME)
    given = logger.info('b', throttle_duration_sec=1e-3, throttle_time_source_type=steady)
    assert system == [True, False]
    assert given is True  # steady time since boot is past 1 ms


def test_messages_must_be_strings_when_printed(capfd: pytest.CaptureFixture[str]) -> None:
    """rclpy's C logging call takes str (or UTF-8 bytes); below the level nothing is checked."""
    logger = get_logger('test_logging_message_type')
    logger.set_level(LoggingSeverity.WARN)
    assert logger.info(42) is False
    with pytest.raises(TypeError, match=r'^rclpy_logging_rcutils_log\(\): incompatible function'):
        logger.warning(42)
    with pytest.raises(TypeError, match=r'Invoked with: .*, 42, '):
        logger.error('text', name=42)
    assert logger.warning(b'bytes are text') is True
    assert logger.warning('cut at\0 the NUL') is True
    messages = [m.group(5) for m in map(LINE.match, capfd.readouterr().err.splitlines()) if m]
    assert messages == ['bytes are text', 'cut at']
