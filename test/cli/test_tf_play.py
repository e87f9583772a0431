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
tf_play: a bag written with rosbags played back over the network, heard by real subscribers.

The played process and the listeners are this run's world (rclpy inside ROS 2, DDS standalone).
Playback loops where a test must see one whole pass: the first messages of a pass may go out
before a new subscriber has matched, as with ``ros2 bag play``.
"""

from __future__ import annotations

from pathlib import Path
import threading
from typing import Any

from conftest import eventually
from conftest import Spinning
import pytest
from tf_demo.cli import tf_play
from tf_demo.cli.tf_play import first_statics
from tf_demo.cli.tf_play import Timeline
from tf_demo.msgs.cdr import decode_tf_message_transforms
from tf_demo.testing.bags import SECOND
from tf_demo.testing.bags import tf_bytes
from tf_demo.testing.bags import transform
from tf_demo.testing.bags import write_bag

pytest.importorskip('rosbags.rosbag2', reason="tf_play needs the 'bag' extra")

T0 = 1_700_000_000 * SECOND
STEPS = 21  # one second of /tf at 20 Hz


def moving(parent: str, child: str, steps: int, hz: int) -> list[tuple[str, int, bytes]]:
    """``steps`` /tf messages at ``hz``: child at x = k metres at step k."""
    stamps = [T0 + k * SECOND // hz for k in range(steps)]
    return [
        ('/tf', stamp, tf_bytes(transform(parent, child, stamp, (k, 0, 0))))
        for k, stamp in enumerate(stamps)
    ]


def static(at_ns: int, parent: str, child: str, xyz: tuple[float, ...]) -> tuple[str, int, bytes]:
    """A /tf_static message recorded at ``at_ns`` (stamped at the bag's start)."""
    return ('/tf_static', at_ns, tf_bytes(transform(parent, child, T0, xyz)))


def played_bag(path: Path, storage: str = 'mcap') -> Path:
    """One second of odom -> base_link; statics recorded late and one changed half-way."""
    messages = [
        *moving('odom', 'base_link', STEPS, 20),
        static(T0 + SECOND // 4, 'base_link', 'laser', (0.1, 0.0, 0.2)),
        static(T0 + SECOND // 2, 'base_link', 'laser', (0.3, 0.0, 0.0)),
        static(T0 + SECOND * 3 // 4, 'map', 'odom', (1.0, 2.0, 0.0)),
    ]
    return write_bag(path, storage, sorted(messages, key=lambda m: m[1]))


class Heard:
    """Raw /tf, /tf_static and /clock samples heard by an in-process node."""

    def __init__(self, nodes: Spinning, name: str) -> None:
        from tf_demo.transport.messages import rosgraph_msgs
        from tf_demo.transport.messages import tf2_msgs
        from tf_demo.transport.qos import DynamicListenerQoS
        from tf_demo.transport.qos import QoSProfile
        from tf_demo.transport.qos import ReliabilityPolicy
        from tf_demo.transport.qos import StaticListenerQoS

        self.lock = threading.Lock()
        self.tf: list[int] = []  # each message's first stamp
        self.statics: list[list[tuple[str, str, tuple[float, ...]]]] = []
        self.clock: list[int] = []
        node = nodes.node(name)
        node.create_subscription(
            tf2_msgs.TFMessage, '/tf', self._tf, DynamicListenerQoS(), raw=True
        )
        node.create_subscription(
            tf2_msgs.TFMessage, '/tf_static', self._static, StaticListenerQoS(), raw=True
        )
        best_effort = QoSProfile(depth=10, reliability=ReliabilityPolicy.BEST_EFFORT)
        node.create_subscription(rosgraph_msgs.Clock, '/clock', self._clock, best_effort)

    def _tf(self, data: bytes) -> None:
        with self.lock:
            self.tf.extend(t[2] for t in decode_tf_message_transforms(bytes(data))[:1])

    def _static(self, data: bytes) -> None:
        transforms = decode_tf_message_transforms(bytes(data))
        with self.lock:
            self.statics.append([(p, c, tuple(xyz)) for p, c, _, xyz, _ in transforms])

    def _clock(self, message: Any) -> None:
        with self.lock:
            self.clock.append(message.clock.sec * SECOND + message.clock.nanosec)

    def a_whole_pass(self) -> bool:
        """Whether every recorded /tf stamp was heard in order, one pass without a gap."""
        wanted = [T0 + k * SECOND // 20 for k in range(STEPS)]
        with self.lock:
            heard = list(self.tf)
        return any(heard[i : i + STEPS] == wanted for i in range(len(heard) - STEPS + 1))


@pytest.mark.dds
@pytest.mark.usefixtures('ros')
def test_every_message_comes_back_in_order_and_statics_are_latched(
    spawn: Any, nodes: Spinning, tmp_path: Path
) -> None:
    heard = Heard(nodes, 'early')
    nodes.start()
    bag = played_bag(tmp_path / 'bag')
    player = spawn.start('tf_play', str(bag), '--loop', '--rate', '4')
    assert eventually(heard.a_whole_pass, 60, 0.05), heard.tf[:50]
    late = Heard(nodes, 'late')  # after the statics were sent: they are latched
    assert eventually(lambda: bool(late.statics), 60, 0.05)
    frames = {(parent, child) for parent, child, _ in late.statics[-1]}
    assert frames == {('base_link', 'laser'), ('map', 'odom')}  # map->odom from the start
    assert player.poll() is None


@pytest.mark.dds
@pytest.mark.usefixtures('ros')
def test_clock_follows_the_recording(spawn: Any, nodes: Spinning, tmp_path: Path) -> None:
    heard = Heard(nodes, 'clocked')
    nodes.start()
    bag = played_bag(tmp_path / 'bag', 'sqlite3')
    spawn.start('tf_play', str(bag), '--loop', '--clock', '100')
    assert eventually(lambda: len(heard.clock) >= 50, 60, 0.05)
    with heard.lock:
        ticks = list(heard.clock)
    assert all(T0 <= tick <= T0 + 2 * SECOND for tick in ticks), ticks
    assert len(set(ticks)) > 10  # it moves


@pytest.mark.dds
@pytest.mark.usefixtures('ros')
def test_a_pass_ends_with_exit_0_and_a_count(spawn: Any, tmp_path: Path) -> None:
    bag = played_bag(tmp_path / 'bag')
    process = spawn.start('tf_play', str(bag), '--rate', '10', '--start-offset', '0.5')
    stdout, stderr = process.communicate(timeout=60)
    assert process.returncode == 0, stderr
    assert f'tf_play: playing {bag} (1.000 s; /tf, /tf_static) at rate 10' in stdout
    assert 'tf_play: done, 11 /tf messages published' in stdout  # 0.5 s to 1 s


@pytest.mark.dds
@pytest.mark.usefixtures('ros')
def test_a_damaged_bag_plays_up_to_the_damage_then_says_where(spawn: Any, tmp_path: Path) -> None:
    bag = write_bag(tmp_path / 'bag', 'sqlite3', moving('a', 'b', 400, 100))
    database = next(bag.glob('*.db3'))
    data = bytearray(database.read_bytes())
    data[len(data) // 2 :] = b'\xff' * (len(data) - len(data) // 2)
    database.write_bytes(bytes(data))
    process = spawn.start('tf_play', str(bag), '--rate', '100')
    _, stderr = process.communicate(timeout=60)
    lines = [line for line in stderr.splitlines() if line.strip()]
    assert process.returncode == 1, stderr
    assert len(lines) == 1, stderr
    assert lines[0].startswith(f'tf_play: error: {bag}')


@pytest.mark.parametrize(
    ('arguments', 'error'),
    [
        (['x', '--rate', '0'], '--rate must be a positive number, got 0.0'),
        (['x', '--rate', 'nan'], '--rate must be a positive number'),
        (['x', '--clock', '-1'], '--clock must be a positive number of Hz'),
        (['x', '--start-offset', '-2'], '--start-offset must be zero or more seconds'),
        (['x', '--delay', 'inf'], '--delay must be zero or more seconds'),
    ],
)
def test_wrong_arguments_give_one_line_and_exit_2(
    arguments: list[str], error: str, capsys: pytest.CaptureFixture[str]
) -> None:
    assert tf_play.main(arguments) == 2
    stderr = capsys.readouterr().err
    assert stderr == f'tf_play: error: {error}\n' or (error in stderr and stderr.count('\n') == 1)


def test_a_missing_or_foreign_bag_gives_one_line_and_exit_1(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    foreign = write_bag(
        tmp_path / 'foreign', 'mcap', [('/chatter', T0, b'\x00\x01\x00\x00')], 'std_msgs/msg/Empty'
    )
    for path, error in (
        (tmp_path / 'none', 'no such bag'),
        (foreign, 'no /tf or /tf_static topic'),
    ):
        assert tf_play.main([str(path)]) == 1
        stderr = capsys.readouterr().err
        assert error in stderr, stderr
        assert stderr.count('\n') == 1, stderr


def test_the_first_recorded_static_of_each_child_holds_from_the_start(tmp_path: Path) -> None:
    from tf_demo.bag import open_tf_bag

    with open_tf_bag(played_bag(tmp_path / 'bag')) as bag:
        statics = first_statics(bag.records(statics_only=True))
        assert sum(1 for _ in bag.records(statics_only=True)) == 3
    assert {child: transform[3] for child, transform in statics.items()} == {
        'laser': (0.1, 0.0, 0.2),
        'odom': (1.0, 2.0, 0.0),
    }


def test_the_timeline_scales_bag_time_by_the_rate() -> None:
    timeline = Timeline(first_ns=T0, started=100.0, rate=2.0)
    assert timeline.due(T0) == 100.0
    assert timeline.due(T0 + 4 * SECOND) == pytest.approx(102.0)
    assert timeline.bag_time(101.0) == T0 + 2 * SECOND
    assert Timeline(T0, 0.0, 0.5).due(T0 + SECOND) == pytest.approx(2.0)
