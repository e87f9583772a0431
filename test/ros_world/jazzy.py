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

"""Helpers for tests that run the real ROS 2 Jazzy tools: ``ros2`` processes and graph polling."""

from __future__ import annotations

from collections.abc import Callable
from collections.abc import Iterator
import contextlib
import os
from pathlib import Path
import shutil
import signal
import subprocess
import time

import pytest

REPO_ROOT = Path(__file__).resolve().parents[2]


def require_ros2_cli() -> str:
    """Return the path of ``ros2``, or skip when the ROS 2 command line is not installed."""
    ros2 = shutil.which('ros2')
    if ros2 is None:
        pytest.skip('the ros2 command line (ros2cli) is not on PATH')
    return ros2


def require_installed_tf_demo(env: dict[str, str]) -> None:
    """Skip unless tf_demo is installed in the sourced workspace (``ros2 run`` finds it)."""
    require_package(
        env,
        'tf_demo',
        'tf_demo is not installed in the sourced workspace (colcon build, then source it)',
    )


def require_package(env: dict[str, str], package: str, reason: str = '') -> None:
    """Skip (with ``reason``) unless the ROS package ``package`` is installed and sourced."""
    require_ros2_cli()
    completed = subprocess.run(
        ['ros2', 'pkg', 'prefix', package],
        env=env,
        capture_output=True,
        text=True,
        timeout=60,
        check=False,
    )
    if completed.returncode != 0:
        pytest.skip(reason or f'the ROS package {package} is not installed')


def ros2(
    env: dict[str, str], *args: str, timeout: float = 60.0
) -> subprocess.CompletedProcess[str]:
    """Run one ``ros2`` command to its end."""
    return subprocess.run(
        ['ros2', *args], env=env, capture_output=True, text=True, timeout=timeout, check=False
    )


def eventually(
    check: Callable[[], object], timeout: float = 30.0, interval: float = 0.5
) -> object:
    """Call ``check`` until it returns something true (returned) or ``timeout`` passes (None)."""
    deadline = time.monotonic() + timeout
    while True:
        value = check()
        if value:
            return value
        if time.monotonic() >= deadline:
            return None
        time.sleep(interval)


def graph_lists(env: dict[str, str], what: str, timeout: float = 30.0) -> Callable[[str], bool]:
    """Return a predicate: whether ``ros2 <what> list`` shows a name (polled, no daemon)."""

    def shows(name: str) -> bool:
        def listed() -> bool:
            completed = ros2(env, what, 'list', '--no-daemon', '--spin-time', '1')
            return name in completed.stdout.split()

        return bool(eventually(listed, timeout))

    return shows


def stop(process: subprocess.Popen[str], timeout: float = 15.0) -> int:
    """Ctrl-C a process started by :func:`started` and return its exit code.

    As a terminal does, SIGINT goes to the whole process group: ``ros2 run`` and ``ros2
    launch`` leave it to their children to stop on the same signal. What does not end within
    ``timeout`` is killed (and the timeout raised).
    """
    if process.poll() is None:
        with contextlib.suppress(ProcessLookupError):
            os.killpg(process.pid, signal.SIGINT)
    try:
        return process.wait(timeout=timeout)
    except subprocess.TimeoutExpired:
        with contextlib.suppress(ProcessLookupError):
            os.killpg(process.pid, signal.SIGKILL)
        process.wait()
        raise


@contextlib.contextmanager
def started(
    command: list[str], env: dict[str, str], cwd: Path | None = None
) -> Iterator[subprocess.Popen[str]]:
    """A background process in its own process group, stopped with :func:`stop` at the end."""
    process = subprocess.Popen(
        command,
        env=env,
        cwd=cwd,
        stdin=subprocess.DEVNULL,
        stdout=subprocess.PIPE,
        stderr=subprocess.STDOUT,
        text=True,
        start_new_session=True,
    )
    try:
        yield process
    finally:
        if process.poll() is None:
            with contextlib.suppress(subprocess.TimeoutExpired):
                stop(process)


def standalone_python() -> str:
    """The Python of a standalone (no ROS) environment with cyclonedds, or skip."""
    python = os.environ.get('TF_DEMO_STANDALONE_PYTHON', '')
    if not python or not Path(python).is_file():
        pytest.skip('TF_DEMO_STANDALONE_PYTHON (a Python with tf_demo[dds], no ROS) is not set')
    return python


def standalone_env(env: dict[str, str]) -> dict[str, str]:
    """The test's environment for a standalone-world process: no ROS paths, DDS backend."""
    clean = {
        key: value
        for key, value in env.items()
        if key not in {'PYTHONPATH', 'AMENT_PREFIX_PATH', 'LD_LIBRARY_PATH', 'COLCON_PREFIX_PATH'}
    }
    clean.update(TF_DEMO_BACKEND='dds', PYTHONPATH=str(REPO_ROOT), PYTHONUNBUFFERED='1')
    return clean


def standalone_command(module: str, *args: str) -> list[str]:
    """Command line that runs ``tf_demo.<module>:main`` in the standalone world."""
    code = f'import sys; from tf_demo.{module} import main; sys.exit(main())'
    return [standalone_python(), '-c', code, *args]


__all__ = [
    'REPO_ROOT',
    'eventually',
    'graph_lists',
    'require_installed_tf_demo',
    'require_package',
    'require_ros2_cli',
    'ros2',
    'standalone_command',
    'standalone_env',
    'started',
    'stop',
]
