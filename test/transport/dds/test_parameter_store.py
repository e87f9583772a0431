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

"""A node's parameters: declaring, overrides from --ros-args, on-set validation, as rclpy's.

Every test runs in both worlds on the world's own objects: a node made by
``tf_demo.transport.create_node`` (``rclpy.node.Node`` inside ROS 2, ``DdsNode`` with its
:class:`~tf_demo.transport.dds.parameter_store.ParameterStore` standalone) and the classes of
``tf_demo.transport.parameters`` (rclpy's inside ROS 2).
"""

from collections.abc import Iterator
from pathlib import Path
from typing import Any

import pytest
from tf_demo import transport
from tf_demo.transport.parameters import FloatingPointRange
from tf_demo.transport.parameters import IntegerRange
from tf_demo.transport.parameters import InvalidParameterTypeException
from tf_demo.transport.parameters import InvalidParameterValueException
from tf_demo.transport.parameters import Parameter
from tf_demo.transport.parameters import ParameterAlreadyDeclaredException
from tf_demo.transport.parameters import ParameterDescriptor
from tf_demo.transport.parameters import ParameterNotDeclaredException
from tf_demo.transport.parameters import ParameterUninitializedException
from tf_demo.transport.parameters import SetParametersResult

Type = Parameter.Type


@pytest.fixture
def make_node(ros: None) -> Iterator[Any]:
    """Create nodes of this run's world (``create_node`` keyword arguments); destroyed after."""
    del ros
    nodes: list[Any] = []

    def make(name: str = 'test_parameters', **kwargs: Any) -> Any:
        node = transport.create_node(name, **kwargs)
        nodes.append(node)
        return node

    yield make
    for node in nodes:
        node.destroy_node()


@pytest.fixture
def node(make_node: Any) -> Any:
    """One node of this run's world without overrides."""
    return make_node()


def test_declare_returns_the_default_and_rejects_redeclaration(node: Any) -> None:
    """declare_parameter returns the parameter; declaring it again raises."""
    assert node.declare_parameter('rate', 10.0).value == 10.0
    assert node.has_parameter('rate')
    with pytest.raises(ParameterAlreadyDeclaredException, match="already declared: \\['rate'\\]"):
        node.declare_parameter('rate', 1.0)


def test_undeclared_parameters_raise_rclpys_error(node: Any) -> None:
    """Getting or setting an undeclared parameter raises ParameterNotDeclaredException."""
    with pytest.raises(ParameterNotDeclaredException, match='undeclared parameter\\(s\\): nope'):
        node.get_parameter('nope')
    # (rclpy's text for set_parameters lists the names after the first, so it is not compared)
    with pytest.raises(ParameterNotDeclaredException, match=r'^Invalid access to undeclared'):
        node.set_parameters([Parameter('nope', value=1)])
    assert node.get_parameter_or('nope').type_ is Type.NOT_SET
    assert node.get_parameter_or('nope').name == 'nope'
    alternative = Parameter('nope', value=3)
    assert node.get_parameter_or('nope', alternative) is alternative
    with pytest.raises(TypeError, match=r'^All names must be instances of type str$'):
        node.get_parameters(['nope', 1])


def test_setting_another_type_is_rejected_unless_dynamically_typed(node: Any) -> None:
    """Static typing rejects with rclpy's reason; dynamic_typing accepts any type."""
    node.declare_parameter('frame', 'map')
    node.declare_parameter('anything', 1, ParameterDescriptor(dynamic_typing=True))
    [result] = node.set_parameters([Parameter('frame', value=3)])
    assert not result.successful
    assert result.reason == "Wrong parameter type, expected 'Type.STRING' got 'Type.INTEGER'"
    assert node.get_parameter('frame').value == 'map'
    [result] = node.set_parameters([Parameter('anything', value='now a string')])
    assert result.successful
    assert node.get_parameter('anything').value == 'now a string'


def test_on_set_callback_can_reject_with_a_reason(node: Any) -> None:
    """A rejecting callback keeps the old value; removing it lets the change through."""
    node.declare_parameter('rate', 10.0)

    def positive_rate(parameters: list[Parameter]) -> SetParametersResult:
        for parameter in parameters:
            if parameter.name == 'rate' and parameter.value <= 0:
                return SetParametersResult(successful=False, reason='rate must be positive')
        return SetParametersResult(successful=True)

    node.add_on_set_parameters_callback(positive_rate)
    [result] = node.set_parameters([Parameter('rate', value=-1.0)])
    assert (result.successful, result.reason) == (False, 'rate must be positive')
    assert node.get_parameter('rate').value == 10.0
    [result] = node.set_parameters([Parameter('rate', value=20.0)])
    assert result.successful
    assert node.get_parameter('rate').value == 20.0
    node.remove_on_set_parameters_callback(positive_rate)
    assert node.set_parameters([Parameter('rate', value=-1.0)])[0].successful


def test_an_on_set_callback_must_return_a_result(node: Any) -> None:
    """As in rclpy, the result's ``successful`` is read: returning None is an AttributeError."""
    node.declare_parameter('rate', 10.0)
    node.add_on_set_parameters_callback(lambda parameters: None)
    with pytest.raises(AttributeError, match="'NoneType' object has no attribute 'successful'"):
        node.set_parameters([Parameter('rate', value=1.0)])


def test_a_rejected_declaration_raises_invalid_value(make_node: Any) -> None:
    """An on-set callback that rejects an overridden value makes declare raise."""
    node = make_node(parameter_overrides=[Parameter('rate', value=-5.0)])
    node.add_on_set_parameters_callback(
        lambda params: SetParametersResult(successful=False, reason='no negative rates')
    )
    with pytest.raises(InvalidParameterValueException, match='Reason: no negative rates: rate'):
        node.declare_parameter('rate', 1.0)


def test_read_only_parameters_cannot_be_set(node: Any) -> None:
    """Setting a read-only parameter fails with a reason naming it."""
    node.declare_parameter('robot', 'r2', ParameterDescriptor(read_only=True))
    [result] = node.set_parameters([Parameter('robot', value='c3po')])
    assert not result.successful
    assert result.reason == 'Trying to set a read-only parameter: robot.'


def test_typed_parameter_without_value_is_uninitialized(node: Any) -> None:
    """Declaring with a Parameter.Type and no override leaves it unreadable until set."""
    node.declare_parameter('urdf', Type.STRING)
    with pytest.raises(ParameterUninitializedException, match="'urdf' is not initialized"):
        node.get_parameter('urdf')
    assert node.get_parameter_or('urdf').type_ is Type.NOT_SET
    assert node.set_parameters([Parameter('urdf', value='<robot/>')])[0].successful
    assert node.get_parameter('urdf').value == '<robot/>'


def test_override_of_the_wrong_type_raises_invalid_type(make_node: Any) -> None:
    """-p rate:=5 for a double default raises rclpy's InvalidParameterTypeException."""
    node = make_node(cli_args=['--ros-args', '-p', 'rate:=5'])
    expected = "Trying to set parameter 'rate' to '5' of type 'INTEGER', expecting type 'DOUBLE'"
    with pytest.raises(InvalidParameterTypeException, match=expected):
        node.declare_parameter('rate', 1.0)


def test_overrides_from_params_file_and_command_line(make_node: Any, tmp_path: Path) -> None:
    """/** and the node's own entry apply in order; -p after the file wins; others ignored."""
    params = tmp_path / 'params.yaml'
    params.write_text(
        '/**:\n'
        '  ros__parameters:\n'
        '    use_sim_time: true\n'
        '    rate: 1.0\n'
        'talker:\n'
        '  ros__parameters:\n'
        '    rate: 2.0\n'
        '    frames:\n'
        '      parent: odom\n'
        '/ns/other:\n'
        '  ros__parameters:\n'
        '    rate: 3.0\n',
        encoding='utf-8',
    )
    args = ['--ros-args', '--params-file', str(params), '-p', 'frames.child:=base_link']
    node = make_node('talker', cli_args=args)
    assert node.declare_parameter('rate', 0.5).value == 2.0
    # use_sim_time is declared by every node; the file's /** entry set it
    assert node.get_parameter('use_sim_time').value is True
    assert node.declare_parameter('frames.parent', 'map').value == 'odom'
    assert node.declare_parameter('frames.child', 'x').value == 'base_link'
    assert node.declare_parameter('untouched', 4).value == 4
    assert node.declare_parameter('ignored', 'a', ignore_override=False).value == 'a'
    other = make_node('other', namespace='/ns', cli_args=args)
    assert other.declare_parameter('rate', 0.5).value == 3.0
    assert other.declare_parameter('frames.parent', 'x', ignore_override=True).value == 'x'


def test_declare_parameters_with_a_namespace(make_node: Any) -> None:
    """declare_parameters prefixes names with the namespace and a dot."""
    node = make_node(parameter_overrides=[Parameter('limits.max', value=9)])
    declared = node.declare_parameters('limits', [('min', 0), ('max', 5)])
    assert [(p.name, p.value) for p in declared] == [('limits.min', 0), ('limits.max', 9)]
    assert set(node.get_parameters_by_prefix('limits')) == {'min', 'max'}
    # rclpy only checks the length of each entry: a list works as well as a tuple
    [listed] = node.declare_parameters('', [['listed', 1.5]])
    assert (listed.name, listed.value) == ('listed', 1.5)


def test_automatically_declared_overrides(make_node: Any) -> None:
    """automatically_declare_parameters_from_overrides declares every override, typed by it."""
    node = make_node(
        parameter_overrides=[Parameter('x', value=1.5)],
        automatically_declare_parameters_from_overrides=True,
    )
    assert node.get_parameter('x').value == 1.5
    descriptor = node.describe_parameter('x')
    assert (descriptor.dynamic_typing, descriptor.type) == (False, Type.DOUBLE.value)
    [result] = node.set_parameters([Parameter('x', value='text')])
    assert result.reason == "Wrong parameter type, expected 'Type.DOUBLE' got 'Type.STRING'"


@pytest.mark.dds
def test_node_takes_overrides_from_init_and_its_own_arguments(
    world_env: dict[str, str], tmp_path: Path
) -> None:
    """A node sees -p from init, its params-file entry and its cli_args (last wins)."""
    del world_env
    params = tmp_path / 'params.yaml'
    params.write_text(
        '/robot/talker:\n  ros__parameters:\n    rate: 2.0\n    frame: odom\n', encoding='utf-8'
    )
    transport.init(['prog', '--ros-args', '-p', 'rate:=1.0', '--params-file', str(params)])
    try:
        node = transport.create_node(
            'talker', namespace='/robot', cli_args=['--ros-args', '-p', 'frame:=map']
        )
        assert node.declare_parameter('rate', 0.5).value == 2.0
        assert node.declare_parameter('frame', 'base').value == 'map'
        rejected: list[str] = []

        def reject_all(parameters: list[Parameter]) -> SetParametersResult:
            rejected.extend(p.name for p in parameters)
            return SetParametersResult(successful=False, reason='frozen')

        node.add_on_set_parameters_callback(reject_all)
        [result] = node.set_parameters([Parameter('rate', value=3.0)])
        assert (result.successful, result.reason, rejected) == (False, 'frozen', ['rate'])
        assert node.get_parameter('rate').value == 2.0
        node.destroy_node()
    finally:
        transport.shutdown()


def test_declaring_only_a_name_is_dynamic_and_deprecated(node: Any) -> None:
    """A bare name declares a dynamically typed parameter, with rclpy's deprecation warning."""
    with pytest.warns(UserWarning, match='only providing its name is deprecated. You have to'):
        parameter = node.declare_parameter('loose')
    assert parameter.type_ is Type.NOT_SET
    assert node.describe_parameter('loose').dynamic_typing
    alternative = Parameter('loose', value='unset')
    assert node.get_parameter_or('loose', alternative) is alternative  # NOT_SET: no value yet
    assert node.set_parameters([Parameter('loose', value=1)])[0].successful
    assert node.set_parameters([Parameter('loose', value='one')])[0].successful


def test_static_parameter_needs_a_type(node: Any) -> None:
    """None with a static descriptor, or Type.NOT_SET, cannot declare a static parameter."""
    with pytest.raises(ValueError, match='default value of type PARAMETER_NOT_SET'):
        node.declare_parameter('x', None, ParameterDescriptor())
    with pytest.raises(ValueError, match='as statically typed of type NOT_SET'):
        node.declare_parameter('x', Type.NOT_SET)
    with pytest.raises(ValueError, match='`dynamic_typing=True` is not allowed'):
        node.declare_parameter('x', Type.INTEGER, ParameterDescriptor(dynamic_typing=True))
    with pytest.raises(TypeError, match='is not a ParameterDescriptor'):
        node.declare_parameters('', [('x', 1, 'descriptor')])


def test_not_set_value_undeclares_dynamic_but_not_static_parameters(node: Any) -> None:
    """Setting NOT_SET removes a dynamic parameter; a static one refuses with rclpy's reason."""
    node.declare_parameter('dynamic', 1, ParameterDescriptor(dynamic_typing=True))
    node.declare_parameter('static', 1)
    assert node.set_parameters([Parameter('dynamic')])[0].successful
    assert not node.has_parameter('dynamic')
    [result] = node.set_parameters([Parameter('static')])
    assert (result.successful, result.reason) == (False, 'Static parameter cannot be undeclared')


def test_descriptor_ranges_are_enforced_with_rclpys_reasons(make_node: Any) -> None:
    """Integer and floating point ranges accept edges and steps and reject the rest."""
    node = make_node()
    node.declare_parameter(
        'count',
        4,
        ParameterDescriptor(integer_range=[IntegerRange(from_value=0, to_value=10, step=2)]),
    )
    node.declare_parameter(
        'ratio',
        0.5,
        ParameterDescriptor(
            floating_point_range=[FloatingPointRange(from_value=0.0, to_value=1.0, step=0.0)]
        ),
    )
    assert node.set_parameters([Parameter('count', value=10)])[0].successful
    [odd] = node.set_parameters([Parameter('count', value=3)])
    assert odd.reason == (
        'The parameter value for count is not a valid step. Min: 0, max: 10, value: 3, step: 2'
    )
    [high] = node.set_parameters([Parameter('count', value=11)])
    assert high.reason == 'Parameter count out of range. Min: 0, Max: 10, value: 11'
    [high] = node.set_parameters([Parameter('ratio', value=1.5)])
    assert high.reason == 'Parameter ratio out of range Min: 0.0, Max: 1.0, value: 1.5'
    assert node.set_parameters([Parameter('ratio', value=1.0 + 1e-9)])[0].successful
    overridden = make_node('ranged', parameter_overrides=[Parameter('count', value=11)])
    with pytest.raises(InvalidParameterValueException, match='out of range'):
        overridden.declare_parameter(
            'count',
            1,
            ParameterDescriptor(integer_range=[IntegerRange(from_value=0, to_value=10, step=0)]),
        )


def test_pre_and_post_set_callbacks(node: Any) -> None:
    """Pre-set callbacks rewrite the list before validation; post-set ones see what was set."""
    node.declare_parameter('width', 1)
    node.declare_parameter('area', 1)
    seen: list[list[str]] = []
    node.add_pre_set_parameters_callback(
        lambda params: [*params, Parameter('area', value=params[0].value ** 2)]
    )
    node.add_post_set_parameters_callback(lambda params: seen.append([p.name for p in params]))
    assert node.set_parameters([Parameter('width', value=3)])[0].successful
    assert node.get_parameter('area').value == 9
    assert seen == [['width', 'area']]
    node.declare_parameter('depth', 2)
    assert seen[-1] == ['depth']  # declaring runs post-set callbacks too
