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
The imperative shell shared by the tools: run one, record tf messages, report errors.

:func:`tool_main` is the ``main`` of a tool with an argparse command line and :func:`run_tool`
runs a tool's body between ``transport.init`` and ``shutdown``. :class:`TfRecorder` subscribes
to ``/tf`` and ``/tf_static`` (tf2's listener QoS) on a node and records every message as an
:class:`~tf_demo.cli._observations.Observation`; :func:`listen` spins the node for a while.
"""

from __future__ import annotations

import argparse
from collections.abc import Callable
from collections.abc import Sequence
import os
import sys
import threading
import time
from typing import Any
from typing import Protocol
from typing import TYPE_CHECKING

from tf_demo import transport
from tf_demo.cli._args import NAMESPACE_HELP
from tf_demo.cli._args import namespace_ros_args
from tf_demo.cli._observations import Observation
from tf_demo.cli._observations import ObservedTransform
from tf_demo.cli._observations import TF_STATIC_TOPIC
from tf_demo.cli._observations import TF_TOPIC
from tf_demo.cli._snapshot import read_snapshot
from tf_demo.cli._snapshot import Snapshot
from tf_demo.cli._snapshot import SnapshotError
from tf_demo.msgs.convert import transform_stamped_args
from tf_demo.msgs.convert import TransformStampedLike
from tf_demo.transport import StopRequest
from tf_demo.transport.logging import format_log_line
from tf_demo.transport.logging import LoggingSeverity
from tf_demo.transport.ros_args import ROS_ARGS_USAGE
from tf_demo.transport.ros_args import split_ros_args

if TYPE_CHECKING:
    from tf_demo.transport.node import Node

MAX_OBSERVATIONS = 1_000_000


class TfMessageLike(Protocol):
    """A ``tf2_msgs/TFMessage`` of either world."""

    @property
    def transforms(self) -> Sequence[TransformStampedLike]:
        """The message's transforms."""


class TfRecorder:
    """Record every message received on ``/tf`` and ``/tf_static`` with its reception time."""

    def __init__(
        self,
        node: Any,  # a Node; its create_subscription is typed for one-argument callbacks only
        *,
        tf_topic: str = TF_TOPIC,
        tf_static_topic: str = TF_STATIC_TOPIC,
        on_message: Callable[[Observation], None] | None = None,
    ) -> None:
        from tf_demo.transport.messages import tf2_msgs
        from tf_demo.transport.qos import DynamicListenerQoS
        from tf_demo.transport.qos import StaticListenerQoS

        self._node = node
        self._clock = node.get_clock()
        self._lock = threading.Lock()
        self._observations: list[Observation] = []
        self._on_message = on_message
        self.dropped = 0
        self._subscriptions = [
            node.create_subscription(
                tf2_msgs.TFMessage,
                tf_topic,
                lambda msg, info: self._record(TF_TOPIC, msg, info),
                DynamicListenerQoS(),
            ),
            node.create_subscription(
                tf2_msgs.TFMessage,
                tf_static_topic,
                lambda msg, info: self._record(TF_STATIC_TOPIC, msg, info),
                StaticListenerQoS(),
            ),
        ]

    def _record(self, topic: str, msg: TfMessageLike, info: object = None) -> None:
        """Record one message; ``info`` is rclpy's MessageInfo (with ``publisher_gid`` on DDS)."""
        publisher = ''
        if isinstance(info, dict):
            gid = info.get('publisher_gid')
            if isinstance(gid, (bytes, bytearray)):
                publisher = bytes(gid).hex()
            elif gid is not None:
                publisher = str(gid)

        receive_ns = self._clock.now().nanoseconds
        transforms = []
        for transform in msg.transforms:
            try:
                parent, child, stamp_ns, translation, rotation = transform_stamped_args(transform)
            except (TypeError, ValueError, AttributeError):
                self.dropped += 1
                continue
            transforms.append(
                ObservedTransform(
                    str(parent),
                    str(child),
                    int(stamp_ns),
                    (float(translation[0]), float(translation[1]), float(translation[2])),
                    (
                        float(rotation[0]),
                        float(rotation[1]),
                        float(rotation[2]),
                        float(rotation[3]),
                    ),
                )
            )
        observation = Observation(topic, receive_ns, tuple(transforms), publisher)
        with self._lock:
            if len(self._observations) < MAX_OBSERVATIONS:
                self._observations.append(observation)
            else:
                self.dropped += 1
        if self._on_message is not None:
            self._on_message(observation)

    def unmatched_publishers(self) -> dict[str, int]:
        """
        Count publishers on each topic that exist in the graph but never matched this listener.

        A /tf_static publisher without transient-local durability, or a best-effort /tf
        publisher, is incompatible with tf2's listener QoS: it shows up in the graph but its
        data never arrives. Returns ``{topic: count}`` for topics with such publishers (empty
        when the backend cannot tell).
        """
        result: dict[str, int] = {}
        for topic, subscription in zip(
            (TF_TOPIC, TF_STATIC_TOPIC), self._subscriptions, strict=True
        ):
            try:
                in_graph = int(self._node.count_publishers(subscription.topic_name))
                matched = int(subscription.get_publisher_count())
            except (AttributeError, TypeError, ValueError):
                return {}
            if in_graph > matched:
                result[topic] = in_graph - matched
        return result

    def observations(self) -> list[Observation]:
        """Return a copy of everything recorded so far."""
        with self._lock:
            return list(self._observations)


def listen(node: Node, seconds: float) -> None:
    """Spin ``node`` for ``seconds`` of wall time (as view_frames does)."""
    deadline = time.monotonic() + max(0.0, seconds)
    while transport.ok():
        remaining = deadline - time.monotonic()
        if remaining <= 0:
            break
        transport.spin_once(node, timeout_sec=min(0.1, remaining))


def print_error(tool: str, text: str) -> None:
    """Print a one-line error for the user on stderr."""
    print(f'{tool}: error: {text}', file=sys.stderr, flush=True)


def log_unnamed(severity_name: str, text: str) -> None:
    """Log like ``RCUTILS_LOG_<SEVERITY>`` without a logger name: ``[WARN] [t] []: text``."""
    line = format_log_line(LoggingSeverity[severity_name], '', text, time.time_ns())
    print(line, file=sys.stderr, flush=True)


def finish_after_damage(tool: str, code: int, damage: Exception | None) -> int:
    """
    Return ``code``, or after a damaged bag's one-line error at least 1.

    The tool's output, printed before, used what came before the damage.
    """
    if damage is None:
        return code
    print_error(tool, f'{damage} (the output used what came before it)')
    return max(code, 1)


def add_namespace_option(parser: argparse.ArgumentParser) -> None:
    """Give a reading tool ``--namespace NS`` (:func:`tool_main` turns it into remaps)."""
    parser.add_argument('--namespace', metavar='NS', help=NAMESPACE_HELP)


class ToolError(Exception):
    """A problem the tool reports as one line on stderr before exiting with code 1."""


def tool_main(
    tool: str,
    args: Sequence[str] | None,
    parser: argparse.ArgumentParser,
    options_error: Callable[[argparse.Namespace], str | None],
    live: Callable[[argparse.Namespace], int],
    *,
    from_snapshot: Callable[[argparse.Namespace, Snapshot], int] | None = None,
    bad_snapshot: int = 1,
    from_bag: Callable[[argparse.Namespace], int] | None = None,
) -> int:
    """
    Run a tool with an argparse command line: ``args`` (default: ``sys.argv[1:]``) to exit code.

    ``--ros-args`` sections are split off and the rest parsed by ``parser``; options that
    ``options_error`` refuses print one line and give 2. With ``--snapshot FILE`` (a tool with
    ``from_snapshot``) the file is read and handed to it instead of listening; with ``--bag
    PATH`` (a tool with ``from_bag``) that runs on the recording; a bad file or bag (or a
    :class:`ToolError`) prints one line and gives ``bad_snapshot``. Else ``live`` runs with
    :func:`run_tool`.
    """
    tool_args, ros_args = split_ros_args(sys.argv[1:] if args is None else args)
    options = parser.parse_args(tool_args)
    problem = options_error(options)
    namespace = getattr(options, 'namespace', None)
    if problem is None and namespace is not None:
        try:
            ros_args = [*ros_args, *namespace_ros_args(namespace)]
        except ValueError as error:
            problem = str(error)
    if problem is not None:
        print_error(tool, problem)
        return 2
    if from_snapshot is not None and options.snapshot is not None:
        try:
            return from_snapshot(options, read_snapshot(options.snapshot))
        except (SnapshotError, ToolError) as error:
            print_error(tool, str(error))
            return bad_snapshot
    if from_bag is not None and options.bag is not None:
        from tf_demo.bag import BagError

        try:
            return from_bag(options)
        except (BagError, ToolError) as error:
            print_error(tool, str(error))
            return bad_snapshot
    return run_tool(tool, ros_args, lambda: live(options))


def run_tool(tool: str, ros_args: Sequence[str], body: Callable[[], int]) -> int:
    """
    Run ``body`` between ``transport.init`` and ``transport.shutdown``.

    Ctrl-C and SIGTERM end the tool with exit code 0 (as a stopped ROS 2 tool): the first one
    interrupts ``body`` (``KeyboardInterrupt``), later ones are ignored while the tool cleans up
    (:class:`tf_demo.transport.StopRequest`), so a double Ctrl-C cannot skip the clean-up. A
    :class:`ToolError` prints one line and gives 1.
    """
    # Installed before init: rclpy.init puts its own handlers on top, which call these and
    # then wake the executors (a blocked transport.spin() would not wake otherwise).
    stop = StopRequest(interrupt=True)
    stop.install()
    try:
        return _run_tool_installed(tool, ros_args, body, stop)
    except KeyboardInterrupt:  # the stop arrived before or after body (init, shutdown)
        return 0
    finally:
        stop.restore()


def _run_tool_installed(
    tool: str, ros_args: Sequence[str], body: Callable[[], int], stop: StopRequest
) -> int:
    """:func:`run_tool` with its signal handlers in place."""
    try:
        transport.init(args=[tool, *ros_args])
    except (transport.RosArgsError, transport.BackendError) as error:
        print(ROS_ARGS_USAGE.replace('<executable>', tool), file=sys.stderr)
        print_error(tool, str(error))
        return 1
    try:
        return body()
    except KeyboardInterrupt:
        return 0
    except BrokenPipeError:
        # The reader went away (``tf_echo a b | head``): stop quietly, like a C++ tool on SIGPIPE.
        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
        return 0
    except ToolError as error:
        print_error(tool, str(error))
        return 1
    except Exception as error:
        if stop.explains(error):
            return 0
        raise
    finally:
        try:
            if transport.ok():
                transport.shutdown()
        except Exception as error:  # a failed clean-up must not become a traceback
            print_error(tool, f'clean shutdown failed: {error}')
