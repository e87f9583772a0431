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
Pure text formatters of the tf command-line tools (upstream texts, tested with golden text).

Every function turns values into the exact text a tool prints; the tools themselves only gather
the values and write the strings. The upstream sources these reproduce are tf2_ros'
``tf2_echo.cpp``, ``static_transform_broadcaster_program.cpp``, ``tf2_monitor.cpp`` and
tf2_tools' ``view_frames.py`` (ROS 2 Jazzy).
"""

from __future__ import annotations

from collections.abc import Mapping
from collections.abc import Sequence
import json
import math
import sys

from tf_demo.core.math3d import matrix_from_quat
from tf_demo.core.math3d import Quat
from tf_demo.core.math3d import rpy_from_quat
from tf_demo.core.math3d import Vec3
import yaml

# ---------------------------------------------------------------------------------------------
# tf_echo

ECHO_USAGE = (
    'Usage: tf2_echo source_frame target_frame [echo_rate]\n'
    '\n'
    'This will echo the transform from the coordinate frame of the source_frame\n'
    'to the coordinate frame of the target_frame. \n'
    'Note: This is the transform to get data from target_frame into the source_frame.\n'
    'Default echo rate is 1 if echo_rate is not given.\n'
)
ECHO_EXTRAS_USAGE = (
    '\n'
    'tf_demo additions (off by default):\n'
    '  -p, --precision N   decimals to print (default 3)\n'
    '  --limit N           exit after N transforms were printed\n'
    '  --json              print one JSON object per line instead of the text block\n'
    '  --bag PATH          echo from a rosbag2 recording (a folder, .mcap or .db3) instead\n'
    '  --at T              with --bag: only the instant T (seconds from the bag start, or\n'
    '                      absolute seconds)\n'
    '  --namespace NS      listen on NS/tf and NS/tf_static (a namespaced robot)\n'
    '  -h, --help          this text (a wrong argument count prints the first part only, as\n'
    '                      tf2_echo does)\n'
)


def format_fixed(value: float, precision: int = 3) -> str:
    """Format like C++ ``std::fixed`` with ``precision``: ``-0.000`` stays, inf/nan as C++ does."""
    if math.isnan(value):
        return '-nan' if math.copysign(1.0, value) < 0 else 'nan'
    if math.isinf(value):
        return 'inf' if value > 0 else '-inf'
    return f'{value:.{precision}f}'


def _joined(values: Sequence[float], precision: int) -> str:
    return ', '.join(format_fixed(v, precision) for v in values)


def echo_rpy(rotation: Quat) -> tuple[Vec3, Vec3]:
    """Roll, pitch, yaw of ``rotation`` in radians and in degrees, as tf2_echo computes them."""
    roll, pitch, yaw = rpy_from_quat(rotation)
    radians = (roll, pitch, yaw)
    degrees = (roll * 180.0 / math.pi, pitch * 180.0 / math.pi, yaw * 180.0 / math.pi)
    return radians, degrees


def echo_matrix(translation: Vec3, rotation: Quat) -> list[list[float]]:
    """Return the 4x4 homogeneous matrix tf2_echo prints (rows)."""
    basis = matrix_from_quat(rotation)
    rows = [[basis[i][0], basis[i][1], basis[i][2], translation[i]] for i in range(3)]
    rows.append([0.0, 0.0, 0.0, 1.0])
    return rows


def format_echo_transform(
    stamp_sec: int,
    stamp_nanosec: int,
    translation: Vec3,
    rotation: Quat,
    precision: int = 3,
) -> str:
    """
    Format one tf2_echo output block, newline-terminated.

    ``At time`` prints the raw ``sec.nanosec`` integers (nanoseconds not zero-padded, as
    upstream). Matrix cells are a space plus the value right-aligned in ``precision + 3`` columns
    (upstream's width 6 at the default precision 3).
    """
    radians, degrees = echo_rpy(rotation)
    width = precision + 3
    lines = [
        f'At time {stamp_sec}.{stamp_nanosec}',
        f'- Translation: [{_joined(translation, precision)}]',
        f'- Rotation: in Quaternion [{_joined(rotation, precision)}]',
        f'- Rotation: in RPY (radian) [{_joined(radians, precision)}]',
        f'- Rotation: in RPY (degree) [{_joined(degrees, precision)}]',
        '- Matrix:',
    ]
    lines.extend(
        ''.join(' ' + format_fixed(cell, precision).rjust(width) for cell in row)
        for row in echo_matrix(translation, rotation)
    )
    return '\n'.join(lines) + '\n'


def format_echo_failure(now_sec: float, what: str, frames_as_string: str) -> str:
    """Format tf2_echo's failure block: time, exception text, frame list, and an empty line."""
    return (
        f'Failure at {format_fixed(now_sec, 3)}\n'
        f'Exception thrown:{what}\n'
        'The current list of frames is:\n'
        f'{frames_as_string}\n'
    )


def format_echo_waiting(source_frame: str, target_frame: str, reason: str) -> str:
    """Return the INFO text tf2_echo logs while it waits (two spaces after ->)."""
    return f'Waiting for transform {source_frame} ->  {target_frame}: {reason}'


def format_echo_json(  # noqa: PLR0917 (one value per printed field)
    source_frame: str,
    target_frame: str,
    stamp_sec: int,
    stamp_nanosec: int,
    translation: Vec3,
    rotation: Quat,
) -> str:
    """One JSON line (``--json``) for a transform: stamp, translation, quaternion, RPY, matrix."""
    radians, degrees = echo_rpy(rotation)
    record = {
        'source_frame': source_frame,
        'target_frame': target_frame,
        'stamp': {'sec': stamp_sec, 'nanosec': stamp_nanosec},
        'translation': list(translation),
        'rotation_xyzw': list(rotation),
        'rpy_radian': list(radians),
        'rpy_degree': list(degrees),
        'matrix': echo_matrix(translation, rotation),
    }
    return json.dumps(record, allow_nan=True) + '\n'


def format_echo_failure_json(now_sec: float, what: str, frames: Sequence[str]) -> str:
    """One JSON line (``--json``) for a failed lookup."""
    return json.dumps({'failure_at': now_sec, 'error': what, 'frames': list(frames)}) + '\n'


# ---------------------------------------------------------------------------------------------
# static_transform_publisher

STATIC_USAGE = (
    'usage: static_transform_publisher [--x X] [--y Y] [--z Z] [--qx QX] [--qy QY] '
    '[--qz QZ] [--qw QW] [--roll ROLL] [--pitch PITCH] [--yaw YAW] --frame-id FRAME_ID '
    '--child-frame-id CHILD_FRAME_ID\n\n'
    'A command line utility for manually sending a static transform.\n\nIf no translation or'
    ' orientation is provided, the identity transform will be published.\n\nThe translation'
    ' offsets are in meters.\n\nThe rotation may be provided with roll, pitch, yaw euler angles'
    ' in radians, or as a quaternion.\n\n'
    'required arguments:\n'
    '  --frame-id FRAME_ID parent frame\n'
    '  --child-frame-id CHILD_FRAME_ID child frame id\n\n'
    'optional arguments:\n'
    '  --x X                 x component of translation\n'
    '  --y Y                 y component of translation\n'
    '  --z Z                 z component of translation\n'
    '  --qx QX               x component of quaternion rotation\n'
    '  --qy QY               y component of quaternion rotation\n'
    '  --qz QZ               z component of quaternion rotation\n'
    '  --qw QW               w component of quaternion rotation\n'
    '  --roll ROLL           roll component Euler rotation\n'
    '  --pitch PITCH         pitch component Euler rotation\n'
    '  --yaw YAW             yaw component Euler rotation\n'
)


def _c_lf(value: float) -> str:
    """C's ``%lf``: six decimals, ``inf``/``nan`` spelled as glibc does."""
    return format_fixed(value, 6)


def format_static_info(
    translation: Vec3, rotation: Quat, frame_id: str, child_frame_id: str
) -> str:
    """static_transform_publisher's start-up INFO text (several lines, no trailing newline)."""
    t = ', '.join(f"'{_c_lf(v)}'" for v in translation)
    r = ', '.join(f"'{_c_lf(v)}'" for v in rotation)
    return (
        'Spinning until stopped - publishing transform\n'
        f'translation: ({t})\n'
        f'rotation: ({r})\n'
        f"from '{frame_id}' to '{child_frame_id}'"
    )


# ---------------------------------------------------------------------------------------------
# view_frames


def _dot_quote(name: object) -> str:
    """Escape backslashes and double quotes for a DOT string (plain names are unchanged)."""
    return str(name).replace('\\', '\\\\').replace('"', '\\"')


def generate_dot(
    data: Mapping[str, Mapping[str, object]] | None, recorded_time: tuple[int, int]
) -> str:
    """
    Turn the YAML-parsed frame map of ``all_frames_as_yaml`` into view_frames' DOT text.

    The output equals tf2_tools' ``generate_dot`` whenever that works (one tree). Where upstream
    crashes or hides trees it stays legible: no data (``None`` or empty) gives the "No tf data
    received" graph, several roots all hang under the legend, and a loop (no root) still renders,
    with the legend standing alone.

    :param data: child frame -> {parent, broadcaster, rate, buffer_length,
        most_recent_transform, oldest_transform}, in the buffer's order.
    :param recorded_time: (sec, nanosec) of the recording clock.
    """
    if not data:
        return 'digraph G { "No tf data received" }'
    dot = ['digraph G {\n']
    roots: list[str] = []
    for child, info in data.items():
        parent = str(info['parent'])
        dot.append(
            f'"{_dot_quote(parent)}" -> "{_dot_quote(child)}"[label=" '
            f'Broadcaster: {_dot_quote(info["broadcaster"])}\\n'
            f'Average rate: {info["rate"]}\\n'
            f'Buffer length: {info["buffer_length"]}\\n'
            f'Most recent transform: {info["most_recent_transform"]}\\n'
            f'Oldest transform: {info["oldest_transform"]}\\n'
            '"];\n'
        )
        if parent not in data and parent not in roots:
            roots.append(parent)
    dot.append('edge [style=invis];\n')
    dot.append(
        ' subgraph cluster_legend { style=bold; color=black; label ="view_frames Result";\n'
    )
    seconds = recorded_time[0] + recorded_time[1] / 1e9
    dot.append(f'"Recorded at time: {seconds}"[ shape=plaintext ] ;\n')
    if len(roots) == 1:
        dot.append(f'}}->"{_dot_quote(roots[0])}";\n}}')
    elif roots:
        targets = ' '.join(f'"{_dot_quote(root)}"' for root in roots)
        dot.append(f'}}->{{{targets}}};\n}}')
    else:
        dot.append('}\n}')
    return ''.join(dot)


# ---------------------------------------------------------------------------------------------
# tf_monitor


def format_cpp_default(value: float) -> str:
    """Format a double as ``std::ostream`` prints it by default (``%g``, 6 significant digits)."""
    if math.isnan(value):
        return '-nan' if math.copysign(1.0, value) < 0 else 'nan'
    return f'{value:g}'


def format_monitor_frames(
    frame_delays: Mapping[str, Sequence[float]],
    frame_authority: Mapping[str, str],
    chain: Sequence[str] | None,
) -> str:
    """Format the ``Frames:`` part of tf2_monitor's report (stdout), frames sorted."""
    lines = ['', 'Frames:']
    for frame in sorted(frame_delays):
        delays = frame_delays[frame]
        if (chain is not None and frame not in chain) or not delays:
            continue
        average = sum(delays) / len(delays)
        maximum = max(0.0, *delays)
        authority = frame_authority.get(frame, '')
        lines.append(
            f'Frame: {frame}, published by {authority}, Average Delay: '
            f'{format_cpp_default(average)}, Max Delay: {format_cpp_default(maximum)}'
        )
    return '\n'.join(lines) + '\n'


def format_monitor_header(
    framea: str | None,
    frameb: str | None,
    chain: Sequence[str] | None,
    avg_delay: float,
    max_delay: float,
) -> str:
    """Format the start of tf2_monitor's report: empty lines, RESULTS, chain, net delay."""
    if framea is None or frameb is None or chain is None:
        return '\n\n\nRESULTS: for all Frames\n'
    return (
        f'\n\n\nRESULTS: for {framea} to {frameb}\n'
        f'Chain is: {" -> ".join(chain)}\n'
        f'Net delay     avg = {format_cpp_default(avg_delay)}: '
        f'max = {format_cpp_default(max_delay)}\n'
    )


def format_monitor_broadcasters(
    authority_delays: Mapping[str, Sequence[float]],
    authority_arrivals: Mapping[str, Sequence[float]],
) -> str:
    """Format tf2_monitor's ``Node:`` lines (stdout; ``All Broadcasters:`` goes to stderr)."""
    lines = []
    for authority in sorted(authority_delays):
        delays = authority_delays[authority]
        arrivals = authority_arrivals.get(authority, ())
        if not delays or not arrivals:
            continue
        average = sum(delays) / len(delays)
        maximum = max(0.0, *delays)
        frequency = len(arrivals) / max(0.00000001, arrivals[-1] - arrivals[0])
        lines.append(
            f'Node: {authority} {format_cpp_default(frequency)} Hz, Average Delay: '
            f'{format_cpp_default(average)} Max Delay: {format_cpp_default(maximum)}'
        )
    return ''.join(line + '\n' for line in lines)


def _message_tree(value: object) -> object:
    """Return a message as ordered mappings and lists, field by field (rosidl_runtime_py's)."""
    fields = getattr(value, 'get_fields_and_field_types', None)
    if fields is not None:
        return _OrderedFields((name, _message_tree(getattr(value, name))) for name in fields())
    if isinstance(value, (list, tuple)):
        return [_message_tree(item) for item in value]
    tolist = getattr(value, 'tolist', None)  # array.array and numpy arrays
    if tolist is not None:
        return tolist()
    return value


class _OrderedFields(dict[str, object]):
    """A message's fields in declaration order (dumped as a plain block mapping)."""


def _represent_fields(dumper: yaml.Dumper, data: _OrderedFields) -> yaml.Node:
    return dumper.represent_mapping('tag:yaml.org,2002:map', data.items())


class _MessageDumper(yaml.Dumper):
    """PyYAML's default dumper, with a message's fields kept in order."""


_MessageDumper.add_representer(_OrderedFields, _represent_fields)


def format_message_yaml(message: object) -> str:
    """Return ``message`` as ``ros2 topic echo`` prints it (block YAML, before the ``---``)."""
    return yaml.dump(
        _message_tree(message),
        Dumper=_MessageDumper,
        allow_unicode=True,
        width=sys.maxsize,
        default_flow_style=False,
    )
