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
Loggers with rclpy's API and rcutils' console output.

A line is ``[LEVEL] [<sec>.<nsec, 9 digits>] [<logger name>]: <message>`` on stderr, the rcutils
default; ``RCUTILS_CONSOLE_OUTPUT_FORMAT`` (``{severity}``, ``{name}``, ``{message}``,
``{time}``, ``{time_as_nanoseconds}``, ``{date_time_with_ms}``, ``{function_name}``,
``{file_name}``, ``{line_number}``) and ``RCUTILS_COLORIZED_OUTPUT`` are honoured, and
``RCUTILS_LOGGING_USE_STDOUT=1`` sends the lines to stdout. Levels follow the logger hierarchy
(``a.b`` inherits from ``a``, then from the default level set by ``--log-level``). Log sinks
(:func:`add_log_sink`; the standalone ``/rosout``) get every message that is emitted.

In the rclpy world :func:`get_logger`, :class:`LoggingSeverity` and the level functions are
rclpy's own.
"""

from __future__ import annotations

from collections.abc import Callable
import contextlib
from enum import IntEnum
import os
import sys
import threading
import time
from typing import Any
from typing import NamedTuple
from typing import TextIO

from tf_demo.transport.backend import rclpy_world

__all__ = [
    'DEFAULT_OUTPUT_FORMAT',
    'Logger',
    'LoggingSeverity',
    'format_log_line',
    'get_logger',
    'get_logger_effective_level',
    'get_logger_level',
    'get_logging_severity_from_string',
    'set_default_logger_level',
    'set_logger_level',
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


def _c_string(value: Any) -> str | None:
    """
    Return ``value`` as rclpy's C extension reads a string argument, else None.

    pybind11 takes ``str`` and ``bytes`` (UTF-8); C stops at the first NUL character.
    """
    if isinstance(value, bytes):
        value = value.decode('utf-8', errors='replace')
    if not isinstance(value, str):
        return None
    return value.partition('\0')[0]


def _incompatible_arguments(function: str, signature: str, arguments: tuple[Any, ...]) -> str:
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
    key = _c_string(log_severity)
    if key is None:
        msg = _incompatible_arguments(
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


class _LoggingState:
    """Process-wide logger levels and output settings (rcutils keeps these globally too)."""

    def __init__(self) -> None:
        self.lock = threading.Lock()
        self.default_level = LoggingSeverity.INFO
        self.levels: dict[str, LoggingSeverity] = {}

    def effective_level(self, name: str) -> LoggingSeverity:
        candidate = name
        while candidate:
            level = self.levels.get(candidate)
            if level is not None and level is not LoggingSeverity.UNSET:
                return level
            candidate = candidate.rpartition('.')[0]
        return self.default_level


_STATE = _LoggingState()


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


def set_default_logger_level(level: LoggingSeverity | int) -> None:
    """Set the level of loggers that have none of their own (``--log-level <level>``)."""
    _STATE.default_level = LoggingSeverity(level)


def set_logger_level(name: str, level: LoggingSeverity | int) -> None:
    """Set the level of logger ``name`` (``--log-level name:=level``)."""
    with _STATE.lock:
        _STATE.levels[name] = LoggingSeverity(level)


def get_logger_level(name: str) -> LoggingSeverity:
    """Return the level set on logger ``name`` (UNSET when none)."""
    return _STATE.levels.get(name, LoggingSeverity.UNSET)


def get_logger_effective_level(name: str) -> LoggingSeverity:
    """Return the level that applies to logger ``name``."""
    return _STATE.effective_level(name)


_SYSTEM_CLOCK: Any = None
"""The throttle filter's default time source, rclpy's module-level ``Clock()`` (system time)."""


def _system_clock() -> Any:
    """Return the one system-time clock the throttle filter defaults to (made on first use)."""
    global _SYSTEM_CLOCK
    if _SYSTEM_CLOCK is None:
        from tf_demo.transport.clock import Clock

        _SYSTEM_CLOCK = Clock()
    return _SYSTEM_CLOCK


def _resolved(default: Any) -> Any:
    """Return a filter parameter's default as a call site stores it (the clock made real)."""
    return _system_clock() if default is _DEFAULT_CLOCK else default


# rclpy's filters, in the order rclpy evaluates them, with their parameters and defaults
# (None: required; _DEFAULT_CLOCK: the system clock). rclpy/rclpy/impl/rcutils_logger.py:
# Throttle, SkipFirst, Once.
_DEFAULT_CLOCK = object()
_FILTER_PARAMETERS: dict[str, dict[str, Any]] = {
    'throttle': {
        'throttle_duration_sec': None,
        'throttle_time_source_type': _DEFAULT_CLOCK,
    },
    'skip_first': {'skip_first': None},
    'once': {'once': None},
}
_FILTER_CLASS_NAMES = {'throttle': 'Throttle', 'skip_first': 'SkipFirst', 'once': 'Once'}
_ALL_FILTER_PARAMETERS = [name for params in _FILTER_PARAMETERS.values() for name in params]
_THIS_FILE = os.path.realpath(__file__)

CallerId = tuple[str, str, int, int]
"""``(function name, file path, line number, last bytecode index)`` of a logging call site."""


def _detect_filters(options: dict[str, Any]) -> list[str]:
    """
    Return the filters requested by ``options``, as rclpy's ``get_filters_from_kwargs``.

    :raises TypeError: a detected filter misses a required parameter, or an option is unknown
        (rclpy's texts, checked in rclpy's order).
    """
    options = dict(options)
    detected = [
        name
        for name, params in _FILTER_PARAMETERS.items()
        if any(options.get(param) for param in params)
    ]
    for name in detected:
        for param, default in _FILTER_PARAMETERS[name].items():
            if param in options:
                continue
            if default is None:
                msg = (
                    f'required parameter "{param}" not specified '
                    f'but is required for the the logging filter "{name}"'
                )
                raise TypeError(msg)
            options[param] = default
    for key in options:
        if key not in _ALL_FILTER_PARAMETERS:
            msg = (
                f'parameter "{key}" is not one of the recognized logging options '
                f'"{_ALL_FILTER_PARAMETERS}"'
            )
            raise TypeError(msg)
    return detected


def _new_context(
    name: str, severity: LoggingSeverity, filters: list[str], options: dict[str, Any]
) -> dict[str, Any]:
    """Return the state of a new call site (rclpy's ``initialize_context`` of each filter)."""
    context: dict[str, Any] = {'name': name, 'severity': severity, 'filters': filters}
    for filter_name in filters:
        for param, default in _FILTER_PARAMETERS[filter_name].items():
            context[param] = options.get(param, _resolved(default))
            if context[param] is None:
                msg = (
                    f'Required parameter "{param}" was not specified for logging filter '
                    f'"{_FILTER_CLASS_NAMES[filter_name]}"'
                )
                raise TypeError(msg)
        if filter_name == 'throttle':
            # rclpy Jazzy: the last time starts at 0 on the chosen clock, so the first call
            # always logs; the time source must be a Clock (system time unless given).
            context['throttle_last_logged'] = 0
            from tf_demo.transport.clock import Clock

            source = context['throttle_time_source_type']
            if not isinstance(source, Clock):
                msg = f'Received throttle_time_source_type of "{source}" is not a clock instance'
                raise ValueError(msg)
        elif filter_name == 'skip_first':
            context['first_has_been_skipped'] = False
        else:
            context['has_been_logged_once'] = False
    return context


def _check_unchanged(
    context: dict[str, Any],
    name: str,
    severity: LoggingSeverity,
    filters: list[str],
    options: dict[str, Any],
) -> None:
    """
    Refuse what rclpy refuses at a call site seen before.

    :raises ValueError: the severity, ``name=``, the filters or a filter parameter differ from
        the first call made from this call site (rclpy's texts).
    """
    if severity != context['severity']:
        msg = 'Logger severity cannot be changed between calls.'
        raise ValueError(msg)
    if name != context['name']:
        msg = 'Logger name cannot be changed between calls.'
        raise ValueError(msg)
    if filters != context['filters']:
        msg = 'Requested logging filters cannot be changed between calls.'
        raise ValueError(msg)
    for filter_name in filters:
        params = _FILTER_PARAMETERS[filter_name]
        if any(context[param] != options.get(param, _resolved(params[param])) for param in params):
            msg = 'Logging filter parameters cannot be changed between calls.'
            raise ValueError(msg)


def _should_log(filter_name: str, context: dict[str, Any]) -> bool:
    """Apply one filter to a call site's state, updating it as rclpy's ``should_log`` does."""
    if filter_name == 'throttle':
        now = context['throttle_time_source_type'].now().nanoseconds
        if now < context['throttle_last_logged'] + context['throttle_duration_sec'] * 1e9:
            return False
        context['throttle_last_logged'] = now
        return True
    if filter_name == 'skip_first':
        if not context['first_has_been_skipped']:
            context['first_has_been_skipped'] = True
            return False
        return True
    if context['has_been_logged_once']:
        return False
    context['has_been_logged_once'] = True
    return True


def _caller_frame() -> Any:
    """Return the first frame outside this module (rclpy's ``_find_caller``)."""
    frame = sys._getframe(1)
    while frame.f_back is not None and os.path.realpath(frame.f_code.co_filename) == _THIS_FILE:
        frame = frame.f_back
    return frame


class Logger:
    """
    A named logger with rclpy's ``RcutilsLogger`` methods and per-call-site rules.

    As in rclpy, each logger object keeps one context per call site
    (:data:`CallerId`): the first call fixes its severity, ``name=`` and filter options, and a
    later call from the same site that changes any of them raises ``ValueError`` — e.g.
    ``(logger.warning if bad else logger.error)(text)`` fails on its second, different call.
    A call below the logger's level is dropped before any of this (rclpy checks the level
    first), so it neither fixes a call site nor has its options checked.
    """

    def __init__(self, name: str = '') -> None:
        self.name = name
        self.parent: Logger | None = None
        """The logger this one is a child of (rcl's rosout sublogger), if any."""
        self._contexts: dict[CallerId, dict[str, Any]] = {}
        self._contexts_lock = threading.Lock()

    def get_child(self, name: str) -> Logger:
        """Return the logger ``<this name>.<name>`` (it logs to its parent's ``/rosout``)."""
        if not name:
            msg = 'Child logger name must not be empty.'
            raise ValueError(msg)
        child = Logger(f'{self.name}.{name}' if self.name else name)
        child.parent = self if self.name else None
        return child

    def set_level(self, level: LoggingSeverity | int) -> None:
        """Set this logger's own level."""
        set_logger_level(self.name, level)

    def get_effective_level(self) -> LoggingSeverity:
        """Return the level that applies to this logger."""
        return get_logger_effective_level(self.name)

    def is_enabled_for(self, severity: LoggingSeverity | int) -> bool:
        """Whether a message of ``severity`` would be printed."""
        return LoggingSeverity(severity) >= self.get_effective_level()

    def log(self, message: Any, severity: LoggingSeverity | int, **kwargs: Any) -> bool:
        """
        Print ``message`` at ``severity`` if enabled and rclpy's filters let it through.

        :param kwargs: ``once=True``, ``skip_first=True``, ``throttle_duration_sec=<float>``
            (evaluated in rclpy's order: throttle, skip_first, once), ``name=`` another logger.
        As in rclpy, a call below the logger's level returns False at once: its options are not
        checked and its call site keeps no state.

        :return: False when the level or a filter dropped the message, else True.
        :raises TypeError: for an unknown or incomplete option, or a message or name that is
            not a string (pybind11's text of rclpy's C logging function).
        :raises ValueError: when this call site changes its severity, name or filter options.
        """
        if not self.is_enabled_for(severity):
            return False
        severity = LoggingSeverity(severity)
        name = kwargs.pop('name', self.name)
        filters = _detect_filters(kwargs)
        frame = _caller_frame()
        caller: CallerId = (
            frame.f_code.co_name,
            os.path.abspath(frame.f_code.co_filename),
            frame.f_lineno,
            frame.f_lasti,
        )
        with self._contexts_lock:
            context = self._contexts.get(caller)
            if context is None:
                context = _new_context(name, severity, filters, kwargs)
                self._contexts[caller] = context
            else:
                _check_unchanged(context, name, severity, filters, kwargs)
            for filter_name in context['filters']:
                if not _should_log(filter_name, context):
                    return False
        text, logger_name = _c_string(message), _c_string(name)
        if text is None or logger_name is None:
            msg = _incompatible_arguments(
                'rclpy_logging_rcutils_log',
                '(arg0: int, arg1: str, arg2: str, arg3: str, arg4: str, arg5: int) -> None',
                (
                    severity, name, message, frame.f_code.co_name,
                    os.path.abspath(frame.f_code.co_filename), frame.f_lineno,
                ),
            )  # fmt: skip
            raise TypeError(msg)
        message, name = text, logger_name
        stream = _stream()
        stamp_ns = time.time_ns()
        line = format_log_line(
            severity,
            name,
            message,
            stamp_ns,
            output_format=_output_format(),
            function_name=frame.f_code.co_name,
            file_name=frame.f_code.co_filename,
            line_number=frame.f_lineno,
        )
        if _colorize(stream):
            line = f'{_COLORS[severity]}{line}{_COLOR_RESET}'
        # a closed stream must not crash the node (rcutils ignores failed writes too)
        with _STATE.lock, contextlib.suppress(OSError, ValueError):
            stream.write(line + '\n')
            stream.flush()
        if _SINKS:
            _emit_to_sinks(
                LogRecord(
                    self, severity, name, message, stamp_ns,
                    frame.f_code.co_name, frame.f_code.co_filename, frame.f_lineno,
                )
            )  # fmt: skip
        return True

    def debug(self, message: Any, **kwargs: Any) -> bool:
        """Log at DEBUG."""
        return self.log(message, LoggingSeverity.DEBUG, **kwargs)

    def info(self, message: Any, **kwargs: Any) -> bool:
        """Log at INFO."""
        return self.log(message, LoggingSeverity.INFO, **kwargs)

    def warning(self, message: Any, **kwargs: Any) -> bool:
        """Log at WARN."""
        return self.log(message, LoggingSeverity.WARN, **kwargs)

    warn = warning

    def error(self, message: Any, **kwargs: Any) -> bool:
        """Log at ERROR."""
        return self.log(message, LoggingSeverity.ERROR, **kwargs)

    def fatal(self, message: Any, **kwargs: Any) -> bool:
        """Log at FATAL."""
        return self.log(message, LoggingSeverity.FATAL, **kwargs)

    def __repr__(self) -> str:
        return f'Logger(name={self.name!r})'


class LogRecord(NamedTuple):
    """One message a logger emitted, as log sinks (``/rosout``) receive it."""

    logger: Logger
    severity: LoggingSeverity
    name: str
    message: str
    stamp_ns: int
    function_name: str
    file_name: str
    line_number: int


LogSink = Callable[[LogRecord], None]
_SINKS: list[LogSink] = []
_in_sink = threading.local()


def add_log_sink(sink: LogSink) -> None:
    """Have ``sink`` called with every message that is emitted (rcutils' output handlers)."""
    with _STATE.lock:
        if sink not in _SINKS:
            _SINKS.append(sink)


def remove_log_sink(sink: LogSink) -> None:
    """Stop calling ``sink``."""
    with _STATE.lock:
        if sink in _SINKS:
            _SINKS.remove(sink)


def _emit_to_sinks(record: LogRecord) -> None:
    """Give ``record`` to every sink; what a sink logs itself is not fed back to sinks."""
    if getattr(_in_sink, 'active', False):
        return
    _in_sink.active = True
    try:
        for sink in tuple(_SINKS):
            with contextlib.suppress(Exception):  # a failing sink must not break logging
                sink(record)
    finally:
        _in_sink.active = False


def get_logger(name: str) -> Logger:
    """Return the logger called ``name`` (as ``rclpy.logging.get_logger``)."""
    if not name:
        msg = 'Logger name must not be empty.'
        raise ValueError(msg)
    return Logger(name)


if rclpy_world():  # pragma: no cover - needs a ROS 2 installation
    from tf_demo.transport import rclpy_backend as _rclpy_backend

    globals().update(_rclpy_backend.logging_exports())
