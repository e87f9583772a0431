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
robot_state_publisher benchmark on real robots (needs ../shared/robots/{pr2,panda}.urdf).

1. Cost per JointState message for the PR2 (~30 moving joints): compute (mimics, closed-form
   quaternions) + encode the TFMessage, and the node's whole per-message path; target <= 100 us.
2. FK agreement with pinocchio for Panda and PR2 (random configurations within limits).
3. Sustained 1 kHz PR2 joint_states through a robot_state_publisher process over DDS: messages
   sent, /tf messages received, lost; the node's CPU time per message.

Run: ``.venv/bin/python bench/bench_rsp.py [--seconds 5] [--robots DIR]``.
"""

from __future__ import annotations

import argparse
import math
import os
from pathlib import Path
import random
import subprocess
import sys
import tempfile
import time

REPO = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(REPO))

from _flow import build_line  # noqa: E402 (bench/ is on the path)
from tf_demo.core.math3d import matrix_from_quat  # noqa: E402
from tf_demo.msgs.cdr import TfMessageEncoder  # noqa: E402
from tf_demo.nodes.robot_state_publisher import JointStateThrottle  # noqa: E402
from tf_demo.nodes.robot_state_publisher import positions_from_joint_state  # noqa: E402
from tf_demo.nodes.robot_state_publisher import publish_interval_ns  # noqa: E402
from tf_demo.testing.urdf_strategies import pinocchio_link_poses  # noqa: E402
from tf_demo.testing.urdf_strategies import random_positions  # noqa: E402
from tf_demo.urdf import RobotModel  # noqa: E402

SECOND = 1_000_000_000


def best_of(repeats: int, loops: int, action) -> float:
    """Smallest mean time per call in seconds over ``repeats`` runs of ``loops`` calls."""
    best = math.inf
    for _ in range(repeats):
        start = time.perf_counter()
        for _ in range(loops):
            action()
        best = min(best, (time.perf_counter() - start) / loops)
    return best


def bench_per_message(pr2: RobotModel) -> None:
    rng = random.Random(1)
    positions = random_positions(pr2, rng)
    # a realistic JointState: every movable joint incl. mimics, as joint_state_publisher sends
    names = [j.name for j in pr2.joints if j.type in {'revolute', 'continuous', 'prismatic'}]
    values = pr2.resolve_positions(positions)
    message_positions = [values[n] for n in names]
    encoder = TfMessageEncoder()
    transforms = pr2.joint_transforms(positions)
    print(
        f'PR2: {len(pr2.movable_joints)} free movable joints, {len(names)} names per JointState, '
        f'{len(transforms)} transforms per /tf message, {len(pr2.static_transforms())} static'
    )

    compute = best_of(5, 2000, lambda: pr2.joint_transforms(positions))
    encode = best_of(5, 2000, lambda: encoder.encode(transforms, 1700000000, 123))
    both = best_of(5, 2000, lambda: encoder.encode(pr2.joint_transforms(positions), 1, 2))
    throttle = JointStateThrottle()
    interval = publish_interval_ns(1000.0)
    stamp = [SECOND]

    def callback_path() -> bytes:
        stamp[0] += 2_000_000
        throttle.should_publish(names, stamp[0], stamp[0], interval, False)
        data = encoder.encode(
            pr2.joint_transforms(positions_from_joint_state(names, message_positions)), 1, 2
        )
        throttle.record(names, stamp[0])
        return data

    path = best_of(5, 2000, callback_path)
    print(f'  compute transforms        {compute * 1e6:7.1f} us')
    print(f'  encode TFMessage (CDR)    {encode * 1e6:7.1f} us')
    print(f'  compute + encode          {both * 1e6:7.1f} us   (target <= 100 us)')
    print(
        f'  node callback path        {path * 1e6:7.1f} us   (size check aside: map, throttle, '
        'mimics, transforms, encode)'
    )
    try:
        from tf_demo.msgs import cdr
        from tf_demo.msgs import geometry_msgs
        from tf_demo.msgs import tf2_msgs

        def via_messages() -> bytes:
            message = tf2_msgs.TFMessage(transforms=[])
            for parent, child, (tx, ty, tz), (qx, qy, qz, qw) in pr2.joint_transforms(positions):
                stamped = geometry_msgs.TransformStamped()
                stamped.header.stamp.sec = 1
                stamped.header.frame_id = parent
                stamped.child_frame_id = child
                stamped.transform.translation.x = tx
                stamped.transform.translation.y = ty
                stamped.transform.translation.z = tz
                rotation = stamped.transform.rotation
                rotation.x, rotation.y, rotation.z, rotation.w = qx, qy, qz, qw
                message.transforms.append(stamped)
            return cdr.serialize(message)

        assert via_messages()[4:] != b''
        generic = best_of(3, 500, via_messages)
        print(
            f'  same via message objects + generic codec {generic * 1e6:7.1f} us '
            f'({generic / both:.1f}x the direct encoder)'
        )
    except ImportError:
        pass


def bench_fk(model: RobotModel, label: str, configurations: int = 200) -> None:
    rng = random.Random(label)
    worst_t = worst_r = 0.0
    for _ in range(configurations):
        positions = random_positions(model, rng)
        ours = model.link_poses(positions)
        theirs = pinocchio_link_poses(model, positions)
        for link, (t, q) in ours.items():
            pin_t, pin_r = theirs[link]
            worst_t = max(worst_t, *(abs(a - b) for a, b in zip(t, pin_t, strict=True)))
            for row, pin_row in zip(matrix_from_quat(q), pin_r, strict=True):
                worst_r = max(worst_r, *(abs(a - b) for a, b in zip(row, pin_row, strict=True)))
    verdict = 'OK' if max(worst_t, worst_r) < 1e-9 else 'MISMATCH'
    print(
        f'FK vs pinocchio, {label}: {configurations} configurations x {len(model.links)} links: '
        f'max |dt| {worst_t:.1e} m, max |dR| {worst_r:.1e}  {verdict}'
    )


def cpu_seconds(pid: int) -> float:
    fields = Path(f'/proc/{pid}/stat').read_text().rsplit(')', 1)[1].split()
    return (int(fields[11]) + int(fields[12])) / os.sysconf('SC_CLK_TCK')


RELIABLE_JOINT_STATES = """robot_state_publisher:
  ros__parameters:
    qos_overrides:
      /joint_states:
        subscription:
          reliability: reliable
          depth: 100
"""


# A separate process counts /tf messages (raw CDR, KEEP_ALL reliable) so that the publishing
# loop's GIL does not slow the counting down; it prints "ready" then, on "stop", the count.
COUNTER = """
import sys, threading
from tf_demo import transport
from tf_demo.transport.executors import SingleThreadedExecutor
from tf_demo.transport.messages import tf2_msgs
from tf_demo.transport.qos import HistoryPolicy, QoSProfile
transport.init(['tf_counter'])
node = transport.create_node('tf_counter')
count = [0]
node.create_subscription(
    tf2_msgs.TFMessage, '/tf', lambda _m: count.__setitem__(0, count[0] + 1),
    QoSProfile(history=HistoryPolicy.KEEP_ALL, depth=1000), raw=True)
executor = SingleThreadedExecutor()
executor.add_node(node)
stop = threading.Event()
def spin():
    while not stop.is_set():
        executor.spin_once(timeout_sec=0.05)
thread = threading.Thread(target=spin, daemon=True)
thread.start()
print('ready', flush=True)
sys.stdin.readline()
stop.set()
thread.join()
print(count[0], flush=True)
node.destroy_node()
transport.shutdown()
"""


def bench_dds(pr2_path: Path, pr2: RobotModel, seconds: float, *, reliable: bool) -> None:
    domain = 150 + (os.getpid() + int(reliable)) % 60
    os.environ.update(
        {
            'ROS_DOMAIN_ID': str(domain),
            'ROS_AUTOMATIC_DISCOVERY_RANGE': 'LOCALHOST',
            'TF_DEMO_BACKEND': 'dds',
        }
    )
    os.environ.pop('ROS_LOCALHOST_ONLY', None)
    env = dict(os.environ, PYTHONPATH=str(REPO), PYTHONUNBUFFERED='1')
    code = 'import sys; from tf_demo.nodes.robot_state_publisher import main; sys.exit(main())'
    arguments = ['-p', f'urdf_file:={pr2_path}', '-p', 'publish_frequency:=1000.0']
    if reliable:
        params = Path(tempfile.mkdtemp()) / 'reliable_joint_states.yaml'
        params.write_text(RELIABLE_JOINT_STATES)
        arguments += ['--params-file', str(params)]
    rsp = subprocess.Popen(
        [sys.executable, '-c', code, '--ros-args', *arguments],
        env=env,
        stdout=subprocess.DEVNULL,
        stderr=subprocess.DEVNULL,
    )
    counter = subprocess.Popen(
        [sys.executable, '-c', COUNTER],
        env=env,
        stdin=subprocess.PIPE,
        stdout=subprocess.PIPE,
        text=True,
    )
    from tf_demo import transport
    from tf_demo.msgs import cdr
    from tf_demo.transport.messages import sensor_msgs

    transport.init(['bench_rsp'])
    node = transport.create_node('bench_rsp')
    publisher = node.create_publisher(sensor_msgs.JointState, 'joint_states', 10)
    try:
        assert counter.stdout is not None
        assert counter.stdin is not None
        counter.stdout.readline()
        deadline = time.monotonic() + 30
        while publisher.get_subscription_count() < 1:
            if time.monotonic() > deadline or rsp.poll() is not None:
                print('robot_state_publisher did not come up')
                return
            time.sleep(0.05)
        time.sleep(1.0)
        names = [j.name for j in pr2.joints if j.type in {'revolute', 'continuous', 'prismatic'}]
        rng = random.Random(5)
        total = int(seconds * 1000)
        payloads = []
        for k in range(total):  # encoded beforehand, so that the loop only paces and writes
            message = sensor_msgs.JointState()
            message.name = names
            message.header.stamp.sec, message.header.stamp.nanosec = divmod(
                10 * SECOND + k * 1_000_000, SECOND
            )
            message.position = [rng.uniform(-1.0, 1.0) for _ in names]
            payloads.append(cdr.serialize(message))
        cpu_before = cpu_seconds(rsp.pid)
        start = time.perf_counter()
        late = 0
        for k, payload in enumerate(payloads):
            target = start + k / 1000.0
            while (now := time.perf_counter()) < target:
                if target - now > 0.0005:
                    time.sleep(0.0002)
            if now - target > 0.002:
                late += 1
            publisher.publish(payload)
        elapsed = time.perf_counter() - start
        time.sleep(2.0)
        cpu = cpu_seconds(rsp.pid) - cpu_before  # includes 2 s of idle spinning
        counter.stdin.write('stop\n')
        counter.stdin.flush()
        received = int(counter.stdout.readline())
        qos = 'reliable depth 100 (qos_overrides)' if reliable else 'upstream sensor-data QoS'
        print(
            f'1 kHz PR2 joint_states over DDS, joint_states {qos}: {elapsed:.2f} s, sent {total} '
            f'({total / elapsed:.0f} Hz, {late} sent >2 ms late), /tf received {received}, '
            f'lost {total - received}; robot_state_publisher CPU {cpu / total * 1e6:.0f} us '
            f'per message ({cpu / elapsed * 100:.0f}% of a core)'
        )
    finally:
        node.destroy_node()
        transport.shutdown()
        for process in (counter, rsp):
            process.terminate()
            process.wait(timeout=10)


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split('\n')[1])
    parser.add_argument('--robots', type=Path, default=REPO.parent / 'shared' / 'robots')
    parser.add_argument('--seconds', type=float, default=5.0)
    parser.add_argument('--skip-dds', action='store_true')
    args = parser.parse_args()
    pr2_path = args.robots / 'pr2.urdf'
    panda_path = args.robots / 'panda.urdf'
    if not pr2_path.is_file():
        print(f'no {pr2_path}; pass --robots DIR')
        return 1
    pr2 = RobotModel.from_file(pr2_path)
    print(f'tf_demo build: {build_line()}')
    print(
        f'load average {os.getloadavg()[0]:.1f} on {os.cpu_count()} cores (timings scale with it)'
    )
    bench_per_message(pr2)
    bench_fk(RobotModel.from_file(panda_path), 'Panda')
    bench_fk(pr2, 'PR2')
    if not args.skip_dds:
        bench_dds(pr2_path, pr2, args.seconds, reliable=False)
        bench_dds(pr2_path, pr2, args.seconds, reliable=True)
    return 0


if __name__ == '__main__':
    sys.exit(main())
