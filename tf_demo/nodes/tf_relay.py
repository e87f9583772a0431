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
``tf_relay /robot1 /robot2 ... [--shared map world]``: merge namespaced robots' TF into one tree.

For each namespace ``NS`` it listens on ``NS/tf`` and ``NS/tf_static`` (tf2's listener QoS) and
republishes on ``/tf`` (tf2's broadcaster QoS) and latched ``/tf_static`` (transient local, keep
last 1), every frame named ``NS/frame`` (without the leading ``/``) unless it already is or is a
shared frame (default ``map``, ``world``, ``earth``; ``--shared`` replaces them). Stamps are kept.
Dynamic transforms are forwarded as they arrive and never sent again, so a robot that stops
stops in the merged tree too; the latched ``/tf_static`` message holds every robot's statics,
one per child frame, as tf2's ``StaticTransformBroadcaster`` keeps them. The global namespace
``/``, or a remap that makes an input one of the outputs, is refused: it would relay its own
output. The bytes are rewritten without message objects (:mod:`tf_demo.msgs.cdr`).

Parameters (``--ros-args --params-file fleet.yaml`` or ``-p``): ``namespaces`` (string array,
used when none is on the command line) and ``shared_frames`` (string array, replaced by
``--shared``).
"""

from __future__ import annotations

import argparse
from collections.abc import Sequence
from dataclasses import dataclass
import sys
from typing import TYPE_CHECKING

from tf_demo.core.relay import check_shared_frames
from tf_demo.core.relay import DEFAULT_SHARED_FRAMES
from tf_demo.core.relay import FramePrefixer
from tf_demo.core.relay import relay_namespaces
from tf_demo.core.relay import RelayConfigError
from tf_demo.core.relay import StaticUnion
from tf_demo.msgs.cdr import CdrError
from tf_demo.msgs.cdr import decode_tf_message_transforms
from tf_demo.msgs.cdr import TfMessageEncoder
from tf_demo.msgs.log_throttle import PerWriterThrottle
from tf_demo.nodes import non_ros_arguments
from tf_demo.nodes.helpers import declare_flexible
from tf_demo.transport import create_internal_node
from tf_demo.transport import run_node
from tf_demo.transport import SubscriptionServer
from tf_demo.transport.dds.names import InvalidNameError
from tf_demo.transport.dds.names import validate_namespace
from tf_demo.transport.messages import tf2_msgs
from tf_demo.transport.node import Node
from tf_demo.transport.qos import DynamicBroadcasterQoS
from tf_demo.transport.qos import DynamicListenerQoS
from tf_demo.transport.qos import StaticBroadcasterQoS
from tf_demo.transport.qos import StaticListenerQoS

if TYPE_CHECKING:
    from collections.abc import Callable

NODE_NAME = 'tf_relay'
TF_TOPIC = '/tf'
TF_STATIC_TOPIC = '/tf_static'


@dataclass(frozen=True)
class RelayArgs:
    """The command line: namespaces (none: the parameter's), ``--shared`` (None: its)."""

    namespaces: tuple[str, ...]
    shared: tuple[str, ...] | None


def _parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(
        prog=NODE_NAME,
        description="Merge namespaced robots' TF trees into /tf and /tf_static, frames prefixed.",
        epilog='Also: --ros-args -p namespaces:="[/robot1, /robot2]" or --params-file f.yaml',
    )
    parser.add_argument(
        'namespaces', nargs='*', metavar='NAMESPACE', help='a robot namespace, e.g. /robot1'
    )
    parser.add_argument(
        '--shared',
        nargs='*',
        metavar='FRAME',
        help=f'frames left unprefixed (default: {" ".join(DEFAULT_SHARED_FRAMES)})',
    )
    return parser


def parse_relay_args(args: Sequence[str]) -> RelayArgs:
    """Parse the command line without its ``--ros-args`` (argparse's errors exit 2)."""
    options = _parser().parse_args(list(args))
    shared = None if options.shared is None else tuple(options.shared)
    return RelayArgs(tuple(options.namespaces), shared)


def _strings(name: str, value: object) -> tuple[str, ...]:
    """Return a string-array parameter's value (a single string is a list of one)."""
    if isinstance(value, str):
        return (value,)
    if isinstance(value, (list, tuple)) and all(isinstance(item, str) for item in value):
        return tuple(value)
    msg = f'parameter {name} must be a list of strings, got {value!r}'
    raise RelayConfigError(msg)


class TfRelay(Node):
    """Relays each namespace's ``tf`` and ``tf_static`` into the global ones, frames prefixed."""

    def __init__(self, command_line: RelayArgs | None = None) -> None:
        """Read the namespaces and shared frames, check them, and subscribe."""
        super().__init__(NODE_NAME)
        given = command_line or RelayArgs((), None)
        from_parameter = _strings('namespaces', declare_flexible(self, 'namespaces', ['']))
        shared_parameter = declare_flexible(self, 'shared_frames', list(DEFAULT_SHARED_FRAMES))
        self.namespaces = relay_namespaces(
            given.namespaces or [name for name in from_parameter if name]
        )
        for namespace in self.namespaces:
            try:
                validate_namespace(namespace)
            except InvalidNameError as error:
                msg = f'invalid namespace {namespace!r}: {error.reason}'
                raise RelayConfigError(msg) from None
        self.shared_frames = check_shared_frames(
            given.shared
            if given.shared is not None
            else _strings('shared_frames', shared_parameter)
        )
        self._check_no_loop()
        self._malformed = PerWriterThrottle('malformed or unrelayable samples')
        self._tf_pub = self.create_publisher(tf2_msgs.TFMessage, TF_TOPIC, DynamicBroadcasterQoS())
        self._static_pub = self.create_publisher(
            tf2_msgs.TFMessage, TF_STATIC_TOPIC, StaticBroadcasterQoS()
        )
        self._statics = StaticUnion()
        self._static_encoder = TfMessageEncoder()
        # The inputs live on an internal node served by a thread of their own (rcl's wait set
        # under rclpy: a quarter of the executor's CPU per message, and no wait behind this
        # node's parameter services); this node keeps the publishers and the parameters.
        inputs = create_internal_node(f'{NODE_NAME}_inputs_{id(self):x}')
        subscriptions = []
        for namespace in self.namespaces:
            prefixer = FramePrefixer(namespace, self.shared_frames)
            encoder = TfMessageEncoder(rename=prefixer)
            subscriptions += [
                inputs.create_subscription(
                    tf2_msgs.TFMessage,
                    namespace + TF_TOPIC,
                    self._dynamic_relay(namespace + TF_TOPIC, encoder),
                    DynamicListenerQoS(),
                    raw=True,
                ),
                inputs.create_subscription(
                    tf2_msgs.TFMessage,
                    namespace + TF_STATIC_TOPIC,
                    self._static_relay(namespace + TF_STATIC_TOPIC, prefixer),
                    StaticListenerQoS(),
                    raw=True,
                ),
            ]
        self._inputs = SubscriptionServer(inputs, subscriptions, 'tf_relay_inputs')
        self.get_logger().info(
            f'Relaying {", ".join(self.namespaces)} onto {TF_TOPIC} and {TF_STATIC_TOPIC} '
            f'(shared frames: {", ".join(sorted(self.shared_frames)) or "none"})'
        )

    def destroy_node(self) -> None:
        """Stop relaying (the inputs' thread and node), then destroy this node."""
        inputs = getattr(self, '_inputs', None)
        if inputs is not None:
            inputs.stop()
        super().destroy_node()

    def _check_no_loop(self) -> None:
        """Refuse an input that remaps resolve to one of the relay's outputs."""
        outputs = {self.resolve_topic_name(TF_TOPIC), self.resolve_topic_name(TF_STATIC_TOPIC)}
        for namespace in self.namespaces:
            for topic in (namespace + TF_TOPIC, namespace + TF_STATIC_TOPIC):
                resolved = self.resolve_topic_name(topic)
                if resolved in outputs:
                    msg = f'{topic} resolves to {resolved}, an output of tf_relay: it would loop'
                    raise RelayConfigError(msg)

    def _dynamic_relay(self, topic: str, encoder: TfMessageEncoder) -> Callable[[bytes], None]:
        publish = self._tf_pub.publish

        def relay(data: bytes) -> None:
            try:
                publish(encoder.encode_stamped(decode_tf_message_transforms(data)))
            except (CdrError, OverflowError) as error:
                self._log_dropped(topic, error)

        return relay

    def _static_relay(self, topic: str, prefixer: FramePrefixer) -> Callable[[bytes], None]:
        def relay(data: bytes) -> None:
            try:
                transforms = [
                    (prefixer(parent), prefixer(child), stamp, translation, rotation)
                    for parent, child, stamp, translation, rotation in (
                        decode_tf_message_transforms(data)
                    )
                ]
                if self._statics.update(transforms):
                    self._static_pub.publish(
                        self._static_encoder.encode_stamped(self._statics.transforms())
                    )
            except (CdrError, OverflowError) as error:
                self._log_dropped(topic, error)

        return relay

    def _log_dropped(self, topic: str, error: Exception) -> None:
        line = self._malformed.line(f"a writer on '{topic}'", f'Dropping a TFMessage: {error}')
        if line is not None:
            self.get_logger().error(line)


def main(args: Sequence[str] | None = None) -> int:
    """Run ``tf_relay NAMESPACE... [--shared FRAME...]`` until Ctrl-C; bad input exits 1."""
    argv = list(sys.argv if args is None else args)  # argv[0] is the program
    command_line = parse_relay_args(non_ros_arguments(argv[1:]))
    return run_node(lambda: TfRelay(command_line), argv)


if __name__ == '__main__':
    sys.exit(main())
