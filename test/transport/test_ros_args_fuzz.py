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
Fuzzing the ``--ros-args`` parser and params files (issue 10, "What must be true").

Whatever the command line or the file holds, parsing returns a result or raises
:class:`RosArgsError` (a ``ValueError``): no other exception, no hang (pytest-timeout), and
memory bounded by a small multiple of the input. Each test is small (``max_examples`` below).
"""

from __future__ import annotations

import contextlib
from pathlib import Path
import tempfile
import tracemalloc
from typing import Any

from hypothesis import given
from hypothesis import HealthCheck
from hypothesis import settings
from hypothesis import strategies as st
import pytest
from tf_demo.transport.params_file import params_file_entries
from tf_demo.transport.params_typing import rcl_scalar
from tf_demo.transport.params_yaml import EventLoader
from tf_demo.transport.params_yaml import LIBYAML_AVAILABLE
from tf_demo.transport.params_yaml import parse_param_value
from tf_demo.transport.params_yaml import PureYamlEventLoader
from tf_demo.transport.params_yaml import YAML_EVENT_LOADER
from tf_demo.transport.params_yaml import yaml_events
from tf_demo.transport.ros_args import parse_ros_args
from tf_demo.transport.ros_args import resolve_node_arguments
from tf_demo.transport.ros_args import RosArgsError
import yaml

pytestmark = [pytest.mark.property, pytest.mark.timeout(240)]

FUZZ = settings(max_examples=200, deadline=None, suppress_health_check=[HealthCheck.too_slow])

# Characters YAML and rcl's rules give meaning to, plus letters, digits and odd code points.
YAML_ALPHABET = st.sampled_from(
    [*'ab019xXeEpP+-._:=/~*&!|>%@`#"\'[]{},? \t\n\r', '\x00', '\x01', '\ufeff', 'é', '\u2028']
)
yaml_text = st.text(alphabet=YAML_ALPHABET, max_size=60)
NUMBER_ALPHABET = st.sampled_from(list('0123456789abcdefxXpPeE+-.infa()_ \t'))
RCL_BOOLS = {
    *('y', 'n', 'Y', 'N', 'on', 'ON', 'On', 'off', 'Off', 'OFF', 'yes', 'no', 'Yes', 'No'),
    *('YES', 'NO', 'true', 'false', 'True', 'False', 'TRUE', 'FALSE'),
}
number_text = st.text(alphabet=NUMBER_ALPHABET, min_size=1, max_size=40)

FLAGS = [
    '--ros-args', '--', '-p', '--param', '-r', '--remap', '--params-file', '--log-level',
    '--log-config-file', '-e', '--enclave', '--enable-stdout-logs', '--disable-rosout-logs',
]  # fmt: skip
RULES = st.one_of(
    st.builds(lambda n, v: f'{n}:={v}', st.text(max_size=12), yaml_text),
    st.builds(
        lambda p, n, v: f'{p}:{n}:={v}', st.text(max_size=6), st.text(max_size=8), yaml_text
    ),
    st.sampled_from(['__node:=x', '__ns:=/a', '__ns:=a', 'a:=b', '~/x:=/y', 'debug', 'x:=INFO']),
    st.text(max_size=20),
)
argv_strategy = st.lists(st.one_of(st.sampled_from(FLAGS), RULES), max_size=12)


def _params_body() -> st.SearchStrategy[Any]:
    """Params-file-shaped documents: node keys, ros__parameters, nested values, shared objects."""
    scalars = st.one_of(
        st.booleans(),
        st.integers(min_value=-(2**70), max_value=2**70),
        st.floats(allow_nan=True, allow_infinity=True),
        st.text(alphabet=YAML_ALPHABET, max_size=10),
        st.none(),
    )
    values = st.recursive(
        scalars | st.lists(scalars, max_size=4),
        lambda inner: (
            st.dictionaries(st.text(max_size=6), inner, max_size=3) | st.lists(inner, max_size=3)
        ),
        max_leaves=12,
    )
    node = st.dictionaries(st.sampled_from(['ros__parameters', 'ns', 'n', '']), values, max_size=2)
    return st.dictionaries(
        st.sampled_from(['/**', 'n', '/ns/n', '/*/n', 'ns', '1']), node, max_size=3
    )


@FUZZ
@given(argv_strategy)
def test_any_command_line_parses_or_raises_ros_args_error(argv: list[str]) -> None:
    """Any argv: a RosArgs whose queries work, or RosArgsError; nothing else."""
    try:
        parsed = parse_ros_args(['prog', *argv])
    except RosArgsError as error:
        message = str(error)
        assert '\n' not in message or '\n' in ''.join(argv)
        return
    parsed.parameter_overrides('/ns/n')
    parsed.node_name('n')
    parsed.namespace('/', 'n')
    parsed.remap_topic('/tf', 'n', '/ns')
    try:
        resolve_node_arguments(['prog', *argv], 'n', '/ns')
    except RosArgsError:
        pytest.fail('resolve_node_arguments refused what parse_ros_args accepted')


@FUZZ
@given(yaml_text)
def test_any_p_value_is_typed_or_refused(text: str) -> None:
    """Any -p value: a bool, int, double, string or homogeneous list, or a ValueError."""
    for loader in (None, PureYamlEventLoader):
        try:
            value = parse_param_value(text, loader=loader)
        except ValueError:
            continue
        assert isinstance(value, (bool, int, float, str, list))
        if isinstance(value, list):
            assert value
            assert len({type(item) for item in value}) == 1


@FUZZ
@given(number_text)
def test_rcl_scalar_on_number_like_text(text: str) -> None:
    """Number-like text never raises; ints stay in int64 and strings stay the text."""
    value = rcl_scalar(text)
    if isinstance(value, bool):
        assert text in RCL_BOOLS
    elif isinstance(value, int):
        assert -(2**63) <= value < 2**63
    elif isinstance(value, str):
        assert value == text
    assert rcl_scalar(text, quoted=True) == text


@settings(max_examples=150, deadline=None)
@given(st.integers(min_value=0, max_value=6000), st.sampled_from(['', '-', '+', '0x', '-0x']))
def test_huge_integers_are_typed_without_int_conversion_limits(digits: int, prefix: str) -> None:
    """Any number of digits: a value (int, double or string), never Python's 4,300-digit error."""
    text = prefix + '7' * max(digits, 1)
    value = rcl_scalar(text)
    assert isinstance(value, (int, float, str))


@settings(max_examples=150, deadline=None)
@given(st.text(alphabet=st.sampled_from(list('ab</="\t\n -!.')), max_size=40))
def test_pure_scanner_reads_urdf_like_values_as_libyaml(text: str) -> None:
    """The pure fallback and libyaml agree on URDF-like plain values, tabs included."""
    if not LIBYAML_AVAILABLE:
        pytest.skip('libyaml is not available to compare with')
    text = '<' + text

    def outcome(loader: EventLoader) -> object:
        try:
            return repr(parse_param_value(text, loader=loader))
        except ValueError:
            return ValueError

    assert outcome(YAML_EVENT_LOADER) == outcome(PureYamlEventLoader)


def _parse_file(data: bytes) -> None:
    with tempfile.TemporaryDirectory() as directory:
        path = Path(directory) / 'params.yaml'
        path.write_bytes(data)
        try:
            parsed = parse_ros_args(['--ros-args', '--params-file', str(path)])
        except RosArgsError as error:
            message = str(error)
            assert message.startswith("Couldn't parse params file: ")
            return
        for fqn in ('/n', '/ns/n', '/x/y/z'):
            parsed.parameter_overrides(fqn)


@settings(max_examples=200, deadline=None)
@given(st.binary(max_size=200))
def test_any_bytes_as_a_params_file(data: bytes) -> None:
    """Arbitrary bytes (not UTF-8, NULs, anything): parsed or RosArgsError."""
    _parse_file(data)


@settings(max_examples=150, deadline=None)
@given(yaml_text)
def test_any_yaml_text_as_a_params_file(text: str) -> None:
    """YAML-alphabet text as a params file: parsed or RosArgsError."""
    _parse_file(text.encode('utf-8', errors='surrogatepass'))


@settings(max_examples=150, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(_params_body(), st.booleans())
def test_params_file_shaped_documents(document: Any, flow: bool) -> None:
    """Params-file-shaped YAML (with anchors and aliases where objects repeat): no surprise."""
    if isinstance(document, dict) and document:
        first = next(iter(document))
        document = {**document, 'alias': document[first]}  # safe_dump writes an anchor/alias
    text = yaml.safe_dump(document, default_flow_style=flow, allow_unicode=True)
    _parse_file(text.encode('utf-8', errors='surrogatepass'))


@settings(max_examples=60, deadline=None)
@given(
    st.integers(min_value=1, max_value=3000),
    st.sampled_from(['[', '{a: ', '- ', 'k:\n']),
    st.booleans(),
)
def test_nesting_and_memory_are_bounded(levels: int, opener: str, in_file: bool) -> None:
    """Nesting of any depth: result or error, with peak memory a small multiple of the input."""
    closer = {'[': ']', '{a: ': '}', '- ': '', 'k:\n': ''}[opener]
    if opener == 'k:\n':
        body = ''.join(f'{"  " * i}k{i}:\n' for i in range(levels)) + '  ' * levels + 'x: 1\n'
    elif opener == '- ':
        body = ''.join(f'{"  " * i}- \n' for i in range(levels)) + '  ' * levels + '1\n'
    else:
        body = opener * levels + '1' + closer * levels
    # The params file's text is parsed as read (core.files' reading is measured on its own).
    text = f'/**:\n  ros__parameters:\n    x: {body}\n'
    tracemalloc.start()
    try:
        with contextlib.suppress(ValueError):
            if in_file:
                params_file_entries(yaml_events(text, YAML_EVENT_LOADER))
            else:
                parse_ros_args(['--ros-args', '-p', f'x:={body}'])
        _, peak = tracemalloc.get_traced_memory()
    finally:
        tracemalloc.stop()
    assert peak < 200 * len(body) + 1_000_000
