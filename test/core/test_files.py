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
``-o`` never damages what it points at: regular files only, links followed and kept, atomic.

Issue 10, point 7: ``tf_saver -o /dev/full`` (as root) turned the device into a regular file and
``-o`` through a symbolic link replaced the link. The device cases use a private device node
made with ``mknod`` (root only) and a FIFO, never the machine's own ``/dev`` entries.
"""

from __future__ import annotations

import os
from pathlib import Path
import stat

import pytest
from tf_demo.cli._snapshot import read_snapshot
from tf_demo.cli._snapshot import Snapshot
from tf_demo.cli._snapshot import SnapshotTransform
from tf_demo.cli._snapshot import write_snapshot
from tf_demo.core.files import InputFileError
from tf_demo.core.files import output_path_error
from tf_demo.core.files import OutputFileError
from tf_demo.core.files import read_text_file
from tf_demo.core.files import write_text_atomically
from tf_demo.core.files import yaml_flow_too_deep

SNAPSHOT = Snapshot(
    transforms=(SnapshotTransform('map', 'odom', (1.0, 2.0, 3.0), (0.0, 0.0, 0.0, 1.0)),)
)


def full_device(tmp_path: Path) -> Path:
    """A character device like /dev/full (major 1, minor 7) in ``tmp_path`` (root only)."""
    if os.geteuid() != 0:
        pytest.skip('making a device node needs root')
    device = tmp_path / 'full'
    try:
        os.mknod(device, 0o666 | stat.S_IFCHR, os.makedev(1, 7))
    except PermissionError:
        pytest.skip('this container may not make device nodes')
    return device


def only_regular_files(tmp_path: Path) -> list[str]:
    """Names in ``tmp_path`` (no temporary file may be left behind)."""
    return sorted(p.name for p in tmp_path.iterdir())


def test_a_device_is_refused_and_stays_a_device(tmp_path: Path) -> None:
    """As root, writing to a /dev/full-like node is refused; the node is still a device."""
    device = full_device(tmp_path)
    with pytest.raises(OutputFileError, match=r'full: not a regular file \(a device'):
        write_snapshot(device, SNAPSHOT)
    assert stat.S_ISCHR(os.lstat(device).st_mode)
    assert only_regular_files(tmp_path) == ['full']
    assert output_path_error(device) is not None


def test_a_link_to_a_device_is_refused_and_both_stay(tmp_path: Path) -> None:
    """A symbolic link to a device is refused like the device; the link and node are kept."""
    device = full_device(tmp_path)
    link = tmp_path / 'link'
    link.symlink_to(device)
    with pytest.raises(OutputFileError, match='not a regular file'):
        write_snapshot(link, SNAPSHOT)
    assert link.is_symlink()
    assert stat.S_ISCHR(os.lstat(device).st_mode)


def test_fifo_and_directory_are_refused_without_blocking(tmp_path: Path) -> None:
    """A FIFO (no reader: opening it would block) and a folder are refused before writing."""
    fifo = tmp_path / 'fifo'
    os.mkfifo(fifo)
    with pytest.raises(OutputFileError, match='fifo: not a regular file'):
        write_text_atomically(fifo, 'x')
    assert stat.S_ISFIFO(os.lstat(fifo).st_mode)
    with pytest.raises(OutputFileError, match='is a directory'):
        write_text_atomically(tmp_path, 'x')
    with pytest.raises(OutputFileError, match='empty'):
        write_text_atomically('', 'x')
    assert only_regular_files(tmp_path) == ['fifo']


def test_dev_null_and_dev_full_are_refused_by_the_check(tmp_path: Path) -> None:
    """The check tf_saver runs before listening names the machine's own devices too."""
    del tmp_path
    for device in ('/dev/null', '/dev/full'):
        if os.path.exists(device):
            problem = output_path_error(device)
            assert problem is not None
            assert problem.startswith(f'{device}: not a regular file')


def test_a_link_to_a_regular_file_is_followed_and_stays_a_link(tmp_path: Path) -> None:
    """Writing through a link replaces the file it points at; the link is kept as it was."""
    real = tmp_path / 'snapshots' / 'real.yaml'
    real.parent.mkdir()
    real.write_text('old', encoding='utf-8')
    real.chmod(0o640)
    link = tmp_path / 'latest.yaml'
    link.symlink_to(Path('snapshots') / 'real.yaml')
    write_snapshot(link, SNAPSHOT)
    assert link.is_symlink()
    assert os.readlink(link) == str(Path('snapshots') / 'real.yaml')
    assert read_snapshot(real) == SNAPSHOT
    assert stat.S_IMODE(real.stat().st_mode) == 0o640  # the file keeps its permissions
    assert only_regular_files(real.parent) == ['real.yaml']


def test_a_dangling_link_creates_the_file_it_names(tmp_path: Path) -> None:
    """A link to a file that does not exist yet: the file is created, the link kept."""
    link = tmp_path / 'latest.yaml'
    link.symlink_to('new.yaml')
    write_snapshot(link, SNAPSHOT)
    assert link.is_symlink()
    assert read_snapshot(tmp_path / 'new.yaml') == SNAPSHOT


def test_a_link_loop_is_refused(tmp_path: Path) -> None:
    """A link that points at itself is an error naming the path, not a traceback."""
    loop = tmp_path / 'loop.yaml'
    loop.symlink_to('loop.yaml')
    with pytest.raises(OutputFileError, match=r'loop\.yaml: cannot write'):
        write_snapshot(loop, SNAPSHOT)
    assert loop.is_symlink()


def test_a_regular_file_is_replaced_atomically(tmp_path: Path) -> None:
    """An existing file gets the new content via a rename: a new inode, no temporary left."""
    target = tmp_path / 'tf.yaml'
    target.write_text('old', encoding='utf-8')
    before = target.stat().st_ino
    write_snapshot(target, SNAPSHOT)
    assert read_snapshot(target) == SNAPSHOT
    assert target.stat().st_ino != before
    assert only_regular_files(tmp_path) == ['tf.yaml']


def test_a_new_file_gets_the_usual_permissions(tmp_path: Path) -> None:
    """A new file is created 0666 minus the umask, as open() would (not mkstemp's 0600)."""
    umask = os.umask(0o022)
    try:
        write_snapshot(tmp_path / 'new.yaml', SNAPSHOT)
    finally:
        os.umask(umask)
    assert stat.S_IMODE((tmp_path / 'new.yaml').stat().st_mode) == 0o644


def test_a_missing_folder_is_one_clear_error(tmp_path: Path) -> None:
    """A path in a folder that does not exist: OutputFileError naming the path and reason."""
    with pytest.raises(OutputFileError, match=r'nowhere/tf.yaml: cannot write \(No such file'):
        write_snapshot(tmp_path / 'nowhere' / 'tf.yaml', SNAPSHOT)


# -- reading -----------------------------------------------------------------------------------


def test_reading_refuses_what_is_not_a_regular_file(tmp_path: Path) -> None:
    """/dev/zero, a FIFO with no writer (no hang) and a folder: one line each, nothing read."""
    fifo = tmp_path / 'pipe'
    os.mkfifo(fifo)
    for path, reason in (
        ('/dev/zero', 'not a regular file'),
        (str(fifo), 'not a regular file'),
        (str(tmp_path), 'is a directory'),
        (str(tmp_path / 'missing.urdf'), 'no such file'),
    ):
        with pytest.raises(InputFileError) as caught:
            read_text_file(path)
        assert str(caught.value).startswith(f'{path}: {reason}'), caught.value


def test_reading_is_bounded_and_names_the_bad_utf8_line(tmp_path: Path) -> None:
    """A file over the limit is refused with its size; bad UTF-8 names the line it is on."""
    big = tmp_path / 'big.yaml'
    big.write_bytes(b'x' * 5000)
    with pytest.raises(InputFileError, match='larger than 4096 bytes'):
        read_text_file(big, 4096)
    assert read_text_file(big, 5000) == 'x' * 5000
    bad = tmp_path / 'bad.yaml'
    bad.write_bytes(b'a: 1\nb: 2\nc: \xff\n')
    with pytest.raises(InputFileError, match=r'bad\.yaml:3: not UTF-8 text'):
        read_text_file(bad)


def test_reading_a_small_file_allocates_little(tmp_path: Path) -> None:
    """No buffer of the size limit is allocated for a three-byte file (a 16 MiB peak before)."""
    import tracemalloc

    small = tmp_path / 'small.txt'
    small.write_text('abc', encoding='utf-8')
    tracemalloc.start()
    try:
        assert read_text_file(small) == 'abc'
        peak = tracemalloc.get_traced_memory()[1]
    finally:
        tracemalloc.stop()
    assert peak < 1024 * 1024, peak


@pytest.mark.parametrize(
    ('text', 'limit', 'line'),
    [
        ('[' * 64 + ']' * 64, 64, None),
        ('[' * 65 + ']' * 65, 64, 1),
        ('{a: ' * 65 + '1' + '}' * 65, 64, 1),
        ('- - [' + '[' * 70, 64, 1),
        ('x:   # [[[[[[\n  ' + '[' * 70, 64, 2),
        ('a' + '[' * 100, 64, None),  # a plain scalar
        ('"' + '[' * 100 + '"', 64, None),  # a double-quoted scalar
        ("'it''s " + '[' * 100 + "'", 64, None),  # '' inside a single-quoted scalar
        ('"\\"' + '[' * 100 + '"', 64, None),  # an escaped quote
        ('[' * 3 + ']' * 3 + ', [[[[', 3, 1),  # depth 4 after returning to 0
    ],
)
def test_yaml_flow_nesting_is_measured_before_parsing(text: str, limit: int, line: int | None):
    """Flow brackets deeper than the limit give their line; scalars and comments do not count."""
    assert yaml_flow_too_deep(text, limit) == line


def test_flow_depth_agrees_with_the_yaml_parser():
    """For nested flow sequences the scan and PyYAML's own events count the same depth."""
    import yaml

    for depth in range(1, 40, 7):
        text = 'k: ' + '[' * depth + '1' + ', [2]' + ']' * depth
        events = yaml.parse(text, Loader=yaml.SafeLoader)
        deepest = current = 0
        for event in events:
            if isinstance(event, yaml.SequenceStartEvent):
                current += 1
                deepest = max(deepest, current)
            elif isinstance(event, yaml.SequenceEndEvent):
                current -= 1
        assert yaml_flow_too_deep(text, deepest) is None
        assert yaml_flow_too_deep(text, deepest - 1) == 1
