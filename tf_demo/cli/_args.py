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
Pure command-line parsing for the tf tools, with upstream's rules, texts and exit codes.

Nothing here touches ROS or DDS: every function maps a list of strings to a value or an error, so
the parsing is tested without processes. The tools split their ``--ros-args`` sections off first
(:func:`tf_demo.transport.ros_args.split_ros_args`, as ``rclcpp::remove_ros_arguments`` does),
and read numbers with C's rules (:func:`tf_demo.transport.params_c_numbers.c_strtod`, as
``std::stod`` does).
"""

from __future__ import annotations

from dataclasses import dataclass
from dataclasses import field
import math
import re

from tf_demo.core.math3d import quat_from_rpy
from tf_demo.nodes.helpers import rate_error
from tf_demo.transport.params_c_numbers import c_strtod
from tf_demo.transport.params_c_numbers import CDouble

FLT_MAX = 3.4028234663852886e38
"""The largest finite C ``float`` (``std::stof`` refuses anything beyond it)."""
FLT_MIN = 1.1754943508222875e-38
"""The smallest normal C ``float`` (glibc's ``strtof`` reports ERANGE below it)."""


def c_float_range_error(number: CDouble, *, single: bool = False) -> str | None:
    """
    Return why ``number`` (what ``strtod`` read) is out of range for ``std::stod`` (``stof``).

    ``std::stod``/``std::stof`` throw ``std::out_of_range`` where ``strtod`` (``strtof``) sets
    ``ERANGE``; the C++ tools then abort. None when the value is in range. A spelled ``inf`` and
    a literal zero are in range.
    """
    value = number.value
    if number.out_of_range:
        return 'out of range (too large)' if math.isinf(value) else 'out of range (too small)'
    if single and math.isfinite(value) and abs(value) > FLT_MAX:
        return 'out of range (too large for a float)'
    if single and 0.0 < abs(value) < FLT_MIN:
        return 'out of range (too small)'
    return None


def whole_number(text: str, maximum: int) -> int | None:
    """Parse ASCII digits ``text`` as an int up to ``maximum``; None if not that (no 10^4300)."""
    if not re.fullmatch(r'[0-9]+', text):
        return None
    digits = text.lstrip('0') or '0'
    if len(digits) > len(str(maximum)):
        return None
    value = int(digits)
    return value if value <= maximum else None


# ---------------------------------------------------------------------------------------------
# static_transform_publisher

STATIC_VALUE_FLAGS = (
    '--x',
    '--y',
    '--z',
    '--qx',
    '--qy',
    '--qz',
    '--qw',
    '--roll',
    '--pitch',
    '--yaw',
    '--frame-id',
    '--child-frame-id',
)
OLD_STYLE_WARNING = 'Old-style arguments are deprecated; see --help for new-style arguments'


@dataclass
class StaticTransformArgs:
    """What static_transform_publisher's command line asks for (or the parse error)."""

    translation: tuple[float, float, float] = (0.0, 0.0, 0.0)
    rotation: tuple[float, float, float, float] = (0.0, 0.0, 0.0, 1.0)
    frame_id: str = ''
    child_frame_id: str = ''
    help: bool = False
    error: str = ''
    warnings: list[str] = field(default_factory=list)


def parse_static_transform_args(args: list[str]) -> StaticTransformArgs:
    """
    Parse static_transform_publisher's arguments (without the program name) as upstream does.

    The rules of tf2_ros' ``static_transform_broadcaster_program.cpp`` (Jazzy): flags take one
    value each, numbers take the longest numeric prefix (``stod``), unknown tokens are positional,
    8 or 9 positional tokens are the deprecated forms ``x y z yaw pitch roll frame child`` and
    ``x y z qx qy qz qw frame child``; nothing is normalized. The first error wins and is returned
    in ``error``; ``help`` is honoured only when parsing succeeded.
    """
    result = StaticTransformArgs()
    translation = [0.0, 0.0, 0.0]
    quat = [0.0, 0.0, 0.0, 1.0]
    rpy = [0.0, 0.0, 0.0]
    saw = {'frame': False, 'quat': False, 'rpy': False, 'trans': False}
    positional: list[str] = []

    def number(name: str, text: str) -> float | None:
        parsed = c_strtod(text)
        if parsed is None:
            result.error = f'Failed to parse {name} argument as float'
            return None
        out_of_range = c_float_range_error(parsed)
        if out_of_range is not None:
            result.error = f'Failed to parse {name} argument as float: {out_of_range}'
            return None
        return parsed.value

    def apply(name: str, key: str, value_text: str) -> bool:
        if key in ('--frame-id', '--child-frame-id'):
            if key == '--frame-id':
                result.frame_id = value_text
            else:
                result.child_frame_id = value_text
            saw['frame'] = True
            return True
        value = number(name, value_text)
        if value is None:
            return False
        axis = key.lstrip('-')
        if axis in ('x', 'y', 'z'):
            translation['xyz'.index(axis)] = value
            saw['trans'] = True
        elif axis in ('qx', 'qy', 'qz', 'qw'):
            quat[('qx', 'qy', 'qz', 'qw').index(axis)] = value
            saw['quat'] = True
        else:
            rpy[('roll', 'pitch', 'yaw').index(axis)] = value
            saw['rpy'] = True
        return True

    index = 0
    while index < len(args):
        token = args[index]
        if token in ('--help', '-h'):
            result.help = True
        elif token in STATIC_VALUE_FLAGS:
            if index == len(args) - 1:
                result.error = f'Not enough arguments for {token}'
                return result
            index += 1
            if not apply(token, token, args[index]):
                return result
        else:
            positional.append(token)
        index += 1

    if result.help:
        return result
    if saw['rpy'] and saw['quat']:
        result.error = 'Cannot specify both quaternion and Euler rotations'
        return result
    if saw['rpy']:
        quat = list(quat_from_rpy(*rpy))

    if len(positional) in (8, 9):
        result.warnings.append(OLD_STYLE_WARNING)
        if saw['frame'] or saw['trans'] or saw['quat']:
            result.error = 'Cannot specify both new-style (flags) and old-style (arguments)'
            return result
        names = ['x', 'y', 'z']
        names += ['yaw', 'pitch', 'roll'] if len(positional) == 8 else ['qx', 'qy', 'qz', 'qw']
        for name, text in zip(names, positional, strict=False):
            if not apply(name, '--' + name, text):
                return result
        if len(positional) == 8:
            quat = list(quat_from_rpy(*rpy))
        result.frame_id, result.child_frame_id = positional[-2], positional[-1]
    elif positional:
        result.error = 'Extra unparsed arguments on command-line'
        return result

    if not result.frame_id:
        result.error = 'Frame id must not be empty'
    elif not result.child_frame_id:
        result.error = 'Child frame id must not be empty'
    result.translation = (translation[0], translation[1], translation[2])
    result.rotation = (quat[0], quat[1], quat[2], quat[3])
    return result


# ---------------------------------------------------------------------------------------------
# tf_echo


@dataclass
class EchoArgs:
    """What tf_echo's command line asks for, or the message and exit code of a refusal."""

    source_frame: str = ''
    target_frame: str = ''
    rate_hz: float = 1.0
    precision: int = 3
    limit: int | None = None
    json: bool = False
    #: ``--bag PATH``: echo from a rosbag2 recording instead of listening.
    bag: str | None = None
    #: ``--at T``: one instant of the bag (bag seconds from its start, or absolute seconds).
    at_s: float | None = None
    #: ``--namespace NS``: listen on ``NS/tf`` and ``NS/tf_static``.
    namespace: str | None = None
    exit_code: int = 0
    error: str = ''
    show_usage: bool = False
    #: ``-h``/``--help``: the usage with tf_demo's additions (exit code 1, as tf2_echo's usage).
    show_help: bool = False


ECHO_EXTRA_FLAGS = ('-p', '--precision', '--limit', '--json', '--bag', '--at', '--namespace')
MAX_PRECISION = 17
MAX_COUNT = 10**18
"""The largest ``--limit`` a tool takes (a count of reports or blocks)."""


def parse_echo_args(args: list[str]) -> EchoArgs:
    """
    Parse tf_echo's arguments (without the program name and ROS arguments).

    Upstream rules (tf2_echo, Jazzy): two or three positional arguments, else the usage text and
    exit code 1; a rate that is not a number exits with 2, a number with trailing characters with
    3. Additions, off by default: ``-p/--precision N``, ``--limit N`` and ``--json``.
    """
    result = EchoArgs()
    positional: list[str] = []
    index = 0
    while index < len(args):
        token = args[index]
        if token == '--json':
            result.json = True
        elif token in ('-h', '--help'):
            result.show_help = result.show_usage = True
            result.exit_code = 1
            return result
        elif token in ('--bag', '--at', '--namespace'):
            if index == len(args) - 1:
                result.error = f'{token} needs a value'
                result.exit_code = 2
                return result
            index += 1
            if token == '--bag':
                result.bag = args[index]
            elif token == '--namespace':
                result.namespace = args[index]
            else:
                at = c_strtod(args[index])
                if at is None or at.length != len(args[index]) or not math.isfinite(at.value):
                    result.error = f'--at needs a number of seconds, got {_shown(args[index])}'
                    result.exit_code = 2
                    return result
                result.at_s = at.value
        elif token in ('-p', '--precision', '--limit'):
            if index == len(args) - 1:
                result.error = f'{token} needs a whole number'
                result.exit_code = 2
                return result
            index += 1
            value = args[index]
            if token == '--limit':
                limit = whole_number(value, MAX_COUNT)
                if limit is None or limit == 0:
                    result.error = (
                        f'--limit needs a whole number from 1 to {MAX_COUNT}, got {_shown(value)}'
                    )
                    result.exit_code = 2
                    return result
                result.limit = limit
            else:
                # More than 17 decimals add nothing to a double: any larger number means 17.
                if not re.fullmatch(r'[0-9]+', value):
                    result.error = f'{token} needs a whole number, got {_shown(value)}'
                    result.exit_code = 2
                    return result
                precision = whole_number(value, MAX_PRECISION)
                result.precision = MAX_PRECISION if precision is None else precision
        else:
            positional.append(token)
        index += 1

    if len(positional) not in (2, 3):
        result.show_usage = True
        result.exit_code = 1
        return result
    if result.at_s is not None and result.bag is None:
        result.error, result.exit_code = '--at needs --bag PATH (an instant of a recording)', 2
        return result
    result.source_frame, result.target_frame = positional[0], positional[1]
    if len(positional) == 3:
        text = positional[2]
        parsed = c_strtod(text)
        failure = f"Failed to convert rate argument '{text}' to a floating-point number"
        if parsed is None:
            result.error, result.exit_code = failure, 2
            return result
        if parsed.length != len(text):
            result.error, result.exit_code = failure, 3
            return result
        out_of_range = c_float_range_error(parsed, single=True)
        if out_of_range is not None:
            result.error, result.exit_code = f'{failure}: {out_of_range}', 2
            return result
        problem = rate_error(parsed.value)
        if problem is not None:
            result.error = f"echo_rate {problem}, got '{_shown(text)}'"
            result.exit_code = 2
            return result
        result.rate_hz = parsed.value
    return result


def count_argument(text: str) -> int:
    """Parse a count for argparse (``type=``): a whole number from 1 to :data:`MAX_COUNT`."""
    import argparse

    value = whole_number(text, MAX_COUNT)
    if value is None or value == 0:
        msg = f'needs a whole number from 1 to {MAX_COUNT}, got {_shown(text)}'
        raise argparse.ArgumentTypeError(msg)
    return value


def _shown(text: str, limit: int = 40) -> str:
    """``text`` for an error message, cut to ``limit`` characters (a 5,000-digit argument)."""
    return text if len(text) <= limit else f'{text[:limit]}... ({len(text)} characters)'


def wait_time_error(wait_time: float) -> str | None:
    """Return the error text for a ``--wait-time`` that is negative, NaN or infinite, else None."""
    if wait_time >= 0 and math.isfinite(wait_time):
        return None
    return f'--wait-time must be a finite number of seconds >= 0, got {wait_time}'


# ---------------------------------------------------------------------------------------------
# --namespace NS (every tool that reads TF)

NAMESPACE_HELP = (
    'listen to a namespaced robot: NS/tf and NS/tf_static (and NS/robot_description) instead '
    'of the global topics, as --ros-args -r /tf:=NS/tf -r /tf_static:=NS/tf_static would'
)
#: The global topics ``--namespace`` moves under the namespace.
NAMESPACED_TOPICS = ('/tf', '/tf_static', '/robot_description')


def namespace_ros_args(namespace: str) -> list[str]:
    """
    Return the ``--ros-args`` remaps that make the TF topics those of ``namespace``.

    ``robot1``, ``/robot1`` and ``/robot1/`` all mean ``/robot1``; ``/`` is the global one.

    :raises ValueError: for a name that is not a valid ROS namespace (rmw's rules).
    """
    from tf_demo.transport.dds.names import InvalidNameError
    from tf_demo.transport.dds.names import validate_namespace

    absolute = '/' + namespace.strip().strip('/')
    try:
        validate_namespace(absolute)
    except InvalidNameError as error:
        reason = str(error).splitlines()[0].removeprefix('Invalid namespace: ').rstrip(':')
        msg = f"--namespace '{_shown(namespace)}' is not a valid namespace: {reason}"
        raise ValueError(msg) from None
    if absolute == '/':
        return []
    remaps = [['-r', f'{topic}:={absolute}{topic}'] for topic in NAMESPACED_TOPICS]
    return ['--ros-args', *(token for remap in remaps for token in remap)]
