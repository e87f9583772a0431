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
``-p name:=value`` typed exactly as rcl's YAML parser types it (issue 10, points 5 and 6).

One table of forms. In both worlds our parser must give each form the table's type and value
(with libyaml and with the pure-Python fallback scanner). In the rclpy world the same test also
starts a real rclpy node with the same ``-p`` arguments and checks every form against
``ros2 param get`` and against the node's own parameters, so the table is rcl's, not ours.
"""

from __future__ import annotations

import ast
from concurrent.futures import ThreadPoolExecutor
import math
from pathlib import Path
import shutil
import subprocess
import sys
from typing import Any

from conftest import ProcessOutput
from conftest import run_captured
import pytest
from tf_demo.transport.params_yaml import parse_param_value
from tf_demo.transport.params_yaml import PureYamlEventLoader
from tf_demo.transport.ros_args import parse_ros_args
from tf_demo.transport.ros_args import RosArgsError

INF = math.inf
NAN = math.nan
BIG = '9' * 5000

# (value text, rclpy type name, value). The 23 forms of the issue come first.
TABLE: list[tuple[str, str, Any]] = [
    ('1e3', 'DOUBLE', 1000.0),
    ('5e-1', 'DOUBLE', 0.5),
    ('inf', 'DOUBLE', INF),
    ('nan', 'DOUBLE', NAN),
    ('y', 'BOOL', True),
    ('n', 'BOOL', False),
    ('1_000', 'STRING', '1_000'),
    ('1:30', 'STRING', '1:30'),
    ('0b11', 'STRING', '0b11'),
    ('0o17', 'STRING', '0o17'),
    ('0x1F', 'INTEGER', 31),
    ('010', 'INTEGER', 8),
    ('-inf', 'DOUBLE', -INF),
    ('.inf', 'DOUBLE', INF),
    ('.nan', 'DOUBLE', NAN),
    ('Y', 'BOOL', True),
    ('yes', 'BOOL', True),
    ('No', 'BOOL', False),
    ('on', 'BOOL', True),
    ('OFF', 'BOOL', False),
    ('~', 'STRING', '~'),
    ('null', 'STRING', 'null'),
    ('2020-01-01', 'STRING', '2020-01-01'),
    # more of rcl's rules: strtoll base 0, strtod, ERANGE, quoting, tags, arrays
    ('TRUE', 'BOOL', True),
    ('tRUE', 'STRING', 'tRUE'),
    ('08', 'DOUBLE', 8.0),
    ('+5', 'INTEGER', 5),
    ('-0', 'INTEGER', 0),
    ('-0x10', 'INTEGER', -16),
    ('1.5', 'DOUBLE', 1.5),
    ('.5', 'DOUBLE', 0.5),
    ('5.', 'DOUBLE', 5.0),
    ('1E3', 'DOUBLE', 1000.0),
    ('-.5e-3', 'DOUBLE', -0.0005),
    ('0x1p3', 'DOUBLE', 8.0),
    ('Infinity', 'DOUBLE', INF),
    ('nan(1)', 'DOUBLE', NAN),
    ('.Nan', 'STRING', '.Nan'),
    ('1e', 'STRING', '1e'),
    ('12abc', 'STRING', '12abc'),
    ('0.1.2', 'STRING', '0.1.2'),
    ('1,000', 'STRING', '1,000'),
    ('9223372036854775807', 'INTEGER', 9223372036854775807),
    ('-9223372036854775808', 'INTEGER', -9223372036854775808),
    ('9223372036854775808', 'DOUBLE', 9.223372036854776e18),
    ('99999999999999999999', 'DOUBLE', 1e20),
    ('0xFFFFFFFFFFFFFFFFF', 'DOUBLE', 2.9514790517935283e20),
    (BIG, 'STRING', BIG),
    ('-' + BIG, 'STRING', '-' + BIG),
    ('1e400', 'STRING', '1e400'),
    ('1e-400', 'STRING', '1e-400'),
    ('1e-310', 'STRING', '1e-310'),
    ('0x1p-1074', 'DOUBLE', 5e-324),
    ('1e308', 'DOUBLE', 1e308),
    ('1.8e308', 'STRING', '1.8e308'),
    ("''", 'STRING', ''),
    ("'42'", 'STRING', '42'),
    ('"true"', 'STRING', 'true'),
    ('!!str 5', 'STRING', '5'),
    ('!!float 5', 'INTEGER', 5),
    ('a # comment', 'STRING', 'a'),
    ('a\tb', 'STRING', 'a\tb'),
    ('/robot/base', 'STRING', '/robot/base'),
    ('[1, 2]', 'INTEGER_ARRAY', [1, 2]),
    ('[1.0, 2.5]', 'DOUBLE_ARRAY', [1.0, 2.5]),
    ('[1e3, 5e-1]', 'DOUBLE_ARRAY', [1000.0, 0.5]),
    ('[y, n, on]', 'BOOL_ARRAY', [True, False, True]),
    ('[a, ~, null]', 'STRING_ARRAY', ['a', '~', 'null']),
    ("['1', '2']", 'STRING_ARRAY', ['1', '2']),
    ('!!python/tuple [1, 2]', 'INTEGER_ARRAY', [1, 2]),
    ('[[1, 2], [3]]', 'INTEGER_ARRAY', [3]),
    ('[[1], 2]', 'INTEGER', 2),
]

# Forms rcl refuses: the whole command line is refused, in both worlds.
REFUSED = ['', '[1, a]', '[1, 2.5]', '{a: 1}', 'a: b', '*anchor', '[a, , b]', '[{a: 1}]']


def _same(actual: Any, expected: Any) -> bool:
    if isinstance(expected, float) and math.isnan(expected):
        return isinstance(actual, float) and math.isnan(actual)
    if isinstance(expected, list):
        return list(actual) == expected and all(
            type(a) is type(e) for a, e in zip(actual, expected, strict=True)
        )
    return type(actual) is type(expected) and actual == expected


def _type_name(value: Any) -> str:
    """The rclpy parameter type name of a value our parser returns."""
    names = {bool: 'BOOL', int: 'INTEGER', float: 'DOUBLE', str: 'STRING'}
    if isinstance(value, list):
        return names[type(value[0])] + '_ARRAY'
    return names[type(value)]


def _case_id(text: str) -> str:
    return repr(text if len(text) <= 20 else f'{text[:10]}...({len(text)})')


@pytest.mark.parametrize(
    ('text', 'type_name', 'expected'), TABLE, ids=[_case_id(t[0]) for t in TABLE]
)
def test_our_parser_types_each_form_as_rcl(text: str, type_name: str, expected: Any) -> None:
    """Each -p form gets rcl's type and value, with libyaml and with the pure scanner."""
    for loader in (None, PureYamlEventLoader):
        value = parse_param_value(text, loader=loader)
        assert _type_name(value) == type_name
        assert _same(value, expected), (value, expected)
    overrides = parse_ros_args(['--ros-args', '-p', f'x:={text}']).parameter_overrides('/n')
    assert _same(overrides['x'].value, expected)
    assert overrides['x'].type_.name == type_name


@pytest.mark.parametrize('text', REFUSED, ids=[repr(t) for t in REFUSED])
def test_forms_rcl_refuses_are_refused_with_one_line(text: str) -> None:
    """A value rcl refuses is a RosArgsError naming the rule, on one line."""
    with pytest.raises(RosArgsError) as caught:
        parse_ros_args(['prog', '--ros-args', '-p', f'x:={text}'])
    message = str(caught.value)
    assert message.startswith(f"Couldn't parse parameter override rule: '-p x:={text}'. Error: ")
    assert '\n' not in message


@pytest.mark.parametrize('text', ['[]', '# only a comment', '[' * 3 + ']' * 3])
def test_a_value_with_no_type_is_refused(text: str) -> None:
    """rcl leaves such a parameter NOT_SET (rclpy then fails to declare it); we say why at once."""
    with pytest.raises(RosArgsError, match='the parameter type cannot be determined'):
        parse_ros_args(['--ros-args', '-p', f'x:={text}'])


def test_the_issue_lists_at_least_23_forms() -> None:
    """The table covers the issue's 23 forms and more."""
    assert len(TABLE) >= 23
    assert len({text for text, _, _ in TABLE}) == len(TABLE)


# -- the rclpy world: the same table against the real rcl -----------------------------------

ROS2_PARAM_GET = ('ros2', 'param', 'get', '--no-daemon', '--timeout', '30')
PROBE = """
import sys
import rclpy
from rclpy.node import Node

rclpy.init(args=sys.argv)
node = Node('typing_probe', automatically_declare_parameters_from_overrides=True)
print('probe ready', flush=True)
try:
    rclpy.spin(node)
except (KeyboardInterrupt, rclpy.executors.ExternalShutdownException):
    pass
"""

_GET_LABELS = {
    'Boolean value is:': 'BOOL',
    'Integer value is:': 'INTEGER',
    'Double value is:': 'DOUBLE',
    'String value is:': 'STRING',
    'Boolean values are:': 'BOOL_ARRAY',
    'Integer values are:': 'INTEGER_ARRAY',
    'Double values are:': 'DOUBLE_ARRAY',
    'String values are:': 'STRING_ARRAY',
}


def _read_param_get(stdout: str) -> tuple[str, Any]:
    """The type and value ``ros2 param get`` printed (its labels, Python reprs of the value)."""
    text = stdout.removesuffix('\n')
    for label, type_name in _GET_LABELS.items():
        if text.startswith(label):
            shown = text[len(label) + 1 :]
            if type_name == 'STRING':
                return type_name, shown
            if type_name == 'DOUBLE':
                return type_name, float(shown)
            if type_name == 'INTEGER':
                return type_name, int(shown)
            return type_name, ast.literal_eval(shown)
    pytest.fail(f'unexpected ros2 param get output: {stdout!r}')


def _probe_arguments() -> list[str]:
    arguments = ['--ros-args']
    for index, (text, _, _) in enumerate(TABLE):
        arguments += ['-p', f'p{index:03d}:={text}']
    return arguments


@pytest.mark.rclpy_world
def test_the_table_is_rcls_in_process(ros: None) -> None:
    """A real rclpy node given every form: each parameter has the table's type and value."""
    from tf_demo import transport

    node = transport.create_node(
        'typing_in_process',
        cli_args=_probe_arguments(),
        automatically_declare_parameters_from_overrides=True,
    )
    try:
        for index, (text, type_name, expected) in enumerate(TABLE):
            parameter = node.get_parameter(f'p{index:03d}')
            assert parameter.type_.name == type_name, text
            assert _same(parameter.value, expected), (text, parameter.value)
    finally:
        node.destroy_node()


@pytest.mark.rclpy_world
@pytest.mark.parametrize('text', REFUSED, ids=[repr(t) for t in REFUSED])
def test_the_forms_we_refuse_are_refused_by_rcl(text: str, ros: None) -> None:
    """rcl refuses each form we refuse (the node cannot be created)."""
    from tf_demo import transport

    with pytest.raises(RuntimeError, match="Couldn't parse parameter override rule"):
        transport.create_node('refused', cli_args=['--ros-args', '-p', f'x:={text}'])


@pytest.mark.rclpy_world
def test_the_table_is_rcls_by_ros2_param_get(world_env: dict[str, str], tmp_path: Path) -> None:
    """A real rclpy node process started with every form; ``ros2 param get`` agrees per form."""
    if shutil.which('ros2') is None:
        pytest.skip('the ros2 command line is not on PATH')
    script = tmp_path / 'typing_probe.py'
    script.write_text(PROBE, encoding='utf-8')
    probe = ProcessOutput(
        subprocess.Popen(
            [sys.executable, str(script), *_probe_arguments()],
            env=world_env,
            stdin=subprocess.DEVNULL,
            stdout=subprocess.PIPE,
            stderr=subprocess.PIPE,
            text=True,
        )
    )
    try:
        probe.wait_for_line('probe ready', timeout=60)

        def get(index: int) -> subprocess.CompletedProcess[str]:
            return run_captured(
                [*ROS2_PARAM_GET, '/typing_probe', f'p{index:03d}'], world_env, timeout=120
            )

        with ThreadPoolExecutor(max_workers=4) as pool:
            answers = list(pool.map(get, range(len(TABLE))))
    finally:
        probe.process.send_signal(2)
        try:
            probe.process.wait(timeout=15)
        except subprocess.TimeoutExpired:
            probe.process.kill()
            probe.process.wait()
    for (text, type_name, expected), answer in zip(TABLE, answers, strict=True):
        assert answer.returncode == 0, (text, answer.stderr)
        got_type, got_value = _read_param_get(answer.stdout)
        assert (got_type, _case_id(text)) == (type_name, _case_id(text))
        assert _same(got_value, expected), (text, got_value)


# -- our own node, both worlds ----------------------------------------------------------------


def test_dynamic_tf_pub_takes_rate_1e3(spawn: Any) -> None:
    """``dynamic_tf_pub --ros-args -p rate:=1e3 -p radius:=5e-1`` starts at 1000 Hz, 0.5 m."""
    process = spawn.start('dynamic_tf_pub', '--ros-args', '-p', 'rate:=1e3', '-p', 'radius:=5e-1')
    output = ProcessOutput(process)
    output.wait_for_line('radius 0.5 m at 1000 Hz', timeout=60, anywhere=True)
    assert process.poll() is None, output.stderr
