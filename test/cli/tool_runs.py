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

"""What the real-process tests of the tf tools share: run a tool, tf_fault_peer scenarios."""

from __future__ import annotations

from conftest import Processes
from conftest import TfPeerEntry

LOG_PREFIX = r'\[(INFO|WARN|ERROR)\] \[\d+\.\d{9}\] \[[^\]]*\]: '
"""The start of a tool's log line on stderr, as rcutils prints it."""


def run(spawn: Processes, name: str, *args: str, timeout: float = 60) -> tuple[int, str, str]:
    """Run one of our executables to completion; return (exit code, stdout, stderr)."""
    process = spawn.start(name, *args)
    out, err = process.communicate(timeout=timeout)
    return process.returncode, out, err


def static(
    parent: str,
    child: str,
    t: tuple[float, float, float] = (0.0, 0.0, 0.0),
    group: str = 'main',
    q: tuple[float, float, float, float] = (0.0, 0.0, 0.0, 1.0),
) -> TfPeerEntry:
    return {
        'parent': parent,
        'child': child,
        't': list(t),
        'q': list(q),
        'static': True,
        'group': group,
    }


def dynamic(parent: str, child: str, **extra: object) -> TfPeerEntry:
    return {'parent': parent, 'child': child, 'static': False, **extra}
