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
tree), updated at ``--update-rate`` Hz. Static frames have a blue origin, dynamic ones
yellow, stale ones (no data for ``--stale-after`` seconds) grey with "(stale)" after the
name; a split tree is shown with a warning. The side panel holds the frame hierarchy with
rates and ages, and the selected frame's transform in tf_echo's numbers.

The robot model comes from ``--urdf FILE`` (URDF or xacro) or the latched ``robot_description``
topic: its visuals are drawn in their links where TF puts them (rviz2's RobotModel), and a
joint panel (joint_state_publisher_gui's) has a slider for every free joint within its limits,
mimic joints following, with centre and randomise buttons. With "Publish /joint_states" ticked
(``--publish-joint-states`` ticks it at start) the panel publishes ``/joint_states`` as
joint_state_publisher does: same QoS, at the node's ``rate`` parameter (Hz, default 10).
Needs the ``view`` extra (``pip install 'tf_demo[view]'``). ``--ros-args`` is accepted.
"""

from __future__ import annotations

import argparse
from collections.abc import Callable
import contextlib
import io
import math
import os
import random
import sys
import threading
from typing import Any
from typing import TYPE_CHECKING

from tf_demo.cli._live import add_namespace_option
from tf_demo.cli._live import tool_main
from tf_demo.cli._live import ToolError
from tf_demo.cli._view_model import build_scene
from tf_demo.cli._view_model import DEFAULT_STALE_AFTER_S
from tf_demo.cli._view_model import echo_markdown
from tf_demo.cli._view_model import FrameView
from tf_demo.cli._view_model import SceneView
from tf_demo.cli._view_model import tree_markdown
from tf_demo.cli._view_robot import visual_meshes
from tf_demo.core.extras import extra_hint
from tf_demo.core.lazy_import import lazy_module
from tf_demo.nodes.helpers import rate_error
from tf_demo.nodes.joint_state_publisher import FreeJoint
from tf_demo.nodes.joint_state_publisher import joint_state_message
from tf_demo.nodes.joint_state_publisher import JointStateTable
from tf_demo.transport.messages import sensor_msgs
from tf_demo.transport.messages import std_msgs
from tf_demo.transport.qos import DurabilityPolicy
from tf_demo.transport.qos import QoSProfile
from tf_demo.transport.qos import ReliabilityPolicy
from tf_demo.urdf import RobotModel
from tf_demo.urdf import UrdfError

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
#: Labels moved per update at most (a label is one message; the triads are one in all).
LABEL_MOVES_PER_UPDATE = 50
AUTO_FIXED_FRAME = '(root of the largest tree)'
#: Longest wait of the executor for work, so that a stop is seen promptly.
SPIN_SLICE_S = 0.1
#: robot_state_publisher latches robot_description: subscribe as joint_state_publisher does.
DESCRIPTION_QOS = QoSProfile(
    depth=1, durability=DurabilityPolicy.TRANSIENT_LOCAL, reliability=ReliabilityPolicy.RELIABLE
)


def build_parser() -> argparse.ArgumentParser:
    """Return tf_view's command line."""
    parser = argparse.ArgumentParser(prog=TOOL, description=__doc__.strip().splitlines()[0])
    parser.add_argument('--fixed-frame', default=None, help='frame the view is drawn in')
    parser.add_argument('--host', default='127.0.0.1', help='address to serve on')
    parser.add_argument('--port', type=int, default=8080, help='port to serve on (0: any)')
    parser.add_argument(
        '--update-rate', type=float, default=20.0, metavar='HZ', help='view updates per second'
    )
    parser.add_argument(
        '--urdf', default=None, metavar='FILE', help='robot description (URDF or xacro) to draw'
    )
    parser.add_argument(
        '--publish-joint-states',
        action='store_true',
        help="publish the joint panel's positions on /joint_states from the start",
    )
    parser.add_argument(
        '--optional',
        action='store_true',
        help="without the 'view' extra, warn in one line and exit 0 (the launch files' viewer)",
    )
    parser.add_argument(
        '--stale-after',
        type=float,
        default=DEFAULT_STALE_AFTER_S,
        metavar='SECONDS',
        help='a dynamic frame without data for this long is shown as stale',
    )
    add_namespace_option(parser)
    return parser


def options_error(options: argparse.Namespace) -> str | None:
    """Return what is wrong with the options, or None."""
    if not (math.isfinite(options.update_rate) and 0.0 < options.update_rate <= 1000.0):
        rate = options.update_rate
        return f'--update-rate must be a number of updates per second in (0, 1000], got {rate}'
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

    def __init__(self, server: Any, fixed_frame: str | None, log: Callable[[str], object]) -> None:
        self.server = server
        self.fixed_frame = fixed_frame
        self._log = log
        self._missing: str | None = None  # the missing fixed frame's warning, once logged
        self.selected: str | None = None
        self._axes: Any = None
        self._origins: Any = None
        self._links: Any = None
        self._labels: dict[str, Any] = {}
        #: Per label: the update it was last moved at, where to and its text.
        self._label_state: dict[str, tuple[int, tuple[float, ...], str]] = {}
        self._created = 0
        self._tick = 0
        # As rviz2 opens: a 1 m grid on the fixed frame's xy plane, seen from above and aside.
        server.scene.add_grid('/grid', width=10.0, height=10.0, cell_size=1.0, section_size=5.0)
        server.initial_camera.position = (2.0, -2.0, 1.5)
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
        if scene.missing_fixed_frame != self._missing:
            self._missing = scene.missing_fixed_frame
            if self._missing is not None:
                self._log(self._missing)
        names = tuple(frame.name for frame in scene.frames)
        if tuple(self._select.options) != ('', *sorted(names)):
            self._select.options = ('', *sorted(names))
            # the chosen fixed frame stays a choice while it does not exist (else the
            # dropdown would fall back to the automatic one, silently)
            asked = {self.fixed_frame} if self.fixed_frame is not None else set()
            self._fixed.options = (AUTO_FIXED_FRAME, *sorted({*names, *asked}))
        shown = [f for f in scene.frames if f.translation is not None and f.rotation is not None]
        self._draw_axes(shown)
        self._draw_labels(shown)
        self._draw_links(shown)
        self._set(self._warning, '\n\n'.join(f'**Warning:** {text}' for text in scene.warnings))
        tree = f'Fixed frame: `{scene.fixed_frame}`\n\n' + tree_markdown(scene)
        self._set(self._tree, tree)
        self._set(self._echo, echo_markdown(core, scene.fixed_frame, self.selected))
        return scene

    @staticmethod
    def _set(markdown: Any, content: str) -> None:
        if markdown.content != content:  # each assignment is a message to every browser
            markdown.content = content

    def _draw_axes(self, shown: list[FrameView]) -> None:
        """All triads in one batched node, all origins (coloured by kind) in one point cloud."""
        positions = np.array([f.translation for f in shown], dtype=np.float32).reshape(-1, 3)
        wxyzs = np.array([_wxyz(f.rotation) for f in shown], dtype=np.float32).reshape(-1, 4)  # type: ignore[arg-type]
        colors = np.array(
            [
                STALE_COLOR if f.stale else STATIC_COLOR if f.is_static else DYNAMIC_COLOR
                for f in shown
            ],
            dtype=np.uint8,
        ).reshape(-1, 3)
        scene_api = self.server.scene
        if self._axes is None:
            self._axes = scene_api.add_batched_axes(
                '/tf/axes', wxyzs, positions, axes_length=AXES_LENGTH, axes_radius=0.01
            )
            self._origins = scene_api.add_point_cloud(
                '/tf/origins', positions, colors, point_size=0.06, point_shape='circle'
            )
            return
        self._axes.batched_positions = positions
        self._axes.batched_wxyzs = wxyzs
        self._origins.points = positions
        self._origins.colors = colors

    def _draw_labels(self, shown: list[FrameView]) -> None:
        """
        One label per frame, moved only when its frame moved more than 1 mm.

        A label is one message per move: at most :data:`LABEL_MOVES_PER_UPDATE` are sent per
        update (the longest waiting first), so a large moving tree stays cheap.
        """
        scene_api = self.server.scene
        wanted = {f.name for f in shown}
        for gone in set(self._labels) - wanted:
            self._labels.pop(gone).remove()
            self._label_state.pop(gone, None)
        moves: list[tuple[int, str, tuple[float, float, float], str]] = []
        for frame in shown:
            text = f'{frame.name} (stale)' if frame.stale else frame.name
            place = tuple(round(c, 3) for c in frame.translation)  # type: ignore[union-attr]
            if frame.name not in self._labels:
                self._labels[frame.name] = scene_api.add_label(
                    f'/tf/labels/l{self._created}', text, position=place
                )
                self._created += 1
                self._label_state[frame.name] = (self._tick, place, text)
                continue
            sent_tick, sent_place, sent_text = self._label_state[frame.name]
            if place != sent_place or text != sent_text:
                moves.append((sent_tick, frame.name, place, text))  # type: ignore[arg-type]
        moves.sort()
        for _, name, place, text in moves[:LABEL_MOVES_PER_UPDATE]:
            label = self._labels[name]
            sent_tick, sent_place, sent_text = self._label_state[name]
            if place != sent_place:
                label.position = place
            if text != sent_text:
                label.text = text
            self._label_state[name] = (self._tick, place, text)
        self._tick += 1

    def _draw_links(self, shown: list[FrameView]) -> None:
        where = {f.name: f.translation for f in shown}
        segments = [
            (where[f.name], where[f.parent])
            for f in shown
            if f.parent is not None and f.parent in where
        ]
        points = np.array(segments, dtype=np.float32).reshape(-1, 2, 3)
        if self._links is None:
            self._links = self.server.scene.add_line_segments(
                '/tf_links', points, LINK_COLOR, thickness=2.0, thickness_units='screen'
            )
        else:
            self._links.points = points


class RobotPanel:
    """
    The robot model and the joint panel: meshes placed by TF, sliders that publish joint states.

    :meth:`set_robot` may run on the node's thread (a new ``robot_description``) while
    :meth:`place` runs on the view's: a lock keeps them apart.
    """

    def __init__(self, server: Any, publish: bool) -> None:
        self.server = server
        self.table: JointStateTable | None = None
        self.problems: list[str] = []
        self._lock = threading.Lock()
        self._links: dict[str, Any] = {}
        self._handles: list[Any] = []
        self._sliders: dict[str, Any] = {}
        self._random = random.Random()
        gui = server.gui
        with gui.add_folder('Joints'):
            self._publish = gui.add_checkbox('Publish /joint_states', initial_value=publish)
            center = gui.add_button('Center')
            center.on_click(lambda _event: self.center())
            randomize = gui.add_button('Randomize')
            randomize.on_click(lambda _event: self.randomize())
            self._joints_folder = gui.add_folder('Positions')
            self._status = gui.add_markdown('No robot description yet.')

    @property
    def publishing(self) -> bool:
        """Whether the panel publishes ``/joint_states``."""
        return bool(self._publish.value)

    def set_robot(self, model: RobotModel, base_dir: str | None) -> None:
        """Draw ``model``'s visuals and give each of its free joints a slider."""
        meshes, problems = visual_meshes(model.description.visuals, base_dir)
        table = JointStateTable.from_model(model)
        with self._lock:
            for handle in self._handles:
                handle.remove()
            self._handles, self._links, self._sliders = [], {}, {}
            scene = self.server.scene
            keys: dict[str, str] = {}
            for index, mesh in enumerate(meshes):
                if mesh.link not in keys:
                    keys[mesh.link] = f'/robot/l{len(keys)}'  # link names may hold '/'
                    link = scene.add_frame(keys[mesh.link], show_axes=False, visible=False)
                    self._links[mesh.link] = link
                    self._handles.append(link)
                self._handles.append(
                    scene.add_mesh_simple(
                        f'{keys[mesh.link]}/v{index}',
                        mesh.vertices,
                        mesh.faces,
                        color=mesh.rgb,
                        opacity=None if mesh.opacity >= 1.0 else mesh.opacity,
                        position=mesh.position,
                        wxyz=mesh.wxyz,
                    )
                )
            with self._joints_folder:
                for joint_name, joint in table.free_joints.items():
                    slider = self.server.gui.add_slider(
                        joint_name,
                        min=joint.minimum,
                        max=joint.maximum,
                        step=(joint.maximum - joint.minimum) / 1000 or 0.001,
                        initial_value=joint.zero,
                    )
                    slider.on_update(self._slider_moved(joint_name))
                    self._sliders[joint_name] = slider
                    self._handles.append(slider)
            self.table = table
            self.problems = problems + table.warnings
        lines = [f'Robot `{model.name}`: {len(table.free_joints)} movable joints.']
        self._status.content = '\n\n'.join(lines + [f'**Warning:** {p}' for p in self.problems])

    def _slider_moved(self, joint_name: str) -> Callable[[object], None]:
        def moved(_event: object) -> None:
            table = self.table
            if table is not None and joint_name in table.free_joints:
                table.free_joints[joint_name].position = float(self._sliders[joint_name].value)

        return moved

    def _set_positions(self, pick: Callable[[FreeJoint], float]) -> None:
        table = self.table
        if table is None:
            return
        for joint_name, joint in table.free_joints.items():
            joint.position = pick(joint)
            self._sliders[joint_name].value = joint.position

    def center(self) -> None:
        """Every free joint to its centre (0, or the middle of limits that exclude 0)."""
        self._set_positions(lambda joint: joint.zero)

    def randomize(self) -> None:
        """Every free joint to a random position within its limits."""
        self._set_positions(lambda joint: self._random.uniform(joint.minimum, joint.maximum))

    def place(self, scene: SceneView) -> None:
        """Put each link's meshes where TF has the link in the fixed frame (hidden if unknown)."""
        poses = {f.name: f for f in scene.frames if f.root == (scene.roots or ('',))[0]}
        with self._lock:
            for link_name, link in self._links.items():
                frame = poses.get(link_name)
                if frame is None or frame.translation is None or frame.rotation is None:
                    link.visible = False
                    continue
                link.position = frame.translation
                link.wxyz = _wxyz(frame.rotation)
                link.visible = True


def _load_robot(path: str) -> RobotModel:
    try:
        return RobotModel.from_file(path)
    except (UrdfError, ValueError) as error:
        raise ToolError(str(error)) from error


def _serve(options: argparse.Namespace) -> int:
    try:
        import viser
    except ImportError as error:
        if options.optional:
            print(
                f"{TOOL}: warning: no view: the 'view' extra is missing ({extra_hint('view')})",
                file=sys.stderr,
                flush=True,
            )
            return 0
        raise ToolError(f"needs the 'view' extra ({extra_hint('view')}): {error}") from error
    from tf_demo import transport
    from tf_demo.ros import Buffer
    from tf_demo.ros import TransformListener
    from tf_demo.transport.executors import SingleThreadedExecutor

    model = _load_robot(options.urdf) if options.urdf is not None else None
    node = transport.create_node(TOOL)
    if not node.has_parameter('rate'):
        node.declare_parameter('rate', 10)
    rate = node.get_parameter('rate').value
    problem = (
        'must be a number of Hz'
        if isinstance(rate, bool) or not isinstance(rate, (int, float))
        else rate_error(float(rate))
    )
    if problem is not None:
        node.destroy_node()
        raise ToolError(f'parameter rate {problem}, got {rate!r}')
    buffer = Buffer(node=node)
    listener = TransformListener(buffer, node)
    try:
        with contextlib.redirect_stdout(io.StringIO()):  # viser's banner: our line says it
            server = viser.ViserServer(host=options.host, port=options.port, verbose=False)
    except OSError as error:
        listener.unregister()
        node.destroy_node()
        raise ToolError(f'cannot serve on {options.host}:{options.port}: {error}') from error
    view = TfView(server, options.fixed_frame, node.get_logger().warning)
    robot = RobotPanel(server, options.publish_joint_states)
    if model is not None:
        robot.set_robot(model, os.path.dirname(os.path.abspath(options.urdf)))
    else:

        def on_description(message: std_msgs.String) -> None:
            try:
                received = RobotModel.from_string(message.data, source='robot_description')
            except UrdfError as error:
                node.get_logger().warning(f'Invalid robot_description given, ignoring: {error}')
                return
            robot.set_robot(received, None)

        node.create_subscription(
            std_msgs.String, 'robot_description', on_description, DESCRIPTION_QOS
        )
    joint_states = node.create_publisher(sensor_msgs.JointState, 'joint_states', 10)

    def publish_joint_states() -> None:
        table = robot.table
        fields = table.message_fields() if table is not None and robot.publishing else None
        if fields is not None:
            stamp = node.get_clock().now().to_msg()
            joint_states.publish(joint_state_message(sensor_msgs.JointState, stamp, fields))

    node.create_timer(1.0 / float(rate), publish_joint_states)
    clock = node.get_clock()

    def redraw() -> None:
        scene = view.update(buffer.core, clock.now().nanoseconds, options.stale_after)
        robot.place(scene)

    node.create_timer(1.0 / options.update_rate, redraw)
    executor = SingleThreadedExecutor()
    executor.add_node(node)
    print(f'tf_view: serving on http://{options.host}:{server.get_port()}', flush=True)
    try:
        while transport.ok():
            executor.spin_once(timeout_sec=SPIN_SLICE_S)
    finally:
        with contextlib.redirect_stdout(io.StringIO()):
            server.stop()
        executor.shutdown()
        listener.unregister()
        node.destroy_node()
    return 0


def main(args: list[str] | None = None) -> int:
    """Run tf_view with ``args`` (default: ``sys.argv[1:]``)."""
    return tool_main(TOOL, args, build_parser(), options_error, _serve)


if __name__ == '__main__':
    sys.exit(main())
