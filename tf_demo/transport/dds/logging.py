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
Loggers with rclpy's API (the standalone world's; the rclpy world uses rclpy's own).

Levels follow the logger hierarchy (``a.b`` inherits from ``a``, then from the default level set
by ``--log-level``); rclpy's ``throttle``, ``skip_first`` and ``once`` filters apply per call
site. Log sinks (:func:`add_log_sink`; the standalone ``/rosout``) get every message that is
emitted. Lines are written in rcutils' format (:mod:`tf_demo.transport.dds.log_format`).
"""

from __future__ import annotations

from collections.abc import Callable
from collections.abc import Mapping
import contextlib
import operator
import os
import sys
import threading
import time
from types import FrameType
from typing import NamedTuple

from tf_demo.transport.dds.clock import Clock
from tf_demo.transport.dds.log_format import c_string
from tf_demo.transport.dds.log_format import console_line
from tf_demo.transport.dds.log_format import incompatible_arguments
from tf_demo.transport.dds.log_format import LoggingSeverity

#: rclpy.logging's names, Logger and --log-level's setter (the facade star-imports these).
__all__ = [
    'Logger',
    'get_logger',
    'get_logger_effective_level',
    'get_logger_level',
    'set_default_logger_level',
    'set_logger_level',
]


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


_SYSTEM_CLOCK: Clock | None = None
"""The throttle filter's default time source, rclpy's module-level ``Clock()`` (system time)."""


def _system_clock() -> Clock:
    """Return the one system-time clock the throttle filter defaults to (made on first use)."""
    global _SYSTEM_CLOCK
    if _SYSTEM_CLOCK is None:
        _SYSTEM_CLOCK = Clock()
    return _SYSTEM_CLOCK


def _resolved(default: object) -> object:
    """Return a filter parameter's default as a call site stores it (the clock made real)."""
    return _system_clock() if default is _DEFAULT_CLOCK else default


# rclpy's filters, in the order rclpy evaluates them, with their parameters and defaults
# (None: required; _DEFAULT_CLOCK: the system clock). rclpy/rclpy/impl/rcutils_logger.py:
# Throttle, SkipFirst, Once.
_DEFAULT_CLOCK = object()
_FILTER_PARAMETERS: dict[str, dict[str, object]] = {
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


def _detect_filters(options: Mapping[str, object]) -> list[str]:
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


class _Throttle:
    """rclpy's ``Throttle``: log at most once per ``throttle_duration_sec`` of its clock."""

    def __init__(self, clock: Clock, duration_sec: object) -> None:
        self.clock = clock
        self.duration_sec = duration_sec
        self.last_logged = 0  # rclpy Jazzy: 0 on the chosen clock, so the first call logs

    def should_log(self) -> bool:
        now = self.clock.now().nanoseconds
        # the duration is the caller's object, multiplied as rclpy does (any number type)
        if now < self.last_logged + operator.mul(self.duration_sec, 1e9):
            return False
        self.last_logged = now
        return True


class _SkipFirst:
    """rclpy's ``SkipFirst``: drop the first message of the call site."""

    def __init__(self) -> None:
        self.skipped = False

    def should_log(self) -> bool:
        if not self.skipped:
            self.skipped = True
            return False
        return True


class _Once:
    """rclpy's ``Once``: log the first message of the call site only."""

    def __init__(self) -> None:
        self.logged = False

    def should_log(self) -> bool:
        if self.logged:
            return False
        self.logged = True
        return True


class _CallSite(NamedTuple):
    """What the first call from a call site fixed, and the state of its filters (rclpy's)."""

    name: object
    severity: LoggingSeverity
    filters: list[str]
    parameters: dict[str, object]
    states: list[_Throttle | _SkipFirst | _Once]


def _new_context(
    name: object, severity: LoggingSeverity, filters: list[str], options: Mapping[str, object]
) -> _CallSite:
    """Return the state of a new call site (rclpy's ``initialize_context`` of each filter)."""
    context = _CallSite(name, severity, filters, {}, [])
    for filter_name in filters:
        parameters = context.parameters
        for param, default in _FILTER_PARAMETERS[filter_name].items():
            parameters[param] = options.get(param, _resolved(default))
            if parameters[param] is None:
                msg = (
                    f'Required parameter "{param}" was not specified for logging filter '
                    f'"{_FILTER_CLASS_NAMES[filter_name]}"'
                )
                raise TypeError(msg)
        if filter_name == 'throttle':
            # the time source must be a Clock (system time unless given)
            source = parameters['throttle_time_source_type']
            if not isinstance(source, Clock):
                msg = f'Received throttle_time_source_type of "{source}" is not a clock instance'
                raise ValueError(msg)
            context.states.append(_Throttle(source, parameters['throttle_duration_sec']))
        elif filter_name == 'skip_first':
            context.states.append(_SkipFirst())
        else:
            context.states.append(_Once())
    return context


def _check_unchanged(
    context: _CallSite,
    name: object,
    severity: LoggingSeverity,
    filters: list[str],
    options: Mapping[str, object],
) -> None:
    """
    Refuse what rclpy refuses at a call site seen before.

    :raises ValueError: the severity, ``name=``, the filters or a filter parameter differ from
        the first call made from this call site (rclpy's texts).
    """
    if severity != context.severity:
        msg = 'Logger severity cannot be changed between calls.'
        raise ValueError(msg)
    if name != context.name:
        msg = 'Logger name cannot be changed between calls.'
        raise ValueError(msg)
    if filters != context.filters:
        msg = 'Requested logging filters cannot be changed between calls.'
        raise ValueError(msg)
    for filter_name in filters:
        params = _FILTER_PARAMETERS[filter_name]
        if any(
            context.parameters[param] != options.get(param, _resolved(params[param]))
            for param in params
        ):
            msg = 'Logging filter parameters cannot be changed between calls.'
            raise ValueError(msg)


def _caller_frame() -> FrameType:
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
        self._contexts: dict[CallerId, _CallSite] = {}
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

    def log(self, message: object, severity: LoggingSeverity | int, **kwargs: object) -> bool:
        """
        Print ``message`` at ``severity`` if enabled and rclpy's filters let it through.

        As in rclpy, a call below the logger's level returns False at once: its options are not
        checked and its call site keeps no state.

        :param kwargs: ``once=True``, ``skip_first=True``, ``throttle_duration_sec=<float>``
            (evaluated in rclpy's order: throttle, skip_first, once), ``name=`` another logger.
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
            for state in context.states:
                if not state.should_log():
                    return False
        text, logger_name = c_string(message), c_string(name)
        if text is None or logger_name is None:
            msg = incompatible_arguments(
                'rclpy_logging_rcutils_log',
                '(arg0: int, arg1: str, arg2: str, arg3: str, arg4: str, arg5: int) -> None',
                (
                    severity, name, message, frame.f_code.co_name,
                    os.path.abspath(frame.f_code.co_filename), frame.f_lineno,
                ),
            )  # fmt: skip
            raise TypeError(msg)
        message, name = text, logger_name
        stamp_ns = time.time_ns()
        stream, line = console_line(
            severity,
            name,
            message,
            stamp_ns,
            function_name=frame.f_code.co_name,
            file_name=frame.f_code.co_filename,
            line_number=frame.f_lineno,
        )
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

    def debug(self, message: object, **kwargs: object) -> bool:
        """Log at DEBUG."""
        return self.log(message, LoggingSeverity.DEBUG, **kwargs)

    def info(self, message: object, **kwargs: object) -> bool:
        """Log at INFO."""
        return self.log(message, LoggingSeverity.INFO, **kwargs)

    def warning(self, message: object, **kwargs: object) -> bool:
        """Log at WARN."""
        return self.log(message, LoggingSeverity.WARN, **kwargs)

    warn = warning

    def error(self, message: object, **kwargs: object) -> bool:
        """Log at ERROR."""
        return self.log(message, LoggingSeverity.ERROR, **kwargs)

    def fatal(self, message: object, **kwargs: object) -> bool:
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
