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
tf_demo inside a real ROS 2 Jazzy against the real tf2_ros, measured in the same run.

1. ``tf_demo.ros.Buffer`` vs ``tf2_ros.Buffer`` on the same REP-105 tree, rclpy messages in and
   out: ``lookup_transform('map', 'camera_link', t)`` at a new interior stamp per call, at
   ``Time()`` (latest), ``can_transform``, and ``set_transform(TransformStamped)``; the median of
   per-round ratios ours/tf2_ros (targets <= 0.35, 0.5, 0.5 and 0.8).
2. A listener process ingesting 1,000 msg/s x 50 transforms that another process publishes for
   ``--seconds`` (default 10): messages lost (target 0) and the listener process' CPU, our
   TransformListener vs tf2_ros's in the same run (target: ours <= 0.2x of theirs), served by
   the user's ``SingleThreadedExecutor`` and with ``spin_thread=True``; and the floor of the
   first: rclpy's executor serving a raw subscription whose callback only counts.

Run inside a sourced Jazzy: ``python bench/bench_ros_world.py [--seconds 10] [--rounds 7]``.
Uses ``ROS_DOMAIN_ID`` if set (else 232), loopback only.
"""

from __future__ import annotations

import argparse
from collections.abc import Callable
import importlib.util
import json
import os
from pathlib import Path
import statistics
import sys
import time
from typing import Any

# tf_demo as the sourced overlay installed it (colcon build compiles it), else this checkout.
if importlib.util.find_spec('tf_demo') is None:
    sys.path.insert(0, str(Path(__file__).resolve().parent.parent))

from _flow import build_line
from _flow import FlowMeter
from _flow import last_json
from _flow import start_role

TOPIC = '/tf'
S = 1_000_000_000
#: REP-105 with a camera: (parent, child, static).
TREE = (
    ('map', 'odom', False),
    ('odom', 'base_footprint', False),
    ('base_footprint', 'base_link', True),
    ('base_link', 'torso', True),
    ('torso', 'head', True),
    ('head', 'camera_link', True),
)
STAMPS = 200  # dynamic samples per link, 10 ms apart


def transform_msg(parent: str, child: str, stamp_ns: int, x: float) -> Any:
    from builtin_interfaces.msg import Time
    from geometry_msgs.msg import TransformStamped

    t = TransformStamped()
    sec, nanosec = divmod(stamp_ns, S)
    t.header.stamp = Time(sec=sec, nanosec=nanosec)
    t.header.frame_id = parent
    t.child_frame_id = child
    t.transform.translation.x = x
    t.transform.translation.y = 0.25
    t.transform.rotation.z = 0.2588190451025208
    t.transform.rotation.w = 0.9659258262890683
    return t


def fill(buffer: Any) -> None:
    for parent, child, static in TREE:
        if static:
            buffer.set_transform_static(transform_msg(parent, child, 0, 0.1), 'bench')
            continue
        for index in range(STAMPS):
            buffer.set_transform(
                transform_msg(parent, child, S + index * 10_000_000, 0.01 * index), 'bench'
            )


def timed(call: Callable[[int], object], calls: int) -> float:
    """Mean ns per call of ``call(i)``."""
    start = time.perf_counter_ns()
    for index in range(calls):
        call(index)
    return (time.perf_counter_ns() - start) / calls


def bench_buffers(rounds: int, calls: int) -> None:
    import rclpy
    from rclpy.time import Time
    import tf2_ros
    from tf_demo.ros import Buffer

    rclpy.init()
    ours, theirs = Buffer(), tf2_ros.Buffer()
    fill(ours)
    fill(theirs)
    interior = [Time(nanoseconds=S + 5_000_000 + 9_000_000 * (i % 200)) for i in range(calls)]
    latest = Time()
    sample = [transform_msg('odom', 'base_footprint', S + 3 * S + i, 0.5) for i in range(calls)]

    def workloads(buffer: Any) -> dict[str, Callable[[int], object]]:
        return {
            "lookup_transform('map', 'camera_link', t)": lambda i: buffer.lookup_transform(
                'map', 'camera_link', interior[i]
            ),
            'lookup_transform at Time() (latest)': lambda i: buffer.lookup_transform(
                'map', 'camera_link', latest
            ),
            'can_transform': lambda i: buffer.can_transform('map', 'camera_link', interior[i]),
            'set_transform(TransformStamped)': lambda i: buffer.set_transform(sample[i], 'bench'),
        }

    targets = {
        "lookup_transform('map', 'camera_link', t)": 0.35,
        'lookup_transform at Time() (latest)': 0.5,
        'can_transform': 0.5,
        'set_transform(TransformStamped)': 0.8,
    }
    ours_work, their_work = workloads(ours), workloads(theirs)
    # Same answers before timing: a benchmark of two different computations means nothing.
    a = ours.lookup_transform('map', 'camera_link', interior[7]).transform.translation
    b = theirs.lookup_transform('map', 'camera_link', interior[7]).transform.translation
    assert max(abs(a.x - b.x), abs(a.y - b.y), abs(a.z - b.z)) < 1e-9, (a, b)
    print(f'{"workload":44s} {"ours":>9s} {"tf2_ros":>9s} {"ratio":>6s} target')
    for name in targets:
        ratios, ours_ns, their_ns = [], [], []
        for _ in range(rounds):
            mine = timed(ours_work[name], calls)
            theirs_time = timed(their_work[name], calls)
            ours_ns.append(mine)
            their_ns.append(theirs_time)
            ratios.append(mine / theirs_time)
        ratio = statistics.median(ratios)
        verdict = 'ok' if ratio <= targets[name] else 'MISSED'
        print(
            f'{name:44s} {statistics.median(ours_ns) / 1000:7.1f}us '
            f'{statistics.median(their_ns) / 1000:7.1f}us {ratio:6.2f} <= {targets[name]} '
            f'{verdict}'
        )
    rclpy.shutdown()


# -- the ingest run: child processes ----------------------------------------------------------


def run_publisher(args: argparse.Namespace) -> None:
    """Publish ``--count`` 50-transform TFMessages at 1 kHz as serialized bytes."""
    import rclpy
    from tf2_msgs.msg import TFMessage
    from tf_demo.msgs import cdr
    from tf_demo.msgs import geometry_msgs
    from tf_demo.msgs import tf2_msgs
    from tf_demo.transport.qos import DynamicBroadcasterQoS

    rclpy.init()
    node = rclpy.create_node('bench_tf_publisher')
    publisher = node.create_publisher(TFMessage, TOPIC, DynamicBroadcasterQoS())
    while publisher.get_subscription_count() == 0:
        time.sleep(0.01)
    time.sleep(0.5)
    transforms = []
    for index in range(50):
        t = geometry_msgs.TransformStamped()
        t.header.frame_id = 'odom' if index == 0 else f'link_{index - 1}'
        t.child_frame_id = f'link_{index}'
        t.transform.translation.y = 0.1 * index
        t.transform.rotation.w = 1.0
        transforms.append(t)
    message = tf2_msgs.TFMessage(transforms=transforms)
    next_time = time.monotonic()
    for index in range(args.count):
        sec, nanosec = divmod(time.time_ns(), S)
        for t in transforms:
            t.header.stamp.sec, t.header.stamp.nanosec = sec, nanosec
        transforms[0].transform.translation.x = float(index)
        publisher.publish(cdr.serialize(message))
        next_time += 0.001
        delay = next_time - time.monotonic()
        if delay > 0:
            time.sleep(delay)
    time.sleep(1.0)
    print(json.dumps({'sent': args.count}), flush=True)
    node.destroy_node()
    rclpy.shutdown()


def run_listener(args: argparse.Namespace) -> None:
    """Count what a TransformListener (ours or tf2_ros's) takes in, and this process' CPU."""
    import rclpy
    from rclpy.executors import SingleThreadedExecutor

    rclpy.init()
    node = rclpy.create_node('bench_tf_listener')
    buffer: Any
    listener: Any
    if args.impl == 'floor':
        run_floor(args, node)
        return
    if args.impl == 'ours':
        import tf_demo.ros

        buffer = tf_demo.ros.Buffer()
        listener = tf_demo.ros.TransformListener(buffer, node, spin_thread=args.spin_thread)
    else:
        import tf2_ros

        buffer = tf2_ros.Buffer()
        listener = tf2_ros.TransformListener(buffer, node, spin_thread=args.spin_thread)
    meter = FlowMeter()
    subscription = listener.tf_sub
    insert = subscription.callback
    if args.impl == 'ours':  # raw: the callback takes (bytes, message info)

        def counted_raw(data: bytes, info: dict[str, object]) -> None:
            insert(data, info)
            meter.count()

        subscription.callback = counted_raw
    else:

        def counted(message: object) -> None:
            insert(message)
            meter.count()

        subscription.callback = counted
    print('ready', flush=True)
    if args.spin_thread:  # the listener's own thread delivers: this one only waits
        meter.spin_until(lambda: time.sleep(0.05), args.count, args.timeout)
    else:
        executor = SingleThreadedExecutor()
        executor.add_node(node)
        meter.spin_until(lambda: executor.spin_once(timeout_sec=0.1), args.count, args.timeout)
    frames = len(buffer.all_frames_as_yaml().split('parent:')) - 1
    result = {'received': meter.received, 'cpu_s': meter.cpu_s(), 'wall_s': meter.wall_s()}
    print(json.dumps({**result, 'frames': frames}))
    own_executor = getattr(listener, 'executor', None)  # tf2_ros's spin_thread executor
    if own_executor is not None:
        own_executor.shutdown()
    rclpy.shutdown()


def run_floor(args: argparse.Namespace, node: Any) -> None:
    """Count raw /tf messages with a callback that does nothing else: the executor's own cost."""
    import rclpy
    from rclpy.executors import SingleThreadedExecutor
    from tf2_msgs.msg import TFMessage

    meter = FlowMeter()
    node.create_subscription(
        TFMessage, TOPIC, lambda data: meter.count(), 100, raw=True
    )  # fmt: skip
    executor = SingleThreadedExecutor()
    executor.add_node(node)
    print('ready', flush=True)
    meter.spin_until(lambda: executor.spin_once(timeout_sec=0.1), args.count, args.timeout)
    result = {'received': meter.received, 'cpu_s': meter.cpu_s(), 'wall_s': meter.wall_s()}
    print(json.dumps(result))
    rclpy.shutdown()


def ingest(env: dict[str, str], impl: str, seconds: float, *extra: str) -> dict[str, float]:
    count = int(1000 * seconds)
    listener = start_role(
        __file__,
        env, '--role', 'listener', '--impl', impl, '--count', str(count),
        '--timeout', str(seconds + 60), *extra,
    )  # fmt: skip
    assert listener.stdout is not None
    listener.stdout.readline()
    publisher = start_role(__file__, env, '--role', 'publisher', '--count', str(count))
    sent = last_json(publisher, seconds + 90).get('sent', 0)
    result = last_json(listener, seconds + 90)
    result['sent'] = sent
    return result


#: The ingest runs: (label, --impl, extra arguments).
INGEST_RUNS = (
    ("tf2_ros TransformListener, the user's executor", 'tf2_ros', ()),
    ("ours    TransformListener, the user's executor", 'ours', ()),
    ("floor: rclpy's executor, a raw callback that only counts", 'floor', ()),
    ('tf2_ros TransformListener, spin_thread=True', 'tf2_ros', ('--spin-thread',)),
    ('ours    TransformListener, spin_thread=True', 'ours', ('--spin-thread',)),
)


def bench_ingest(seconds: float) -> None:
    env = dict(os.environ)
    env.setdefault('ROS_DOMAIN_ID', '232')
    env['ROS_AUTOMATIC_DISCOVERY_RANGE'] = 'LOCALHOST'
    results = {label: ingest(env, impl, seconds, *extra) for label, impl, extra in INGEST_RUNS}
    per_message = {}
    for label, result in results.items():
        wall = result.get('wall_s', 0.0) or float('nan')
        per_message[label] = result.get('cpu_s', 0.0) / max(1.0, result.get('received', 0.0))
        print(
            f'ingest 1000 msg/s x 50 transforms, {label}: received '
            f'{int(result.get("received", 0))}/{int(result["sent"])} '
            f'(lost {int(result["sent"] - result.get("received", 0))}, target 0), '
            f'{int(result.get("frames", 0))} frames, CPU {result.get("cpu_s", 0.0):.2f} s '
            f'over {wall:.2f} s ({100 * result.get("cpu_s", 0.0) / wall:.0f} % of a core), '
            f'{1e6 * per_message[label]:.0f} us per message'
        )
    # A listener that cannot keep up spends its CPU on fewer messages: per message as well.
    labels = [label for label, _, _ in INGEST_RUNS]
    for theirs, ours, mode in ((0, 1, "the user's executor"), (3, 4, 'spin_thread=True')):
        their_cpu = results[labels[theirs]].get('cpu_s', 0.0) or float('nan')
        ratio = results[labels[ours]].get('cpu_s', 0.0) / their_cpu
        per = per_message[labels[ours]] / (per_message[labels[theirs]] or float('nan'))
        verdict = 'ok' if ratio <= 0.2 else 'MISSED'
        print(
            f'listener CPU ours/tf2_ros, {mode}: {ratio:.2f} (target <= 0.2) {verdict}; '
            f'per received message {per:.2f}'
        )
    floor = per_message[labels[2]] / (per_message[labels[0]] or float('nan'))
    print(
        f"rclpy's executor alone (floor) costs {floor:.2f} of tf2_ros's CPU per message: "
        "no listener served by the user's executor can go below it"
    )


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[1])
    parser.add_argument('--role', choices=('main', 'publisher', 'listener'), default='main')
    parser.add_argument('--impl', choices=('ours', 'tf2_ros', 'floor'), default='ours')
    parser.add_argument('--count', type=int, default=10_000)
    parser.add_argument('--timeout', type=float, default=60.0)
    parser.add_argument('--spin-thread', action='store_true')
    parser.add_argument('--seconds', type=float, default=10.0)
    parser.add_argument('--rounds', type=int, default=7)
    parser.add_argument('--calls', type=int, default=2000)
    parser.add_argument('--skip-ingest', action='store_true')
    args = parser.parse_args()
    try:
        import rclpy  # noqa: F401
        import tf2_ros  # noqa: F401
    except ImportError:
        sys.exit('bench_ros_world.py runs inside ROS 2 Jazzy: source /opt/ros/jazzy/setup.bash')
    os.environ['TF_DEMO_BACKEND'] = 'rclpy'
    if args.role == 'main':
        print(f'tf_demo build: {build_line()}')
    if args.role == 'publisher':
        run_publisher(args)
    elif args.role == 'listener':
        run_listener(args)
    else:
        bench_buffers(args.rounds, args.calls)
        if not args.skip_ingest:
            bench_ingest(args.seconds)


if __name__ == '__main__':
    main()
