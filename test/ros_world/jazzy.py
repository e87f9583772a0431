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
import threading
from typing import Any

from conftest import eventually
from conftest import ProcessOutput
from conftest import REPO_ROOT
from conftest import run_captured
import pytest


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
    if run_captured(['ros2', 'pkg', 'prefix', package], env).returncode != 0:
        pytest.skip(reason or f'the ROS package {package} is not installed')


def ros2(
    env: dict[str, str], *args: str, timeout: float = 60.0
) -> subprocess.CompletedProcess[str]:
    """Run one ``ros2`` command to its end."""
    return run_captured(['ros2', *args], env, timeout=timeout)


def graph_lists(env: dict[str, str], what: str, timeout: float = 30.0) -> Callable[[str], bool]:
    """Return a predicate: whether ``ros2 <what> list`` shows a name (polled, no daemon)."""

    def shows(name: str) -> bool:
        def listed() -> bool:
            completed = ros2(env, what, 'list', '--no-daemon', '--spin-time', '1')
            return name in completed.stdout.split()

        return bool(eventually(listed, timeout))

    return shows


# -- processes in a session of their own, stopped as a terminal stops them ----------------------


def start_session(
    command: list[str], env: dict[str, str], cwd: Path | None = None, *, stderr: int
) -> subprocess.Popen[str]:
    """Start ``command`` in its own process group, stdout piped as text (``stderr``: where to)."""
    return subprocess.Popen(
        command,
        env=env,
        cwd=cwd,
        stdin=subprocess.DEVNULL,
        stdout=subprocess.PIPE,
        stderr=stderr,
        text=True,
        start_new_session=True,
    )


def kill_group(process: subprocess.Popen[str]) -> None:
    """SIGKILL whatever is left of the process group of ``process`` (started as a session)."""
    with contextlib.suppress(ProcessLookupError, PermissionError):
        os.killpg(process.pid, signal.SIGKILL)
    if process.poll() is None:
        process.wait()


def stop(process: subprocess.Popen[str], timeout: float = 20.0) -> int:
    """Ctrl-C a process started as a session and return its exit code.

    As a terminal does, SIGINT goes to the whole process group: ``ros2 run`` and ``ros2
    launch`` leave it to their children to stop on the same signal. Whatever of the group is
    left afterwards is killed (and a ``timeout`` that passed is raised).
    """
    if process.poll() is None:
        with contextlib.suppress(ProcessLookupError):
            os.killpg(process.pid, signal.SIGINT)
    try:
        return process.wait(timeout=timeout)
    finally:
        kill_group(process)


@contextlib.contextmanager
def _session(
    command: list[str], env: dict[str, str], cwd: Path | None, stderr: int
) -> Iterator[subprocess.Popen[str]]:
    process = start_session(command, env, cwd, stderr=stderr)
    try:
        yield process
    finally:
        with contextlib.suppress(subprocess.TimeoutExpired):
            stop(process)


def started(
    command: list[str], env: dict[str, str], cwd: Path | None = None
) -> contextlib.AbstractContextManager[subprocess.Popen[str]]:
    """A background process (own group; stderr into stdout), stopped with :func:`stop`."""
    return _session(command, env, cwd, subprocess.STDOUT)


@contextlib.contextmanager
def running(
    command: list[str], env: dict[str, str], cwd: Path | None = None
) -> Iterator[ProcessOutput]:
    """A background process (own group), its stdout and stderr lines collected; stopped."""
    with _session(command, env, cwd, subprocess.PIPE) as process:
        yield ProcessOutput(process)


# -- the standalone world beside this one -------------------------------------------------------


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


# -- a real rclpy node in this process ---------------------------------------------------------


class RclpyNode:
    """A real rclpy node in this process, with a context of its own, spun by its own thread."""

    def __init__(self, name: str, domain_id: int | None = None) -> None:
        import rclpy
        from rclpy.executors import SingleThreadedExecutor

        self._rclpy = rclpy
        self.context = rclpy.Context()
        rclpy.init(context=self.context, domain_id=domain_id)
        self.node = rclpy.create_node(name, context=self.context)
        self.executor = SingleThreadedExecutor(context=self.context)
        self.executor.add_node(self.node)
        self._thread = threading.Thread(target=self._spin, daemon=True)
        self._thread.start()

    def _spin(self) -> None:
        while self.context.ok():
            try:
                self.executor.spin_once(timeout_sec=0.1)
            except Exception:  # the context was shut down under spin_once
                return

    def collect(self, message_type: Any, topic: str, qos: Any) -> list[Any]:
        """Subscribe to ``topic``; return the list the messages are appended to."""
        received: list[Any] = []
        self.node.create_subscription(message_type, topic, received.append, qos)
        return received

    def call(self, srv_type: Any, name: str, request: Any, timeout: float = 60.0) -> Any:
        """Call a service (waiting for it); the response, or None."""
        client = self.node.create_client(srv_type, name)
        if not client.wait_for_service(timeout_sec=timeout):
            return None
        future = client.call_async(request)
        if not eventually(future.done, timeout, 0.05):
            return None
        return future.result()

    def close(self) -> None:
        self.executor.shutdown(timeout_sec=1.0)
        self.node.destroy_node()
        self._rclpy.shutdown(context=self.context)
        self._thread.join(timeout=10)


@contextlib.contextmanager
def rclpy_node(name: str, domain_id: int | None = None) -> Iterator[RclpyNode]:
    """A :class:`RclpyNode`, closed at the end."""
    node = RclpyNode(name, domain_id)
    try:
        yield node
    finally:
        node.close()


__all__ = [
    'REPO_ROOT',
    'RclpyNode',
    'graph_lists',
    'kill_group',
    'rclpy_node',
    'require_installed_tf_demo',
    'require_package',
    'require_ros2_cli',
    'ros2',
    'running',
    'standalone_command',
    'standalone_env',
    'standalone_python',
    'start_session',
    'started',
    'stop',
]
