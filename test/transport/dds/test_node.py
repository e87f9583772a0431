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

"""DdsNode: rcl's naming rules, --ros-args, executors, timers, sim time and bad input."""

from __future__ import annotations

from collections.abc import Callable
from collections.abc import Iterator
import time

from conftest import STANDALONE_ONLY
import pytest

pytest.importorskip('cyclonedds', reason=STANDALONE_ONLY)

from tf_demo.msgs import builtin_interfaces
from tf_demo.msgs import geometry_msgs
from tf_demo.msgs import rosgraph_msgs
from tf_demo.msgs import std_msgs
from tf_demo.msgs import tf2_msgs
from tf_demo.transport import dds_backend
from tf_demo.transport.dds.endpoints import MessageInfo
from tf_demo.transport.parameters import Parameter
from tf_demo.transport.qos import QoSProfile
from tf_demo.transport.qos import ReliabilityPolicy

# -- names (pure) -------------------------------------------------------------------------------


@pytest.mark.parametrize(
    ('topic', 'namespace', 'expanded'),
    [
        ('tf', '/', '/tf'),
        ('/tf', '/robot', '/tf'),
        ('tf', '/robot', '/robot/tf'),
        ('a/b', '/robot', '/robot/a/b'),
        ('~', '/robot', '/robot/talker'),
        ('~/status', '/', '/talker/status'),
        ('~/status', '/robot', '/robot/talker/status'),
        ('{node}/x', '/', '/talker/x'),
        ('{ns}/x', '/robot', '/robot/x'),
    ],
)
def test_topic_names_expand_like_rcl(topic, namespace, expanded):
    """Relative names join the namespace, ~ is the node's FQN, {node}/{ns} are substituted."""
    assert dds_backend.expand_topic_name(topic, 'talker', namespace) == expanded


@pytest.mark.parametrize(
    ('topic', 'reason', 'index'),
    [
        ('', 'must not be empty', 0),
        ('a//b', "repeated '/'", 1),
        ('a/1b', 'must not start with a number', 2),
        ('a b', 'characters other than', 1),
        ('tf/', "must not end with '/'", 2),
        ('~x', "'~' must be followed by '/'", 1),
        ('a~', "'~' must only be the first character", 1),
        ('{bogus}/x', 'unknown substitution', 6),
    ],
)
def test_invalid_topic_names_are_refused_with_a_pointer(topic, reason, index):
    """Each rcl topic-name rule yields InvalidNameError naming the rule and the position."""
    with pytest.raises(dds_backend.InvalidNameError) as caught:
        dds_backend.expand_topic_name(topic, 'talker', '/')
    assert reason in str(caught.value)
    assert caught.value.index == index


def test_node_name_and_namespace_rules():
    """Node names are alphanumerics/underscore not starting with a digit; namespaces absolute."""
    dds_backend.validate_node_name('my_node2')
    dds_backend.validate_namespace('/')
    dds_backend.validate_namespace('/a/b_c')
    with pytest.raises(dds_backend.InvalidNameError, match='must not start with a number'):
        dds_backend.validate_node_name('2node')
    with pytest.raises(dds_backend.InvalidNameError, match='other than alphanumerics') as caught:
        dds_backend.validate_node_name('my-node')
    assert "\n  'my-node'\n     ^" in str(caught.value)
    with pytest.raises(dds_backend.InvalidNameError, match='must be absolute'):
        dds_backend.validate_namespace('robot')
    with pytest.raises(dds_backend.InvalidNameError, match="must not end with '/'"):
        dds_backend.validate_namespace('/robot/')


# -- nodes on real DDS (in this process) --------------------------------------------------------


@pytest.fixture
def world(dds_env: dict[str, str]) -> Iterator[None]:
    """An initialised standalone world on the test's private domain, shut down afterwards."""
    dds_backend.init()
    yield
    dds_backend.shutdown()


def spin_until(
    executor: dds_backend.DdsExecutor, done: Callable[[], bool], timeout: float = 10.0
) -> bool:
    deadline = time.monotonic() + timeout
    while not done() and time.monotonic() < deadline:
        executor.spin_once(timeout_sec=0.05)
    return done()


def one_transform(x: float) -> tf2_msgs.TFMessage:
    transform = geometry_msgs.TransformStamped()
    transform.header.frame_id = 'odom'
    transform.child_frame_id = 'base_link'
    transform.transform.translation.x = x
    transform.transform.rotation.w = 1.0
    return tf2_msgs.TFMessage(transforms=[transform])


@pytest.mark.dds
def test_ros_args_rename_remap_and_override(world):
    """__node, __ns, -r and -p from cli_args shape the node's name, topics and parameters."""
    node = dds_backend.DdsNode(
        'original',
        cli_args=[
            '--ros-args', '-r', '__node:=renamed', '-r', '__ns:=/robot',
            '-r', 'chatter:=talk', '-p', 'rate:=5.0',
        ],
    )  # fmt: skip
    assert node.get_name() == 'renamed'
    assert node.get_namespace() == '/robot'
    assert node.get_fully_qualified_name() == '/robot/renamed'
    publisher = node.create_publisher(std_msgs.String, 'chatter', 10)
    assert publisher.topic_name == '/robot/talk'
    assert node.declare_parameter('rate', 1.0).value == 5.0
    assert node.count_publishers('/robot/talk') == 1
    assert node.count_subscribers('/robot/talk') == 0


@pytest.mark.dds
def test_one_executor_runs_callbacks_of_several_nodes(world):
    """A publisher node and a subscriber node spun by one executor exchange messages in order."""
    talker = dds_backend.DdsNode('talker')
    listener = dds_backend.DdsNode('listener')
    received: list[float] = []
    listener.create_subscription(
        tf2_msgs.TFMessage,
        '/tf',
        lambda m: received.append(m.transforms[0].transform.translation.x),
        100,
    )
    publisher = talker.create_publisher(tf2_msgs.TFMessage, '/tf', 100)
    executor = dds_backend.SingleThreadedExecutor()
    executor.add_node(talker)
    executor.add_node(listener)
    sent = iter(range(20))
    talker.create_timer(0.005, lambda: publisher.publish(one_transform(float(next(sent, 19)))))
    assert spin_until(executor, lambda: len(received) >= 20)
    assert received[:20] == [float(i) for i in range(20)]
    executor.shutdown()


@pytest.mark.dds
def test_malformed_payload_is_logged_and_the_subscription_keeps_working(world, capfd):
    """Garbage bytes on a topic produce an error line naming the type; good messages still come."""
    node = dds_backend.DdsNode('robust')
    received: list[tf2_msgs.TFMessage] = []
    node.create_subscription(tf2_msgs.TFMessage, '/tf', received.append, 10)
    publisher = node.create_publisher(tf2_msgs.TFMessage, '/tf', 10)
    executor = dds_backend.SingleThreadedExecutor()
    executor.add_node(node)
    publisher.publish(b'\x00\x01\x00\x00\x05\x00\x00\x00')
    publisher.publish(one_transform(3.0))
    assert spin_until(executor, lambda: len(received) == 1)
    assert received[0].transforms[0].transform.translation.x == 3.0
    assert "Dropped a malformed tf2_msgs/msg/TFMessage message on '/tf'" in capfd.readouterr().err
    executor.shutdown()


@pytest.mark.dds
def test_publish_rejects_the_wrong_message_type(world):
    """Publishing a String on a TFMessage publisher raises TypeError naming both types."""
    node = dds_backend.DdsNode('strict')
    publisher = node.create_publisher(tf2_msgs.TFMessage, '/tf', 10)
    with pytest.raises(TypeError, match='Expected TFMessage, got String'):
        publisher.publish(std_msgs.String(data='x'))  # type: ignore[arg-type]  # refused
    with pytest.raises(TypeError, match='QoSProfile or a history depth'):
        node.create_publisher(tf2_msgs.TFMessage, '/tf', 'reliable')  # type: ignore[arg-type]


@pytest.mark.dds
def test_timers_fire_periodically_and_stop_when_canceled(world):
    """A 10 ms timer fires repeatedly under spin_once; after cancel() it no longer fires."""
    node = dds_backend.DdsNode('ticker')
    ticks: list[int] = []
    timer = node.create_timer(0.01, lambda: ticks.append(1))
    executor = dds_backend.SingleThreadedExecutor()
    executor.add_node(node)
    assert spin_until(executor, lambda: len(ticks) >= 5)
    timer.cancel()
    count = len(ticks)
    for _ in range(5):
        executor.spin_once(timeout_sec=0.02)
    assert len(ticks) == count
    with pytest.raises(ValueError, match='timer period must be non-negative'):
        node.create_timer(-0.01, lambda: None)


@pytest.mark.dds
def test_timer_period_and_autostart_follow_rclpy(world):
    """Periods truncate to whole ns, 0 s fires on every spin, autostart=False waits for reset()."""
    node = dds_backend.DdsNode('rclpy_timers')
    assert node.create_timer(1.9e-9, lambda: None).timer_period_ns == 1
    busy: list[int] = []
    node.create_timer(0, lambda: busy.append(1))
    waiting: list[int] = []
    idle = node.create_timer(0.001, lambda: waiting.append(1), autostart=False)
    assert idle.is_canceled()
    executor = dds_backend.SingleThreadedExecutor()
    executor.add_node(node)
    assert spin_until(executor, lambda: len(busy) >= 3)
    assert waiting == []
    idle.reset()
    assert spin_until(executor, lambda: len(waiting) >= 2)


@pytest.mark.dds
def test_use_sim_time_drives_the_node_clock_from_clock_topic(world):
    """With use_sim_time true, get_clock().now() follows the /clock messages."""
    node = dds_backend.DdsNode('sim', parameter_overrides=[Parameter('use_sim_time', value=True)])
    clock_node = dds_backend.DdsNode('clock_source')
    clock_publisher = clock_node.create_publisher(
        rosgraph_msgs.Clock,
        '/clock',
        QoSProfile(depth=1, reliability=ReliabilityPolicy.BEST_EFFORT),
    )
    executor = dds_backend.SingleThreadedExecutor()
    executor.add_node(node)
    deadline = time.monotonic() + 10
    while node.get_clock().now().nanoseconds != 42_000_000_007 and time.monotonic() < deadline:
        clock_publisher.publish(
            rosgraph_msgs.Clock(clock=builtin_interfaces.Time(sec=42, nanosec=7))
        )
        executor.spin_once(timeout_sec=0.05)
    assert node.get_clock().now().nanoseconds == 42_000_000_007
    assert node.get_parameter('use_sim_time').value is True


@pytest.mark.dds
def test_destroyed_node_refuses_new_entities(world):
    """After destroy_node, creating a publisher says the node was destroyed."""
    node = dds_backend.DdsNode('gone', namespace='ns')
    assert node.get_fully_qualified_name() == '/ns/gone'
    node.destroy_node()
    with pytest.raises(RuntimeError, match="node '/ns/gone' was destroyed"):
        node.create_publisher(std_msgs.String, 'x', 1)


@pytest.mark.dds
def test_two_argument_callbacks_get_message_info_with_the_publisher_gid(world):
    """A (msg, info) callback gets rclpy's MessageInfo keys and the sending writer's GUID."""
    node = dds_backend.DdsNode('informed')
    infos: list[MessageInfo] = []
    node.create_subscription(tf2_msgs.TFMessage, '/tf', lambda _msg, info: infos.append(info), 10)
    first = node.create_publisher(tf2_msgs.TFMessage, '/tf', 10)
    second = dds_backend.DdsNode('other').create_publisher(tf2_msgs.TFMessage, '/tf', 10)
    executor = dds_backend.SingleThreadedExecutor()
    executor.add_node(node)
    before = time.time_ns()
    first.publish(one_transform(1.0))
    second.publish(one_transform(2.0))
    assert spin_until(executor, lambda: len(infos) == 2)
    assert {info['publisher_gid'] for info in infos} == {first._writer.guid, second._writer.guid}
    assert first._writer.guid != second._writer.guid
    for info in infos:
        assert before <= info['source_timestamp'] <= info['received_timestamp']
        assert set(info) >= {'publication_sequence_number', 'reception_sequence_number'}


@pytest.mark.dds
def test_ros_discovery_info_follows_entity_and_node_changes(world):
    """ros_discovery_info is republished when a publisher or a node goes away."""
    from tf_demo.msgs import cdr
    from tf_demo.msgs import rmw_dds_common
    from tf_demo.transport.dds import wire as dds_wire

    participant = dds_wire.get_participant()
    reader = participant.create_reader(
        dds_wire.DISCOVERY_INFO_TOPIC,
        dds_wire.DISCOVERY_INFO_TYPE,
        dds_wire.EndpointQos(reliable=True, transient_local=True, keep_all=True),
        b'',
    )
    latest: list[rmw_dds_common.ParticipantEntitiesInfo] = []

    def nodes_now() -> dict[str, tuple[int, int]]:
        deadline = time.monotonic() + 5
        while time.monotonic() < deadline:
            payloads = reader.take()
            if payloads:
                latest.append(
                    cdr.deserialize(rmw_dds_common.ParticipantEntitiesInfo, payloads[-1])
                )
                break
            time.sleep(0.01)
        return {
            n.node_name: (len(n.reader_gid_seq), len(n.writer_gid_seq))
            for n in latest[-1].node_entities_info_seq
        }

    # Every node has rclpy's built-ins: the six parameter services (request readers, reply
    # writers) and the /parameter_events and /rosout writers.
    builtin_readers, builtin_writers = 6, 8
    keeper = dds_backend.DdsNode('keeper')
    node = dds_backend.DdsNode('changing')
    publisher = node.create_publisher(std_msgs.String, 'chatter', 10)
    assert nodes_now() == {
        'keeper': (builtin_readers, builtin_writers),
        'changing': (builtin_readers, builtin_writers + 1),
    }
    assert bytes(latest[-1].gid.data) == participant.guid
    node.destroy_publisher(publisher)
    assert nodes_now() == {
        'keeper': (builtin_readers, builtin_writers),
        'changing': (builtin_readers, builtin_writers),
    }
    node.destroy_node()
    assert nodes_now() == {'keeper': (builtin_readers, builtin_writers)}
    del keeper


def test_node_before_init_is_refused(dds_env):
    """Creating a node before init() (or after shutdown) raises a RuntimeError saying so."""
    dds_backend.init()
    dds_backend.shutdown()
    with pytest.raises(RuntimeError, match=r'call tf_demo\.transport\.init\(\) before'):
        dds_backend.DdsNode('early')


@pytest.mark.dds
def test_executor_keeps_working_after_shutdown_and_init_again(dds_env):
    """An executor made before shutdown() delivers messages again after a new init()."""
    dds_backend.init()
    executor = dds_backend.SingleThreadedExecutor()
    dds_backend.shutdown()
    dds_backend.init()
    try:
        node = dds_backend.DdsNode('reborn')
        received: list[object] = []
        node.create_subscription(std_msgs.String, 'echo', received.append, 10)
        node.create_publisher(std_msgs.String, 'echo', 10).publish(std_msgs.String(data='hi'))
        executor.add_node(node)
        assert spin_until(executor, lambda: len(received) == 1)
    finally:
        dds_backend.shutdown()


class Gate:
    """A minimal awaitable that yields until opened (rclpy Future's await protocol)."""

    def __init__(self) -> None:
        self.opened = False

    def __await__(self):
        while not self.opened:
            yield
        return 'open'


@pytest.mark.dds
def test_async_callbacks_run_as_tasks_until_their_await_completes(world):
    """An async timer callback awaiting a gate resumes once a subscription callback opens it."""
    node = dds_backend.DdsNode('awaiter')
    gate = Gate()
    outcomes: list[str] = []

    async def on_timer() -> None:
        timer.cancel()
        outcomes.append(await gate)

    timer = node.create_timer(0.01, on_timer)
    node.create_subscription(
        std_msgs.String, 'open', lambda _msg: setattr(gate, 'opened', True), 1
    )
    publisher = node.create_publisher(std_msgs.String, 'open', 1)
    executor = dds_backend.SingleThreadedExecutor()
    executor.add_node(node)
    for _ in range(10):
        executor.spin_once(timeout_sec=0.02)
    assert outcomes == []
    publisher.publish(std_msgs.String(data='now'))
    assert spin_until(executor, lambda: outcomes == ['open'])


@pytest.mark.dds
def test_create_task_result_and_exceptions_propagate(world):
    """create_task runs a coroutine to its result; an async callback's exception leaves spin."""
    node = dds_backend.DdsNode('tasks')
    executor = dds_backend.SingleThreadedExecutor()
    executor.add_node(node)

    async def answer() -> int:
        return 42

    task = executor.create_task(answer)
    executor.spin_until_future_complete(task, timeout_sec=5)
    assert task.done()
    assert task.result() == 42

    async def broken(_msg: object) -> None:
        raise ArithmeticError('callback failed')

    node.create_subscription(std_msgs.String, 'boom', broken, 1)
    node.create_publisher(std_msgs.String, 'boom', 1).publish(std_msgs.String(data='x'))
    with pytest.raises(ArithmeticError, match='callback failed'):
        spin_until(executor, lambda: False, timeout=5)


@pytest.mark.dds
def test_parameter_callbacks_validate_and_observe_changes(world):
    """On-set callbacks can reject a value; pre-set may add parameters; post-set sees results."""
    from tf_demo.transport.parameters import SetParametersResult

    node = dds_backend.DdsNode('params')
    node.declare_parameter('rate', 10.0)
    node.declare_parameter('unit', 'Hz')
    seen: list[list[str]] = []
    node.add_on_set_parameters_callback(
        lambda params: SetParametersResult(
            successful=all(p.name != 'rate' or p.value > 0 for p in params), reason='rate <= 0'
        )
    )
    node.add_pre_set_parameters_callback(
        lambda params: (
            [*params, Parameter('unit', value='kHz')]
            if any(p.name == 'rate' for p in params)
            else params
        )
    )
    node.add_post_set_parameters_callback(lambda params: seen.append([p.name for p in params]))
    (rejected,) = node.set_parameters([Parameter('rate', value=-1.0)])
    assert not rejected.successful
    assert rejected.reason == 'rate <= 0'
    assert node.get_parameter('rate').value == 10.0
    assert all(result.successful for result in node.set_parameters([Parameter('rate', value=2.0)]))
    assert node.get_parameter('rate').value == 2.0
    assert node.get_parameter('unit').value == 'kHz'
    assert seen == [['rate', 'unit']]


@pytest.mark.dds
def test_sim_time_timer_follows_clock_and_survives_a_backward_jump(world):
    """A 1 s timer on /clock time fires as sim time advances, also after /clock jumps back."""
    node = dds_backend.DdsNode(
        'sim_timer', parameter_overrides=[Parameter('use_sim_time', value=True)]
    )
    clock_node = dds_backend.DdsNode('sim_clock')
    clock_publisher = clock_node.create_publisher(
        rosgraph_msgs.Clock,
        '/clock',
        QoSProfile(depth=1, reliability=ReliabilityPolicy.BEST_EFFORT),
    )
    fired_at: list[int] = []
    node.create_timer(1.0, lambda: fired_at.append(node.get_clock().now().nanoseconds))
    executor = dds_backend.SingleThreadedExecutor()
    executor.add_node(node)

    def advance_to(seconds: float) -> None:
        target = round(seconds * 1e9)
        sec, nanosec = divmod(target, 1_000_000_000)
        deadline = time.monotonic() + 5
        while node.get_clock().now().nanoseconds != target and time.monotonic() < deadline:
            clock_publisher.publish(
                rosgraph_msgs.Clock(clock=builtin_interfaces.Time(sec=sec, nanosec=nanosec))
            )
            executor.spin_once(timeout_sec=0.02)
        for _ in range(3):
            executor.spin_once(timeout_sec=0.02)

    for seconds in (100.0, 100.5, 101.2):
        advance_to(seconds)
    # Created at sim time 0, the timer is overdue when /clock jumps to 100 s (as in rcl).
    assert fired_at == [100_000_000_000, 101_200_000_000]
    for seconds in (10.0, 10.6, 11.3):
        advance_to(seconds)
    assert fired_at == [100_000_000_000, 101_200_000_000, 11_300_000_000]


def test_second_shutdown_raises_like_rclpy_and_try_shutdown_is_quiet(dds_env):
    """shutdown() twice raises RuntimeError (rclpy's Context); try_shutdown() never does."""
    dds_backend.init(args=['prog'])
    dds_backend.shutdown()
    with pytest.raises(RuntimeError, match='already called'):
        dds_backend.shutdown()
    dds_backend.try_shutdown()
    dds_backend.init()
    dds_backend.try_shutdown()
    assert not dds_backend.ok()


@pytest.mark.dds
def test_endpoint_options_the_backend_cannot_honour_are_refused(world):
    """event_callbacks / qos_overriding_options raise instead of being ignored; typos TypeError."""
    node = dds_backend.DdsNode('options')
    with pytest.raises(NotImplementedError, match='qos_overriding_options'):
        node.create_publisher(std_msgs.String, 'x', 10, qos_overriding_options=object())
    with pytest.raises(NotImplementedError, match='event_callbacks'):
        node.create_subscription(std_msgs.String, 'x', print, 10, event_callbacks=object())
    with pytest.raises(TypeError):
        node.create_publisher(std_msgs.String, 'x', 10, callback_grup=None)  # type: ignore[call-arg]
    assert node.publishers == []
    assert node.subscriptions == []
