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

"""What the process benchmarks share: child roles, their JSON verdicts, a flow meter."""

from __future__ import annotations

from collections.abc import Callable
import importlib.util
import json
import os
import resource
import subprocess
import sys
import time


def build_line() -> str:
    """
    Say which tf_demo this process imports: ``python -m tf_demo`` in a child with its folder.

    Version, compiled or interpreted, Python.
    """
    spec = importlib.util.find_spec('tf_demo')
    if spec is None or spec.origin is None:
        return 'tf_demo is not importable here'
    root = os.path.dirname(os.path.dirname(spec.origin))
    paths = [root, *filter(None, [os.environ.get('PYTHONPATH')])]
    done = subprocess.run(
        [sys.executable, '-m', 'tf_demo'],
        env={**os.environ, 'PYTHONPATH': os.pathsep.join(paths)},
        capture_output=True,
        text=True,
        check=False,
    )
    return done.stdout.strip() or f'tf_demo not importable: {done.stderr.strip()[-200:]}'


def cpu_seconds() -> float:
    """CPU time (user + system) of this process so far."""
    usage = resource.getrusage(resource.RUSAGE_SELF)
    return usage.ru_utime + usage.ru_stime


def start_role(script: str, env: dict[str, str], *args: str) -> subprocess.Popen[str]:
    """Run ``script`` (a benchmark, in another role) with this interpreter; stdout piped."""
    return subprocess.Popen(
        [sys.executable, script, *args], env=env, stdout=subprocess.PIPE, text=True
    )


def last_json(process: subprocess.Popen[str], timeout: float) -> dict[str, float]:
    """The last JSON line a child printed before it ended (``{}`` if none)."""
    out, _ = process.communicate(timeout=timeout)
    lines = [line for line in out.splitlines() if line.startswith('{')]
    return dict(json.loads(lines[-1])) if lines else {}


class FlowMeter:
    """Counts samples; CPU and wall time from the first sample to the last hundredth one."""

    def __init__(self) -> None:
        self.received = 0
        self._first = self._last = (0.0, 0.0)

    def count(self) -> None:
        """Note one sample."""
        if self.received == 0:
            self._first = (cpu_seconds(), time.monotonic())
        self.received += 1
        if self.received % 100 == 0:
            self._last = (cpu_seconds(), time.monotonic())

    def cpu_s(self) -> float:
        """CPU seconds spent while samples flowed."""
        return self._last[0] - self._first[0]

    def wall_s(self) -> float:
        """Wall seconds while samples flowed."""
        return self._last[1] - self._first[1]

    def spin_until(self, spin_once: Callable[[], object], expect: int, timeout_s: float) -> None:
        """Call ``spin_once`` until ``expect`` samples arrived, 2 s of quiet, or the timeout."""
        deadline = time.monotonic() + timeout_s
        last_count, last_change = 0, time.monotonic()
        while self.received < expect and time.monotonic() < deadline:
            spin_once()
            if self.received != last_count:
                last_count, last_change = self.received, time.monotonic()
            elif self.received and time.monotonic() - last_change > 2.0:
                return
