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
tf_view under load: 200 frames at 20 Hz, a real browser watching; tf_view's CPU and lag.

A publisher process sends ``--frames`` dynamic transforms (ten chains under ``world``) in one
TFMessage ``--rate`` times a second; ``tf_view`` runs as its own process with a headless
chromium (Debian's, through selenium) showing the page. Over ``--seconds`` the benchmark reads
tf_view's CPU time from ``/proc`` and, once a second, the ages the page's tree panel shows
(how old the newest sample of each frame is when the page draws it). Targets (issue 13): the
view keeps up (the largest age shown stays below three publishing periods) and tf_view uses at
most 30% of a core.

Run: ``.venv/bin/python bench/bench_view.py`` (standalone world; needs the ``view`` extra,
selenium, chromium and chromium-driver).
"""

from __future__ import annotations

import argparse
import contextlib
import os
from pathlib import Path
import re
import statistics
import subprocess
import sys
import time

sys.path.insert(0, str(Path(__file__).resolve().parent.parent))

from _flow import build_line

CHAINS = 10
CPU_TARGET = 0.30
AGE = re.compile(r'(\d+\.\d+) s old')


def publish(frames: int, rate: float) -> None:
    """Publish ``frames`` moving transforms in one TFMessage at ``rate`` Hz until stopped."""
    import math

    from tf_demo import transport
    from tf_demo.ros import TransformBroadcaster
    from tf_demo.transport.messages import geometry_msgs

    transport.init(['bench_view_publisher'])
    node = transport.create_node('bench_view_publisher')
    broadcaster = TransformBroadcaster(node)
    per_chain = max(1, frames // CHAINS)

    def tick() -> None:
        now = node.get_clock().now()
        angle = now.nanoseconds / 1e9
        batch = []
        for index in range(frames):
            message = geometry_msgs.TransformStamped()
            message.header.stamp = now.to_msg()
            message.header.frame_id = 'world' if index % per_chain == 0 else f'f{index - 1}'
            message.child_frame_id = f'f{index}'
            message.transform.translation.x = 0.1 + 0.02 * math.cos(angle + index)
            message.transform.translation.y = 0.02 * math.sin(angle + index)
            message.transform.rotation.z = math.sin(0.05)
            message.transform.rotation.w = math.cos(0.05)
            batch.append(message)
        broadcaster.sendTransform(batch)

    node.create_timer(1.0 / rate, tick)
    with contextlib.suppress(KeyboardInterrupt):
        transport.spin(node)


def cpu_seconds(pid: int) -> float:
    """User + system CPU time of a process so far (``/proc/<pid>/stat``)."""
    fields = Path(f'/proc/{pid}/stat').read_text().rsplit(')', 1)[1].split()
    return (int(fields[11]) + int(fields[12])) / os.sysconf('SC_CLK_TCK')


def browser() -> object:
    from selenium import webdriver
    from selenium.webdriver.chrome.options import Options
    from selenium.webdriver.chrome.service import Service

    options = Options()
    options.binary_location = '/usr/bin/chromium'
    for flag in (
        '--headless=new',
        '--no-sandbox',
        '--disable-gpu',
        '--enable-unsafe-swiftshader',
        '--disable-background-networking',
        '--disable-component-update',
        '--no-first-run',
        '--window-size=1280,800',
    ):
        options.add_argument(flag)
    return webdriver.Chrome(service=Service('/usr/bin/chromedriver'), options=options)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.strip().splitlines()[0])
    parser.add_argument('--frames', type=int, default=200)
    parser.add_argument('--rate', type=float, default=20.0)
    parser.add_argument('--seconds', type=float, default=20.0)
    parser.add_argument('--publish', action='store_true', help=argparse.SUPPRESS)
    options = parser.parse_args(argv)
    if options.publish:
        publish(options.frames, options.rate)
        return 0
    print(f'tf_demo build: {build_line()}')
    env = dict(os.environ, ROS_DOMAIN_ID=os.environ.get('ROS_DOMAIN_ID', '97'))
    env.setdefault('ROS_AUTOMATIC_DISCOVERY_RANGE', 'LOCALHOST')
    code = 'import sys; from tf_demo.cli.tf_view import main; sys.exit(main())'
    publisher = subprocess.Popen(
        [
            sys.executable,
            __file__,
            '--publish',
            '--frames',
            str(options.frames),
            '--rate',
            str(options.rate),
        ],
        env=env,
    )
    view = subprocess.Popen(
        [sys.executable, '-c', code, '--port', '0', '--fixed-frame', 'world'],
        env=env,
        stdout=subprocess.PIPE,
        text=True,
    )
    page = None
    try:
        assert view.stdout is not None
        url = view.stdout.readline().split()[-1]
        page = browser()
        page.get(url)  # type: ignore[attr-defined]
        last = f'f{options.frames - 1}'
        deadline = time.monotonic() + 60
        while last not in page.execute_script('return document.body.innerText'):  # type: ignore[attr-defined]
            if time.monotonic() > deadline:
                print(f'bench_view: the page never showed {last}', file=sys.stderr)
                return 1
            time.sleep(0.5)
        start_cpu, start = cpu_seconds(view.pid), time.monotonic()
        largest_ages: list[float] = []
        while time.monotonic() - start < options.seconds:
            time.sleep(1.0)
            text = page.execute_script('return document.body.innerText')  # type: ignore[attr-defined]
            ages = [float(a) for a in AGE.findall(text)]
            if ages:
                largest_ages.append(max(ages))
        cpu = (cpu_seconds(view.pid) - start_cpu) / (time.monotonic() - start)
    finally:
        if page is not None:
            page.quit()  # type: ignore[attr-defined]
        for process in (view, publisher):
            process.send_signal(2)
            try:
                process.wait(timeout=10)
            except subprocess.TimeoutExpired:
                process.kill()
    period = 1.0 / options.rate
    worst = max(largest_ages) if largest_ages else float('nan')
    print(
        f'tf_view, {options.frames} frames at {options.rate:g} Hz, {options.seconds:g} s, '
        'a headless chromium watching'
    )
    print(
        f'  CPU of tf_view        {cpu:6.1%} of a core   (target <= {CPU_TARGET:.0%}) '
        f'{"ok" if cpu <= CPU_TARGET else "MISSED"}'
    )
    print(
        f'  largest age on page   median {statistics.median(largest_ages):.3f} s, '
        f'worst {worst:.3f} s   (keeps up: worst < {3 * period:.2f} s) '
        f'{"ok" if worst < 3 * period else "MISSED"}'
    )
    return 0


if __name__ == '__main__':
    sys.exit(main())
