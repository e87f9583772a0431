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
``view_frames [-t SECONDS] [-o NAME] [--snapshot FILE]``: draw the tf tree as .gv and .pdf files.

As tf2_tools' view_frames (Jazzy): listens for ``--wait-time`` seconds (default 5), takes tf2's
``all_frames_as_yaml`` dump, writes ``frames_<%Y-%m-%d_%H.%M.%S>.gv`` (or ``NAME.gv``) with the
same DOT content and renders ``.pdf`` with graphviz ``dot``. Unlike upstream it also draws several
trees, loops and an empty buffer instead of crashing, and ``--snapshot FILE`` draws a file written
by ``tf_saver`` without listening.
"""

from __future__ import annotations

import argparse
from collections.abc import Mapping
import shutil
import subprocess
import sys
import time
from typing import Protocol

from tf_demo.cli._args import wait_time_error
from tf_demo.cli._live import add_namespace_option
from tf_demo.cli._live import finish_after_damage
from tf_demo.cli._live import listen
from tf_demo.cli._live import TfRecorder
from tf_demo.cli._live import tool_main
from tf_demo.cli._live import ToolError
from tf_demo.cli._observations import buffer_from_observations
from tf_demo.cli._observations import observations_from_bag
from tf_demo.cli._snapshot import frames_yaml_data
from tf_demo.cli._snapshot import Snapshot
from tf_demo.cli.formatting import generate_dot
from tf_demo.core.files import OutputFileError
from tf_demo.core.files import write_text_atomically
import yaml

TOOL = 'view_frames'


def build_parser() -> argparse.ArgumentParser:
    """Return view_frames' argument parser (upstream's options plus ``--snapshot``)."""
    parser = argparse.ArgumentParser(
        prog=TOOL, description='Create a diagram of the TF frames being broadcast over ROS'
    )
    parser.add_argument(
        '--wait-time',
        '-t',
        type=float,
        default=5.0,
        help='Listen to the /tf topic for this many seconds before rendering the frame tree',
    )
    parser.add_argument('-o', '--output', help='Output filename')
    parser.add_argument('--tf_topic', help='Topic for dynamic transforms', default='/tf')
    parser.add_argument(
        '--tf_static_topic', help='Topic for static transforms', default='/tf_static'
    )
    parser.add_argument(
        '--snapshot', metavar='FILE', help='Draw a tf_saver snapshot file instead of listening'
    )
    parser.add_argument(
        '--bag', metavar='PATH', help='Draw the tree of a rosbag2 recording instead of listening'
    )
    add_namespace_option(parser)
    return parser


def output_names(output: str | None) -> tuple[str, str]:
    """Return the (.gv, .pdf) file names: ``NAME.*`` or ``frames_<local date>.*``."""
    if output is not None:
        return f'{output}.gv', f'{output}.pdf'
    stamp = time.strftime('%Y-%m-%d_%H.%M.%S')
    return f'frames_{stamp}.gv', f'frames_{stamp}.pdf'


class InfoLogger(Protocol):
    """What :func:`write_graph` logs with: a node's logger, or :class:`_StderrLogger`."""

    def info(self, text: str, /) -> object:
        """Log ``text`` at INFO."""


def write_graph(
    logger: InfoLogger,
    data: Mapping[str, Mapping[str, object]] | None,
    recorded_time: tuple[int, int],
    output: str | None,
) -> int:
    """Write the .gv file and render the .pdf with ``dot``; return the exit code."""
    frames_gv, frames_pdf = output_names(output)
    logger.info(f'Exporting graph in {frames_pdf} file...')
    try:
        write_text_atomically(frames_gv, generate_dot(data, recorded_time))
    except OutputFileError as error:
        raise ToolError(str(error)) from None
    dot = shutil.which('dot')
    if dot is None:
        msg = f"graphviz 'dot' is not installed; the graph is in {frames_gv}"
        raise ToolError(msg)
    completed = subprocess.run(
        [dot, '-Tpdf', frames_gv, '-o', frames_pdf],
        check=False,
        capture_output=True,
        text=True,
    )
    if completed.returncode != 0:
        msg = f'dot failed on {frames_gv}: {completed.stderr.strip()}'
        raise ToolError(msg)
    return 0


def _listen_and_draw(options: argparse.Namespace) -> int:
    from tf_demo import transport

    node = transport.create_node(TOOL)
    try:
        recorder = TfRecorder(
            node, tf_topic=options.tf_topic, tf_static_topic=options.tf_static_topic
        )
        logger = node.get_logger()
        logger.info(f'Listening to tf data for {options.wait_time} seconds...')
        listen(node, options.wait_time)
        logger.info('Generating graph...')
        frame_yaml = buffer_from_observations(recorder.observations()).all_frames_as_yaml()
        logger.info(f'Result:tf2_msgs.srv.FrameGraph_Response(frame_yaml={frame_yaml!r})')
        data = yaml.safe_load(frame_yaml)
        now = node.get_clock().now().nanoseconds
        return write_graph(logger, data, divmod(now, 1_000_000_000), options.output)
    finally:
        node.destroy_node()


class _StderrLogger:
    """The few logger methods the snapshot mode needs, printed like rclpy's INFO lines."""

    def info(self, text: str) -> None:
        from tf_demo.transport.logging import format_log_line
        from tf_demo.transport.logging import LoggingSeverity

        line = format_log_line(LoggingSeverity.INFO, TOOL, text, time.time_ns())
        print(line, file=sys.stderr, flush=True)


def options_error(options: argparse.Namespace) -> str | None:
    """Return why parsed ``options`` cannot run, else None."""
    return wait_time_error(options.wait_time)


def _draw_snapshot(options: argparse.Namespace, snapshot: Snapshot) -> int:
    """Draw the ``--snapshot`` file instead of listening (stamped when it was recorded)."""
    stamp = snapshot.recorded_at_ns or time.time_ns()
    return write_graph(
        _StderrLogger(), frames_yaml_data(snapshot), divmod(stamp, 1_000_000_000), options.output
    )


def _draw_bag(options: argparse.Namespace) -> int:
    """Draw the ``--bag`` recording's tree as it stands at the bag's end (rates from the bag)."""
    bag = observations_from_bag(options.bag, options.tf_topic, options.tf_static_topic)
    cache_ns = bag.end_ns - bag.start_ns + 10**10
    core = buffer_from_observations(bag.observations, cache_time_ns=cache_ns)
    data = yaml.safe_load(core.all_frames_as_yaml(bag.end_ns))
    code = write_graph(_StderrLogger(), data, divmod(bag.end_ns, 1_000_000_000), options.output)
    return finish_after_damage(TOOL, code, bag.damage)


def main(args: list[str] | None = None) -> int:
    """Run view_frames with ``args`` (default: ``sys.argv[1:]``)."""
    return tool_main(
        TOOL,
        args,
        build_parser(),
        options_error,
        _listen_and_draw,
        from_snapshot=_draw_snapshot,
        from_bag=_draw_bag,
    )


if __name__ == '__main__':
    sys.exit(main())
