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
``tf_plot TARGET SOURCE (--bag PATH | --duration S) -o FILE``: plot a transform over time.

Looks ``TARGET_T_SOURCE`` up (tf2's ``lookup_transform(TARGET, SOURCE, t)``) at evenly spaced
times of a rosbag2 recording, or of what was heard on ``/tf`` and ``/tf_static`` for
``--duration`` seconds (Ctrl-C ends the listening early), and draws x, y, z and roll, pitch, yaw
over time and the path in the x-y plane. Where the lookup failed (no data yet, a gap at the end,
another tree) the time is shaded and labelled with tf2's error. PNG or SVG by the file name.
Needs the ``bag`` extra (rosbags, matplotlib). ``--ros-args`` is accepted.
"""

from __future__ import annotations

import argparse
import io
import math
from pathlib import Path
import sys
from typing import Any

from tf_demo.cli._live import add_namespace_option
from tf_demo.cli._live import finish_after_damage
from tf_demo.cli._live import listen
from tf_demo.cli._live import TfRecorder
from tf_demo.cli._live import tool_main
from tf_demo.cli._live import ToolError
from tf_demo.cli._observations import buffer_from_observations
from tf_demo.cli._plot_model import live_span
from tf_demo.cli._plot_model import old_stamps_hint
from tf_demo.cli._plot_model import sample_times
from tf_demo.cli._plot_model import sample_track
from tf_demo.cli._plot_model import Track
from tf_demo.core.buffer_core import BufferCore
from tf_demo.core.extras import extra_hint
from tf_demo.core.files import output_path_error
from tf_demo.core.files import OutputFileError
from tf_demo.core.files import write_bytes_atomically

TOOL = 'tf_plot'
FORMATS = ('.png', '.svg')
#: A live recording keeps this much more than its duration in the buffer.
_CACHE_MARGIN_NS = 10_000_000_000
#: Colours of the shaded failure spans, one per distinct error (cycled).
_SPAN_COLOURS = ('#d62728', '#7f7f7f', '#9467bd', '#8c564b', '#e377c2')
_AXIS_COLOURS = ('#1f77b4', '#2ca02c', '#ff7f0e')  # x/roll, y/pitch, z/yaw


def build_parser() -> argparse.ArgumentParser:
    """Return tf_plot's command line."""
    parser = argparse.ArgumentParser(prog=TOOL, description=__doc__.strip().splitlines()[0])
    parser.add_argument('target_frame', help='the frame the pose is expressed in (e.g. map)')
    parser.add_argument('source_frame', help='the frame whose pose is plotted (e.g. base_link)')
    parser.add_argument('-o', '--output', required=True, help='the plot file (.png or .svg)')
    parser.add_argument('--bag', metavar='PATH', help='plot a rosbag2 recording')
    parser.add_argument(
        '--duration', type=float, metavar='S', help='listen this many seconds, then plot'
    )
    parser.add_argument(
        '--rate', type=float, metavar='HZ', help='samples per second (default 50, long bags less)'
    )
    parser.add_argument('--tf-topic', default='/tf', help='topic of dynamic transforms')
    parser.add_argument('--tf-static-topic', default='/tf_static', help='topic of static ones')
    add_namespace_option(parser)
    return parser


def options_error(options: argparse.Namespace) -> str | None:
    """Return what is wrong with the options, or None."""
    if (options.bag is None) == (options.duration is None):
        return 'give either --bag PATH or --duration S'
    if options.duration is not None and not (
        math.isfinite(options.duration) and options.duration > 0
    ):
        return f'--duration must be a positive number of seconds, not {options.duration}'
    if options.rate is not None and not (math.isfinite(options.rate) and options.rate > 0):
        return f'--rate must be a positive number of samples per second, not {options.rate}'
    if Path(options.output).suffix.lower() not in FORMATS:
        return f'{options.output}: the plot file must end in .png or .svg'
    return output_path_error(options.output)


def _track(core: BufferCore, options: argparse.Namespace, start_ns: int, end_ns: int) -> Track:
    try:
        times = sample_times(start_ns, end_ns, options.rate)
    except ValueError as error:
        raise ToolError(str(error)) from None
    return sample_track(core, options.target_frame, options.source_frame, times)


def _plot_bag(options: argparse.Namespace) -> int:
    from tf_demo.bag import load_bag

    _require_matplotlib()
    loaded = load_bag(options.bag, None, options.tf_topic, options.tf_static_topic)
    track = _track(loaded.core, options, loaded.start_ns, loaded.end_ns)
    code = _write_plot(track, options.output, f'bag {Path(options.bag).name}')
    return finish_after_damage(TOOL, code, loaded.damage)


def _plot_live(options: argparse.Namespace) -> int:
    from tf_demo import transport

    _require_matplotlib()
    node = transport.create_node(TOOL)
    try:
        recorder = TfRecorder(
            node, tf_topic=options.tf_topic, tf_static_topic=options.tf_static_topic
        )
        clock = node.get_clock()
        start_ns = clock.now().nanoseconds
        node.get_logger().info(f'Listening to tf data for {options.duration:g} seconds...')
        try:
            listen(node, options.duration)
        except KeyboardInterrupt:
            node.get_logger().info('Stopped: plotting what was heard')
        end_ns = clock.now().nanoseconds
        observations = recorder.observations()
    finally:
        node.destroy_node()
    start_ns, end_ns = live_span(start_ns, end_ns, [o.receive_ns for o in observations])
    cache_ns = end_ns - start_ns + _CACHE_MARGIN_NS
    core = buffer_from_observations(observations, cache_time_ns=cache_ns)
    track = _track(core, options, start_ns, end_ns)
    code = _write_plot(track, options.output, f'live, {len(observations)} messages')
    if (hint := old_stamps_hint(track)) is not None:
        print(f'{TOOL}: hint: {hint}', flush=True)
    return code


def _require_matplotlib() -> None:
    try:
        import matplotlib  # noqa: F401 (only whether it is there)
    except ImportError as error:
        msg = f"plotting needs matplotlib, of the 'bag' extra ({extra_hint('bag')}): {error}"
        raise ToolError(msg) from None


def _write_plot(track: Track, output: str, origin: str) -> int:
    """Render ``track`` into ``output`` and say what is in it."""
    data = render(track, origin, Path(output).suffix.lower().lstrip('.'))
    try:
        write_bytes_atomically(output, data)
    except OutputFileError as error:
        raise ToolError(str(error)) from None
    failed = int((~track.succeeded).sum())
    print(
        f'{TOOL}: wrote {output}: {len(track.times_ns)} samples of {track.target} -> '
        f'{track.source}, {failed} failed in {len(track.failures)} span(s)',
        flush=True,
    )
    for span in track.failures:
        start, end = ((t - track.start_ns) / 1e9 for t in (span.start_ns, span.end_ns))
        print(f'  {start:.3f} s to {end:.3f} s: {span.kind}: {span.error}', flush=True)
    return 0


def render(track: Track, origin: str, file_format: str) -> bytes:
    """Draw ``track`` (see the module docstring) as ``file_format`` (``png`` or ``svg``)."""
    import matplotlib

    matplotlib.use('Agg')
    from matplotlib.figure import Figure

    figure = Figure(figsize=(13, 7.5), layout='constrained')
    grid = figure.add_gridspec(2, 2, width_ratios=(1.7, 1))
    position = figure.add_subplot(grid[0, 0])
    rotation = figure.add_subplot(grid[1, 0], sharex=position)
    path = figure.add_subplot(grid[:, 1])
    seconds = track.seconds
    for axis, values, names, unit in (
        (position, track.translations, ('x', 'y', 'z'), 'm'),
        (rotation, track.rpy, ('roll', 'pitch', 'yaw'), 'rad'),
    ):
        for column, (name, colour) in enumerate(zip(names, _AXIS_COLOURS, strict=True)):
            axis.plot(seconds, values[:, column], color=colour, label=name, linewidth=1.3)
        axis.set_ylabel(unit)
        axis.grid(visible=True, alpha=0.3)
    _shade_failures(track, (position, rotation))
    position.legend(loc='upper left', fontsize=8)
    rotation.legend(loc='upper left', fontsize=8)
    rotation.set_xlabel('time since the start [s]')
    position.set_title(f'{track.source} in {track.target}: position', fontsize=10)
    rotation.set_title('orientation (as tf2_echo: roll, pitch, yaw)', fontsize=10)
    _draw_path(path, track)
    figure.suptitle(
        f'tf_plot {track.target} {track.source} — {origin}, {1e9 / track.step_ns:g} samples/s',
        fontsize=11,
    )
    buffer = io.BytesIO()
    with matplotlib.rc_context({'svg.fonttype': 'none', 'svg.hashsalt': 'tf_plot'}):
        figure.savefig(buffer, format=file_format, dpi=100)
    return buffer.getvalue()


def _shade_failures(track: Track, axes: tuple[Any, Any]) -> None:
    """Shade each failure span in both time plots, name its error; a legend gives tf2's text."""
    from matplotlib.patches import Patch

    colours: dict[str, str] = {}
    for span in track.failures:
        colour = colours.setdefault(span.label, _SPAN_COLOURS[len(colours) % len(_SPAN_COLOURS)])
        start = (span.start_ns - track.start_ns) / 1e9
        end = (span.end_ns - track.start_ns) / 1e9
        end = max(end, start + track.step_ns / 1e9)  # one failed sample still shows
        for axis in axes:
            axis.axvspan(start, end, color=colour, alpha=0.18, linewidth=0)
        axes[0].text(
            start, 0.98, f' {span.kind}', transform=axes[0].get_xaxis_transform(),
            va='top', ha='left', fontsize=7, color=colour, clip_on=True,
        )  # fmt: skip
    if colours:
        handles = [
            Patch(color=colour, alpha=0.3, label=label) for label, colour in colours.items()
        ]
        axes[0].figure.legend(
            handles=handles, loc='outside lower center', fontsize=8, title='lookup failed (tf2)'
        )


def _draw_path(axis: Any, track: Track) -> None:
    """Draw the path of the source frame's origin in the target's x-y plane."""
    ok = track.succeeded
    x, y = track.translations[:, 0], track.translations[:, 1]
    axis.plot(x, y, color=_AXIS_COLOURS[0], linewidth=1.3)
    if ok.any():
        first, last = int(ok.argmax()), int(len(ok) - 1 - ok[::-1].argmax())
        axis.plot(x[first], y[first], 'o', color='#2ca02c', label='first pose')
        axis.plot(x[last], y[last], 's', color='#d62728', label='last pose')
        axis.legend(loc='upper right', fontsize=8)
    else:
        axis.text(0.5, 0.5, 'no successful lookup', ha='center', transform=axis.transAxes)
    axis.set_aspect('equal', adjustable='datalim')
    axis.set_xlabel(f'x in {track.target} [m]')
    axis.set_ylabel(f'y in {track.target} [m]')
    axis.set_title('path in the x-y plane', fontsize=10)
    axis.grid(visible=True, alpha=0.3)


def main(args: list[str] | None = None) -> int:
    """Run tf_plot with ``args`` (default: ``sys.argv[1:]``)."""
    return tool_main(TOOL, args, build_parser(), options_error, _plot_live, from_bag=_plot_bag)


if __name__ == '__main__':
    sys.exit(main())
