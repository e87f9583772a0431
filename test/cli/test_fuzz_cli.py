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
Fuzzing the snapshot loader and every executable's argument parsing, in process (issue 10).

The contract: hostile input ends in the package's documented error (``SnapshotError`` for a
snapshot, an error result or ``SystemExit`` with a usage message for arguments,
``RosArgsError`` for ``--ros-args``), never in another exception, and quickly (pytest-timeout
guards against a hang). Each test is small; the case counts are in ``FUZZ_*`` below.
"""

from __future__ import annotations

import argparse
from collections.abc import Callable
import contextlib
import io
import math
import re

from hypothesis import given
from hypothesis import HealthCheck
from hypothesis import settings
from hypothesis import strategies as st
import pytest
from tf_demo.cli import tf_demo_live
from tf_demo.cli import tf_doctor
from tf_demo.cli import tf_loader
from tf_demo.cli import tf_monitor
from tf_demo.cli import tf_saver
from tf_demo.cli import view_frames
from tf_demo.cli._args import parse_echo_args
from tf_demo.cli._args import parse_static_transform_args
from tf_demo.cli._snapshot import dump_snapshot
from tf_demo.cli._snapshot import ENTRY_KEYS
from tf_demo.cli._snapshot import parse_snapshot
from tf_demo.cli._snapshot import Snapshot
from tf_demo.cli._snapshot import SnapshotError
from tf_demo.cli._snapshot import SnapshotTransform
from tf_demo.cli._snapshot import TOP_KEYS
from tf_demo.nodes import non_ros_arguments
from tf_demo.nodes.helpers import MIN_RATE_HZ
from tf_demo.transport.params_c_numbers import c_strtod
from tf_demo.transport.ros_args import parse_ros_args
from tf_demo.transport.ros_args import RosArgsError
from tf_demo.transport.ros_args import split_ros_args
import yaml

pytestmark = [pytest.mark.property, pytest.mark.timeout(120)]

FUZZ_SNAPSHOT = 200
FUZZ_ARGS = 150
_QUIET = [HealthCheck.too_slow, HealthCheck.data_too_large]


# --- numbers and tokens a careless user or an attacker types -------------------------------------

HUGE_NUMBERS = [
    '9' * 400,
    '1' * 4300,
    '7' * 5000,
    '0x' + 'f' * 400,
    '1e-300',
    '1e-400',
    '1e400',
    '-1e308',
    '4.9e-324',
    '0x1p-1074',
    '1:' * 200 + '1',
    '1_000',
    '0b11',
    'nan',
    '-inf',
    'Infinity',
    'nan(123)',
    '.',
    '-',
    '+.e5',
    '1e',
    '١٢٣',  # Arabic-Indic digits: int() takes them, strtod does not
    '\udcff',  # an undecodable argv byte, as Python passes it
]
numbers = st.one_of(
    st.sampled_from(HUGE_NUMBERS),
    st.floats().map(repr),
    st.integers().map(str),
    st.integers(min_value=0, max_value=5000).map(lambda n: '9' * n),
)
words = st.text(st.characters(blacklist_categories=['Cs']), max_size=12) | st.sampled_from(
    ['--ros-args', '--', '-p', '-r', '-h', '--help', '--json', '--limit', '--precision']
)


def argvs(flags: list[str]) -> st.SearchStrategy[list[str]]:
    """Argument lists made of the tool's own flags, hostile numbers and odd words."""
    return st.lists(st.sampled_from(flags) | numbers | words, max_size=12)


# --- the snapshot loader ------------------------------------------------------------------------

finite = st.floats(allow_nan=False, allow_infinity=False)
frame_names = st.text(st.characters(blacklist_categories=('Cc', 'Cs')), min_size=1, max_size=8)


@st.composite
def snapshot_texts(draw: st.DrawFn) -> str:
    """A valid snapshot's text, as tf_saver writes it."""
    frames = draw(st.lists(frame_names, min_size=2, max_size=5, unique=True))
    entries = tuple(
        SnapshotTransform(
            frames[draw(st.integers(0, index - 1))],
            child,
            draw(st.tuples(finite, finite, finite)),
            (0.0, 0.0, 0.0, 1.0),
            draw(st.booleans()),
            draw(st.none() | st.integers(0, 2**31 * 10**9 - 1)),
            draw(st.none() | frame_names),
            draw(st.none() | st.floats(0, 1e6)),
            draw(st.none() | st.integers(0, 10**6)),
        )
        for index, child in enumerate(frames[1:], start=1)
    )
    return dump_snapshot(Snapshot(entries, draw(st.none() | st.integers(0, 10**18))))


NUMBER = re.compile(r'(?<![\w"])-?[0-9][0-9.e+-]*')


def _parse_or_refuse(text: str) -> None:
    """Parse ``text``: a Snapshot or a SnapshotError naming the source, nothing else."""
    try:
        snapshot = parse_snapshot(text, 'fuzz.yaml')
    except SnapshotError as error:
        refusal = str(error)
    else:
        for entry in snapshot.transforms:
            assert all(math.isfinite(v) for v in (*entry.translation, *entry.rotation))
        return
    assert refusal.startswith('fuzz.yaml')
    assert len(refusal) < 2000  # one readable line, never a 5,000-digit dump


@settings(max_examples=FUZZ_SNAPSHOT, deadline=None, suppress_health_check=_QUIET)
@given(st.text(max_size=400))
def test_snapshot_loader_survives_any_text(text: str) -> None:
    """Arbitrary text is a snapshot or a SnapshotError."""
    _parse_or_refuse(text)


@settings(max_examples=FUZZ_SNAPSHOT, deadline=None, suppress_health_check=_QUIET)
@given(snapshot_texts(), st.data())
def test_snapshot_loader_survives_mutated_files(text: str, data: st.DataObject) -> None:
    """A real file with a value swapped for a hostile one, a cut or an insertion."""
    kind = data.draw(st.sampled_from(['number', 'replace', 'cut', 'insert']))
    if kind == 'number':  # one number of the file (a translation, a stamp, a count) swapped
        spans = [m.span() for m in NUMBER.finditer(text)]
        start, end = data.draw(st.sampled_from(spans))
        mutated = text[:start] + data.draw(numbers) + text[end:]
    elif kind == 'replace':
        tokens = text.split(' ')
        index = data.draw(st.integers(0, len(tokens) - 1))
        replacement = data.draw(numbers | words | st.sampled_from(['[', '{', '&a', '*a', '!!x']))
        tokens[index] = replacement + (',' if tokens[index].endswith(',') else '')
        mutated = ' '.join(tokens)
    elif kind == 'cut':
        mutated = text[: data.draw(st.integers(0, len(text)))]
    else:
        at = data.draw(st.integers(0, len(text)))
        mutated = text[:at] + data.draw(st.text(max_size=20)) + text[at:]
    _parse_or_refuse(mutated)


yaml_scalars = st.one_of(
    st.none(),
    st.booleans(),
    st.integers(),
    st.integers(min_value=10**300, max_value=10**310),
    st.floats(),
    st.text(max_size=10),
)
yaml_keys = st.sampled_from([*TOP_KEYS, *ENTRY_KEYS, 'sec', 'nanosec'])
yaml_documents = st.recursive(
    yaml_scalars,
    lambda children: st.lists(children, max_size=5) | st.dictionaries(yaml_keys, children),
    max_leaves=30,
)


@settings(max_examples=FUZZ_SNAPSHOT, deadline=None, suppress_health_check=_QUIET)
@given(yaml_documents)
def test_snapshot_loader_survives_schema_shaped_yaml(document: object) -> None:
    """YAML built from the schema's own keys with any values (huge ints, NaN, nesting)."""
    _parse_or_refuse(yaml.safe_dump(document))


# --- the executables' arguments -----------------------------------------------------------------


@settings(max_examples=FUZZ_ARGS, deadline=None, suppress_health_check=_QUIET)
@given(argvs(['a', 'b', '-p', '--precision', '--limit', '--json']))
def test_tf_echo_arguments(argv: list[str]) -> None:
    """tf_echo: usage (1), a refused rate or option (2, 3), or a usable rate and options."""
    tool_args, _ = split_ros_args(argv)
    parsed = parse_echo_args(tool_args)
    assert parsed.exit_code in (0, 1, 2, 3)
    if parsed.exit_code == 0:
        assert not parsed.error
        assert MIN_RATE_HZ <= parsed.rate_hz < math.inf
        assert 0 <= parsed.precision <= 17
        assert parsed.limit is None or parsed.limit >= 1
        assert 1.0 / parsed.rate_hz * 1e9 < 2**63
    else:
        assert parsed.show_usage or parsed.error


STATIC_FLAGS = ['--x', '--y', '--z', '--qx', '--qy', '--qz', '--qw', '--roll', '--pitch']
STATIC_FLAGS += ['--yaw', '--frame-id', '--child-frame-id', 'base', 'laser', '-h']


@settings(max_examples=FUZZ_ARGS, deadline=None, suppress_health_check=_QUIET)
@given(argvs(STATIC_FLAGS))
def test_static_transform_publisher_arguments(argv: list[str]) -> None:
    """static_transform_publisher: an error text, help, or frames and seven numbers."""
    tool_args, _ = split_ros_args(argv)
    parsed = parse_static_transform_args(tool_args)
    if parsed.error or parsed.help:
        return
    assert parsed.frame_id
    assert parsed.child_frame_id
    assert len(parsed.translation) == 3
    assert len(parsed.rotation) == 4


@settings(max_examples=FUZZ_ARGS, deadline=None, suppress_health_check=_QUIET)
@given(st.text(max_size=30))
def test_c_strtod_never_raises(text: str) -> None:
    """strtod's prefix rule on any text: a value and a length, or None."""
    parsed = c_strtod(text)
    if parsed is not None:
        assert 0 < parsed.length <= len(text)


def _argparse_tool(
    parse: Callable[[list[str]], argparse.Namespace],
    check: Callable[[argparse.Namespace], str | None],
    argv: list[str],
) -> None:
    """Parse like the tool's main: SystemExit 0 (help) or 2 with usage, else a checked value."""
    tool_args, _ = split_ros_args(argv)
    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        try:
            options = parse(tool_args)
        except SystemExit as stop:
            code = stop.code
        else:
            problem = check(options)
            assert problem is None or isinstance(problem, str)
            return
    assert code in (0, 2)
    assert code == 0 or 'usage:' in err.getvalue()


ARGPARSE_TOOLS: dict[
    str, tuple[list[str], Callable[..., argparse.Namespace], Callable[..., str | None]]
] = {
    'view_frames': (
        ['-t', '--wait-time', '-o', '--snapshot', '--tf_topic', '--tf_static_topic'],
        lambda a: view_frames.build_parser().parse_args(a),
        view_frames.options_error,
    ),
    'tf_saver': (
        ['-t', '-o', '--output', '--flatten', 'map', 'odom'],
        lambda a: tf_saver.build_parser().parse_args(a),
        tf_saver.options_error,
    ),
    'tf_doctor': (
        ['-t', '--frames', '--snapshot', '--json', 'map'],
        lambda a: tf_doctor.build_parser().parse_args(a),
        tf_doctor.options_error,
    ),
    'tf_loader': (
        ['--check', 'file.yaml'],
        lambda a: tf_loader.build_parser().parse_args(a),
        lambda options: None,
    ),
    'tf_monitor': (
        ['--interval', '--limit', 'map', 'odom'],
        lambda a: tf_monitor.build_parser().parse_args(a),
        tf_monitor.options_error,
    ),
    'tf_demo_live': (
        ['--duration', '--rate', '--target', '--source', '--robot', '--quiet', '--no-echo'],
        tf_demo_live.parse_arguments,
        lambda options: None,
    ),
}


@pytest.mark.parametrize('tool', sorted(ARGPARSE_TOOLS))
def test_argparse_tool_arguments(tool: str) -> None:
    """view_frames, tf_saver, tf_doctor, tf_loader, tf_monitor, tf_demo_live (FUZZ_ARGS each)."""
    flags, parse, check = ARGPARSE_TOOLS[tool]

    @settings(max_examples=FUZZ_ARGS, deadline=None, suppress_health_check=_QUIET)
    @given(argvs(flags))
    def run(argv: list[str]) -> None:
        _argparse_tool(parse, check, argv)

    run()


NODE_FLAGS = ['--ros-args', '-p', '-r', '--params-file', '--log-level', '--', 'x:=1', 'a:=b']
NODE_FLAGS += ['__node:=n', '-e', '--enclave', 'x:=[[[1]]]', 'rate:=1e400']


@settings(max_examples=FUZZ_ARGS, deadline=None, suppress_health_check=_QUIET)
@given(argvs(NODE_FLAGS))
def test_node_arguments(argv: list[str]) -> None:
    """Every node's command line: plain arguments plus --ros-args (RosArgsError if refused)."""
    plain = non_ros_arguments(argv)
    assert all(isinstance(arg, str) for arg in plain)
    with contextlib.suppress(RosArgsError):
        parse_ros_args(['node', *argv])
