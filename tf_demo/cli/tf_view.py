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
``tf_view``: a live 3D view of the TF tree in the browser (viser), rviz2's TF display without rviz.

Every frame of the buffer is drawn as an axes triad with its name and a line to its parent,
relative to a fixed frame chosen in the page (``--fixed-frame``, else the root of the largest
tree), updated at ``--rate`` Hz. Static frames have a blue origin, dynamic ones yellow, stale
ones (no data for ``--stale-after`` seconds) grey with "(stale)" after the name; a split tree
is shown with a warning. The side panel holds the frame hierarchy with rates and ages, and the
selected frame's transform in tf_echo's numbers. Needs the ``view`` extra
(``pip install 'tf_demo[view]'``). ``--ros-args`` is accepted.
"""

from __future__ import annotations

import argparse
import contextlib
import io
import math
import sys
import time
from typing import Any
from typing import TYPE_CHECKING

from tf_demo.cli._live import tool_main
from tf_demo.cli._live import ToolError
from tf_demo.cli._view_model import build_scene
from tf_demo.cli._view_model import DEFAULT_STALE_AFTER_S
from tf_demo.cli._view_model import echo_markdown
from tf_demo.cli._view_model import FrameView
from tf_demo.cli._view_model import SceneView
from tf_demo.cli._view_model import tree_markdown
from tf_demo.core.lazy_import import lazy_module

if TYPE_CHECKING:
    import numpy as np
    from tf_demo.core.buffer_core import BufferCore
else:
    np = lazy_module('numpy')

TOOL = 'tf_view'
#: The view's colours (RGB): origin spheres by kind, the parent lines.
STATIC_COLOR = (40, 110, 230)
DYNAMIC_COLOR = (236, 200, 0)
STALE_COLOR = (150, 150, 150)
LINK_COLOR = (230, 120, 40)
AXES_LENGTH = 0.2
AUTO_FIXED_FRAME = '(root of the largest tree)'


def build_parser() -> argparse.ArgumentParser:
    """Return tf_view's command line."""
    parser = argparse.ArgumentParser(prog=TOOL, description=__doc__.strip().splitlines()[0])
    parser.add_argument('--fixed-frame', default=None, help='frame the view is drawn in')
    parser.add_argument('--host', default='127.0.0.1', help='address to serve on')
    parser.add_argument('--port', type=int, default=8080, help='port to serve on (0: any)')
    parser.add_argument('--rate', type=float, default=20.0, help='updates per second')
    parser.add_argument(
        '--stale-after',
        type=float,
        default=DEFAULT_STALE_AFTER_S,
        metavar='SECONDS',
        help='a dynamic frame without data for this long is shown as stale',
    )
    return parser


def options_error(options: argparse.Namespace) -> str | None:
    """Return what is wrong with the options, or None."""
    if not (math.isfinite(options.rate) and 0.0 < options.rate <= 1000.0):
        return f'--rate must be a number of updates per second in (0, 1000], got {options.rate}'
    if not (math.isfinite(options.stale_after) and options.stale_after > 0.0):
        return f'--stale-after must be a positive number of seconds, got {options.stale_after}'
    if not 0 <= options.port <= 65535:
        return f'--port must be in 0..65535, got {options.port}'
    return None


def _wxyz(rotation: tuple[float, float, float, float]) -> tuple[float, float, float, float]:
    x, y, z, w = rotation
    return (w, x, y, z)


class TfView:
    """The viser scene and panels, redrawn from a :class:`SceneView` on every update."""

    def __init__(self, server: Any, fixed_frame: str | None) -> None:
        self.server = server
        self.fixed_frame = fixed_frame
        self.selected: str | None = None
        self._frames: dict[str, tuple[Any, Any]] = {}
        self._created = 0
        self._links: Any = None
        # As rviz2 opens: a 1 m grid on the fixed frame's xy plane, seen from above and aside.
        server.scene.add_grid('/grid', width=10.0, height=10.0, cell_size=1.0, section_size=5.0)
        server.initial_camera.position = (3.0, -3.0, 2.5)
        server.initial_camera.look_at = (0.0, 0.0, 0.0)
        gui = server.gui
        self._fixed = gui.add_dropdown(
            'Fixed frame', (AUTO_FIXED_FRAME,), initial_value=AUTO_FIXED_FRAME
        )
        self._fixed.on_update(self._on_fixed)
        self._warning = gui.add_markdown('')
        with gui.add_folder('Frames'):
            self._tree = gui.add_markdown(tree_markdown(SceneView(None, (), (), ())))
        with gui.add_folder('Selected frame'):
            self._select = gui.add_dropdown('Frame', ('',), initial_value='')
            self._select.on_update(self._on_select)
            self._echo = gui.add_markdown('')
        if fixed_frame is not None:
            self._fixed.options = (AUTO_FIXED_FRAME, fixed_frame)
            self._fixed.value = fixed_frame

    def _on_fixed(self, _event: object) -> None:
        value = self._fixed.value
        self.fixed_frame = None if value == AUTO_FIXED_FRAME else value

    def _on_select(self, _event: object) -> None:
        self.selected = self._select.value or None

    def update(self, core: BufferCore, now_ns: int, stale_after_s: float) -> SceneView:
        """Draw the buffer's frames as they are at ``now_ns``."""
        scene = build_scene(core, self.fixed_frame, now_ns, stale_after_s)
        names = tuple(frame.name for frame in scene.frames)
        if tuple(self._select.options) != ('', *sorted(names)):
            self._select.options = ('', *sorted(names))
            fixed_options = (AUTO_FIXED_FRAME, *sorted(names))
            self._fixed.options = fixed_options
        for frame in scene.frames:
            self._draw_frame(frame)
        for gone in set(self._frames) - set(names):
            for handle in self._frames.pop(gone):
                handle.remove()
        self._draw_links(scene)
        self._warning.content = '\n\n'.join(f'**Warning:** {text}' for text in scene.warnings)
        self._tree.content = f'Fixed frame: `{scene.fixed_frame}`\n\n' + tree_markdown(scene)
        self._echo.content = echo_markdown(core, scene.fixed_frame, self.selected)
        return scene

    def _draw_frame(self, frame: FrameView) -> None:
        scene_api = self.server.scene
        if frame.name not in self._frames:
            key = f'/tf/f{self._created}'  # frame ids may hold '/', viser's path separator
            self._created += 1
            axes = scene_api.add_frame(key, axes_length=AXES_LENGTH, axes_radius=0.01)
            label = scene_api.add_label(f'{key}/label', frame.name)
            self._frames[frame.name] = (axes, label)
        axes, label = self._frames[frame.name]
        visible = frame.translation is not None and frame.rotation is not None
        axes.visible = visible
        if not visible:
            return
        axes.position = frame.translation
        axes.wxyz = _wxyz(frame.rotation)  # type: ignore[arg-type]
        color = STATIC_COLOR if frame.is_static else DYNAMIC_COLOR
        axes.origin_color = STALE_COLOR if frame.stale else color
        label.text = f'{frame.name} (stale)' if frame.stale else frame.name

    def _draw_links(self, scene: SceneView) -> None:
        where = {f.name: f.translation for f in scene.frames if f.translation is not None}
        segments = [
            (where[f.name], where[f.parent])
            for f in scene.frames
            if f.parent is not None and f.name in where and f.parent in where
        ]
        points = np.array(segments, dtype=np.float32).reshape(-1, 2, 3)
        if self._links is None:
            self._links = self.server.scene.add_line_segments(
                '/tf_links', points, LINK_COLOR, thickness=2.0, thickness_units='screen'
            )
        else:
            self._links.points = points


def _serve(options: argparse.Namespace) -> int:
    try:
        import viser
    except ImportError as error:
        raise ToolError(
            f"needs the 'view' extra (pip install 'tf_demo[view]'): {error}"
        ) from error
    from tf_demo import transport
    from tf_demo.ros import Buffer
    from tf_demo.ros import TransformListener

    node = transport.create_node(TOOL)
    buffer = Buffer(node=node)
    listener = TransformListener(buffer, node, spin_thread=True)
    try:
        with contextlib.redirect_stdout(io.StringIO()):  # viser's banner: our line says it
            server = viser.ViserServer(host=options.host, port=options.port, verbose=False)
    except OSError as error:
        listener.unregister()
        node.destroy_node()
        raise ToolError(f'cannot serve on {options.host}:{options.port}: {error}') from error
    view = TfView(server, options.fixed_frame)
    print(f'tf_view: serving on http://{options.host}:{server.get_port()}', flush=True)
    period = 1.0 / options.rate
    clock = node.get_clock()
    try:
        while transport.ok():
            view.update(buffer.core, clock.now().nanoseconds, options.stale_after)
            time.sleep(period)
    finally:
        with contextlib.redirect_stdout(io.StringIO()):
            server.stop()
        listener.unregister()
        node.destroy_node()
    return 0


def main(args: list[str] | None = None) -> int:
    """Run tf_view with ``args`` (default: ``sys.argv[1:]``)."""
    return tool_main(TOOL, args, build_parser(), options_error, _serve)


if __name__ == '__main__':
    sys.exit(main())
