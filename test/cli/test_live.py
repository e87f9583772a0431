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

"""The tools' shared shell: options refused in one line, snapshots, init and ToolError exits."""

from __future__ import annotations

import argparse
from pathlib import Path

import pytest
from tf_demo.cli._live import tool_main
from tf_demo.cli._live import ToolError
from tf_demo.cli._snapshot import Snapshot
from tf_demo.cli._snapshot import SnapshotTransform
from tf_demo.cli._snapshot import write_snapshot


def parser() -> argparse.ArgumentParser:
    """A tool's command line: one count and an optional ``--snapshot``."""
    result = argparse.ArgumentParser(prog='probe')
    result.add_argument('count', type=int)
    result.add_argument('--snapshot', type=Path)
    return result


def never(_options: argparse.Namespace) -> int:
    msg = 'the live part must not run'
    raise AssertionError(msg)


def test_refused_options_exit_2_with_one_line(capsys: pytest.CaptureFixture[str]) -> None:
    """What options_error refuses is printed as ``tool: error: ...`` and gives exit code 2."""

    def refuse(options: argparse.Namespace) -> str | None:
        return 'count must be positive' if options.count <= 0 else None

    code = tool_main('probe', ['0'], parser(), options_error=refuse, live=never)
    assert code == 2
    assert capsys.readouterr().err == 'probe: error: count must be positive\n'


def test_a_snapshot_is_read_and_handed_over_instead_of_listening(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    """--snapshot FILE goes to from_snapshot; a bad file or a ToolError is one line, code 3."""
    good = tmp_path / 'tree.yaml'
    write_snapshot(
        good, Snapshot((SnapshotTransform('map', 'odom', (1.0, 0.0, 0.0), (0.0, 0.0, 0.0, 1.0)),))
    )
    seen: list[Snapshot] = []

    def from_snapshot(_options: argparse.Namespace, snapshot: Snapshot) -> int:
        seen.append(snapshot)
        if len(seen) > 1:
            msg = 'no such frame'
            raise ToolError(msg)
        return 0

    def run(path: Path) -> int:
        return tool_main(
            'probe',
            ['1', '--snapshot', str(path)],
            parser(),
            options_error=lambda _options: None,
            live=never,
            from_snapshot=from_snapshot,
            bad_snapshot=3,
        )

    assert run(good) == 0
    assert [(t.parent, t.child) for t in seen[0].transforms] == [('map', 'odom')]
    assert run(tmp_path / 'missing.yaml') == 3
    assert capsys.readouterr().err.startswith('probe: error: ')
    assert run(good) == 3
    assert capsys.readouterr().err == 'probe: error: no such frame\n'


def test_the_live_part_runs_in_an_initialised_world(
    world_env: dict[str, str], capsys: pytest.CaptureFixture[str]
) -> None:
    """live runs between init and shutdown; its code is the exit code, a ToolError gives 1."""
    del world_env
    from tf_demo import transport

    def live(options: argparse.Namespace) -> int:
        assert transport.ok()
        if options.count == 2:
            msg = 'nothing to show'
            raise ToolError(msg)
        return int(options.count)

    def run(*args: str) -> int:
        return tool_main('probe', list(args), parser(), options_error=lambda _o: None, live=live)

    assert run('5') == 5
    assert not transport.ok()
    assert run('2') == 1
    assert capsys.readouterr().err.endswith('probe: error: nothing to show\n')
    assert run('1', '--ros-args', '--bogus') == 1
    assert 'probe: error: ' in capsys.readouterr().err
