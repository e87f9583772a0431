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
``tf_demo_live``: the README's demo in one command, without ROS.

Starts ``static_tf_pub``, ``dynamic_tf_pub``, ``tf_listener`` and ``tf_echo <target> <source>``
as child processes on the same DDS domain and shows their output, each line prefixed with the
child's name; listens to TF itself and prints the live transform target <- source (default
odom <- camera_link); stops everything cleanly after ``--duration`` seconds or on Ctrl-C.

With ``--robot`` the children are the REP-105 mobile robot instead: ``robot_state_publisher`` on
``urdf/mobile_robot.urdf.xacro``, ``joint_state_publisher`` (model from ``robot_description``),
``dynamic_tf_pub`` moving odom -> base_footprint, and ``tf_echo odom lidar_link``.

Where the ``view`` extra is installed it also starts ``tf_view`` (the live 3D view in the
browser, fixed frame ``--target``), whose line ``tf_view: serving on http://...`` gives the URL
(shown even with ``--quiet``); ``--no-view`` leaves it out, ``--view-port`` picks the port.

    tf_demo_live [--robot] [--duration S] [--rate HZ] [--target odom] [--source F] [--quiet]
                 [--no-echo] [--no-view] [--view-port PORT]
"""

from __future__ import annotations

import argparse
from collections.abc import Sequence
from dataclasses import dataclass
import importlib.util
import math
import os
from pathlib import Path
import signal
import subprocess
import sys
import threading
import time
from typing import IO
from typing import TYPE_CHECKING

from tf_demo.core.exceptions import TransformException
from tf_demo.core.extras import extra_hint
from tf_demo.core.python_child import python_child_command
from tf_demo.msgs.convert import transform_stamped_args
from tf_demo.msgs.convert import TransformStampedLike
from tf_demo.transport.ros_args import split_ros_args

if TYPE_CHECKING:
    from tf_demo.transport import StopRequest
    from tf_demo.transport.node import Node

DEMO_NODES = ('static_tf_pub', 'dynamic_tf_pub', 'tf_listener')
ROBOT_XACRO = 'mobile_robot.urdf.xacro'
DEFAULT_SOURCE = 'camera_link'
ROBOT_DEFAULT_SOURCE = 'lidar_link'
ECHO_TOOL = 'tf_echo'
VIEW_TOOL = 'tf_view'
CHILD_STOP_TIMEOUT_S = 5.0
SPIN_SLICE_S = 0.1


def parse_arguments(argv: Sequence[str]) -> argparse.Namespace:
    """Parse the tool's own arguments (``--ros-args`` sections are removed before)."""
    parser = argparse.ArgumentParser(
        prog='tf_demo_live',
        description='Run the tf_demo course demo (static, dynamic, listener) and print live '
        'transforms until Ctrl-C or --duration.',
    )
    parser.add_argument('--duration', type=_non_negative, default=None, help='seconds, then stop')
    parser.add_argument('--rate', type=_rate, default=2.0, help='print rate in Hz (2)')
    parser.add_argument('--target', default='odom', help='target frame (odom)')
    parser.add_argument(
        '--source',
        default=None,
        help=f'source frame ({DEFAULT_SOURCE}; {ROBOT_DEFAULT_SOURCE} with --robot)',
    )
    parser.add_argument(
        '--robot',
        action='store_true',
        help='run the REP-105 mobile robot (robot_state_publisher, joint_state_publisher)',
    )
    parser.add_argument(
        '--quiet', action='store_true', help="hide the child processes' own output"
    )
    parser.add_argument('--no-echo', action='store_true', help='do not start tf_echo')
    parser.add_argument(
        '--no-view', action='store_true', help='do not start tf_view (the 3D view in the browser)'
    )
    parser.add_argument(
        '--view-port', type=_port, default=8080, help="tf_view's port (8080; taken: the next)"
    )
    options = parser.parse_args(list(argv))
    if options.source is None:
        options.source = ROBOT_DEFAULT_SOURCE if options.robot else DEFAULT_SOURCE
    return options


def _rate(text: str) -> float:
    from tf_demo.nodes.helpers import rate_error

    value = _number(text)
    problem = rate_error(value)
    if problem is not None:
        msg = f'{problem}, got {text}'
        raise argparse.ArgumentTypeError(msg)
    return value


def _port(text: str) -> int:
    value = int(text) if text.strip().isdigit() else -1
    if not 0 <= value <= 65535:
        msg = f'not a port number (0..65535): {text!r}'
        raise argparse.ArgumentTypeError(msg)
    return value


def _non_negative(text: str) -> float:
    value = _number(text)
    if value < 0.0:
        msg = f'must be >= 0, got {text}'
        raise argparse.ArgumentTypeError(msg)
    return value


def _number(text: str) -> float:
    try:
        value = float(text)
    except ValueError:
        msg = f'not a number: {text!r}'
        raise argparse.ArgumentTypeError(msg) from None
    if not math.isfinite(value):
        msg = f'must be finite, got {text}'
        raise argparse.ArgumentTypeError(msg)
    return value


def format_live_transform(target: str, source: str, transform: TransformStampedLike) -> str:
    """One printed line: stamp, translation and rotation (x, y, z, w) of source in target."""
    _, _, stamp_ns, (x, y, z), (qx, qy, qz, qw) = transform_stamped_args(transform)
    return (
        f'{target} <- {source} @ {stamp_ns / 1e9:.3f}: '
        f'translation [{x:+.3f}, {y:+.3f}, {z:+.3f}] '
        f'rotation (xyzw) [{qx:+.3f}, {qy:+.3f}, {qz:+.3f}, {qw:+.3f}]'
    )


def format_waiting(target: str, source: str, reason: object) -> str:
    """Return the line printed while the transform is not available yet."""
    return f'{target} <- {source}: waiting ({reason})'


@dataclass
class Child:
    """A started child process and the thread that relays its output."""

    name: str
    process: subprocess.Popen[str]
    relay: threading.Thread | None


def child_command(module: str, *args: str) -> list[str]:
    """Command line running ``module``'s ``main()`` with this interpreter."""
    code = f'import sys; from {module} import main; sys.exit(main())'
    return python_child_command(code, *args)


def prefixed(name: str, line: str) -> str:
    """Return a child's output line as shown by the demo: ``[name] line``."""
    return f'[{name}] {line.rstrip()}'


def _relay(name: str, stream: IO[str]) -> None:
    for line in stream:
        print(prefixed(name, line), flush=True)


def start_child(name: str, command: list[str], quiet: bool) -> Child:
    """Start one child; unless ``quiet``, relay its stdout and stderr with a name prefix."""
    process = subprocess.Popen(
        command,
        stdin=subprocess.DEVNULL,
        stdout=subprocess.DEVNULL if quiet else subprocess.PIPE,
        stderr=subprocess.DEVNULL if quiet else subprocess.STDOUT,
        text=True,
        start_new_session=True,  # Ctrl-C reaches only the demo, which stops children in order
    )
    relay = None
    if process.stdout is not None:
        relay = threading.Thread(target=_relay, args=(name, process.stdout), daemon=True)
        relay.start()
    return Child(name, process, relay)


def robot_xacro_path() -> Path:
    """Return ``mobile_robot.urdf.xacro``: the source tree's, else the installed share's."""
    source = Path(__file__).resolve().parents[2] / 'urdf' / ROBOT_XACRO
    if source.is_file():
        return source
    from tf_demo.urdf.loading import find_package_share

    return find_package_share('tf_demo') / 'urdf' / ROBOT_XACRO


def demo_nodes(robot: bool) -> list[tuple[str, list[str]]]:
    """Return the node executables to start and their arguments (course demo or ``--robot``)."""
    if not robot:
        return [(name, []) for name in DEMO_NODES]
    odometry = ['--ros-args', '-p', 'parent_frame:=odom', '-p', 'child_frame:=base_footprint']
    return [
        ('robot_state_publisher', ['--ros-args', '-p', f'urdf_file:={robot_xacro_path()}']),
        ('joint_state_publisher', []),
        ('dynamic_tf_pub', odometry),
    ]


def start_children(options: argparse.Namespace, children: list[Child]) -> None:
    """
    Start the demo nodes, tf_echo and tf_view (same environment, so the same ROS_DOMAIN_ID).

    Each child is appended to ``children`` as soon as it runs, so a Ctrl-C in the middle still
    leaves every started child to :func:`stop_children`.
    """
    for name, args in demo_nodes(options.robot):
        command = child_command(f'tf_demo.nodes.{name}', *args)
        children.append(start_child(name, command, options.quiet))
    if not options.no_echo:
        command = child_command(f'tf_demo.cli.{ECHO_TOOL}', options.target, options.source)
        children.append(start_child(ECHO_TOOL, command, options.quiet))
    if not options.no_view:
        if importlib.util.find_spec('viser') is None:
            print(
                "tf_demo_live: tf_view not started: install the 'view' extra "
                f'({extra_hint("view")}) for the 3D view in the browser',
                flush=True,
            )
            return
        view_args = ('--fixed-frame', options.target, '--port', str(options.view_port))
        command = child_command(f'tf_demo.cli.{VIEW_TOOL}', *view_args)
        children.append(start_child(VIEW_TOOL, command, quiet=False))  # its line is the URL


def stop_children(children: list[Child]) -> list[int]:
    """SIGINT every child, wait up to 5 s each, kill the stragglers; return exit codes."""
    for child in children:
        if child.process.poll() is None:
            child.process.send_signal(signal.SIGINT)
    codes = []
    for child in children:
        try:
            codes.append(child.process.wait(timeout=CHILD_STOP_TIMEOUT_S))
        except subprocess.TimeoutExpired:
            child.process.kill()
            codes.append(child.process.wait())
        if child.relay is not None:
            child.relay.join(timeout=CHILD_STOP_TIMEOUT_S)
    return codes


def _dead_child(children: list[Child]) -> str | None:
    for child in children:
        code = child.process.poll()
        if code is not None:
            return f'{child.name} exited with code {code}'
    return None


def run(options: argparse.Namespace, ros_args: list[str]) -> int:
    """Start the children, print transforms until the deadline or Ctrl-C, stop everything."""
    from tf_demo import transport

    # Ctrl-C or SIGTERM interrupts the loop below; a second one is ignored while the children
    # are stopped (they run in their own sessions: an interrupted clean-up would orphan them).
    stop = transport.StopRequest(interrupt=True)
    stop.install()
    try:
        return _run_installed(options, ros_args, stop)
    except KeyboardInterrupt:
        return 0
    finally:
        stop.restore()


def _run_installed(options: argparse.Namespace, ros_args: list[str], stop: StopRequest) -> int:
    """:func:`run` with its signal handlers in place."""
    from tf_demo import transport
    from tf_demo.ros.buffer import Buffer
    from tf_demo.ros.transform_listener import TransformListener
    from tf_demo.transport.clock import Time
    from tf_demo.transport.executors import SingleThreadedExecutor

    children: list[Child] = []
    failure: str | None = None
    node: Node | None = None
    try:
        start_children(options, children)
        transport.init(args=['tf_demo_live', *ros_args])
        node = transport.create_node('tf_demo_live')
        tf_buffer = Buffer(node=node)
        listener = TransformListener(tf_buffer, node)

        def print_once() -> None:
            try:
                transform = tf_buffer.lookup_transform(options.target, options.source, Time())
            except TransformException as error:
                print(format_waiting(options.target, options.source, error), flush=True)
                return
            print(format_live_transform(options.target, options.source, transform), flush=True)

        node.create_timer(1.0 / options.rate, print_once)
        executor = SingleThreadedExecutor()
        executor.add_node(node)
        deadline = None if options.duration is None else time.monotonic() + options.duration
        while transport.ok() and (deadline is None or time.monotonic() < deadline):
            executor.spin_once(timeout_sec=SPIN_SLICE_S)
            failure = _dead_child(children)
            if failure is not None:
                break
        listener.unregister()
    except KeyboardInterrupt:
        pass
    except Exception as error:
        if not stop.explains(error):
            raise
    finally:
        stop_children(children)
        if node is not None:
            node.destroy_node()
        transport.try_shutdown()
    if failure is not None:
        print(f'tf_demo_live: {failure}', file=sys.stderr)
        return 1
    return 0


def main(args: list[str] | None = None) -> int:
    """Entry point: ``tf_demo_live [--robot] [--duration S] [--rate HZ] [--target/--source F]``."""
    argv = list(sys.argv[1:] if args is None else args)
    tool_args, ros_args = split_ros_args(argv)
    options = parse_arguments(tool_args)
    os.environ.setdefault('PYTHONUNBUFFERED', '1')
    try:
        return run(options, ros_args)
    except KeyboardInterrupt:
        return 0


if __name__ == '__main__':
    sys.exit(main())
