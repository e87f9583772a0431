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
Inside a real ROS 2 Jazzy: ``ros2 run``, ``ros2 launch``, ros2cli and real tf2_ros on the wire.

These run in the ROS world only (``colcon test`` in a workspace sourced on Jazzy), against the
tf_demo installed in that workspace.
"""

from __future__ import annotations

from collections.abc import Iterator
import math
from pathlib import Path
import time
from typing import Any

from conftest import eventually
from conftest import ProcessOutput
from conftest import REPO_ROOT
from conftest import run_captured
import pytest
from ros_world.jazzy import graph_lists
from ros_world.jazzy import ros2
from ros_world.jazzy import running
from ros_world.jazzy import standalone_command
from ros_world.jazzy import standalone_env
from ros_world.jazzy import started
from ros_world.jazzy import stop

pytestmark = [pytest.mark.rclpy_world, pytest.mark.timeout(180)]

URDF = REPO_ROOT / 'urdf'


class RealTf2Listener:
    """A real ``tf2_ros`` Buffer and TransformListener in this process, spinning in a thread."""

    def __init__(self) -> None:
        import rclpy
        import tf2_ros

        self._rclpy = rclpy
        # tf2_ros's spin thread runs on the default context.
        rclpy.init()
        self.node = rclpy.create_node('real_tf2_listener')
        self.buffer = tf2_ros.Buffer()
        self.listener = tf2_ros.TransformListener(self.buffer, self.node, spin_thread=True)

    def lookup(self, target: str, source: str, timeout: float = 20.0) -> Any:
        """The latest target <- source transform, waiting up to ``timeout`` s (None if none)."""
        from rclpy.time import Time

        def ready() -> bool:
            return bool(self.buffer.can_transform(target, source, Time()))

        if not eventually(ready, timeout, 0.1):
            return None
        return self.buffer.lookup_transform(target, source, Time())

    def translation_from(
        self,
        command: list[str],
        env: dict[str, str],
        target: str,
        source: str,
        cwd: Path | None = None,
    ) -> tuple[float, float, float] | None:
        """While ``command`` runs: the translation of target <- source (None if none came)."""
        with started(command, env, cwd):
            transform = self.lookup(target, source)
        return None if transform is None else translation(transform)

    def close(self) -> None:
        # Stop tf2_ros's spin thread before the context goes, or it raises in its thread.
        self.listener.executor.shutdown()
        self.listener.dedicated_listener_thread.join(timeout=10)
        self.listener.unregister()
        self.node.destroy_node()
        self._rclpy.try_shutdown()


@pytest.fixture
def real_tf2(jazzy_env: dict[str, str]) -> Iterator[RealTf2Listener]:
    del jazzy_env
    listener = RealTf2Listener()
    try:
        yield listener
    finally:
        listener.close()


def translation(transform: Any) -> tuple[float, float, float]:
    t = transform.transform.translation
    return (t.x, t.y, t.z)


# -- ros2 run of every executable ---------------------------------------------------------------

NODE_RUNS: dict[str, tuple[str, ...]] = {
    'static_tf_pub': (),
    'dynamic_tf_pub': (),
    'frame_broadcaster': (),
    'tf_listener': (),
    'odom_tf_broadcaster': (),
    'point_transformer': (),
    'robot_state_publisher': ('--ros-args', '-p', f'urdf_file:={URDF / "example_revolute.urdf"}'),
    # joint_state_publisher's file argument (upstream's form; it also reads /robot_description).
    'joint_state_publisher': (str(URDF / 'example_revolute.urdf'),),
}


@pytest.mark.parametrize('executable', sorted(NODE_RUNS))
def test_ros2_run_starts_each_node_in_the_graph_and_ctrl_c_exits_0(
    jazzy_env: dict[str, str], executable: str
) -> None:
    """``ros2 run tf_demo <node>``: the node shows in ``ros2 node list``; Ctrl-C gives exit 0."""
    with started(['ros2', 'run', 'tf_demo', executable, *NODE_RUNS[executable]], jazzy_env) as p:
        assert graph_lists(jazzy_env, 'node')(f'/{executable}'), p.stdout
        code = stop(p)
        output = p.stdout.read() if p.stdout else ''
    assert code == 0, output
    assert 'Traceback' not in output


TOOL_RUNS: dict[str, tuple[tuple[str, ...], str]] = {
    # executable: (arguments, a line that must be printed); a static a -> b is being published.
    'tf_echo': (('a', 'b'), '- Translation: [1.000, 2.000, 3.000]'),
    'tf2_echo': (('a', 'b'), '- Translation: [1.000, 2.000, 3.000]'),
    'view_frames': (('--wait-time', '2'), ''),
    'tf_monitor': (('a', 'b'), 'RESULTS: for a to b'),
    'tf_doctor': (('-t', '2'), ''),
    'tf_saver': (('-t', '2', '-o', 'snapshot.yaml'), ''),
    'static_transform_publisher': (
        ('--x', '1', '--frame-id', 'c', '--child-frame-id', 'd'),
        'Spinning until stopped - publishing transform',
    ),
}


@pytest.mark.parametrize('executable', sorted(TOOL_RUNS))
def test_ros2_run_of_each_tool_does_its_job(
    jazzy_env: dict[str, str], executable: str, tmp_path: Path
) -> None:
    """``ros2 run tf_demo <tool>`` against a static a -> b from our static_tf_pub."""
    args, expected = TOOL_RUNS[executable]
    publisher = [
        'ros2', 'run', 'tf_demo', 'static_tf_pub', '--ros-args',
        '-p', 'parent_frame:=a', '-p', 'child_frame:=b',
        '-p', 'translation:=[1.0, 2.0, 3.0]',
    ]  # fmt: skip
    with (
        started(publisher, jazzy_env),
        started(['ros2', 'run', 'tf_demo', executable, *args], jazzy_env, cwd=tmp_path) as tool,
    ):
        deadline = time.monotonic() + 40
        lines: list[str] = []
        assert tool.stdout is not None
        while time.monotonic() < deadline:
            line = tool.stdout.readline()
            if not line:
                break
            lines.append(line.rstrip('\n'))
            if expected and expected in line:
                break
        code = stop(tool) if tool.poll() is None else tool.wait()
        lines += (tool.stdout.read() or '').splitlines()
    output = '\n'.join(lines)
    assert 'Traceback' not in output, output
    allowed = (0, 1) if executable == 'tf_doctor' else (0,)  # tf_doctor: 1 = found problems
    assert code in allowed, output
    if expected:
        assert any(expected in line for line in lines), output
    if executable == 'view_frames':
        assert list(tmp_path.glob('frames_*.gv')), output
        assert '"a" -> "b"' in next(tmp_path.glob('frames_*.gv')).read_text(encoding='utf-8')
    if executable == 'tf_saver':
        assert 'a' in (tmp_path / 'snapshot.yaml').read_text(encoding='utf-8')


def test_ros2_run_tf_loader_republishes_a_snapshot(
    jazzy_env: dict[str, str], real_tf2: RealTf2Listener, tmp_path: Path
) -> None:
    """``ros2 run tf_demo tf_saver`` then ``tf_loader``: a real tf2_ros listener sees the tree."""
    publisher = ['ros2', 'run', 'tf_demo', 'static_tf_pub', '--ros-args', '-p', 'parent_frame:=s0']
    with started(publisher, jazzy_env):
        saver = ['ros2', 'run', 'tf_demo', 'tf_saver', '-t', '3', '-o', 'tree.yaml']
        saved = run_captured(saver, jazzy_env, cwd=tmp_path)
    assert saved.returncode == 0, saved.stderr
    loader = ['ros2', 'run', 'tf_demo', 'tf_loader', 'tree.yaml']
    loaded = real_tf2.translation_from(loader, jazzy_env, 's0', 'camera_link', cwd=tmp_path)
    assert loaded == pytest.approx((0.5, 0.0, 0.2))


# -- real tf2_ros on the other end ---------------------------------------------------------------


@pytest.mark.parametrize(
    ('executable', 'expected'),
    [('static_tf_pub', (0.5, 0.0, 0.2)), ('frame_broadcaster', (0.1, 0.2, 0.3))],
)
def test_real_tf2_ros_listener_receives_base_link_to_camera_link(
    jazzy_env: dict[str, str],
    real_tf2: RealTf2Listener,
    executable: str,
    expected: tuple[float, float, float],
) -> None:
    """static_tf_pub's latched (/tf_static) and frame_broadcaster's (/tf) base_link ->
    camera_link reach a real tf2_ros listener."""
    command = ['ros2', 'run', 'tf_demo', executable]
    published = real_tf2.translation_from(command, jazzy_env, 'base_link', 'camera_link')
    assert published == pytest.approx(expected)


def test_real_tf2_ros_listener_follows_dynamic_tf_pub(
    jazzy_env: dict[str, str], real_tf2: RealTf2Listener
) -> None:
    """dynamic_tf_pub's odom -> base_link circle: a real listener sees it move on radius 2."""
    command = ['ros2', 'run', 'tf_demo', 'dynamic_tf_pub', '--ros-args', '-p', 'radius:=2.0']
    with started(command, jazzy_env):
        first = real_tf2.lookup('odom', 'base_link')
        assert first is not None
        time.sleep(0.5)
        second = real_tf2.lookup('odom', 'base_link')
    assert second is not None
    for transform in (first, second):
        x, y, z = translation(transform)
        assert math.hypot(x, y) == pytest.approx(2.0, abs=1e-6)
        assert z == 0.0
    assert translation(first) != translation(second)


def test_real_tf2_ros_listener_follows_tf_play(
    jazzy_env: dict[str, str], real_tf2: RealTf2Listener, tmp_path: Path
) -> None:
    """``ros2 run tf_demo tf_play`` on a bag written with rosbags: a real tf2_ros listener gets
    the static recorded late (latched from the start) and the moving /tf under it."""
    pytest.importorskip('rosbags.rosbag2', reason="tf_play needs the 'bag' extra")
    from tf_demo.testing.bags import SECOND
    from tf_demo.testing.bags import tf_bytes
    from tf_demo.testing.bags import transform
    from tf_demo.testing.bags import write_bag

    start = 1_700_000_000 * SECOND
    stamps = [start + k * SECOND // 20 for k in range(21)]
    messages = [
        ('/tf', stamp, tf_bytes(transform('odom', 'base_link', stamp, (k, 0, 0))))
        for k, stamp in enumerate(stamps)
    ]
    messages.append(
        ('/tf_static', stamps[-1], tf_bytes(transform('map', 'odom', start, (1, 2, 0))))
    )
    bag = write_bag(tmp_path / 'bag', 'mcap', messages)
    command = ['ros2', 'run', 'tf_demo', 'tf_play', str(bag), '--loop']
    with running(command, jazzy_env) as play:
        looked_up = real_tf2.lookup('map', 'base_link')
        lines = list(play.lines)
    assert looked_up is not None, '\n'.join(lines)
    x, y, z = translation(looked_up)
    assert (x - 1.0) in set(range(21))
    assert (y, z) == (2.0, 0.0)


def test_real_tf2_ros_listener_receives_robot_state_publisher(
    jazzy_env: dict[str, str], real_tf2: RealTf2Listener
) -> None:
    """Our robot_state_publisher + joint_state_publisher on the course URDF, seen by tf2_ros."""
    urdf = URDF / 'example_revolute.urdf'
    rsp = ['ros2', 'run', 'tf_demo', 'robot_state_publisher', '--ros-args', '-p']
    jsp = ['ros2', 'run', 'tf_demo', 'joint_state_publisher', str(urdf)]
    with started([*rsp, f'urdf_file:={urdf}'], jazzy_env), started(jsp, jazzy_env):
        frames: set[str] = set()

        def all_frames() -> bool:
            frames.update(real_tf2.buffer.all_frames_as_string().split())
            return 'frame_2' in real_tf2.buffer.all_frames_as_string()

        assert eventually(all_frames, 20.0), frames


def test_our_listener_receives_real_tf2_ros_broadcasters(
    jazzy_env: dict[str, str], tmp_path: Path
) -> None:
    """Real tf2_ros broadcasters (Python, in another process) -> our tf_listener's lookups."""
    script = tmp_path / 'real_broadcaster.py'
    script.write_text(REAL_BROADCASTER, encoding='utf-8')
    listener = [
        'ros2', 'run', 'tf_demo', 'tf_listener', '--ros-args',
        '-p', 'target_frame:=world', '-p', 'source_frame:=robot', '-p', 'period:=0.2',
    ]  # fmt: skip
    with started(['python3', str(script)], jazzy_env), started(listener, jazzy_env) as ours:
        assert ours.stdout is not None
        found = None
        deadline = time.monotonic() + 30
        while time.monotonic() < deadline and found is None:
            line = ours.stdout.readline()
            if 'world' in line and '3.000' in line:
                found = line
    assert found is not None


REAL_BROADCASTER = """
import rclpy
from geometry_msgs.msg import TransformStamped
from tf2_ros import StaticTransformBroadcaster, TransformBroadcaster

rclpy.init()
node = rclpy.create_node('real_broadcaster')
static = StaticTransformBroadcaster(node)
dynamic = TransformBroadcaster(node)
t = TransformStamped()
t.header.frame_id = 'world'
t.child_frame_id = 'station'
t.transform.translation.x = 1.0
t.transform.rotation.w = 1.0
static.sendTransform(t)


def tick():
    m = TransformStamped()
    m.header.stamp = node.get_clock().now().to_msg()
    m.header.frame_id = 'station'
    m.child_frame_id = 'robot'
    m.transform.translation.x = 2.0
    m.transform.rotation.w = 1.0
    dynamic.sendTransform(m)


node.create_timer(0.05, tick)
try:
    rclpy.spin(node)
except KeyboardInterrupt:
    pass
"""


# -- launch files ---------------------------------------------------------------------------------

# rviz2 is not built here: the default viewer is then tf_view (web), which prints its URL.
LAUNCHES: dict[str, tuple[tuple[str, ...], tuple[str, str]]] = {
    'tf_demo.launch.py': (('viewer:=none',), ('odom', 'camera_link')),
    'rep105.launch.py': ((), ('map', 'base_link')),
    'mobile_robot.launch.py': (('viewer:=web',), ('odom', 'lidar_link')),
}


@pytest.mark.parametrize('launch_file', sorted(LAUNCHES))
def test_ros2_launch_starts_the_tree(
    jazzy_env: dict[str, str], real_tf2: RealTf2Listener, launch_file: str
) -> None:
    """``ros2 launch tf_demo <file>`` (no rviz): a real tf2_ros listener sees the tree."""
    has_view = 'viewer:=none' not in LAUNCHES[launch_file][0]
    args, (target, source) = LAUNCHES[launch_file]
    with started(['ros2', 'launch', 'tf_demo', launch_file, *args], jazzy_env) as launch:
        output = ProcessOutput(launch)
        transform = real_tf2.lookup(target, source, timeout=40.0)
        if has_view:
            output.wait_for_line('tf_view: serving on http://', timeout=60, anywhere=True)
        code = stop(launch, timeout=30)
        time.sleep(0.1)  # let the pump threads drain the pipe
    text = '\n'.join(output.lines)
    assert transform is not None, text
    assert code == 0, text
    assert 'Traceback' not in '\n'.join(_without_launchs_lost_interrupt(output.lines)), text
    assert ('tf_view: serving on http://' in text) == has_view, text


@pytest.mark.parametrize('viewer_args', [('rviz:=false',), ('viewer:=web',)])
def test_the_course_launch_takes_rviz_and_goes_on_without_a_viewer(
    jazzy_env: dict[str, str], real_tf2: RealTf2Listener, tmp_path: Path, viewer_args: tuple[str]
) -> None:
    """The course's ``rviz:=false`` starts no viewer; tf_view without viser warns in one line."""
    hidden = tmp_path / 'hidden' / 'viser'  # viser made unimportable for the launched nodes
    hidden.mkdir(parents=True)
    (hidden / '__init__.py').write_text("raise ImportError('viser is hidden by this test')\n")
    env = {**jazzy_env, 'PYTHONPATH': f'{hidden.parent}:{jazzy_env.get("PYTHONPATH", "")}'}
    command = ['ros2', 'launch', 'tf_demo', 'tf_demo.launch.py', *viewer_args]
    with started(command, env) as launch:
        output = ProcessOutput(launch)
        transform = real_tf2.lookup('odom', 'camera_link', timeout=40.0)
        if viewer_args == ('viewer:=web',):
            output.wait_for_line('tf_view: warning: no view', timeout=60, anywhere=True)
            # It ends cleanly and the launch goes on: its nodes stay in the graph. (A Ctrl-C
            # while tf_view exits, or while launch logs that, is lost in upstream launch.)
            output.wait_for_line('[INFO] [tf_view-3]: process has finished cleanly', timeout=30)
            assert graph_lists(env, 'node')('/dynamic_tf_pub'), '\n'.join(output.lines)
        code = stop(launch, timeout=30)
        time.sleep(0.1)  # let the pump threads drain the pipe
    text = '\n'.join(output.lines)
    assert transform is not None, text
    assert code == 0, text
    assert 'process has died' not in text, text
    assert 'rviz2' not in text, text
    warnings = [line for line in output.lines if 'tf_view: warning: no view' in line]
    assert len(warnings) == (viewer_args == ('viewer:=web',)), text


def _without_launchs_lost_interrupt(lines: list[str]) -> list[str]:
    """
    ``lines`` without the one traceback that is upstream launch's own, not a node's.

    ``ros2 launch`` takes Ctrl-C as Python's KeyboardInterrupt; when it lands in a weakref
    callback of the launch process, Python prints "Exception ignored in: ..." and its traceback
    (unprefixed: the launch process, not a ``[node-N]`` line) and launch still shuts every node
    down cleanly. Our nodes' lines are all kept.
    """
    kept: list[str] = []
    skipping = False
    for line in lines:
        if line.startswith('Exception ignored in: '):
            skipping = True
        elif skipping and line.startswith('KeyboardInterrupt'):
            skipping = False
            continue
        if not skipping:
            kept.append(line)
    return kept


# -- ros2cli on our nodes -------------------------------------------------------------------------


def test_ros2_topic_node_and_param_on_our_nodes(jazzy_env: dict[str, str]) -> None:
    """``ros2 node list``, ``ros2 topic list``, ``ros2 param list/get/set`` on dynamic_tf_pub."""
    with started(['ros2', 'run', 'tf_demo', 'dynamic_tf_pub'], jazzy_env):
        assert graph_lists(jazzy_env, 'node')('/dynamic_tf_pub')
        assert graph_lists(jazzy_env, 'topic')('/tf')
        listed = eventually(
            lambda: 'radius' in ros2(jazzy_env, 'param', 'list', '/dynamic_tf_pub').stdout
        )
        assert listed
        got = ros2(jazzy_env, 'param', 'get', '/dynamic_tf_pub', 'radius')
        assert got.stdout.strip() == 'Double value is: 1.0', got
        changed = ros2(jazzy_env, 'param', 'set', '/dynamic_tf_pub', 'radius', '2.5')
        assert changed.stdout.strip() == 'Set parameter successful', changed
        got = ros2(jazzy_env, 'param', 'get', '/dynamic_tf_pub', 'radius')
        assert got.stdout.strip() == 'Double value is: 2.5', got


# -- the two worlds on one wire ------------------------------------------------------------------


def test_standalone_and_rclpy_worlds_exchange_tf_both_ways(
    jazzy_env: dict[str, str], real_tf2: RealTf2Listener
) -> None:
    """Standalone static and dynamic publishers -> rclpy world; rclpy -> standalone tf_echo."""
    standalone = standalone_env(jazzy_env)
    static = standalone_command(
        'nodes.static_tf_pub', '--ros-args', '-p', 'parent_frame:=st_parent'
    )
    dynamic = standalone_command(
        'nodes.dynamic_tf_pub',
        '--ros-args',
        '-p',
        'parent_frame:=st_odom',
        '-p',
        'child_frame:=st_base',
    )
    with started(static, standalone), started(dynamic, standalone):
        assert real_tf2.lookup('st_parent', 'camera_link') is not None
        assert real_tf2.lookup('st_odom', 'st_base') is not None
    rclpy_static = [
        'ros2', 'run', 'tf_demo', 'static_tf_pub', '--ros-args',
        '-p', 'parent_frame:=ros_parent', '-p', 'child_frame:=ros_child',
    ]  # fmt: skip
    rclpy_dynamic = [
        'ros2',
        'run',
        'tf_demo',
        'frame_broadcaster',
        '--ros-args',
        '-r',
        '__node:=fb_ros',
    ]
    echo_static = standalone_command('cli.tf_echo', 'ros_parent', 'ros_child', '--limit', '1')
    echo_dynamic = standalone_command('cli.tf_echo', 'base_link', 'camera_link', '--limit', '1')
    with started(rclpy_static, jazzy_env), started(rclpy_dynamic, jazzy_env):
        for command, expected in (
            (echo_static, '- Translation: [0.500, 0.000, 0.200]'),
            (echo_dynamic, '- Translation: [0.100, 0.200, 0.300]'),
        ):
            echoed = run_captured(command, standalone)
            assert expected in echoed.stdout, (echoed.stdout, echoed.stderr)
