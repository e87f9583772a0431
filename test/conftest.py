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

"""Shared fixtures: a private DDS domain per test and real processes of our executables."""

from __future__ import annotations

from collections.abc import Callable
from collections.abc import Iterator
from collections.abc import Mapping
from collections.abc import Sequence
import contextlib
import fcntl
import importlib.util
import json
import os
from pathlib import Path
import signal
import subprocess
import sys
import tempfile
import threading
import time
from typing import Any
from typing import IO
from typing import Protocol
from typing import TYPE_CHECKING
from typing import TypeVar

from hypothesis import settings
import pytest
import tf_demo
from tf_demo.testing import strategies  # noqa: F401  (registers the 'ci' and 'nightly' profiles)
from tf_demo.transport.backend import backend_name
from tf_demo.transport.backend import BackendError

if TYPE_CHECKING:
    from tf_demo.transport.dds.participant import DdsParticipant

REPO_ROOT = Path(__file__).resolve().parent.parent
#: Where the tf_demo under test is imported from: this checkout (an editable install), or an
#: installed package (the ROS world's colcon test); child processes import the same one.
PACKAGE_ROOT = Path(tf_demo.__file__).resolve().parent.parent
#: Where tests save what a person should look at (screenshots, plots): ``$TF_DEMO_ARTIFACTS``.
ARTIFACTS = Path(os.environ.get('TF_DEMO_ARTIFACTS', REPO_ROOT / 'test-artifacts'))


# The browser tests (tf_view's, the documentation site's): Debian's chromium and its driver.
CHROMIUM = '/usr/bin/chromium'
CHROMEDRIVER = '/usr/bin/chromedriver'
# Chromium as root in a container: no sandbox, no GPU (WebGL through SwiftShader), and none
# of the background connections this machine's closed network refuses.
CHROMIUM_FLAGS = (
    '--headless=new',
    '--no-sandbox',
    '--disable-gpu',
    '--enable-unsafe-swiftshader',
    '--disable-quic',
    '--no-first-run',
    '--disable-background-networking',
    '--disable-component-update',
    '--disable-sync',
    '--window-size=1280,800',
)


@pytest.fixture
def browser(tmp_path: Path) -> Iterator[Any]:
    """A headless Debian chromium with its own empty profile (skips where it or selenium lacks)."""
    if not (os.path.exists(CHROMIUM) and os.path.exists(CHROMEDRIVER)):
        pytest.skip("needs Debian's chromium and chromium-driver")
    webdriver = pytest.importorskip('selenium.webdriver', reason='the browser tests use selenium')
    from selenium.webdriver.chrome.options import Options
    from selenium.webdriver.chrome.service import Service

    options = Options()
    options.binary_location = CHROMIUM
    for flag in (*CHROMIUM_FLAGS, f'--user-data-dir={tmp_path / "chromium"}'):
        options.add_argument(flag)
    driver = webdriver.Chrome(service=Service(CHROMEDRIVER), options=options)
    try:
        yield driver
    finally:
        driver.quit()


def save_artifact(name: str, data: bytes) -> Path:
    """Save ``data`` as the test artifact ``name`` and return its path."""
    ARTIFACTS.mkdir(parents=True, exist_ok=True)
    path = ARTIFACTS / name
    path.write_bytes(data)
    return path


TF_FAULT_PEER = REPO_ROOT / 'test' / 'cli' / 'tf_fault_peer.py'

# Every hypothesis test runs deterministically in CI (derandomized 'ci' profile) unless
# TF_DEMO_HYPOTHESIS_PROFILE=nightly asks for the larger random run.
settings.load_profile(os.environ.get('TF_DEMO_HYPOTHESIS_PROFILE', 'ci'))
_LOCK_DIR = Path(tempfile.gettempdir()) / 'tf_demo_domains'
# Domain ids 0..232 are valid for Cyclone's port mapping; keep clear of 0 (the user's default).
_FIRST_DOMAIN, _LAST_DOMAIN = 100, 230


@contextlib.contextmanager
def _exclusive_domain() -> Iterator[int]:
    """Hold an inter-process lock on one free domain id for the duration of a test."""
    _LOCK_DIR.mkdir(exist_ok=True)
    start = _FIRST_DOMAIN + os.getpid() % (_LAST_DOMAIN - _FIRST_DOMAIN)
    span = _LAST_DOMAIN - _FIRST_DOMAIN
    for offset in range(span):
        domain = _FIRST_DOMAIN + (start - _FIRST_DOMAIN + offset) % span
        handle: IO[str] = open(_LOCK_DIR / f'{domain}.lock', 'w')  # noqa: SIM115
        try:
            fcntl.flock(handle, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except OSError:
            handle.close()
            continue
        try:
            yield domain
        finally:
            fcntl.flock(handle, fcntl.LOCK_UN)
            handle.close()
        return
    msg = 'no free DDS domain id for the test'
    raise RuntimeError(msg)


HAVE_CYCLONEDDS = importlib.util.find_spec('cyclonedds') is not None
STANDALONE_ONLY = (
    'standalone world only: needs the cyclonedds Python package (pip install tf_demo[dds])'
)
"""Reason for ``pytest.importorskip('cyclonedds', reason=STANDALONE_ONLY)`` in test modules."""

PARAMETER_SERVICES = (
    'describe_parameters',
    'get_parameter_types',
    'get_parameters',
    'list_parameters',
    'set_parameters',
    'set_parameters_atomically',
)
"""The suffixes of the six parameter services every ROS 2 node offers (rcl), in sorted order."""

# The import shims of test/upstream are packages named tf2_ros and tf2_geometry_msgs: never
# collect (import) them as tests.
collect_ignore = ['upstream/shims']


@pytest.hookimpl(tryfirst=True)
def pytest_pycollect_makemodule(
    module_path: Path, parent: pytest.Collector
) -> pytest.Module | None:
    """Collect test modules as plain pytest does, before launch_testing's plugin can.

    Inside ROS 2, launch_testing's pytest plugin imports every test module itself to look for
    launch tests; a module-level skip (``importorskip``) raised there ends the whole collection.
    This suite has no launch tests, so its modules are collected by pytest's own ``Module``.
    """
    if module_path.name == '__init__.py':
        return None
    return pytest.Module.from_parent(parent, path=module_path)


def _world() -> str:
    """The world this pytest process runs in: ``'rclpy'`` or ``'dds'`` (standalone)."""
    try:
        return backend_name()
    except BackendError:
        return 'dds'


WORLD = _world()
"""``'rclpy'`` inside ROS 2 (rclpy imports), ``'dds'`` in the standalone world."""

_WORLD_SKIPS = {
    'standalone': (
        WORLD != 'dds' or not HAVE_CYCLONEDDS,
        'standalone world only: needs the cyclonedds Python package and TF_DEMO_BACKEND=dds '
        '(this run is the '
        + ('rclpy world' if WORLD == 'rclpy' else 'standalone world without cyclonedds')
        + ')',
    ),
    'rclpy_world': (
        WORLD != 'rclpy',
        'rclpy world only: needs ROS 2 Jazzy sourced (rclpy does not import in this run)',
    ),
}


def pytest_collection_modifyitems(items: list[pytest.Item]) -> None:
    """Skip, with the reason, every test whose world this run is not."""
    for item in items:
        for marker, (skip, reason) in _WORLD_SKIPS.items():
            if skip and item.get_closest_marker(marker) is not None:
                item.add_marker(pytest.mark.skip(reason=reason))


@pytest.fixture
def world_env(monkeypatch: pytest.MonkeyPatch) -> Iterator[dict[str, str]]:
    """Environment for a test that talks to other nodes, in this run's world.

    Its own domain id and loopback-only discovery; ``TF_DEMO_BACKEND`` is this run's world, so
    child processes run in the same world as the test. The variables are also set in this
    process, so in-process nodes use the same domain.
    """
    with _exclusive_domain() as domain:
        env = dict(os.environ)
        env.update(
            {
                'ROS_DOMAIN_ID': str(domain),
                'ROS_AUTOMATIC_DISCOVERY_RANGE': 'LOCALHOST',
                'TF_DEMO_BACKEND': WORLD,
                'PYTHONUNBUFFERED': '1',
                'PYTHONPATH': os.pathsep.join(
                    p for p in (str(PACKAGE_ROOT), os.environ.get('PYTHONPATH', '')) if p
                ),
            }
        )
        if WORLD == 'rclpy':
            env.setdefault('RMW_IMPLEMENTATION', 'rmw_cyclonedds_cpp')
        env.pop('ROS_LOCALHOST_ONLY', None)
        env.pop('CYCLONEDDS_URI', None)
        for key in ('ROS_DOMAIN_ID', 'ROS_AUTOMATIC_DISCOVERY_RANGE', 'TF_DEMO_BACKEND'):
            monkeypatch.setenv(key, env[key])
        monkeypatch.delenv('ROS_LOCALHOST_ONLY', raising=False)
        monkeypatch.delenv('CYCLONEDDS_URI', raising=False)
        yield env


@pytest.fixture
def dds_env(world_env: dict[str, str]) -> dict[str, str]:
    """:func:`world_env` for a standalone-only test (mark it ``standalone``): forces DDS."""
    if WORLD != 'dds':
        pytest.skip('standalone world only (this run is the rclpy world)')
    return world_env


@pytest.fixture
def dds_world(dds_env: dict[str, str]) -> Iterator[None]:
    """An initialised standalone world on the test's private domain, shut down afterwards."""
    del dds_env
    from tf_demo.transport import dds_backend

    dds_backend.init()
    yield
    dds_backend.shutdown()


@pytest.fixture
def dds_participant(dds_env: dict[str, str]) -> Iterator[DdsParticipant]:
    """This process' own DDS participant on the test's private domain, closed afterwards."""
    del dds_env
    from tf_demo.transport.dds import participant

    yield participant.get_participant()
    participant.close_participant()


@pytest.fixture
def jazzy_env(world_env: dict[str, str]) -> dict[str, str]:
    """:func:`world_env` of a ROS-world test with tf_demo installed in the sourced workspace."""
    from ros_world.jazzy import require_installed_tf_demo

    require_installed_tf_demo(world_env)
    return world_env


_T = TypeVar('_T')


def eventually(check: Callable[[], _T], timeout: float = 30.0, interval: float = 0.5) -> _T | None:
    """Call ``check`` until it returns something true (returned) or ``timeout`` passes (None).

    A bounded wait for what arrives from another process, not a timing assertion.
    """
    deadline = time.monotonic() + timeout
    while True:
        value = check()
        if value:
            return value
        if time.monotonic() >= deadline:
            return None
        time.sleep(interval)


def run_captured(
    args: Sequence[str],
    env: Mapping[str, str] | None = None,
    *,
    cwd: Path | None = None,
    timeout: float = 60.0,
) -> subprocess.CompletedProcess[str]:
    """Run command line ``args`` to its end: output captured as text, the exit code unchecked."""
    return subprocess.run(
        list(args), env=env, cwd=cwd, capture_output=True, text=True, timeout=timeout, check=False
    )


def executable_command(name: str, *args: str) -> list[str]:
    """Command line that runs one of this package's executables from the source tree."""
    for layer in ('nodes', 'cli'):
        module = f'tf_demo.{layer}.{name}'
        if importlib.util.find_spec(module) is not None:
            code = f'import sys; from {module} import main; sys.exit(main())'
            return [sys.executable, '-c', code, *args]
    msg = f'no executable named {name!r} in tf_demo.nodes or tf_demo.cli'
    raise LookupError(msg)


class Processes:
    """Starts executables as real processes and stops every one of them at the end of a test."""

    def __init__(self, env: dict[str, str], workdir: Path) -> None:
        self._env = env
        self._workdir = workdir
        self._started: list[subprocess.Popen[str]] = []

    def start(
        self,
        name: str,
        *args: str,
        env: dict[str, str] | None = None,
        stdin: int | None = subprocess.DEVNULL,
    ) -> subprocess.Popen[str]:
        """Start executable `name` with `args`; stdout and stderr are pipes of text."""
        process = subprocess.Popen(
            executable_command(name, *args),
            env=env or self._env,
            cwd=self._workdir,
            stdin=stdin,
            stdout=subprocess.PIPE,
            stderr=subprocess.PIPE,
            text=True,
        )
        self._started.append(process)
        return process

    def stop_all(self) -> None:
        """SIGINT every process still running, then kill what does not exit within 5 s."""
        for process in self._started:
            if process.poll() is None:
                process.send_signal(signal.SIGINT)
        for process in self._started:
            try:
                process.wait(timeout=5)
            except subprocess.TimeoutExpired:
                process.kill()
                process.wait()


@pytest.fixture
def spawn(world_env: dict[str, str], tmp_path: Path) -> Iterator[Processes]:
    """Start this package's executables as real processes on the test's private domain."""
    processes = Processes(world_env, tmp_path)
    try:
        yield processes
    finally:
        processes.stop_all()


TfPeerEntry = dict[str, object]
"""One transform of a ``test/cli/tf_fault_peer.py`` scenario (see its docstring)."""


class StartTfPeer(Protocol):
    """The ``tf_peers`` fixture: start a tf_fault_peer publishing ``entries``."""

    def __call__(self, *entries: TfPeerEntry) -> subprocess.Popen[str]: ...


@pytest.fixture
def tf_peers(world_env: dict[str, str]) -> Iterator[StartTfPeer]:
    """Start tf_fault_peer processes publishing a JSON scenario; stop them at the end."""
    started: list[subprocess.Popen[str]] = []

    def start(*entries: TfPeerEntry) -> subprocess.Popen[str]:
        process = subprocess.Popen(
            [sys.executable, str(TF_FAULT_PEER), json.dumps(list(entries))],
            env=world_env,
            stdout=subprocess.PIPE,
            stderr=subprocess.PIPE,
            text=True,
        )
        started.append(process)
        assert process.stdout is not None
        assert process.stderr is not None
        assert process.stdout.readline().strip() == 'ready', process.stderr.read()
        return process

    yield start
    for process in started:
        process.send_signal(signal.SIGINT)
    for process in started:
        try:
            process.wait(timeout=5)
        except subprocess.TimeoutExpired:
            process.kill()
            process.wait()


# -- appended by reviewer: one output collector for the child processes of the DDS tests ------


class ProcessOutput:
    """The stdout and stderr lines of a running process, collected by threads as they arrive."""

    def __init__(self, process: subprocess.Popen[str]) -> None:
        self.process = process
        self.stdout: list[str] = []
        self.stderr: list[str] = []
        self.lines: list[str] = []
        """Lines of both streams in arrival order."""
        self._arrived = threading.Condition()
        pipes = [(process.stdout, self.stdout), (process.stderr, self.stderr)]
        # None: not a pipe (stderr merged into stdout)
        self._open = sum(1 for stream, _ in pipes if stream is not None)
        for stream, sink in pipes:
            if stream is not None:
                threading.Thread(target=self._pump, args=(stream, sink), daemon=True).start()

    def _pump(self, stream: IO[str], sink: list[str]) -> None:
        for raw in stream:
            line = raw.rstrip('\n')
            with self._arrived:
                sink.append(line)
                self.lines.append(line)
                self._arrived.notify_all()
        with self._arrived:
            self._open -= 1  # at the end of both, no line can come any more
            self._arrived.notify_all()

    def line_where(self, matches: Callable[[str], bool], timeout: float) -> str | None:
        """
        Return the first line (already seen or arriving within ``timeout`` s) that matches.

        None at once when the process closed its output without one.
        """
        deadline = time.monotonic() + timeout
        checked = 0
        with self._arrived:
            while True:
                for line in self.lines[checked:]:
                    if matches(line):
                        return line
                checked = len(self.lines)
                remaining = deadline - time.monotonic()
                if remaining <= 0 or self._open == 0:
                    return None
                self._arrived.wait(remaining)

    def wait_for_line(self, text: str, timeout: float = 30.0, *, anywhere: bool = False) -> str:
        """Return the first line starting with (``anywhere``: containing) ``text``, else fail."""
        line = self.line_where(
            (lambda line: text in line) if anywhere else (lambda line: line.startswith(text)),
            timeout,
        )
        if line is None:
            where = 'containing' if anywhere else 'starting with'
            pytest.fail(
                f'no line {where} {text!r} within {timeout} s (or before the output ended); '
                f'stdout={self.stdout} stderr={self.stderr}'
            )
        return line


class ChildProcess(ProcessOutput):
    """A command started with piped output (:class:`ProcessOutput`); ``finish`` and ``stop``."""

    def __init__(
        self, command: list[str], env: dict[str, str], *, finish_timeout: float = 30.0
    ) -> None:
        super().__init__(
            subprocess.Popen(
                command,
                env=env,
                stdin=subprocess.DEVNULL,
                stdout=subprocess.PIPE,
                stderr=subprocess.PIPE,
                text=True,
            )
        )
        self._finish_timeout = finish_timeout

    def finish(self, timeout: float | None = None) -> int:
        """Wait for the process to exit and return its exit code (output drained)."""
        code = self.process.wait(timeout=self._finish_timeout if timeout is None else timeout)
        time.sleep(0.05)  # let the pump threads drain the pipes
        return code

    def stop(self) -> None:
        """Kill the process if it still runs."""
        if self.process.poll() is None:
            self.process.kill()
        self.process.wait()


@pytest.fixture
def ros(world_env: dict[str, str]) -> Iterator[None]:
    """Initialise this run's backend in this process on the test's private domain."""
    del world_env
    from tf_demo import transport

    transport.init(['test'])
    try:
        yield
    finally:
        transport.shutdown()


class Spinning:
    """Nodes of this run's world in this process, spun by one executor thread once started."""

    def __init__(self) -> None:
        from tf_demo import transport
        from tf_demo.transport.executors import SingleThreadedExecutor

        self._transport = transport
        self.nodes: list[Any] = []
        self.executor = SingleThreadedExecutor()
        self._stop = threading.Event()
        self._thread: threading.Thread | None = None

    def add(self, node: Any) -> Any:
        """Spin ``node`` too (destroyed at the end); return it."""
        self.nodes.append(node)
        self.executor.add_node(node)
        return node

    def node(self, name: str) -> Any:
        """A new node called ``name``, spun with the others."""
        return self.add(self._transport.create_node(name))

    def start(self) -> None:
        """Start spinning (nodes may still be added)."""

        def spin() -> None:
            while not self._stop.is_set():
                self.executor.spin_once(timeout_sec=0.05)

        self._thread = threading.Thread(target=spin, daemon=True)
        self._thread.start()

    def close(self) -> None:
        self._stop.set()
        if self._thread is not None:
            self._thread.join(timeout=10)
        for node in self.nodes:
            node.destroy_node()


@pytest.fixture
def nodes(ros: None) -> Iterator[Spinning]:
    """In-process nodes on the test's private domain, spun by one thread (:class:`Spinning`)."""
    del ros
    spinning = Spinning()
    try:
        yield spinning
    finally:
        spinning.close()


@pytest.fixture
def executors(ros: None) -> Iterator[list[Any]]:
    """Executors made by the test; shut down at its end (before the world is)."""
    del ros
    made: list[Any] = []
    yield made
    for executor in made:
        executor.shutdown()


def executor_with(executors: list[Any], executor: Any, *nodes: Any) -> Any:
    """Return ``executor`` with ``nodes`` added, shut down at the test's end (``executors``)."""
    executors.append(executor)
    for node in nodes:
        executor.add_node(node)
    return executor
