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

"""Parameters: rclpy's typing rules, overrides from --ros-args and on-set validation."""

from pathlib import Path

import pytest
from tf_demo.transport.parameters import FloatingPointRange
from tf_demo.transport.parameters import IntegerRange
from tf_demo.transport.parameters import InvalidParameterTypeException
from tf_demo.transport.parameters import InvalidParameterValueException
from tf_demo.transport.parameters import Parameter
from tf_demo.transport.parameters import ParameterAlreadyDeclaredException
from tf_demo.transport.parameters import ParameterDescriptor
from tf_demo.transport.parameters import ParameterNotDeclaredException
from tf_demo.transport.parameters import ParameterStore
from tf_demo.transport.parameters import ParameterUninitializedException
from tf_demo.transport.parameters import SetParametersResult
from tf_demo.transport.ros_args import parse_ros_args

Type = Parameter.Type


def test_parameter_type_is_inferred_as_rclpy_infers_it() -> None:
    """bool before int, homogeneous lists become arrays, an empty list is a BYTE_ARRAY."""
    assert Parameter('a', value=True).type_ is Type.BOOL
    assert Parameter('a', value=1).type_ is Type.INTEGER
    assert Parameter('a', value=1.0).type_ is Type.DOUBLE
    assert Parameter('a', value='x').type_ is Type.STRING
    assert Parameter('a', value=[1.0, 2.0]).type_ is Type.DOUBLE_ARRAY
    assert Parameter('a', value=['x']).type_ is Type.STRING_ARRAY
    assert Parameter('a', value=[]).type_ is Type.BYTE_ARRAY
    assert Parameter('a').type_ is Type.NOT_SET
    assert str(Type.DOUBLE) == 'Type.DOUBLE'
    with pytest.raises(TypeError, match='not a list of one of the allowed types'):
        Parameter('a', value=[1, 'x'])
    with pytest.raises(ValueError, match=r"Type 'Type\.DOUBLE' and value '1' do not agree"):
        Parameter('a', Type.DOUBLE, 1)


def test_declare_returns_the_default_and_rejects_redeclaration() -> None:
    """declare_parameter returns the parameter; declaring it again raises."""
    store = ParameterStore()
    assert store.declare_parameter('rate', 10.0).value == 10.0
    assert store.has_parameter('rate')
    with pytest.raises(ParameterAlreadyDeclaredException, match="already declared: \\['rate'\\]"):
        store.declare_parameter('rate', 1.0)


def test_undeclared_parameters_raise_rclpys_error() -> None:
    """Getting or setting an undeclared parameter raises ParameterNotDeclaredException."""
    store = ParameterStore()
    with pytest.raises(ParameterNotDeclaredException, match='undeclared parameter\\(s\\): nope'):
        store.get_parameter('nope')
    with pytest.raises(ParameterNotDeclaredException):
        store.set_parameters([Parameter('nope', value=1)])
    assert store.get_parameter_or('nope').type_ is Type.NOT_SET
    alternative = Parameter('nope', value=3)
    assert store.get_parameter_or('nope', alternative) is alternative


def test_setting_another_type_is_rejected_unless_dynamically_typed() -> None:
    """Static typing rejects with rclpy's reason; dynamic_typing accepts any type."""
    store = ParameterStore()
    store.declare_parameter('frame', 'map')
    store.declare_parameter('anything', 1, ParameterDescriptor(dynamic_typing=True))
    [result] = store.set_parameters([Parameter('frame', value=3)])
    assert not result.successful
    assert result.reason == "Wrong parameter type, expected 'Type.STRING' got 'Type.INTEGER'"
    assert store.get_parameter('frame').value == 'map'
    [result] = store.set_parameters([Parameter('anything', value='now a string')])
    assert result.successful
    assert store.get_parameter('anything').value == 'now a string'


def test_on_set_callback_can_reject_with_a_reason() -> None:
    """A rejecting callback keeps the old value; removing it lets the change through."""
    store = ParameterStore()
    store.declare_parameter('rate', 10.0)

    def positive_rate(parameters: list[Parameter]) -> SetParametersResult:
        for parameter in parameters:
            if parameter.name == 'rate' and parameter.value <= 0:
                return SetParametersResult(successful=False, reason='rate must be positive')
        return SetParametersResult(successful=True)

    store.add_on_set_parameters_callback(positive_rate)
    [result] = store.set_parameters([Parameter('rate', value=-1.0)])
    assert (result.successful, result.reason) == (False, 'rate must be positive')
    assert store.get_parameter('rate').value == 10.0
    [result] = store.set_parameters([Parameter('rate', value=20.0)])
    assert result.successful
    assert store.get_parameter('rate').value == 20.0
    store.remove_on_set_parameters_callback(positive_rate)
    assert store.set_parameters([Parameter('rate', value=-1.0)])[0].successful


def test_a_rejected_declaration_raises_invalid_value() -> None:
    """An on-set callback that rejects an overridden value makes declare raise."""
    store = ParameterStore({'rate': Parameter('rate', value=-5.0)})
    store.add_on_set_parameters_callback(
        lambda params: SetParametersResult(successful=False, reason='no negative rates')
    )
    with pytest.raises(InvalidParameterValueException, match='Reason: no negative rates: rate'):
        store.declare_parameter('rate', 1.0)


def test_read_only_parameters_cannot_be_set() -> None:
    """Setting a read-only parameter fails with a reason naming it."""
    store = ParameterStore()
    store.declare_parameter('robot', 'r2', ParameterDescriptor(read_only=True))
    [result] = store.set_parameters([Parameter('robot', value='c3po')])
    assert not result.successful
    assert 'read-only parameter: robot' in result.reason


def test_typed_parameter_without_value_is_uninitialized() -> None:
    """Declaring with a Parameter.Type and no override leaves it unreadable until set."""
    store = ParameterStore()
    store.declare_parameter('urdf', Type.STRING)
    with pytest.raises(ParameterUninitializedException, match="'urdf' is not initialized"):
        store.get_parameter('urdf')
    assert store.set_parameters([Parameter('urdf', value='<robot/>')])[0].successful
    assert store.get_parameter('urdf').value == '<robot/>'


def test_override_of_the_wrong_type_raises_invalid_type() -> None:
    """-p rate:=5 for a double default raises rclpy's InvalidParameterTypeException."""
    overrides = parse_ros_args(['--ros-args', '-p', 'rate:=5']).parameter_overrides('/n')
    store = ParameterStore(overrides)
    expected = "Trying to set parameter 'rate' to '5' of type 'INTEGER', expecting type 'DOUBLE'"
    with pytest.raises(InvalidParameterTypeException, match=expected):
        store.declare_parameter('rate', 1.0)


def test_overrides_from_params_file_and_command_line(tmp_path: Path) -> None:
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
    args = parse_ros_args(
        ['--ros-args', '--params-file', str(params), '-p', 'frames.child:=base_link']
    )
    store = ParameterStore(args.parameter_overrides('/talker'))
    assert store.declare_parameter('rate', 0.5).value == 2.0
    assert store.declare_parameter('use_sim_time', False).value is True
    assert store.declare_parameter('frames.parent', 'map').value == 'odom'
    assert store.declare_parameter('frames.child', 'x').value == 'base_link'
    assert store.declare_parameter('untouched', 4).value == 4
    assert store.declare_parameter('ignored', 'a', ignore_override=False).value == 'a'
    other = ParameterStore(args.parameter_overrides('/ns/other'))
    assert other.declare_parameter('rate', 0.5).value == 3.0
    assert other.declare_parameter('rate2', 0.5, ignore_override=True).value == 0.5


def test_declare_parameters_with_a_namespace() -> None:
    """declare_parameters prefixes names with the namespace and a dot."""
    store = ParameterStore({'limits.max': Parameter('limits.max', value=9)})
    declared = store.declare_parameters('limits', [('min', 0), ('max', 5)])
    assert [(p.name, p.value) for p in declared] == [('limits.min', 0), ('limits.max', 9)]
    assert set(store.get_parameters_by_prefix('limits')) == {'min', 'max'}


def test_automatically_declared_overrides() -> None:
    """automatically_declare_parameters_from_overrides declares every override."""
    store = ParameterStore(
        {'x': Parameter('x', value=1.5)}, automatically_declare_parameters_from_overrides=True
    )
    assert store.get_parameter('x').value == 1.5


@pytest.mark.dds
def test_standalone_node_takes_overrides_from_init_and_its_own_arguments(
    dds_env: dict[str, str], tmp_path: Path
) -> None:
    """A DDS node sees -p from init, its params-file entry and its cli_args (last wins)."""
    from tf_demo import transport

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
        rejected = []

        def reject_all(parameters: list[Parameter]) -> SetParametersResult:
            rejected.extend(p.name for p in parameters)
            return SetParametersResult(successful=False, reason='frozen')

        node.add_on_set_parameters_callback(reject_all)
        [result] = node.set_parameters([Parameter('rate', value=3.0)])
        assert (result.successful, result.reason, rejected) == (False, 'frozen', ['rate'])
        assert node.get_parameter('rate').value == 2.0
    finally:
        transport.shutdown()


def test_declaring_only_a_name_is_dynamic_and_deprecated() -> None:
    """A bare name declares a dynamically typed parameter, with rclpy's deprecation warning."""
    store = ParameterStore()
    with pytest.warns(UserWarning, match='only providing its name is deprecated'):
        parameter = store.declare_parameter('loose')
    assert parameter.type_ is Type.NOT_SET
    assert store.describe_parameter('loose').dynamic_typing
    assert store.set_parameters([Parameter('loose', value=1)])[0].successful
    assert store.set_parameters([Parameter('loose', value='one')])[0].successful


def test_static_parameter_needs_a_type() -> None:
    """None with a static descriptor, or Type.NOT_SET, cannot declare a static parameter."""
    store = ParameterStore()
    with pytest.raises(ValueError, match='default value of type PARAMETER_NOT_SET'):
        store.declare_parameter('x', None, ParameterDescriptor())
    with pytest.raises(ValueError, match='as statically typed of type NOT_SET'):
        store.declare_parameter('x', Type.NOT_SET)
    with pytest.raises(ValueError, match='`dynamic_typing=True` is not allowed'):
        store.declare_parameter('x', Type.INTEGER, ParameterDescriptor(dynamic_typing=True))
    with pytest.raises(TypeError, match='is not a ParameterDescriptor'):
        store.declare_parameters('', [('x', 1, 'descriptor')])


def test_not_set_value_undeclares_dynamic_but_not_static_parameters() -> None:
    """Setting NOT_SET removes a dynamic parameter; a static one refuses with rclpy's reason."""
    store = ParameterStore()
    store.declare_parameter('dynamic', 1, ParameterDescriptor(dynamic_typing=True))
    store.declare_parameter('static', 1)
    assert store.set_parameters([Parameter('dynamic')])[0].successful
    assert not store.has_parameter('dynamic')
    [result] = store.set_parameters([Parameter('static')])
    assert (result.successful, result.reason) == (False, 'Static parameter cannot be undeclared')


def test_descriptor_ranges_are_enforced_with_rclpys_reasons() -> None:
    """Integer and floating point ranges accept edges and steps and reject the rest."""
    store = ParameterStore()
    store.declare_parameter(
        'count',
        4,
        ParameterDescriptor(integer_range=[IntegerRange(from_value=0, to_value=10, step=2)]),
    )
    store.declare_parameter(
        'ratio', 0.5, ParameterDescriptor(floating_point_range=[FloatingPointRange(0.0, 1.0, 0.0)])
    )
    assert store.set_parameters([Parameter('count', value=10)])[0].successful
    [odd] = store.set_parameters([Parameter('count', value=3)])
    assert odd.reason == (
        'The parameter value for count is not a valid step. Min: 0, max: 10, value: 3, step: 2'
    )
    [high] = store.set_parameters([Parameter('ratio', value=1.5)])
    assert high.reason == 'Parameter ratio out of range Min: 0.0, Max: 1.0, value: 1.5'
    assert store.set_parameters([Parameter('ratio', value=1.0 + 1e-9)])[0].successful
    with pytest.raises(InvalidParameterValueException, match='out of range'):
        ParameterStore({'count': Parameter('count', value=11)}).declare_parameter(
            'count', 1, ParameterDescriptor(integer_range=[IntegerRange(0, 10, 0)])
        )


def test_pre_and_post_set_callbacks() -> None:
    """Pre-set callbacks rewrite the list before validation; post-set ones see what was set."""
    store = ParameterStore()
    store.declare_parameter('width', 1)
    store.declare_parameter('area', 1)
    seen: list[list[str]] = []
    store.add_pre_set_parameters_callback(
        lambda params: [*params, Parameter('area', value=params[0].value ** 2)]
    )
    store.add_post_set_parameters_callback(lambda params: seen.append([p.name for p in params]))
    assert store.set_parameters([Parameter('width', value=3)])[0].successful
    assert store.get_parameter('area').value == 9
    assert seen == [['width', 'area']]
    store.declare_parameter('depth', 2)
    assert seen[-1] == ['depth']  # declaring runs post-set callbacks too
