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
Benchmark of the standalone (DDS) transport, across real processes on loopback.

1. Publish cost of a 1-transform TFMessage through ``DdsNode`` (serialize + write), with one
   matched reliable subscriber in another process (target <= 20 us).
2. A listener ingesting 1,000 msg/s of 50-transform TFMessages for a few seconds: messages lost
   (target 0) and the listener process' CPU use (target < 100 % of one core), for a plain
   decoding subscription and for tf_demo's TransformListener filling a Buffer.
3. One-way latency at 1 kHz, 1 transform, stamp = CLOCK_REALTIME at publish (target p50 <= 200 us).
4. The TransformListener's capacity: 50-transform messages at rising rates (pre-encoded by the
   source, so the source is never the limit) until one is lost; the highest rate received with 0
   loss, in transforms/s, and the listener's CPU there (target >= 1,000,000 transforms/s on one
   core).

Run: ``.venv/bin/python bench/bench_transport.py [--seconds 5]``. Uses ``ROS_DOMAIN_ID`` if set
(else 231) with loopback-only discovery.
"""

from __future__ import annotations

import argparse
import json
import os
from pathlib import Path
import statistics
import sys
import time

sys.path.insert(0, str(Path(__file__).resolve().parent.parent))

from _flow import build_line
from _flow import FlowMeter
from _flow import last_json
from _flow import start_role
from tf_demo.msgs import cdr
from tf_demo.msgs import geometry_msgs
from tf_demo.msgs import tf2_msgs
from tf_demo.transport import dds_backend
from tf_demo.transport.clock import Duration
from tf_demo.transport.qos import DynamicBroadcasterQoS

TOPIC = '/bench_tf'


def tf_message(transforms: int, stamp_ns: int = 0, first_x: float = 0.0) -> tf2_msgs.TFMessage:
    items = []
    for index in range(transforms):
        t = geometry_msgs.TransformStamped()
        t.header.stamp.sec, t.header.stamp.nanosec = divmod(stamp_ns, 1_000_000_000)
        t.header.frame_id = 'odom' if index == 0 else f'link_{index - 1}'
        t.child_frame_id = f'link_{index}'
        t.transform.translation.x = first_x
        t.transform.translation.y = 0.1 * index
        t.transform.rotation.w = 1.0
        items.append(t)
    return tf2_msgs.TFMessage(transforms=items)


def percentile(values: list[float], fraction: float) -> float:
    ordered = sorted(values)
    return ordered[min(len(ordered) - 1, int(fraction * len(ordered)))]


# -- roles run in child processes ---------------------------------------------------------------


def run_sink(args: argparse.Namespace) -> None:
    """Count (and time) messages until ``--expect`` arrived or the source went quiet."""
    dds_backend.init()
    node = dds_backend.DdsNode('bench_sink')
    meter = FlowMeter()
    latencies_us: list[float] = []

    def on_message(msg: tf2_msgs.TFMessage | bytes) -> None:  # bytes: the listener's raw /tf
        meter.count()
        if args.latency and isinstance(msg, tf2_msgs.TFMessage):  # never with --listener
            stamp = msg.transforms[0].header.stamp
            sent_ns = stamp.sec * 1_000_000_000 + stamp.nanosec
            latencies_us.append((time.time_ns() - sent_ns) / 1000.0)

    if args.listener:
        from tf_demo.ros import Buffer
        from tf_demo.ros import TransformListener

        buffer = Buffer(node=node)
        listener = TransformListener(buffer, node, tf_topic=TOPIC)
        subscription = listener.tf_sub
        assert subscription is not None  # the listener subscribes /tf when it is created
        insert = subscription.callback

        def insert_and_count(msg: bytes, info: dict[str, object]) -> None:
            insert(msg, info)  # the listener's raw callback takes the sample info (its writer)
            on_message(msg)

        subscription.callback = insert_and_count
    else:
        node.create_subscription(tf2_msgs.TFMessage, TOPIC, on_message, DynamicBroadcasterQoS())
    executor = dds_backend.SingleThreadedExecutor()
    executor.add_node(node)
    print('ready', flush=True)
    meter.spin_until(lambda: executor.spin_once(timeout_sec=0.1), args.expect, args.timeout)
    # CPU share while messages were flowing (first to last hundredth message).
    wall, cpu = meter.wall_s(), meter.cpu_s()
    result = {'received': meter.received, 'cpu_percent': 100.0 * cpu / wall if wall else 0.0}
    if latencies_us:
        result['p50_us'] = percentile(latencies_us, 0.50)
        result['p99_us'] = percentile(latencies_us, 0.99)
    print(json.dumps(result), flush=True)
    dds_backend.shutdown()


def run_source(args: argparse.Namespace) -> None:
    """Publish ``--count`` messages at ``--rate`` Hz once the sink matched."""
    dds_backend.init()
    node = dds_backend.DdsNode('bench_source')
    publisher = node.create_publisher(tf2_msgs.TFMessage, TOPIC, DynamicBroadcasterQoS())
    while publisher.get_subscription_count() == 0:
        time.sleep(0.01)
    time.sleep(0.2)
    template = tf_message(args.transforms)
    period = 1.0 / args.rate
    encoded: list[bytes] = []
    if args.pre_encoded:  # stamps 1 ms apart from now; publishing bytes costs the source little
        start_ns = time.time_ns()
        for index in range(args.count):
            sec, nanosec = divmod(start_ns + index * 1_000_000, 1_000_000_000)
            for transform in template.transforms:
                transform.header.stamp.sec, transform.header.stamp.nanosec = sec, nanosec
            encoded.append(cdr.serialize(template))
    next_time = time.monotonic()
    for index in range(args.count):
        if encoded:
            publisher.publish(encoded[index])
        else:
            sec, nanosec = divmod(time.time_ns(), 1_000_000_000)
            for transform in template.transforms:
                transform.header.stamp.sec, transform.header.stamp.nanosec = sec, nanosec
            template.transforms[0].transform.translation.x = float(index)
            publisher.publish(template)
        next_time += period
        delay = next_time - time.monotonic()
        if delay > 0:
            time.sleep(delay)
    publisher.wait_for_all_acked(Duration(seconds=5.0))
    print(json.dumps({'sent': args.count}), flush=True)
    dds_backend.shutdown()


# -- orchestration ------------------------------------------------------------------------------


def bench_publish_cost(env: dict[str, str], calls: int) -> None:
    raw_calls = min(calls, 5000)
    sink = start_role(
        __file__, env, '--role', 'sink', '--expect', str(calls + raw_calls), '--timeout', '120'
    )
    assert sink.stdout is not None
    sink.stdout.readline()
    dds_backend.init()
    node = dds_backend.DdsNode('bench_publisher')
    publisher = node.create_publisher(tf2_msgs.TFMessage, TOPIC, DynamicBroadcasterQoS())
    while publisher.get_subscription_count() == 0:
        time.sleep(0.01)
    message = tf_message(1)
    payload = cdr.serialize(message)
    samples_us: list[float] = []
    for index in range(calls):
        message.transforms[0].transform.translation.x = float(index)
        start = time.perf_counter_ns()
        publisher.publish(message)
        samples_us.append((time.perf_counter_ns() - start) / 1000.0)
        if index % 64 == 63:
            time.sleep(0.0005)  # let the subscriber keep up (KEEP_LAST 100, no loss wanted)
    start = time.perf_counter_ns()
    for _ in range(calls):
        cdr.serialize(message)
    serialize_us = (time.perf_counter_ns() - start) / 1000.0 / calls
    raw_us: list[float] = []
    for index in range(raw_calls):
        start = time.perf_counter_ns()
        publisher.publish(payload)
        raw_us.append((time.perf_counter_ns() - start) / 1000.0)
        if index % 64 == 63:
            time.sleep(0.0005)
    publisher.wait_for_all_acked(Duration(seconds=5.0))
    dds_backend.shutdown()
    sink.kill()
    sink.wait()
    print(
        f'publish 1-transform TFMessage: mean {statistics.fmean(samples_us):.1f} us, '
        f'p50 {percentile(samples_us, 0.5):.1f} us, p99 {percentile(samples_us, 0.99):.1f} us '
        f'(target <= 20 us; serialize alone {serialize_us:.1f} us, '
        f'write of pre-encoded bytes p50 {percentile(raw_us, 0.5):.1f} us)'
    )


def run_pair(
    sink_args: list[str], source_args: list[str], timeout: float
) -> tuple[int, dict[str, float]]:
    """Start a sink, then a source; return what the source sent and the sink's verdict."""
    env = dict(os.environ)
    sink = start_role(__file__, env, '--role', 'sink', '--timeout', str(timeout), *sink_args)
    assert sink.stdout is not None
    sink.stdout.readline()
    source = start_role(__file__, env, '--role', 'source', *source_args)
    sent = int(last_json(source, timeout + 60).get('sent', 0))
    return sent, last_json(sink, timeout + 60)


def bench_ingest(seconds: float, *, listener: bool) -> None:
    count = int(1000 * seconds)
    sent, result = run_pair(
        ['--expect', str(count), *(['--listener'] if listener else [])],
        ['--count', str(count), '--rate', '1000', '--transforms', '50'],
        seconds + 30,
    )
    what = 'TransformListener -> Buffer' if listener else 'DdsNode subscription (decode)'
    lost = int(sent - result.get('received', 0))
    print(
        f'ingest 1000 msg/s x 50 transforms, {what}: received {result.get("received", 0)}/'
        f'{sent} (lost {lost}, target 0), listener CPU '
        f'{result.get("cpu_percent", 0.0):.0f} % of one core (target < 100 %)'
    )


def bench_listener_capacity(seconds: float) -> None:
    """Raise the rate of 50-transform messages until the TransformListener loses one."""
    best: tuple[int, float] | None = None
    for rate in (1000, 2000, 3000, 4000, 5000, 6000, 8000):
        count = int(rate * seconds)
        sent, result = run_pair(
            ['--expect', str(count), '--listener'],
            ['--count', str(count), '--rate', str(rate), '--transforms', '50', '--pre-encoded'],
            seconds + 60,
        )
        received = int(result.get('received', 0))
        cpu = result.get('cpu_percent', 0.0)
        print(
            f'  listener at {rate} msg/s x 50 = {50 * rate} transforms/s: received '
            f'{received}/{sent}, CPU {cpu:.0f} % of one core'
        )
        if received < sent:
            break
        best = (50 * rate, cpu)
    if best is None:
        print('TransformListener capacity: lost messages already at 50,000 transforms/s')
        return
    verdict = 'ok' if best[0] >= 1_000_000 else 'MISSED'
    print(
        f'TransformListener capacity: {best[0]} transforms/s with 0 loss at {best[1]:.0f} % of '
        f'one core (target >= 1,000,000 transforms/s) {verdict}'
    )


def bench_latency(seconds: float) -> None:
    count = int(1000 * seconds)
    _, result = run_pair(
        ['--expect', str(count), '--latency'],
        ['--count', str(count), '--rate', '1000', '--transforms', '1'],
        seconds + 30,
    )
    print(
        f'one-way latency 1 kHz, 1 transform: p50 {result.get("p50_us", float("nan")):.0f} us, '
        f'p99 {result.get("p99_us", float("nan")):.0f} us (target p50 <= 200 us; '
        f'received {result.get("received", 0)}/{count})'
    )


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[1])
    parser.add_argument('--role', choices=['main', 'sink', 'source'], default='main')
    parser.add_argument('--seconds', type=float, default=5.0)
    parser.add_argument('--expect', type=int, default=0)
    parser.add_argument('--count', type=int, default=0)
    parser.add_argument('--rate', type=float, default=1000.0)
    parser.add_argument('--transforms', type=int, default=1)
    parser.add_argument('--timeout', type=float, default=60.0)
    parser.add_argument('--latency', action='store_true')
    parser.add_argument('--listener', action='store_true')
    parser.add_argument('--pre-encoded', action='store_true')
    parser.add_argument(
        '--only',
        choices=['publish', 'ingest', 'listener', 'latency', 'capacity'],
        help='run one benchmark',
    )
    args = parser.parse_args()
    if args.role == 'sink':
        run_sink(args)
        return
    if args.role == 'source':
        run_source(args)
        return
    # This process and its children: loopback, the benchmark's own domain, the DDS world.
    os.environ.setdefault('ROS_DOMAIN_ID', '231')
    os.environ['ROS_AUTOMATIC_DISCOVERY_RANGE'] = 'LOCALHOST'
    os.environ['TF_DEMO_BACKEND'] = 'dds'
    os.environ.pop('ROS_LOCALHOST_ONLY', None)
    env = dict(os.environ)
    print(f'tf_demo build: {build_line()}')
    print(f'tf_demo DDS transport benchmark (domain {env["ROS_DOMAIN_ID"]}, loopback)')
    if args.only in (None, 'publish'):
        bench_publish_cost(env, 20000)
    if args.only in (None, 'ingest'):
        bench_ingest(args.seconds, listener=False)
    if args.only in (None, 'listener'):
        bench_ingest(args.seconds, listener=True)
    if args.only in (None, 'latency'):
        bench_latency(args.seconds)
    if args.only in (None, 'capacity'):
        bench_listener_capacity(min(args.seconds, 3.0))


if __name__ == '__main__':
    main()
