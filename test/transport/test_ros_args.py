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

"""--ros-args parsing as rcl does it, and how a real executable reports bad arguments."""

import os
from pathlib import Path
import sys

from conftest import PACKAGE_ROOT
from conftest import run_captured
import pytest
from tf_demo.transport.ros_args import expand_topic_name
from tf_demo.transport.ros_args import parse_ros_args
from tf_demo.transport.ros_args import remove_ros_args
from tf_demo.transport.ros_args import RosArgsError
from tf_demo.transport.ros_args import split_ros_args


def test_user_arguments_outside_ros_args_are_kept_in_order() -> None:
    """Arguments before --ros-args and after -- are the user's, unchanged."""
    argv = [
        'prog',
        'a',
        '--flag',
        '--ros-args',
        '-p',
        'x:=1',
        '--',
        'b',
        '--ros-args',
        '-r',
        'a:=b',
    ]
    parsed = parse_ros_args(argv)
    assert parsed.user_args == ('prog', 'a', '--flag', 'b')
    assert remove_ros_args(argv) == ['prog', 'a', '--flag', 'b']
    assert len(parsed.remap_rules) == 1


# A flag that takes a value takes the next token, ``--`` and ``--ros-args`` included (rcl).
SPLITS = [
    (['a', '--ros-args', '-r', 'x:=y', '--', 'b'], ['a', 'b'], ['--ros-args', '-r', 'x:=y']),
    (['--ros-args', '-r', '--', 'b'], [], ['--ros-args', '-r', '--', 'b']),
    (['--ros-args', '-e', '--'], [], ['--ros-args', '-e', '--']),
    (
        ['--ros-args', '--log-config-file', '--', 'a'],
        [],
        ['--ros-args', '--log-config-file', '--', 'a'],
    ),
    (['--ros-args', '-r', '--ros-args', '--', 'b'], ['b'], ['--ros-args', '-r', '--ros-args']),
    (
        ['--ros-args', '--ros-args', '-p', 'a:=1', '--', '--', 'c'],
        ['--', 'c'],
        ['--ros-args', '--ros-args', '-p', 'a:=1'],
    ),
    (['--', 'a'], ['--', 'a'], []),
    (
        ['--ros-args', '--enable-stdout-logs', '--', 'z'],
        ['z'],
        ['--ros-args', '--enable-stdout-logs'],
    ),
    (['--ros-args', '-p'], [], ['--ros-args', '-p']),
]


@pytest.mark.parametrize(('argv', 'user', 'ros'), SPLITS)
def test_split_ros_args_walks_as_rcl(argv: list[str], user: list[str], ros: list[str]) -> None:
    """Sections run to ``--`` or the end; a value flag's value is never a section's end."""
    assert split_ros_args(argv) == (user, ros)


@pytest.mark.rclpy_world
@pytest.mark.parametrize(('argv', 'user', 'ros'), SPLITS)
def test_split_ros_args_agrees_with_rclpy(
    argv: list[str], user: list[str], ros: list[str]
) -> None:
    """The real rclpy.utilities.remove_ros_args keeps the same user arguments, or refuses."""
    from rclpy.utilities import remove_ros_args as rclpy_remove_ros_args

    del ros
    try:
        kept = rclpy_remove_ros_args(['prog', *argv])
    except RuntimeError:  # rcl refuses the ROS arguments (RCLInvalid/UnknownROSArgsError)
        with pytest.raises(RosArgsError):
            parse_ros_args(['prog', *argv])
    else:
        assert kept == ['prog', *user]


def test_topic_name_expansion_follows_rcl() -> None:
    """Relative names join the namespace, ~ is the node's name, {node} is substituted."""
    assert expand_topic_name('chatter', 'talker', '/') == '/chatter'
    assert expand_topic_name('chatter', 'talker', '/ns') == '/ns/chatter'
    assert expand_topic_name('~/state', 'talker', '/ns') == '/ns/talker/state'
    assert expand_topic_name('{node}/out', 'talker', '/') == '/talker/out'
    assert expand_topic_name('/abs', 'talker', '/ns') == '/abs'


@pytest.mark.parametrize(
    ('argv', 'message'),
    [
        (['-p'], "Couldn't parse trailing -p flag. No parameter override rule found."),
        (['--param', 'x'], "Couldn't parse parameter override rule: '--param x'. Error: "),
        (['-p', 'x:=[1, a]'], 'Sequence should be of same type'),
        (['-p', 'x:={a: 1}'], 'a mapping is not a parameter value'),
        (['-p', 'bad name:=1'], "Invalid parameter name 'bad name'"),
        (['-r'], "Couldn't parse trailing -r flag. No remap rule found."),
        (['-r', 'a'], "Couldn't parse remap rule: '-r a'. Error: "),
        (['-r', '__ns:=relative'], 'must be absolute'),
        (['-r', '__node:=a/b'], "Invalid node name 'a/b'"),
        (['-r', 'a:=b//c'], "must not contain repeated '/'"),
        (['--params-file'], "Couldn't parse trailing --params-file flag. No file path provided."),
        (['--params-file', '/nonexistent/p.yaml'], '/nonexistent/p.yaml: no such file'),
        (['--log-level'], "Couldn't parse trailing log level flag: '--log-level'."),
        (
            ['--log-level', 'loud'],
            "Couldn't parse log level: '--log-level loud'. "
            'Error: Argument does not use a valid severity level',
        ),
        (['-e', 'relative'], 'must be fully qualified'),
        (['--unknown', 'x'], "Found unknown ROS arguments: ['--unknown', 'x']"),
    ],
)
def test_bad_arguments_raise_rcl_style_errors(argv: list[str], message: str) -> None:
    """Every malformed ROS argument raises RosArgsError naming the argument and the reason."""
    with pytest.raises(RosArgsError) as caught:
        parse_ros_args(['prog', '--ros-args', *argv])
    assert message in str(caught.value)


NODE_SCRIPT = """
import sys
from tf_demo.transport import run_node

def never_built():
    raise AssertionError('the node must not be built when the arguments are bad')

sys.exit(run_node(never_built))
"""


@pytest.mark.parametrize(
    ('ros_args', 'message'),
    [
        (['-p'], "Couldn't parse trailing -p flag"),
        (['-r', '__ns:=oops'], "Couldn't parse remap rule: '-r __ns:=oops'"),
        (['--bogus'], "Found unknown ROS arguments: ['--bogus']"),
    ],
)
def test_executable_with_bad_arguments_exits_1_with_usage(
    tmp_path: Path, ros_args: list[str], message: str
) -> None:
    """A real process prints usage and a one-line error, exits 1, and shows no traceback."""
    script = tmp_path / 'node.py'
    script.write_text(NODE_SCRIPT, encoding='utf-8')
    env = dict(os.environ, PYTHONPATH=str(PACKAGE_ROOT), TF_DEMO_BACKEND='dds')
    completed = run_captured([sys.executable, str(script), '--ros-args', *ros_args], env)
    assert completed.returncode == 1
    lines = completed.stderr.strip().splitlines()
    assert lines[0].startswith('usage: node.py ')
    assert len(lines) == 2
    assert lines[1].startswith('node.py: error: ')
    assert message in lines[1]
    assert 'Traceback' not in completed.stderr


def test_split_ros_args_drops_each_section_for_the_tool() -> None:
    """--ros-args sections run to '--' and are removed from the tool's arguments."""
    tool, ros = split_ros_args(
        ['a', '--ros-args', '-p', 'x:=1', '--', 'b', '--ros-args', '-r', 'q']
    )
    assert tool == ['a', 'b']
    assert ros == ['--ros-args', '-p', 'x:=1', '--ros-args', '-r', 'q']
