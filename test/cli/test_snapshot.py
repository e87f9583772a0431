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

"""Tests of the snapshot schema: exact round trip and every refused file, each with its line."""

import math

import pytest
from tf_demo.cli._snapshot import dump_snapshot
from tf_demo.cli._snapshot import frames_yaml_data
from tf_demo.cli._snapshot import MAX_FILE_BYTES
from tf_demo.cli._snapshot import parse_snapshot
from tf_demo.cli._snapshot import read_snapshot
from tf_demo.cli._snapshot import Snapshot
from tf_demo.cli._snapshot import SnapshotError
from tf_demo.cli._snapshot import SnapshotTransform
from tf_demo.cli._snapshot import write_snapshot

GOOD = """\
tf_demo_transforms: 1
transform_count: 2
transforms:
  - parent: map
    child: odom
    translation: [1.0, 2.0, 0.0]
    rotation: [0.0, 0.0, 0.0, 1.0]
  - parent: odom
    child: base_link
    translation: [0.1, 0, 0]
    rotation: [0.0, 0.0, 0.7071067811865476, 0.7071067811865476]
    static: false
    stamp: {sec: 5, nanosec: 7}
"""


def _sample() -> Snapshot:
    return Snapshot(
        transforms=(
            SnapshotTransform('map', 'odom', (1.0, 2.0, 3.0), (0.0, 0.0, 0.0, 1.0)),
            SnapshotTransform(
                'odom',
                'base "link"\u00e9',
                (0.1, -1e-300, 1 / 3),
                (0.0, 0.0, math.sqrt(0.5), math.sqrt(0.5)),
                is_static=False,
                stamp_ns=1_700_000_000_123_456_789,
                authority='node',
                rate_hz=20.5,
                sample_count=41,
            ),
        ),
        recorded_at_ns=1_700_000_001_000_000_000,
    )


def test_round_trip_is_exact():
    """dump then parse gives back the same snapshot, floats bit for bit, names with quotes."""
    snapshot = _sample()
    assert parse_snapshot(dump_snapshot(snapshot)) == snapshot


def test_empty_snapshot_round_trips():
    """A snapshot without transforms is valid."""
    assert parse_snapshot(dump_snapshot(Snapshot(transforms=()))) == Snapshot(transforms=())


def test_hand_written_file_parses():
    """Integers are accepted where floats are expected; static defaults to true."""
    snapshot = parse_snapshot(GOOD)
    assert snapshot.transforms[0].is_static
    assert snapshot.transforms[1].translation == (0.1, 0.0, 0.0)
    assert snapshot.transforms[1].stamp_ns == 5_000_000_007


def test_write_and_read_file(tmp_path):
    """write_snapshot and read_snapshot agree through a real file."""
    path = tmp_path / 'tf.yaml'
    write_snapshot(path, _sample())
    assert read_snapshot(path) == _sample()


def _replace(old: str, new: str) -> str:
    assert old in GOOD
    return GOOD.replace(old, new, 1)


def _with_sample_count(text: str) -> str:
    return GOOD + f'    sample_count: {text}\n'


BAD_FILES = [
    ('', 'empty file'),
    ('[1, 2]\n', 'the file must be a mapping'),
    ('transforms: [\n', 'not valid YAML'),
    (_replace('tf_demo_transforms: 1', 'tf_demo_transforms: 2'), ':1: unsupported schema version'),
    (_replace('tf_demo_transforms: 1\n', ''), "missing 'tf_demo_transforms'"),
    (_replace('transform_count: 2', 'transform_count: 3'), ':2: transform_count says 3'),
    (GOOD[: GOOD.index('  - parent: odom')], ':2: transform_count says 2 but the file has 1'),
    (GOOD[: GOOD.index('    rotation: [0.0, 0.0, 0.7')], ":8: transforms[1] has no 'rotation'"),
    (_replace('[1.0, 2.0, 0.0]', '[1.0, .nan, 0.0]'), ':6: transforms[0].translation[1] must be'),
    (_replace('[1.0, 2.0, 0.0]', '[1.0, .inf, 0.0]'), ':6: transforms[0].translation[1] must be'),
    (_replace('[1.0, 2.0, 0.0]', '[1.0, "2", 0.0]'), ':6: transforms[0].translation[1] must be'),
    (_replace('[1.0, 2.0, 0.0]', '[1.0, true, 0.0]'), ':6: transforms[0].translation[1] must be'),
    (_replace('[1.0, 2.0, 0.0]', '[1.0, 2.0]'), ':6: transforms[0].translation must have 3'),
    (_replace('[1.0, 2.0, 0.0]', '1.0'), ':6: transforms[0].translation must be a list'),
    (_replace('[0.0, 0.0, 0.0, 1.0]', '[0.0, 0.0, 0.0, 2.0]'), ':7: transforms[0].rotation'),
    (_replace('child: odom', 'child: map'), ":5: transforms[0]: frame 'map' cannot be its own"),
    (
        _replace('parent: odom\n    child: base_link', 'parent: map\n    child: odom'),
        ":8: frame 'odom' appears twice",
    ),
    (_replace('parent: map', 'parent: base_link'), 'the parent links form a loop'),
    (_replace('child: odom', 'child: ""'), ':5: transforms[0].child must not be empty'),
    (_replace('child: odom', 'child: 12'), ':5: transforms[0].child must be a string'),
    (_replace('child: odom', 'child: [a]'), ':5: expected a single value'),
    (
        _replace('child: odom', 'child: odom\n    colour: red'),
        ":6: transforms[0]: unknown key 'colour'",
    ),
    (
        _replace('child: odom', 'child: odom\n    child: x'),
        ":6: transforms[0]: duplicate key 'child'",
    ),
    (
        _replace('static: false', 'static: maybe'),
        ':12: transforms[1].static must be true or false',
    ),
    (_replace('nanosec: 7', 'nanosec: 1000000000'), ':13: transforms[1].stamp is out of range'),
    (_replace('child: odom', 'child: !!python/name:os.system'), 'tag tag:yaml.org,2002:python'),
    (_replace('child: odom', 'child: !custom odom'), ':5: tag !custom is not allowed'),
    (
        _replace('translation: [1.0, 2.0, 0.0]', 'translation: &t [1.0, 2.0, 0.0]').replace(
            'translation: [0.1, 0, 0]', 'translation: *t'
        ),
        'anchors and aliases',
    ),
    ('tf_demo_transforms: 1\ntransform_count: 20000\ntransforms: []\n', 'more than 10000'),
    # Issue 10: huge numbers are one clear line, not ValueError/OverflowError tracebacks.
    (
        _replace('[1.0, 2.0, 0.0]', '[1.0, ' + '9' * 400 + ', 0.0]'),
        ':6: transforms[0].translation[1]: number 9999',
    ),
    (
        _replace('[1.0, 2.0, 0.0]', '[1.0, ' + '9' * 400 + '.5, 0.0]'),
        ':6: transforms[0].translation[1]: number 9999',
    ),
    (
        _replace('[1.0, 2.0, 0.0]', '[0x' + 'f' * 300 + ', 2.0, 0.0]'),
        ':6: transforms[0].translation[0]: number 0xfff',
    ),
    (
        _with_sample_count('7' * 4300),
        ':14: transforms[1].sample_count: number 7777',
    ),
    (
        _with_sample_count('7' * 5000),
        '(5000 characters) is longer than 64 characters',
    ),
    (_with_sample_count('1:' * 30_000 + '1'), 'sample_count: number'),
    (_with_sample_count('9' * 30), 'sample_count must be <='),
    (_replace('nanosec: 7', 'nanosec: ' + '9' * 50), ':13: transforms[1].stamp.nanosec must be'),
    (_replace('tf_demo_transforms: 1', 'tf_demo_transforms: ' + '1' * 4300), ':1: tf_demo_'),
    (_replace('child: odom', 'child: odom\n    ' + 'k' * 1000 + ': 1'), '(1002 characters)'),
    (_replace('child: odom', 'child: od\udcffom'), ':5: not UTF-8 text (a lone surrogate)'),
]


@pytest.mark.parametrize(('text', 'message'), BAD_FILES)
def test_bad_files_are_refused_with_line(text, message):
    """Each corrupt, truncated or hostile file is refused, naming the problem (and the line)."""
    with pytest.raises(SnapshotError) as caught:
        parse_snapshot(text, 'f.yaml')
    assert message in str(caught.value)
    assert str(caught.value).startswith('f.yaml')


def test_billion_laughs_is_refused_quickly():
    """Nested aliases are refused at the first reuse instead of being expanded."""
    lines = ['tf_demo_transforms: 1', 'transform_count: 0', 'a0: &a0 [x, x, x, x, x, x, x, x]']
    lines += [f'a{i}: &a{i} [{", ".join([f"*a{i - 1}"] * 9)}]' for i in range(1, 12)]
    lines.append('transforms: []')
    with pytest.raises(SnapshotError, match='unknown key'):
        parse_snapshot('\n'.join(lines))
    aliased = 'tf_demo_transforms: 1\ntransform_count: &c 0\ntransforms: []\nx: *c\n'
    with pytest.raises(SnapshotError):
        parse_snapshot(aliased)


def test_file_errors(tmp_path):
    """Missing files, directories, binary junk and huge files are refused by read_snapshot."""
    with pytest.raises(SnapshotError, match='no such file'):
        read_snapshot(tmp_path / 'missing.yaml')
    with pytest.raises(SnapshotError, match='is a directory'):
        read_snapshot(tmp_path)
    junk = tmp_path / 'junk.yaml'
    junk.write_bytes(b'tf_demo_transforms: 1\n\xff\xfe\x00')
    with pytest.raises(SnapshotError, match=r'junk.yaml:2: not UTF-8'):
        read_snapshot(junk)
    huge = tmp_path / 'huge.yaml'
    with huge.open('wb') as handle:
        handle.truncate(MAX_FILE_BYTES + 1)
    with pytest.raises(SnapshotError, match='larger than'):
        read_snapshot(huge)


def test_frames_yaml_data_for_view_frames():
    """A snapshot becomes the frame map that view_frames draws (static frames at 10000 Hz)."""
    data = frames_yaml_data(_sample())
    assert data['odom']['parent'] == 'map'
    assert data['odom']['rate'] == 10000.0
    assert data['base "link"\u00e9']['rate'] == 20.5
    stamp = data['base "link"\u00e9']['most_recent_transform']
    assert isinstance(stamp, float)
    assert math.isclose(stamp, 1_700_000_000.123456789)


@pytest.mark.parametrize(
    'text',
    [
        'transforms: ' + '[' * 100_000 + ']' * 100_000,
        'a: ' + '{a: ' * 5_000 + '1' + '}' * 5_000,
        '- ' * 50_000 + 'x',
    ],
)
def test_deep_nesting_is_refused_without_recursion_error(text):
    """Deeply nested YAML is refused with a message instead of a RecursionError."""
    with pytest.raises(SnapshotError, match=r'^f:1: nesting is deeper than 16 levels$'):
        parse_snapshot(text, 'f')
