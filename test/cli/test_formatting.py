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

"""Golden-text tests of the pure formatters (texts taken from upstream tools' real output)."""

import json
import math

from tf_demo.cli import formatting
import yaml

SQRT_HALF = math.sqrt(0.5)


def test_echo_block_identity_matches_upstream_output():
    """An identity rotation prints tf2_echo's block, including its '-0.000' pitch."""
    text = formatting.format_echo_transform(0, 0, (0.0, 1.0, 0.0), (0.0, 0.0, 0.0, 1.0))
    assert text == (
        'At time 0.0\n'
        '- Translation: [0.000, 1.000, 0.000]\n'
        '- Rotation: in Quaternion [0.000, 0.000, 0.000, 1.000]\n'
        '- Rotation: in RPY (radian) [0.000, -0.000, 0.000]\n'
        '- Rotation: in RPY (degree) [0.000, -0.000, 0.000]\n'
        '- Matrix:\n'
        '  1.000  0.000  0.000  0.000\n'
        '  0.000  1.000  0.000  1.000\n'
        '  0.000  0.000  1.000  0.000\n'
        '  0.000  0.000  0.000  1.000\n'
    )


def test_echo_block_quarter_turn_with_negative_zeros():
    """A yaw of 90 degrees prints negative zeros and a nanosecond field that is not padded."""
    text = formatting.format_echo_transform(
        5, 1_000_000, (-0.0, -0.155, -0.305), (-0.0, -0.0, SQRT_HALF, SQRT_HALF)
    )
    assert text == (
        'At time 5.1000000\n'
        '- Translation: [-0.000, -0.155, -0.305]\n'
        '- Rotation: in Quaternion [-0.000, -0.000, 0.707, 0.707]\n'
        '- Rotation: in RPY (radian) [-0.000, -0.000, 1.571]\n'
        '- Rotation: in RPY (degree) [-0.000, -0.000, 90.000]\n'
        '- Matrix:\n'
        '  0.000 -1.000 -0.000 -0.000\n'
        '  1.000  0.000  0.000 -0.155\n'
        '  0.000 -0.000  1.000 -0.305\n'
        '  0.000  0.000  0.000  1.000\n'
    )


def test_echo_block_precision_widens_cells():
    """-p 5 prints five decimals and keeps the matrix columns aligned."""
    text = formatting.format_echo_transform(1, 2, (1.0, 0.0, 0.0), (0.0, 0.0, 0.0, 1.0), 5)
    assert '- Translation: [1.00000, 0.00000, 0.00000]' in text
    assert '  1.00000  0.00000  0.00000  1.00000\n' in text


def test_echo_failure_block():
    """The failure block: 3 decimals, no space after the colon, frames, a blank line."""
    text = formatting.format_echo_failure(
        1700000000.12345,
        'Invalid frame ID "a" passed to canTransform argument target_frame - frame does not exist',
        'Frame b exists with parent c.\n',
    )
    assert text == (
        'Failure at 1700000000.123\n'
        'Exception thrown:Invalid frame ID "a" passed to canTransform argument target_frame - '
        'frame does not exist\n'
        'The current list of frames is:\n'
        'Frame b exists with parent c.\n'
        '\n'
    )


def test_echo_waiting_line_has_two_spaces():
    """The waiting text keeps upstream's two spaces after the arrow."""
    assert formatting.format_echo_waiting('a', 'b', 'why') == 'Waiting for transform a ->  b: why'


def test_echo_json_line_is_one_object():
    """--json prints one parseable object per line with the matrix and both RPY forms."""
    line = formatting.format_echo_json(
        'a', 'b', 3, 4, (1.0, 2.0, 3.0), (0, 0, SQRT_HALF, SQRT_HALF)
    )
    assert line.endswith('\n')
    assert line.count('\n') == 1
    record = json.loads(line)
    assert record['stamp'] == {'sec': 3, 'nanosec': 4}
    assert record['translation'] == [1.0, 2.0, 3.0]
    assert math.isclose(record['rpy_degree'][2], 90.0)
    assert math.isclose(record['matrix'][1][0], 1.0)
    assert record['matrix'][3] == [0.0, 0.0, 0.0, 1.0]


def test_static_info_line_matches_upstream():
    """The start-up INFO text of static_transform_publisher (printf %lf)."""
    text = formatting.format_static_info((1.0, 1.0, 1.0), (0.0, 0.0, 0.0, 1.0), '/base', '/odom')
    assert text == (
        'Spinning until stopped - publishing transform\n'
        "translation: ('1.000000', '1.000000', '1.000000')\n"
        "rotation: ('0.000000', '0.000000', '0.000000', '1.000000')\n"
        "from '/base' to '/odom'"
    )


def test_static_usage_starts_and_ends_like_upstream():
    """The usage text begins with upstream's synopsis and ends with the yaw line."""
    assert formatting.STATIC_USAGE.startswith(
        'usage: static_transform_publisher [--x X] [--y Y] [--z Z] [--qx QX] [--qy QY] [--qz QZ] '
        '[--qw QW] [--roll ROLL] [--pitch PITCH] [--yaw YAW] --frame-id FRAME_ID '
        '--child-frame-id CHILD_FRAME_ID\n\nA command line utility for manually sending a static '
        'transform.\n'
    )
    assert formatting.STATIC_USAGE.endswith(
        '  --yaw YAW             yaw component Euler rotation\n'
    )


# A frame map as the tf2_frames service returns it, YAML-parsed (static + dynamic).
FRAMES_YAML = """\
odom:\x20
  parent: 'map'
  broadcaster: 'default_authority'
  rate: 10000.000
  most_recent_transform: 0.000000
  oldest_transform: 0.000000
  buffer_length: 0.000
base_link:\x20
  parent: 'odom'
  broadcaster: 'default_authority'
  rate: 20.004
  most_recent_transform: 1638875734.962492
  oldest_transform: 1638875730.012000
  buffer_length: 4.950
"""


def test_generate_dot_matches_upstream_for_one_tree():
    """One tree gives upstream's DOT text byte for byte (values are Python str() of the YAML)."""
    dot = formatting.generate_dot(yaml.safe_load(FRAMES_YAML), (1638875735, 500000000))
    assert dot == (
        'digraph G {\n'
        '"map" -> "odom"[label=" Broadcaster: default_authority\\nAverage rate: 10000.0\\n'
        'Buffer length: 0.0\\nMost recent transform: 0.0\\nOldest transform: 0.0\\n"];\n'
        '"odom" -> "base_link"[label=" Broadcaster: default_authority\\nAverage rate: 20.004\\n'
        'Buffer length: 4.95\\nMost recent transform: 1638875734.962492\\n'
        'Oldest transform: 1638875730.012\\n"];\n'
        'edge [style=invis];\n'
        ' subgraph cluster_legend { style=bold; color=black; label ="view_frames Result";\n'
        '"Recorded at time: 1638875735.5"[ shape=plaintext ] ;\n'
        '}->"map";\n'
        '}'
    )


def test_generate_dot_without_data():
    """No data (empty map or the empty YAML of a cleared buffer) gives the placeholder graph."""
    assert formatting.generate_dot({}, (0, 0)) == 'digraph G { "No tf data received" }'
    assert formatting.generate_dot(None, (0, 0)) == 'digraph G { "No tf data received" }'


def _info(parent: str) -> dict[str, object]:
    return {
        'parent': parent,
        'broadcaster': 'b',
        'rate': 1.0,
        'buffer_length': 0.0,
        'most_recent_transform': 0.0,
        'oldest_transform': 0.0,
    }


def test_generate_dot_several_roots_all_hang_under_legend():
    """Two trees: the legend points at both roots instead of hiding one."""
    dot = formatting.generate_dot({'odom': _info('map'), 'laser': _info('base_link')}, (1, 0))
    assert dot.endswith('}->{"map" "base_link"};\n}')


def test_generate_dot_loop_renders():
    """A loop (no root at all) still gives a closed graph, where upstream raised NameError."""
    dot = formatting.generate_dot({'a': _info('b'), 'b': _info('a')}, (1, 0))
    assert '"b" -> "a"' in dot
    assert '"a" -> "b"' in dot
    assert dot.endswith('] ;\n}\n}')


def test_generate_dot_escapes_quotes_in_names():
    """A hostile frame name cannot break out of its DOT string."""
    dot = formatting.generate_dot({'x"]; evil': _info('map')}, (1, 0))
    assert '"map" -> "x\\"]; evil"' in dot


def test_monitor_texts_match_upstream():
    """tf2_monitor's lines with C++ default stream formatting (%g)."""
    frames = formatting.format_monitor_frames(
        {'/odom': [0.0346603]}, {'/odom': '<no authority available>'}, None
    )
    assert frames == (
        '\nFrames:\nFrame: /odom, published by <no authority available>, '
        'Average Delay: 0.0346603, Max Delay: 0.0346603\n'
    )
    nodes = formatting.format_monitor_broadcasters(
        {'<no authority available>': [0.0346603]}, {'<no authority available>': [12.0]}
    )
    assert nodes == (
        'Node: <no authority available> 1e+08 Hz, Average Delay: 0.0346603 Max Delay: 0.0346603\n'
    )
    header = formatting.format_monitor_header('a', 'c', ['a', 'b', 'c'], 0.5, 1.25)
    assert header == (
        '\n\n\nRESULTS: for a to c\nChain is: a -> b -> c\nNet delay     avg = 0.5: max = 1.25\n'
    )
    assert formatting.format_monitor_header(None, None, None, 0, 0) == (
        '\n\n\nRESULTS: for all Frames\n'
    )


def test_monitor_frames_filtered_by_chain():
    """In chain mode only the chain's frames are listed, in sorted order."""
    text = formatting.format_monitor_frames(
        {'c': [1.0, 3.0], 'a': [2.0], 'x': [5.0]}, {'a': 'n', 'c': 'n', 'x': 'n'}, ['a', 'c']
    )
    assert text.splitlines()[2:] == [
        'Frame: a, published by n, Average Delay: 2, Max Delay: 2',
        'Frame: c, published by n, Average Delay: 2, Max Delay: 3',
    ]


def test_view_frames_default_file_names():
    """Without -o the files are frames_<%Y-%m-%d_%H.%M.%S>.gv/.pdf, with -o NAME.gv/.pdf."""
    import re

    from tf_demo.cli.view_frames import output_names

    gv, pdf = output_names(None)
    assert re.fullmatch(r'frames_\d{4}-\d{2}-\d{2}_\d{2}\.\d{2}\.\d{2}\.gv', gv)
    assert pdf == gv[:-3] + '.pdf'
    assert output_names('tree') == ('tree.gv', 'tree.pdf')
