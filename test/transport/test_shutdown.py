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

"""Ctrl-C and SIGTERM stop a real node process cleanly; config errors exit 1 on one line."""

from collections.abc import Iterator
from pathlib import Path
import signal
import subprocess
import sys
import time
import weakref

import pytest
from tf_demo import transport
from tf_demo.transport.executors import ExternalShutdownException
from tf_demo.transport.executors import SingleThreadedExecutor
from tf_demo.transport.messages import std_msgs
from tf_demo.transport.qos import QoSProfile

pytestmark = pytest.mark.dds

COUNTER_NODE = """
import sys
from tf_demo.transport import NodeConfigError, run_node
from tf_demo.transport.node import Node
from tf_demo.transport.messages import std_msgs


class Counter(Node):
    def __init__(self):
        super().__init__('counter')
        period = self.declare_parameter('period', 0.01).value
        if period <= 0.0:
            raise NodeConfigError(f'period must be positive, got {period}')
        self.count = 0
        self.publisher = self.create_publisher(std_msgs.String, 'count', 1000)
        self.timer = self.create_timer(period, self.tick)
        self.get_logger().info('counting')

    def tick(self):
        self.count += 1
        self.publisher.publish(std_msgs.String(data=str(self.count)))

    def destroy_node(self):
        print(f'last {self.count}', flush=True)
        super().destroy_node()


sys.exit(run_node(Counter))
"""


def start_counter(tmp_path: Path, env: dict[str, str], *args: str) -> subprocess.Popen[str]:
    script = tmp_path / 'counter.py'
    script.write_text(COUNTER_NODE, encoding='utf-8')
    return subprocess.Popen(
        [sys.executable, str(script), *args],
        env=env,
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
    )


def wait_for_line(process: subprocess.Popen[str], text: str) -> None:
    """Read stderr lines until one contains text (bounded by the process's own output)."""
    assert process.stderr is not None
    for line in process.stderr:
        if text in line:
            return
    pytest.fail(f'process ended before printing {text!r}')


@pytest.mark.parametrize(
    'signals',
    [
        (signal.SIGINT,),
        (signal.SIGTERM,),
        (signal.SIGINT, signal.SIGINT),
        (signal.SIGTERM, signal.SIGINT),
    ],
    ids=['SIGINT', 'SIGTERM', 'double-SIGINT', 'SIGTERM-then-SIGINT'],
)
def test_signal_stops_node_with_exit_0_and_flushes_its_publisher(
    world_env: dict[str, str], tmp_path: Path, signals: tuple[signal.Signals, ...]
) -> None:
    """
    After SIGINT or SIGTERM the node exits 0 without traceback and its last sample arrives.

    A second signal a moment later (a double Ctrl-C) is ignored while the node shuts down: the
    node is still destroyed (it prints its last count) and its last sample still arrives.
    """
    transport.init(['test'])
    received: list[int] = []
    try:
        listener = transport.create_node('shutdown_listener')
        listener.create_subscription(
            std_msgs.String,
            'count',
            lambda msg: received.append(int(msg.data)),
            QoSProfile(depth=1000),
        )
        executor = SingleThreadedExecutor()
        executor.add_node(listener)
        process = start_counter(tmp_path, world_env)
        try:
            wait_for_line(process, 'counting')
            deadline = time.monotonic() + 30
            while len(received) < 20 and time.monotonic() < deadline:
                executor.spin_once(timeout_sec=0.1)
            assert received, 'no sample from the counter node'
            for index, signum in enumerate(signals):
                if index:
                    time.sleep(0.02)  # the second one lands while the first's shutdown runs
                if process.poll() is None:
                    process.send_signal(signum)
            stdout, stderr = process.communicate(timeout=20)
        finally:
            if process.poll() is None:
                process.kill()
                process.wait()
        assert process.returncode == 0, stderr
        assert 'Traceback' not in stderr
        last = int(stdout.split('last ')[-1])
        deadline = time.monotonic() + 10
        while received[-1] < last and time.monotonic() < deadline:
            executor.spin_once(timeout_sec=0.1)
        assert received[-1] == last
        assert received == list(range(received[0], last + 1))
    finally:
        transport.shutdown()


def counter_refusal(tmp_path: Path, env: dict[str, str], period: str) -> list[str]:
    """Start the counter with ``-p period:=<period>``; it must exit 1: its stderr lines."""
    process = start_counter(tmp_path, env, '--ros-args', '-p', f'period:={period}')
    _, stderr = process.communicate(timeout=60)
    assert process.returncode == 1
    return stderr.strip().splitlines()


def test_config_error_from_the_node_exits_1_on_one_line(
    world_env: dict[str, str], tmp_path: Path
) -> None:
    """A NodeConfigError raised by the constructor prints one line and exits 1."""
    assert counter_refusal(tmp_path, world_env, '-1.0') == [
        'counter.py: error: period must be positive, got -1.0'
    ]


def test_parameter_type_error_exits_1_with_rclpys_text(
    world_env: dict[str, str], tmp_path: Path
) -> None:
    """An override of the wrong type (int for a double) is a config error, not a traceback."""
    assert counter_refusal(tmp_path, world_env, '1') == [
        "counter.py: error: Trying to set parameter 'period' to '1' of type 'INTEGER', "
        "expecting type 'DOUBLE': period"
    ]


@pytest.fixture
def tool_stop_request() -> Iterator[transport.StopRequest]:
    """
    A tool's :class:`StopRequest`, for the test to install; the old handlers restored after.

    Installed by the test itself: pytest puts its own ``sys.unraisablehook`` in place for each
    phase of a test, so one installed while fixtures are set up would not be the one called.
    """
    handlers = {signum: signal.getsignal(signum) for signum in (signal.SIGINT, signal.SIGTERM)}
    stop = transport.StopRequest(interrupt=True)
    try:
        yield stop
    finally:
        stop.restore()
        for signum, handler in handlers.items():
            signal.signal(signum, handler)


def test_only_a_stop_or_an_external_shutdown_explains_an_error(
    tool_stop_request: transport.StopRequest,
) -> None:
    """What running code raises is the stop's doing once a stop was asked for, else a fault."""
    external = ExternalShutdownException()
    assert tool_stop_request.explains(external)  # the context was shut down elsewhere
    assert not tool_stop_request.explains(RuntimeError('a bug'))
    tool_stop_request.install()
    with pytest.raises(KeyboardInterrupt):
        signal.raise_signal(signal.SIGINT)
    assert tool_stop_request.explains(RuntimeError('rclpy: the context is not valid'))
    assert tool_stop_request.explains(external)


def test_an_interrupt_lost_in_a_callback_is_raised_again(
    tool_stop_request: transport.StopRequest, capsys: pytest.CaptureFixture[str]
) -> None:
    """A Ctrl-C whose KeyboardInterrupt lands in a weakref callback still stops the tool."""
    tool_stop_request.install()

    class Thing:
        pass

    def callback(_ref: object) -> None:
        signal.raise_signal(signal.SIGINT)  # the handler runs here, inside the callback

    def drop_and_wait() -> None:
        thing = Thing()  # made here: on 3.10 a caller's argument outlives the callee's del
        ref = weakref.ref(thing, callback)
        del thing  # the callback runs: Python cannot raise out of it
        idle_for(1.0)  # the interrupt raised again lands here
        del ref

    with pytest.raises(KeyboardInterrupt):
        drop_and_wait()
    assert tool_stop_request.event.is_set()
    assert 'Exception ignored' not in capsys.readouterr().err


def test_an_rclpy_object_half_built_by_the_interrupt_is_not_reported(
    tool_stop_request: transport.StopRequest, monkeypatch: pytest.MonkeyPatch
) -> None:
    """
    rclpy's executor builds a Task when the Ctrl-C lands: its __del__ failing is not printed.

    rclpy's ``Future.__del__`` reads ``self._exception``, which a constructor cut short by the
    KeyboardInterrupt never set (seen at a launch's SIGINT). Other failures still reach the
    previous hook: the same failure before any stop, and any other module's finaliser.
    """
    reported: list[str] = []
    monkeypatch.setattr(sys, 'unraisablehook', lambda args: reported.append(repr(args.object)))
    tool_stop_request.install()
    classes: dict[str, object] = {}
    for module in ('rclpy.task', 'elsewhere'):
        namespace: dict[str, object] = {'__name__': module}
        exec(
            'import signal\n'
            'class Future:\n'
            '    def __init__(self, interrupt):\n'
            '        if interrupt:\n'
            '            signal.raise_signal(signal.SIGINT)\n'
            '        self._exception = None\n'
            '    def __del__(self):\n'
            '        if self._exception is not None:\n'
            '            print(self._exception)\n',
            namespace,
        )
        classes[module] = namespace['Future']
    rclpy_future, other_future = classes['rclpy.task'], classes['elsewhere']
    assert isinstance(rclpy_future, type)
    assert isinstance(other_future, type)
    del_before_stop: object = object.__new__(rclpy_future)
    del del_before_stop  # no stop requested: reported
    assert len(reported) == 1
    with pytest.raises(KeyboardInterrupt):
        rclpy_future(True)  # the interrupt cuts the constructor short; its __del__ fails
    assert tool_stop_request.event.is_set()
    assert len(reported) == 1  # not reported
    del_elsewhere: object = object.__new__(other_future)
    del del_elsewhere  # not rclpy's: reported
    assert len(reported) == 2


def idle_for(seconds: float) -> None:
    """Run Python code (where a pending signal handler can run) for ``seconds``."""
    started = time.monotonic()
    while time.monotonic() - started < seconds:
        time.sleep(0.001)


SPIN_NODE = """
import tf_demo.transport as rclpy

rclpy.init()
node = rclpy.create_node('spinner')
try:  # the signal may come as soon as the line is out: inside the try
    print('spinning', flush=True)
    rclpy.spin(node)
except KeyboardInterrupt:  # the standalone world's SIGINT handler
    print('interrupted', flush=True)
except Exception as error:  # rclpy's: it shuts the context down under spin
    print('stopped by shutdown:', type(error).__name__, flush=True)
"""


def test_kill_int_stops_a_node_started_with_sigint_ignored(world_env: dict[str, str]) -> None:
    """``node &`` from a script inherits SIGINT ignored; ``init`` takes it back, as rclpy does."""
    process = subprocess.Popen(
        [sys.executable, '-c', SPIN_NODE],
        env=world_env,
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
        preexec_fn=lambda: signal.signal(signal.SIGINT, signal.SIG_IGN),  # noqa: PLW1509
    )
    try:
        assert process.stdout is not None
        assert process.stdout.readline().strip() == 'spinning'
        process.send_signal(signal.SIGINT)
        stdout, stderr = process.communicate(timeout=30)
    finally:
        process.kill()
        process.wait()
    # It stopped (communicate did not time out): standalone by KeyboardInterrupt, under rclpy
    # by the shutdown its handler makes (ExternalShutdownException, or RCLError in a race).
    assert 'interrupted' in stdout or 'stopped by shutdown' in stdout, (stdout, stderr)
