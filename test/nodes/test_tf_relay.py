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
tf_relay as a real process between namespaced publishers and readers of the global /tf.

Each robot's nodes run in their namespace with ``/tf`` and ``/tf_static`` remapped to the
namespace's (``-r /tf:=tf``, as a namespaced robot_state_publisher is run); the relay merges them.
"""

from __future__ import annotations

import json
from pathlib import Path
import signal
import time

from conftest import eventually
from conftest import Processes
from conftest import Spinning
import pytest
from tf_demo.cli._live import TfRecorder
from tf_demo.cli._observations import Observation

pytestmark = [pytest.mark.dds, pytest.mark.timeout(180)]

S = 1_000_000_000


def run(spawn: Processes, name: str, *args: str, timeout: float = 60) -> tuple[int, str, str]:
    """Run one of our executables to completion; return (exit code, stdout, stderr)."""
    process = spawn.start(name, *args)
    out, err = process.communicate(timeout=timeout)
    return process.returncode, out, err


def in_namespace(namespace: str, *parameters: str) -> list[str]:
    """ROS arguments that put a node in ``namespace`` with its tf topics there too."""
    args = [
        '--ros-args',
        '-r',
        f'__ns:={namespace}',
        '-r',
        '/tf:=tf',
        '-r',
        '/tf_static:=tf_static',
    ]
    for parameter in parameters:
        args += ['-p', parameter]
    return args


def edges(observations: list[Observation], topic: str) -> set[tuple[str, str]]:
    return {(t.parent, t.child) for o in observations if o.topic == topic for t in o.transforms}


def echo_json(spawn: Processes, source: str, target: str) -> dict[str, object]:
    """One tf_echo --json block of ``source`` <- ``target`` read on the global /tf."""
    code, out, err = run(spawn, 'tf_echo', source, target, '10', '--limit', '1', '--json')
    assert code == 0, err
    record: dict[str, object] = json.loads(out.splitlines()[-1])
    return record


def test_relay_merges_robots_keeps_stamps_and_statics_reach_a_late_listener(
    spawn: Processes, nodes: Spinning
) -> None:
    """Two robots' trees on /tf and one latched /tf_static union; map (shared) kept as it is."""
    spawn.start('dynamic_tf_pub', *in_namespace('/robot1'))
    spawn.start('static_tf_pub', *in_namespace('/robot1'))
    spawn.start('dynamic_tf_pub', *in_namespace('/robot2', 'parent_frame:=map'))
    spawn.start('static_tf_pub', *in_namespace('/robot2', 'translation:=[0.0, 1.0, 2.0]'))
    relay = spawn.start('tf_relay', '/robot1', 'robot2', '--shared', 'map', 'world')
    node = nodes.node('relay_check')
    relayed = TfRecorder(node)
    original = TfRecorder(node, tf_topic='/robot1/tf', tf_static_topic='/robot1/tf_static')
    nodes.start()
    wanted = {('robot1/odom', 'robot1/base_link'), ('map', 'robot2/base_link')}
    seen = eventually(lambda: wanted <= edges(relayed.observations(), '/tf'), timeout=60)
    assert seen, (edges(relayed.observations(), '/tf'), relay.poll())
    # The last latched message holds both robots' statics.
    statics = [o for o in relayed.observations() if o.topic == '/tf_static']
    assert {(t.parent, t.child) for t in statics[-1].transforms} == {
        ('robot1/base_link', 'robot1/camera_link'),
        ('robot2/base_link', 'robot2/camera_link'),
    }
    # Stamps and values as the robot sent them.
    sent = {
        t.stamp_ns: t.translation
        for o in original.observations()
        if o.topic == '/tf'
        for t in o.transforms
    }
    got = {
        t.stamp_ns: t.translation
        for o in relayed.observations()
        if o.topic == '/tf'
        for t in o.transforms
        if t.child == 'robot1/base_link'
    }
    both = set(sent) & set(got)
    assert both
    assert all(got[stamp] == sent[stamp] for stamp in both)
    # Late listeners (new processes) get the statics through the shared frame map.
    record = echo_json(spawn, 'robot2/base_link', 'robot2/camera_link')
    assert record['translation'] == [0.0, 1.0, 2.0]
    record = echo_json(spawn, 'robot1/odom', 'robot1/camera_link')
    assert isinstance(record['stamp'], dict)
    assert record['stamp']['sec'] > 0
    echo_json(spawn, 'map', 'robot2/camera_link')
    relay.send_signal(signal.SIGINT)
    _, err = relay.communicate(timeout=15)
    assert relay.returncode == 0, err
    assert 'Relaying /robot1, /robot2 onto /tf and /tf_static (shared frames: map, world)' in err


def test_a_stopped_robot_stops_in_the_merged_tree(
    spawn: Processes, nodes: Spinning, tmp_path: Path
) -> None:
    """A fleet from a params file; robot1 stopped: its frames stop, robot2's go on."""
    fleet = tmp_path / 'fleet.yaml'
    fleet.write_text(
        'tf_relay:\n  ros__parameters:\n    namespaces: [/robot1, /robot2]\n'
        '    shared_frames: [map]\n',
        encoding='utf-8',
    )
    robot1 = spawn.start('dynamic_tf_pub', *in_namespace('/robot1'))
    spawn.start('dynamic_tf_pub', *in_namespace('/robot2'))
    spawn.start('tf_relay', '--ros-args', '--params-file', str(fleet))
    node = nodes.node('relay_check')
    relayed = TfRecorder(node)
    nodes.start()

    def children_since(since_ns: int) -> set[str]:
        return {
            t.child
            for o in relayed.observations()
            if o.topic == '/tf' and o.receive_ns > since_ns
            for t in o.transforms
        }

    both = {'robot1/base_link', 'robot2/base_link'}
    assert eventually(lambda: both <= children_since(0), timeout=60), children_since(0)
    robot1.send_signal(signal.SIGINT)
    robot1.wait(timeout=15)
    stopped_ns = time.time_ns()
    time.sleep(2.0)
    assert children_since(stopped_ns + S // 2) == {'robot2/base_link'}


@pytest.mark.parametrize(
    ('args', 'problem'),
    [
        (['/', '/robot1'], "namespace '/' is the global one"),
        (['/robot1', '--ros-args', '-r', '/robot1/tf:=/tf'], '/robot1/tf resolves to /tf'),
        ([], 'no namespace to relay'),
        (['/robot 1'], "invalid namespace '/robot 1'"),
    ],
)
def test_no_loop_and_bad_namespaces_are_one_line_errors(
    spawn: Processes, args: list[str], problem: str
) -> None:
    code, out, err = run(spawn, 'tf_relay', *args)
    assert code == 1
    assert out == ''
    lines = err.strip().splitlines()
    assert len(lines) == 1
    assert problem in lines[0]
    assert ': error: ' in lines[0]


def test_relay_process_never_hears_its_own_output(spawn: Processes, nodes: Spinning) -> None:
    """A relay of /robot1 beside a publisher on the global /tf does not send that back."""
    spawn.start('dynamic_tf_pub')  # on the global /tf: odom -> base_link
    spawn.start('dynamic_tf_pub', *in_namespace('/robot1'))
    spawn.start('tf_relay', '/robot1')
    node = nodes.node('relay_check')
    relayed = TfRecorder(node)
    nodes.start()
    assert eventually(
        lambda: ('robot1/odom', 'robot1/base_link') in edges(relayed.observations(), '/tf'),
        timeout=60,
    )
    time.sleep(1.0)
    assert edges(relayed.observations(), '/tf') == {
        ('odom', 'base_link'),
        ('robot1/odom', 'robot1/base_link'),
    }


def test_invalid_command_line_exits_2_with_usage(spawn: Processes) -> None:
    code, _, err = run(spawn, 'tf_relay', '/robot1', '--bogus')
    assert code == 2
    assert 'unrecognized arguments: --bogus' in err
