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
``tf_doctor``: listen to tf (or read a snapshot) and explain what is wrong, with the fix.

Usage::

    tf_doctor [-t SECONDS] [--frames A B ...] [--json]
    tf_doctor --snapshot FILE [--frames A B ...] [--json]
    tf_doctor --bag PATH [--frames A B ...] [--json]

It reports frames that do not exist (with close matches), disconnected trees (each island and the
likely missing link, such as odom→base_link), frames with two parents or publishers fighting, a
frame on both /tf and /tf_static, stamps far in the future or past (clock or use_sim_time
mismatch), data too sparse for lookups or streams that stopped, loops, REP 105 order, frame ids
with a leading '/', publishers whose QoS never matches tf2's listeners, and frames that are
expected but missing (named by failed lookups in /rosout, links of /robot_description, REP 105's
map and odom). Exit code 0 when
healthy, 1 when problems were found, 2 for bad arguments. The analysis is
:func:`tf_demo.cli._doctor.diagnose`.
"""

from __future__ import annotations

import argparse
from collections.abc import Sequence
import sys
import threading
from typing import Protocol
from typing import TYPE_CHECKING

from tf_demo.build_info import version_line
from tf_demo.cli._args import wait_time_error
from tf_demo.cli._doctor import diagnose
from tf_demo.cli._doctor_expected import frames_in_failed_lookups
from tf_demo.cli._doctor_report import exit_code
from tf_demo.cli._doctor_report import format_report
from tf_demo.cli._doctor_report import format_report_json
from tf_demo.cli._doctor_report import summarize
from tf_demo.cli._doctor_robot import RobotInfo
from tf_demo.cli._doctor_robot import RobotJoint
from tf_demo.cli._live import add_namespace_option
from tf_demo.cli._live import finish_after_damage
from tf_demo.cli._live import listen
from tf_demo.cli._live import TfRecorder
from tf_demo.cli._live import tool_main
from tf_demo.cli._observations import Observation
from tf_demo.cli._observations import observations_from_bag
from tf_demo.cli._observations import observations_from_snapshot
from tf_demo.cli._snapshot import Snapshot

if TYPE_CHECKING:
    from tf_demo.transport.node import Node

TOOL = 'tf_doctor'


def build_parser() -> argparse.ArgumentParser:
    """Return tf_doctor's argument parser."""
    parser = argparse.ArgumentParser(
        prog=TOOL,
        description='Listen to /tf and /tf_static and explain tf problems in plain language.',
    )
    parser.add_argument(
        '-t',
        '--wait-time',
        type=float,
        default=3.0,
        help='seconds to listen (default 3)',
    )
    parser.add_argument(
        '--frames', nargs='+', default=[], metavar='FRAME', help='frames you need to use'
    )
    parser.add_argument('--snapshot', metavar='FILE', help='diagnose a tf_saver file instead')
    parser.add_argument(
        '--bag', metavar='PATH', help='diagnose a rosbag2 recording instead (timing checks too)'
    )
    parser.add_argument('--json', action='store_true', help='print one JSON object')
    parser.add_argument(
        '--version',
        action='version',
        version=version_line(),
        help="print tf_demo's version and build (compiled or interpreted), then exit",
    )
    add_namespace_option(parser)
    return parser


def _report(
    options: argparse.Namespace,
    observations: list[Observation],
    source: str,
    *,
    timing: bool,
    listen_ns: int,
    unmatched: dict[str, int] | None = None,
    robot: RobotInfo | None = None,
    looked_up: Sequence[str] = (),
    start_ns: int | None = None,
) -> int:
    findings = diagnose(
        observations,
        listen_ns=listen_ns,
        frames=options.frames,
        check_timing=timing,
        unmatched_publishers=unmatched,
        robot=robot,
        looked_up=looked_up,
    )
    summary = summarize(observations)
    if options.json:
        sys.stdout.write(format_report_json(findings, summary, source))
    else:
        sys.stdout.write(format_report(findings, summary, source, start_ns))
    sys.stdout.flush()
    return exit_code(findings)


MAX_JOINT_NAMES = 10_000
"""At most this many joint names (and frames of failed lookups) are kept."""


class _StringLike(Protocol):
    """A ``std_msgs/String`` of either world."""

    data: str


class _JointStateLike(Protocol):
    """The part of a ``sensor_msgs/JointState`` of either world that is read here."""

    @property
    def name(self) -> Sequence[str]:
        """The joint names."""


class RobotRecorder:
    """
    Hear ``/robot_description`` (latched) and which joints ``/joint_states`` names.

    With them the report can say that a link is missing because its moving joint never got a
    position (joint_state_publisher or the driver is not running).
    """

    def __init__(self, node: Node) -> None:
        from tf_demo.transport.messages import sensor_msgs
        from tf_demo.transport.messages import std_msgs
        from tf_demo.transport.qos import DurabilityPolicy
        from tf_demo.transport.qos import qos_profile_sensor_data
        from tf_demo.transport.qos import QoSProfile
        from tf_demo.transport.qos import ReliabilityPolicy

        self._lock = threading.Lock()
        self.description: str | None = None
        self.joint_state_messages = 0
        self.joint_names: set[str] = set()
        latched = QoSProfile(
            depth=1,
            durability=DurabilityPolicy.TRANSIENT_LOCAL,
            reliability=ReliabilityPolicy.RELIABLE,
        )
        self._subscriptions = [
            node.create_subscription(
                std_msgs.String, '/robot_description', self._on_description, latched
            ),
            node.create_subscription(
                sensor_msgs.JointState,
                '/joint_states',
                self._on_joint_states,
                qos_profile_sensor_data,
            ),
        ]

    def _on_description(self, message: _StringLike) -> None:
        with self._lock:
            self.description = str(message.data)

    def _on_joint_states(self, message: _JointStateLike) -> None:
        with self._lock:
            self.joint_state_messages += 1
            for name in message.name:
                if len(self.joint_names) >= MAX_JOINT_NAMES:
                    break
                self.joint_names.add(str(name))

    def info(self) -> RobotInfo | None:
        """Return the robot as heard, or None without a (valid) robot_description."""
        from tf_demo.urdf import RobotModel
        from tf_demo.urdf import UrdfError

        with self._lock:
            description = self.description
            messages, names = self.joint_state_messages, frozenset(self.joint_names)
        if description is None:
            return None
        try:
            model = RobotModel.from_string(description, source='/robot_description')
        except (UrdfError, ValueError):
            return None  # a broken description is robot_state_publisher's to report
        joints = tuple(
            RobotJoint(j.name, j.type, j.parent, j.child, j.mimic.joint if j.mimic else None)
            for j in model.joints
        )
        return RobotInfo(joints, messages, names)


class _LogLike(Protocol):
    """The part of an ``rcl_interfaces/Log`` of either world that is read here."""

    msg: str


class LookupRecorder:
    """
    Hear ``/rosout`` (its recent history too) for tf2's "frame does not exist" errors.

    A node whose lookups fail logs them (tf_listener's "Could not transform ..."); the frames they
    name are frames the tree is expected to have.
    """

    def __init__(self, node: Node) -> None:
        from tf_demo.transport.messages import message_module
        from tf_demo.transport.qos import DurabilityPolicy
        from tf_demo.transport.qos import QoSProfile
        from tf_demo.transport.qos import ReliabilityPolicy

        self._lock = threading.Lock()
        self._frames: list[str] = []
        rosout = QoSProfile(  # rcl's /rosout profile, whose last 1000 messages stay for 10 s
            depth=1000,
            durability=DurabilityPolicy.TRANSIENT_LOCAL,
            reliability=ReliabilityPolicy.RELIABLE,
        )
        log_type = message_module('rcl_interfaces').Log
        self._subscription = node.create_subscription(log_type, '/rosout', self._on_log, rosout)

    def _on_log(self, message: _LogLike) -> None:
        frames = frames_in_failed_lookups([str(message.msg)])
        with self._lock:
            self._frames.extend(frames[: MAX_JOINT_NAMES - len(self._frames)])

    def frames(self) -> list[str]:
        """Return the frames failed lookups named, repeats kept."""
        with self._lock:
            return list(self._frames)


def _listen_and_report(options: argparse.Namespace) -> int:
    from tf_demo import transport

    node = transport.create_node(TOOL)
    try:
        recorder = TfRecorder(node)
        robot = RobotRecorder(node)
        lookups = LookupRecorder(node)
        start = node.get_clock().now().nanoseconds
        listen(node, options.wait_time)
        listen_ns = node.get_clock().now().nanoseconds - start
        return _report(
            options,
            recorder.observations(),
            f'listened {options.wait_time:g} s',
            timing=True,
            listen_ns=listen_ns,
            unmatched=recorder.unmatched_publishers(),
            robot=robot.info(),
            looked_up=lookups.frames(),
        )
    finally:
        node.destroy_node()


def options_error(options: argparse.Namespace) -> str | None:
    """Return why parsed ``options`` cannot run, else None."""
    return wait_time_error(options.wait_time)


def _report_snapshot(options: argparse.Namespace, snapshot: Snapshot) -> int:
    """Diagnose the ``--snapshot`` file instead of listening (no timing checks)."""
    return _report(
        options,
        observations_from_snapshot(snapshot),
        options.snapshot,
        timing=False,
        listen_ns=0,
    )


def _report_bag(options: argparse.Namespace) -> int:
    """Diagnose the ``--bag`` recording: every check, timing included, over the bag's span."""
    bag = observations_from_bag(options.bag)
    code = _report(
        options,
        bag.observations,
        options.bag,
        timing=True,
        listen_ns=max(bag.end_ns - bag.start_ns, 1),
        start_ns=bag.start_ns,
    )
    return finish_after_damage(TOOL, code, bag.damage)


def main(args: list[str] | None = None) -> int:
    """Run tf_doctor with ``args`` (default: ``sys.argv[1:]``)."""
    return tool_main(
        TOOL,
        args,
        build_parser(),
        options_error=options_error,
        live=_listen_and_report,
        from_snapshot=_report_snapshot,
        bad_snapshot=2,
        from_bag=_report_bag,
    )


if __name__ == '__main__':
    sys.exit(main())
