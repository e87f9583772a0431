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

"""DdsNode publishers and subscriptions in separate processes over real DDS on loopback."""

from __future__ import annotations

from collections.abc import Iterator
from pathlib import Path
import sys
import time

from conftest import STANDALONE_ONLY
import pytest

pytest.importorskip('cyclonedds', reason=STANDALONE_ONLY)

from conftest import ChildProcess
from tf_demo.msgs import cdr
from tf_demo.msgs import rmw_dds_common
from tf_demo.transport.dds import wire as dds_wire

pytestmark = [pytest.mark.dds, pytest.mark.timeout(120)]

HELPER = Path(__file__).with_name('dds_peer_node.py')


class Peer(ChildProcess):
    """One helper process; its stdout and stderr lines are collected by reader threads."""

    def __init__(self, env: dict[str, str], *args: str) -> None:
        super().__init__([sys.executable, str(HELPER), *args], env)


@pytest.fixture
def peers(dds_env: dict[str, str]) -> Iterator[list[Peer]]:
    """Start helper processes on the test's private domain; kill leftovers at the end."""
    started: list[Peer] = []
    yield started
    for peer in started:
        peer.stop()


def start(peers: list[Peer], env: dict[str, str], *args: str) -> Peer:
    peer = Peer(env, *args)
    peers.append(peer)
    return peer


LATCHED = ('--durability', 'transient_local')


def latch(peers: list[Peer], env: dict[str, str], topic: str, frame: str, *args: str) -> None:
    """A publisher of one message on ``topic`` (depth 1, transient local), held for 30 s."""
    start(
        peers, env, 'pub', '--topic', topic, '--frame', frame, *LATCHED, '--depth', '1',
        '--hold', '30', *args,
    ).wait_for_line('sent 1')  # fmt: skip


def late_subscriber(peers: list[Peer], env: dict[str, str], topic: str, count: int) -> Peer:
    """A transient local subscription of ``count`` messages on ``topic``, finished."""
    subscriber = start(
        peers, env, 'sub', '--topic', topic, *LATCHED, '--count', str(count), '--timeout', '20'
    )
    assert subscriber.finish() == 0
    return subscriber


def received_x(peer: Peer) -> list[float]:
    return [float(line.split()[2]) for line in peer.stdout if line.startswith('msg ')]


def test_reliable_delivery_at_1khz_loses_nothing(dds_env, peers):
    """2,000 TFMessages published at 1 kHz, RELIABLE KEEP_ALL, all arrive in order."""
    # KEEP_ALL makes the outcome independent of how long a loaded machine starves the
    # subscriber; tf's KEEP_LAST 100 under the same load is measured in bench/bench_transport.py.
    count = 2000
    subscriber = start(
        peers, dds_env, 'sub', '--name', 'sink', '--count', str(count), '--keep-all'
    )
    subscriber.wait_for_line('ready')
    publisher = start(
        peers, dds_env, 'pub', '--name', 'source', '--count', str(count), '--rate', '1000',
        '--wait-subs', '1', '--keep-all',
    )  # fmt: skip
    assert subscriber.finish() == 0
    assert publisher.finish() == 0
    assert subscriber.stdout[-1] == f'done {count}'
    assert received_x(subscriber) == [float(i) for i in range(count)]


def test_shutdown_right_after_a_burst_still_delivers_it(dds_env, peers):
    """A publisher that shuts down right after publishing 500 messages gets all of them out."""
    count = 500
    subscriber = start(
        peers, dds_env, 'sub', '--count', str(count), '--keep-all', '--timeout', '30'
    )
    subscriber.wait_for_line('ready')
    publisher = start(
        peers, dds_env, 'pub', '--count', str(count), '--burst', '--keep-all', '--wait-subs', '1'
    )
    assert publisher.finish() == 0
    assert subscriber.finish() == 0
    assert received_x(subscriber) == [float(i) for i in range(count)]


def test_transient_local_late_joiner_gets_latched_message(dds_env, peers):
    """A TRANSIENT_LOCAL subscription started after the publish still receives the message."""
    latch(peers, dds_env, '/latched', 'latched_frame')
    subscriber = late_subscriber(peers, dds_env, '/latched', 1)
    assert subscriber.stdout[-1] == 'done 1'
    assert 'msg latched_frame 0 world 0 0 0 0 0 1' in subscriber.stdout


def test_two_tf_static_publishers_both_reach_a_late_joiner(dds_env, peers):
    """Two latched /tf_static publishers (depth 1 each) both reach a depth-100 late listener."""
    for frame in ('static_a', 'static_b'):
        latch(peers, dds_env, '/tf_static', frame, '--name', f'pub_{frame}')
    subscriber = late_subscriber(peers, dds_env, '/tf_static', 2)
    assert sorted(line.split()[1] for line in subscriber.stdout if line.startswith('msg ')) == [
        'static_a',
        'static_b',
    ]


def test_incompatible_qos_warns_on_both_sides_and_delivers_nothing(dds_env, peers):
    """A TRANSIENT_LOCAL subscription and a VOLATILE publisher warn like rclpy and never match."""
    incompatible = start(
        peers, dds_env, 'sub', '--name', 'strict', '--topic', '/x', *LATCHED,
        '--count', '1000000', '--timeout', '4',
    )  # fmt: skip
    compatible = start(
        peers, dds_env, 'sub', '--name', 'lenient', '--topic', '/x', '--count', '1000000',
        '--timeout', '4',
    )  # fmt: skip
    incompatible.wait_for_line('ready')
    compatible.wait_for_line('ready')
    publisher = start(
        peers, dds_env, 'pub', '--name', 'talker', '--topic', '/x', '--count', '100',
        '--rate', '50', '--wait-subs', '1',
    )  # fmt: skip
    assert publisher.finish() == 0
    assert incompatible.finish() == 0
    assert compatible.finish() == 0
    subscription_warning = (
        "[strict]: New publisher discovered on topic '/x', offering incompatible QoS. "
        'No messages will be received from it. Last incompatible policy: DURABILITY'
    )
    publisher_warning = (
        "[talker]: New subscription discovered on topic '/x', requesting incompatible QoS. "
        'No messages will be sent to it. Last incompatible policy: DURABILITY'
    )
    assert any(subscription_warning in line for line in incompatible.stderr), incompatible.stderr
    assert any(publisher_warning in line for line in publisher.stderr), publisher.stderr
    assert incompatible.stdout[-1] == 'done 0'
    assert compatible.stdout[-1] == 'done 100'


def test_ros_discovery_info_names_the_node_and_its_endpoints(dds_env, peers, dds_participant):
    """ros_discovery_info, decoded with our codec, lists the node with its writer's GID."""
    start(
        peers, dds_env, 'pub', '--name', 'graph_probe', '--topic', '/probe', '--hold', '30',
    ).wait_for_line('sent 1')  # fmt: skip
    reader = dds_participant.create_reader(
        dds_wire.DISCOVERY_INFO_TOPIC,
        dds_wire.DISCOVERY_INFO_TYPE,
        dds_wire.EndpointQos(reliable=True, transient_local=True, keep_all=True),
        f'typehash={rmw_dds_common.ParticipantEntitiesInfo.__typehash__};'.encode(),
    )
    waitset = dds_wire.WaitSet(dds_participant)
    waitset.attach(reader.read_condition)
    deadline = time.monotonic() + 20
    infos: list[rmw_dds_common.ParticipantEntitiesInfo] = []
    while time.monotonic() < deadline:
        waitset.wait(200_000_000)
        infos += [
            cdr.deserialize(rmw_dds_common.ParticipantEntitiesInfo, p) for p in reader.take()
        ]
        if any(n.node_name == 'graph_probe' for i in infos for n in i.node_entities_info_seq):
            break
    waitset.close()
    with_probe = [
        i for i in infos if any(n.node_name == 'graph_probe' for n in i.node_entities_info_seq)
    ]
    assert with_probe, infos
    (node,) = with_probe[-1].node_entities_info_seq
    info = with_probe[-1]
    assert (node.node_namespace, node.node_name) == ('/', 'graph_probe')
    # Its publisher, then rclpy's built-ins: six parameter services (request readers, reply
    # writers), the /parameter_events and /rosout writers.
    assert len(node.writer_gid_seq) == 1 + 8
    assert len(node.reader_gid_seq) == 6
    writer_gid = bytes(node.writer_gid_seq[0].data)
    participant_gid = bytes(info.gid.data)
    assert writer_gid[:12] == participant_gid[:12]
    assert dds_participant.count_endpoints('rt/probe', publications=True) == 1


def test_deprecated_ros_localhost_only_still_connects_and_warns(dds_env, peers):
    """ROS_LOCALHOST_ONLY=1 (range unset) selects the loopback config and logs rcl's warning."""
    env = dict(dds_env, ROS_LOCALHOST_ONLY='1')
    env.pop('ROS_AUTOMATIC_DISCOVERY_RANGE')
    subscriber = start(peers, env, 'sub', '--count', '3')
    subscriber.wait_for_line('ready')
    publisher = start(peers, env, 'pub', '--count', '3', '--wait-subs', '1')
    assert publisher.finish() == 0
    assert subscriber.finish() == 0
    assert subscriber.stdout[-1] == 'done 3'
    assert any('ROS_LOCALHOST_ONLY is deprecated' in line for line in publisher.stderr)


def test_user_cyclonedds_uri_is_applied_on_top_of_the_loopback_config(dds_env, peers):
    """A user's CYCLONEDDS_URI domain tag separates processes: same tag talks, other tag not."""
    tagged = (
        '<CycloneDDS><Domain id="any"><Discovery><Tag>{}</Tag></Discovery></Domain></CycloneDDS>'
    )
    env_a = dict(dds_env, CYCLONEDDS_URI=tagged.format('team_a'))
    env_b = dict(dds_env, CYCLONEDDS_URI=tagged.format('team_b'))
    same = start(peers, env_a, 'sub', '--name', 'same', '--count', '3', '--timeout', '6')
    other = start(peers, env_b, 'sub', '--name', 'other', '--count', '3', '--timeout', '6')
    same.wait_for_line('ready')
    other.wait_for_line('ready')
    publisher = start(peers, env_a, 'pub', '--count', '3', '--wait-subs', '1')
    assert publisher.finish() == 0
    assert same.finish() == 0
    assert other.finish() == 0
    assert same.stdout[-1] == 'done 3'
    assert other.stdout[-1] == 'done 0'
