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

"""One --ros-args rule (-p, -r, --log-level) read as rcl reads it, node-prefixed or not."""

from conftest import REPO_ROOT
import pytest
from tf_demo.transport.dds.log_format import LoggingSeverity
from tf_demo.transport.ros_args import parse_ros_args
from tf_demo.transport.ros_args import resolve_node_arguments


def test_param_rules_can_name_a_node() -> None:
    """-p node:name:=value applies only to that node; plain -p to every node."""
    parsed = parse_ros_args(['--ros-args', '-p', 'talker:rate:=5.0', '--param', 'frame:=map'])
    assert {n: p.value for n, p in parsed.parameter_overrides('/talker').items()} == {
        'rate': 5.0,
        'frame': 'map',
    }
    assert set(parsed.parameter_overrides('/listener')) == {'frame'}


def test_node_name_and_namespace_remaps() -> None:
    """__node:=, __name:= and __ns:= rename the node; node-prefixed rules target one node."""
    resolved = resolve_node_arguments(
        ['--ros-args', '-r', '__node:=renamed', '-r', '__ns:=/robot1'], 'talker', ''
    )
    assert (resolved.node_name, resolved.namespace) == ('renamed', '/robot1')
    other = resolve_node_arguments(['--ros-args', '-r', 'talker:__name:=t2'], 'listener', '/x')
    assert (other.node_name, other.namespace) == ('listener', '/x')
    assert (
        resolve_node_arguments(['--ros-args', '-r', 'talker:__name:=t2'], 'talker', '').node_name
        == 't2'
    )


def test_topic_remaps_apply_to_expanded_names() -> None:
    """from:=to matches after expansion (relative, ~) and the first matching rule wins."""
    parsed = parse_ros_args(
        ['--ros-args', '-r', 'tf:=/robot/tf', '-r', '/tf:=/other', '-r', '~/out:=/private']
    )
    assert parsed.remap_topic('/tf', 'node', '/') == '/robot/tf'
    assert parsed.remap_topic('/ns/tf', 'node', '/ns') == '/robot/tf'
    assert parsed.remap_topic('/ns/node/out', 'node', '/ns') == '/private'
    assert parsed.remap_topic('/tf_static', 'node', '/') == '/tf_static'


def test_log_level_rules() -> None:
    """--log-level sets the default or one logger's level; the named rule wins for it."""
    parsed = parse_ros_args(['--ros-args', '--log-level', 'warn', '--log-level', 'talker:=DEBUG'])
    assert parsed.log_level_for('talker') is LoggingSeverity.DEBUG
    assert parsed.log_level_for('listener') is LoggingSeverity.WARN
    assert (
        resolve_node_arguments(
            ['--ros-args', '--log-level', 'ns.talker:=error'], 'talker', '/ns'
        ).log_level
        is LoggingSeverity.ERROR
    )


PANDA_URDF = REPO_ROOT.parent / 'shared' / 'robots' / 'panda.urdf'


def _override_rules() -> list[object]:
    rules: list[object] = [
        pytest.param(['-p', 'qos_overrides./tf_static.publisher.depth:=3'], id='slash-name'),
        pytest.param(['-p', 'a.b/c.d:=x'], id='dots'),
    ]
    if PANDA_URDF.is_file():  # a tab inside, which PyYAML's own scanner refuses and rcl's takes
        rule = ['-p', f'robot_description:={PANDA_URDF.read_text(encoding="utf-8")}']
        rules.append(pytest.param(rule, id='panda-urdf'))
    return rules


@pytest.mark.parametrize('rule', _override_rules())
def test_param_rules_read_as_rcl_reads_them(rule: list[str]) -> None:
    """Names with '/' inside tokens, and values only libyaml's scanner (rcl's) accepts."""
    parsed = parse_ros_args(['--ros-args', *rule])
    assert len(parsed.parameter_overrides('/n')) == 1


@pytest.mark.rclpy_world
@pytest.mark.parametrize('rule', _override_rules())
def test_param_rules_give_the_real_rcls_values(rule: list[str], ros: None) -> None:
    """Each rule through the real rcl gives the same name, value and type as ours."""
    from tf_demo import transport

    ours = {
        n: p.value
        for n, p in parse_ros_args(['--ros-args', *rule]).parameter_overrides('/n').items()
    }
    node = transport.create_node(
        'n', cli_args=['--ros-args', *rule], automatically_declare_parameters_from_overrides=True
    )
    try:
        real = {name: node.get_parameter(name).value for name in ours}
    finally:
        node.destroy_node()
    assert real == ours


def test_node_prefixed_param_rule_names_the_node_key_as_rcl_does() -> None:
    """-p talker:x:=1 is the key /talker: it does not reach /ns/talker."""
    parsed = parse_ros_args(['--ros-args', '-p', 'talker:x:=1'])
    assert set(parsed.parameter_overrides('/talker')) == {'x'}
    assert parsed.parameter_overrides('/ns/talker') == {}
