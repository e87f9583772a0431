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
A whole URDF given with ``-p robot_description:=...`` (issue 10, point 12).

rcl reads every ``-p`` value as YAML, with libyaml. What libyaml refuses (a comment such as
``Arguments: prefix``) is refused in both worlds with advice: ``urdf_file`` or a params file.
What libyaml accepts (panda.urdf, whose tab-indented lines PyYAML's own scanner refuses) is
accepted in both worlds, with libyaml and with the pure-Python fallback, and
robot_state_publisher runs on it as the real one does.
"""

from __future__ import annotations

import subprocess
from typing import Any

from conftest import executable_command
from conftest import ProcessOutput
from conftest import REPO_ROOT
from conftest import run_captured
import pytest
from ros_world.jazzy import require_ros2_cli
from ros_world.jazzy import running
from tf_demo.transport import ros_args
from tf_demo.transport.ros_args import explain_rcl_error
from tf_demo.transport.ros_args import parse_param_value
from tf_demo.transport.ros_args import parse_ros_args
from tf_demo.transport.ros_args import RosArgsError

PANDA_URDF = REPO_ROOT.parent / 'shared' / 'robots' / 'panda.urdf'

# rcl refuses this value: 'Arguments: prefix' is a mapping inside a multi-line plain scalar.
COMMENTED_URDF = """<?xml version="1.0"?>
<!-- A two-link robot.
     Arguments: prefix (frame name prefix) -->
<robot name="commented">
  <link name="base_link"/>
  <link name="arm"/>
  <joint name="base_to_arm" type="fixed">
    <parent link="base_link"/>
    <child link="arm"/>
    <origin xyz="0 0 0.5" rpy="0 0 0"/>
  </joint>
</robot>
"""


def _panda() -> str:
    if not PANDA_URDF.is_file():
        pytest.skip(f'{PANDA_URDF} is not present')
    return PANDA_URDF.read_text(encoding='utf-8')


def _assert_advice(message: str) -> None:
    assert '\n' not in message
    assert '-p urdf_file:=' in message
    assert '--params-file' in message
    assert len(message) < 1000  # the 500-character URDF is shortened


def test_a_urdf_rcl_refuses_is_refused_with_advice() -> None:
    """The comment makes the value invalid YAML: the error says what to do instead."""
    with pytest.raises(RosArgsError) as caught:
        parse_ros_args(['prog', '--ros-args', '-p', f'robot_description:={COMMENTED_URDF}'])
    message = str(caught.value)
    _assert_advice(message)
    assert 'line 3: invalid YAML (column 15): mapping values are not allowed' in message
    assert message.startswith(
        "Couldn't parse parameter override rule: '-p robot_description:=<?xml version="
    )


def test_a_multiline_value_rcl_refuses_suggests_a_params_file() -> None:
    """Any other multi-line value that is not valid YAML points to a params file."""
    with pytest.raises(RosArgsError, match='put a multi-line value in a --params-file'):
        parse_ros_args(['--ros-args', '-p', 'notes:=first line\nkey: value'])


@pytest.mark.parametrize('loader', ['libyaml', 'pure'])
def test_panda_given_with_p_is_accepted(loader: str) -> None:
    """panda.urdf's tab-indented lines are read as libyaml reads them, by both scanners."""
    text = _panda()
    assert '\n\t<' in text  # the case: tabs at the start of continuation lines
    chosen = ros_args.YAML_EVENT_LOADER if loader == 'libyaml' else ros_args.PureYamlEventLoader
    value = parse_param_value(text, loader=chosen)
    assert isinstance(value, str)
    assert value == ' '.join(line.strip(' \t') for line in text.strip().split('\n'))


def test_pure_scanner_refuses_a_tab_that_breaks_indentation_as_libyaml_does() -> None:
    """A tab left of a block mapping value's indentation is refused by both scanners."""
    text = 'a: b\n\tc\n'
    for loader in (ros_args.YAML_EVENT_LOADER, ros_args.PureYamlEventLoader):
        with pytest.raises(ValueError, match=r'a mapping is not a parameter value|tab'):
            parse_param_value(text, loader=loader)


def _rsp(world_env: dict[str, str], *ros_arguments: str) -> subprocess.CompletedProcess[str]:
    command = executable_command('robot_state_publisher', '--ros-args', *ros_arguments)
    return run_captured(command, world_env, timeout=120)


def test_robot_state_publisher_refuses_the_commented_urdf_with_advice(
    world_env: dict[str, str],
) -> None:
    """A real robot_state_publisher process: exit 1, usage and one error line with advice."""
    completed = _rsp(world_env, '-p', f'robot_description:={COMMENTED_URDF}')
    assert completed.returncode == 1, completed.stderr
    assert 'Traceback' not in completed.stderr
    errors = [line for line in completed.stderr.splitlines() if ': error: ' in line]
    assert len(errors) == 1, completed.stderr
    _assert_advice(errors[0])


def test_robot_state_publisher_runs_on_panda_given_with_p(spawn: Any) -> None:
    """``robot_state_publisher --ros-args -p robot_description:="$(cat panda.urdf)"`` runs."""
    process = spawn.start(
        'robot_state_publisher', '--ros-args', '-p', f'robot_description:={_panda()}'
    )
    output = ProcessOutput(process)
    output.wait_for_line('Robot initialized', timeout=60, anywhere=True)
    assert process.poll() is None, output.stderr


# -- the rclpy world: rcl's own verdicts -----------------------------------------------------


@pytest.mark.rclpy_world
def test_the_real_rcl_refuses_the_commented_urdf_and_we_explain_it(ros: None) -> None:
    """rcl refuses the same value; its message, explained, carries the same advice."""
    from tf_demo import transport

    arguments = ['--ros-args', '-p', f'robot_description:={COMMENTED_URDF}']
    with pytest.raises(RuntimeError, match="Couldn't parse parameter override rule") as caught:
        transport.create_node('rsp_refused', cli_args=arguments)
    _assert_advice(explain_rcl_error(str(caught.value), arguments))


@pytest.mark.rclpy_world
def test_rclpy_init_refusal_is_a_ros_args_error_with_advice() -> None:
    """rclpy.init through the backend: rcl's refusal is a one-line RosArgsError."""
    from tf_demo.transport import rclpy_backend

    with pytest.raises(RosArgsError) as caught:
        rclpy_backend.init(
            args=['rsp', '--ros-args', '-p', f'robot_description:={COMMENTED_URDF}']
        )
    _assert_advice(str(caught.value))
    assert ', at /' not in str(caught.value)  # rcl's C source locations are dropped
    with pytest.raises(RosArgsError, match=r"Found unknown ROS arguments: \['--bogus'\]"):
        rclpy_backend.init(args=['rsp', '--ros-args', '--bogus'])


@pytest.mark.rclpy_world
def test_ros2_run_robot_state_publisher_on_panda(world_env: dict[str, str]) -> None:
    """The issue's command under ``ros2 run``: accepted, the robot initialised."""
    require_ros2_cli()
    command = ['ros2', 'run', 'tf_demo', 'robot_state_publisher', '--ros-args', '-p']
    with running([*command, f'robot_description:={_panda()}'], world_env) as output:
        output.wait_for_line('Robot initialized', timeout=90, anywhere=True)
        assert output.process.poll() is None, output.stderr
    assert 'Traceback' not in '\n'.join(output.stderr)
