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
rcutils' console output: severities, the line format and its settings.

A line is ``[LEVEL] [<sec>.<nsec, 9 digits>] [<logger name>]: <message>``, the rcutils default;
``RCUTILS_CONSOLE_OUTPUT_FORMAT`` (``{severity}``, ``{name}``, ``{message}``, ``{time}``,
``{time_as_nanoseconds}``, ``{date_time_with_ms}``, ``{function_name}``, ``{file_name}``,
``{line_number}``) and ``RCUTILS_COLORIZED_OUTPUT`` are honoured, and
``RCUTILS_LOGGING_USE_STDOUT=1`` sends the lines to stdout. Pure functions of their arguments
and the environment: the tools print their own lines with :func:`format_log_line` in both worlds.
"""

from __future__ import annotations

from collections.abc import Callable
from enum import IntEnum
import os
import sys
import time
from typing import TextIO

#: rclpy.logging's names and the two the tools use in both worlds (the facade star-imports these).
__all__ = [
    'DEFAULT_OUTPUT_FORMAT',
    'LoggingSeverity',
    'format_log_line',
    'get_logging_severity_from_string',
]

DEFAULT_OUTPUT_FORMAT = '[{severity}] [{time}] [{name}]: {message}'


class LoggingSeverity(IntEnum):
    """Severity levels, with rcutils' values."""

    UNSET = 0
    DEBUG = 10
    INFO = 20
    WARN = 30
    ERROR = 40
    FATAL = 50


_COLORS = {
    LoggingSeverity.DEBUG: '\033[32m',
    LoggingSeverity.INFO: '\033[0m',
    LoggingSeverity.WARN: '\033[33m',
    LoggingSeverity.ERROR: '\033[31m',
    LoggingSeverity.FATAL: '\033[31m',
}
_COLOR_RESET = '\033[0m'


_ASCII_UPPER = str.maketrans('abcdefghijklmnopqrstuvwxyz', 'ABCDEFGHIJKLMNOPQRSTUVWXYZ')


def c_string(value: object) -> str | None:
    """
    Return ``value`` as rclpy's C extension reads a string argument, else None.

    pybind11 takes ``str`` and ``bytes`` (UTF-8); C stops at the first NUL character.
    """
    if isinstance(value, bytes):
        value = value.decode('utf-8', errors='replace')
    if not isinstance(value, str):
        return None
    return value.partition('\0')[0]


def incompatible_arguments(function: str, signature: str, arguments: tuple[object, ...]) -> str:
    """pybind11's text for a call of ``function`` with arguments of the wrong types."""
    invoked = ', '.join(repr(argument) for argument in arguments)
    return (
        f'{function}(): incompatible function arguments. The following argument types are '
        f'supported:\n    1. {signature}\n\nInvoked with: {invoked}'
    )


def get_logging_severity_from_string(log_severity: str) -> LoggingSeverity:
    """
    Return the severity named ``log_severity``, as rcutils parses it.

    The name is compared in ASCII upper case with ``UNSET``, ``DEBUG``, ``INFO``, ``WARN``,
    ``ERROR`` and ``FATAL`` (no ``warning``, no stripping).

    :raises RuntimeError: for an unknown name (rclpy's text).
    :raises TypeError: for a value that is not a string (pybind11's text).
    """
    key = c_string(log_severity)
    if key is None:
        msg = incompatible_arguments(
            'rclpy_logging_severity_level_from_string', '(arg0: str) -> int', (log_severity,)
        )
        raise TypeError(msg)
    severity = LoggingSeverity.__members__.get(key.translate(_ASCII_UPPER))
    if severity is None:
        msg = 'Failed to get severity name'
        raise RuntimeError(msg)
    return severity


def format_log_line(
    severity: LoggingSeverity,
    name: str,
    message: str,
    stamp_ns: int,
    *,
    output_format: str = DEFAULT_OUTPUT_FORMAT,
    function_name: str = '',
    file_name: str = '',
    line_number: int = 0,
) -> str:
    """
    Format one console line as rcutils does (without the trailing newline).

    As rcutils: ``{time}`` has at least 10 digits of seconds, ``{time_as_nanoseconds}`` at
    least 19 digits; of a ``{`` that does not start a known token only the ``{`` is copied and
    the search goes on after it (``{x{name}}`` gives ``{x<name>}``).
    """
    sec, nsec = divmod(abs(stamp_ns), 1_000_000_000)
    sign = '-' if stamp_ns < 0 else ''
    tokens: dict[str, Callable[[], str]] = {
        'severity': lambda: severity.name,
        'name': lambda: name,
        'message': lambda: message,
        # rcutils_time_point_value_as_seconds_string: "%s%.10" PRId64 ".%.9" PRId64
        'time': lambda: f'{sign}{sec:010d}.{nsec:09d}',
        # "%.19" PRId64: at least 19 digits
        'time_as_nanoseconds': lambda: f'{sign}{abs(stamp_ns):019d}',
        # rcutils appends ".%.3s" of the unpadded nanoseconds (42 ns gives ".42")
        'date_time_with_ms': lambda: (
            time.strftime('%Y-%m-%d %H:%M:%S', time.localtime(sec)) + f'.{str(nsec)[:3]}'
        ),
        'function_name': lambda: function_name,
        'file_name': lambda: file_name,
        'line_number': lambda: str(line_number),
    }
    pieces: list[str] = []
    index = 0
    while index < len(output_format):
        start = output_format.find('{', index)
        if start < 0:
            pieces.append(output_format[index:])
            break
        end = output_format.find('}', start)
        if end < 0:
            pieces.append(output_format[index:])
            break
        pieces.append(output_format[index:start])
        producer = tokens.get(output_format[start + 1 : end])
        if producer is None:
            pieces.append('{')
            index = start + 1
            continue
        pieces.append(producer())
        index = end + 1
    return ''.join(pieces)


_FORMAT_ESCAPES = {'a': '\a', 'b': '\b', 'n': '\n', 'r': '\r', 't': '\t'}
_MAX_OUTPUT_FORMAT_LEN = 2048
"""rcutils' RCUTILS_LOGGING_MAX_OUTPUT_FORMAT_LEN (the format is cut to one less)."""


def _output_format() -> str:
    r"""
    Return ``RCUTILS_CONSOLE_OUTPUT_FORMAT`` decoded as rcutils decodes it, else the default.

    ``\a``, ``\b``, ``\n``, ``\r``, ``\t`` and ``\x1b`` become the characters they
    name; any other backslash pair is kept as it is.
    """
    raw = os.environ.get('RCUTILS_CONSOLE_OUTPUT_FORMAT') or DEFAULT_OUTPUT_FORMAT
    raw = raw[: _MAX_OUTPUT_FORMAT_LEN - 1]
    pieces: list[str] = []
    index = 0
    while index < len(raw):
        slash = raw.find('\\', index)
        if slash < 0:
            pieces.append(raw[index:])
            break
        pieces.append(raw[index:slash])
        if raw.startswith('x1b', slash + 1):
            pieces.append('\x1b')
            index = slash + 4
            continue
        escaped = _FORMAT_ESCAPES.get(raw[slash + 1 : slash + 2])
        pieces.append(escaped if escaped is not None else raw[slash : slash + 2])
        index = slash + 2
    return ''.join(pieces)


def _stream() -> TextIO:
    use_stdout = os.environ.get('RCUTILS_LOGGING_USE_STDOUT', '0') == '1'
    return sys.stdout if use_stdout else sys.stderr


def _colorize(stream: TextIO) -> bool:
    setting = os.environ.get('RCUTILS_COLORIZED_OUTPUT')
    if setting == '1':
        return True
    if setting == '0':
        return False
    isatty = getattr(stream, 'isatty', None)
    return bool(isatty and isatty())


def console_line(
    severity: LoggingSeverity,
    name: str,
    message: str,
    stamp_ns: int,
    *,
    function_name: str,
    file_name: str,
    line_number: int,
) -> tuple[TextIO, str]:
    """Return the stream a log line goes to and the line as rcutils writes it there."""
    stream = _stream()
    line = format_log_line(
        severity,
        name,
        message,
        stamp_ns,
        output_format=_output_format(),
        function_name=function_name,
        file_name=file_name,
        line_number=line_number,
    )
    if _colorize(stream):
        line = f'{_COLORS[severity]}{line}{_COLOR_RESET}'
    return stream, line
