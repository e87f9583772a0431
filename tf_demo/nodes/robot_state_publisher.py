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
robot_state_publisher: publishes a robot's link transforms from its URDF and its joint states.

The contract is upstream's (ROS 2 Jazzy, ``ros/robot_state_publisher``), see
``spec/robot_state_publisher.md``:

- parameters ``robot_description`` (URDF text), ``publish_frequency`` (default 20.0, valid in
  (0, 1000]), ``ignore_timestamp``, ``frame_prefix``; changes are validated before they are
  accepted, and an accepted ``robot_description`` reloads the model;
- fixed (and planar) joints on ``/tf_static`` as one accumulated, latched message;
- for each accepted ``joint_states`` message, one ``TFMessage`` on ``/tf`` with the moving
  joints it names (and their mimics), stamped with the message's stamp, subject to upstream's
  throttle;
- ``robot_description`` republished (reliable, transient local, depth 1).

Beyond upstream, for the standalone world where no launch file runs xacro: ``urdf_file`` (a
URDF or xacro path, used when ``robot_description`` is empty) and ``xacro_args``
(``'name:=value ...'``).
"""

from __future__ import annotations

from collections.abc import Iterable
from collections.abc import Sequence
from itertools import repeat
import sys
import time
from typing import Any

from tf_demo.msgs.cdr import TfMessageEncoder
from tf_demo.nodes import non_ros_arguments
from tf_demo.nodes.helpers import declare_qos_overrides
from tf_demo.transport import run_node
from tf_demo.transport.logging import get_logger
from tf_demo.transport.messages import builtin_interfaces
from tf_demo.transport.messages import geometry_msgs
from tf_demo.transport.messages import sensor_msgs
from tf_demo.transport.messages import std_msgs
from tf_demo.transport.messages import tf2_msgs
from tf_demo.transport.node import Node
from tf_demo.transport.parameters import Parameter
from tf_demo.transport.parameters import SetParametersResult
from tf_demo.transport.qos import DurabilityPolicy
from tf_demo.transport.qos import DynamicBroadcasterQoS
from tf_demo.transport.qos import HistoryPolicy
from tf_demo.transport.qos import qos_profile_sensor_data
from tf_demo.transport.qos import QoSProfile
from tf_demo.transport.qos import ReliabilityPolicy
from tf_demo.urdf import JointPositionError
from tf_demo.urdf import JointTransform
from tf_demo.urdf import parse_xacro_args
from tf_demo.urdf import RobotModel
from tf_demo.urdf import UrdfError

__all__ = [
    'DroppedMessageLog',
    'JointStateThrottle',
    'RobotDescriptionError',
    'RobotStatePublisher',
    'check_publish_frequency',
    'joint_state_problem',
    'main',
    'positions_from_joint_state',
]

NODE_NAME = 'robot_state_publisher'
DEFAULT_PUBLISH_FREQUENCY = 20.0
_NS_PER_MS = 1_000_000


class RobotDescriptionError(ValueError):
    """The node cannot start: no usable robot description or an invalid parameter."""


def check_publish_frequency(value: float) -> bool:
    """Tell whether ``publish_frequency`` is acceptable: 0 < value <= 1000."""
    return 0.0 < value <= 1000.0


def publish_interval_ns(publish_frequency: float) -> int:
    """Return upstream's throttle interval: ``floor(1000 / frequency)`` whole milliseconds."""
    return int(1000.0 / publish_frequency) * _NS_PER_MS


class JointStateThrottle:
    """
    Upstream's rule for which ``joint_states`` messages are published.

    A message passes when ``ignore_timestamp`` is set, or when its stamp is at least
    ``floor(1000 / publish_frequency)`` ms after the last published stamp of the least recently
    published joint it names (never-seen joints count as 0, the minimum starts from the node's
    ``now``). A node clock that moves backwards forgets every last-published stamp.
    """

    def __init__(self) -> None:
        self.last_published_ns: dict[str, int] = {}
        self._last_callback_ns = 0

    def clock_moved_backwards(self, now_ns: int) -> bool:
        """Record the node clock at a callback; reset and return True if it went backwards."""
        backwards = self._last_callback_ns > now_ns
        if backwards:
            self.last_published_ns.clear()
        self._last_callback_ns = now_ns
        return backwards

    def should_publish(
        self,
        names: Sequence[str],
        stamp_ns: int,
        now_ns: int,
        interval_ns: int,
        ignore_timestamp: bool,
    ) -> bool:
        """Tell whether a message with these joint names and stamp is published."""
        if ignore_timestamp:
            return True
        last = now_ns
        if names:
            last = min(last, *map(self.last_published_ns.get, names, repeat(0)))
        return stamp_ns >= last + interval_ns

    def record(self, names: Iterable[str], stamp_ns: int) -> None:
        """Remember ``stamp_ns`` as the last published time of every name (known or not)."""
        self.last_published_ns.update(dict.fromkeys(names, stamp_ns))


def joint_state_problem(
    names: Sequence[str],
    positions: Sequence[float],
    velocities: Sequence[float] = (),
    efforts: Sequence[float] = (),
) -> tuple[int, str] | None:
    """
    Return ``(logging level, text)`` when a JointState must be dropped, else None.

    Upstream drops a message whose ``name`` and ``position`` lengths differ, with a warning when
    ``position`` is empty and an error otherwise (its texts). A ``velocity`` or ``effort`` that
    is neither empty nor as long as ``name`` makes the message invalid too (a warning). Values
    are not looked at here: see :class:`~tf_demo.urdf.JointPositionError`.
    """
    if len(names) != len(positions):
        if len(positions) == 0:
            return (
                30,
                'Robot state publisher ignored a JointState message about joint(s) '
                f'"{names[0]}"(,...) whose position member was empty.',
            )
        return (40, 'Robot state publisher ignored an invalid JointState message')
    for field, values in (('velocity', velocities), ('effort', efforts)):
        if len(values) not in {0, len(names)}:
            return (
                30,
                f'Robot state publisher ignored a JointState message with {len(names)} names '
                f'but {len(values)} {field} values',
            )
    return None


class DroppedMessageLog:
    """
    Throttle the warnings about dropped messages, so a flood of bad input is not a log flood.

    The first message of each kind is logged at once; after that at most one per
    ``interval_s``, saying how many were dropped without a line in between.
    """

    def __init__(self, interval_s: float = 5.0) -> None:
        self.interval_s = interval_s
        self._last_logged: dict[str, float] = {}
        self._unlogged: dict[str, int] = {}

    def text(self, kind: str, message: str, now_s: float) -> str | None:
        """Return the line to log now for a dropped message of ``kind``, or None to stay quiet."""
        last = self._last_logged.get(kind)
        if last is not None and now_s - last < self.interval_s:
            self._unlogged[kind] = self._unlogged.get(kind, 0) + 1
            return None
        self._last_logged[kind] = now_s
        unlogged = self._unlogged.pop(kind, 0)
        if unlogged and last is not None:
            message += (
                f' ({unlogged} more such message(s) dropped in the last {now_s - last:.0f} s)'
            )
        return message


def positions_from_joint_state(
    names: Sequence[str], positions: Sequence[float]
) -> dict[str, float]:
    """Map names to positions; when a name repeats, its first position wins (as upstream)."""
    if len(names) != len(positions):
        msg = f'{len(names)} names but {len(positions)} positions'
        raise ValueError(msg)
    # later duplicates are written first, so the first occurrence is the one that stays
    return dict(zip(reversed(names), reversed(positions), strict=True))


def _load_model(xml: str) -> RobotModel:
    """Build the model; an invalid description raises RobotDescriptionError with the reason."""
    if not xml:
        msg = 'Empty URDF is not allowed'
        raise RobotDescriptionError(msg)
    try:
        return RobotModel.from_string(xml, source='robot_description')
    except UrdfError as error:
        msg = f'Unable to initialize urdf::model from robot description: {error}'
        raise RobotDescriptionError(msg) from None


_JOINT_STATES_OVERRIDABLE = ('history', 'depth', 'reliability')
_TF_OVERRIDABLE = ('depth', 'durability', 'history', 'reliability')
_TF_STATIC_OVERRIDABLE = ('depth', 'history', 'reliability')
_LATCHED = QoSProfile(
    depth=1,
    history=HistoryPolicy.KEEP_LAST,
    reliability=ReliabilityPolicy.RELIABLE,
    durability=DurabilityPolicy.TRANSIENT_LOCAL,
)


class RobotStatePublisher(Node):
    """The robot_state_publisher node (see the module docstring)."""

    def __init__(self, file_arguments: Sequence[str] = (), **kwargs: Any) -> None:
        super().__init__(NODE_NAME, **kwargs)
        logger = self.get_logger()
        xml = self.declare_parameter('robot_description', '').value
        urdf_file = self.declare_parameter('urdf_file', '').value
        xacro_args = self.declare_parameter('xacro_args', '').value
        if not xml and not urdf_file and file_arguments:
            logger.warning(
                'No robot_description parameter, but command-line argument available.  '
                'Assuming argument is name of URDF file.  This backwards compatibility '
                'fallback will be removed in the future.'
            )
            urdf_file = file_arguments[0]
            what = 'URDF file'
        else:
            what = 'urdf_file'
        if not xml and urdf_file:
            try:
                xml = RobotModel.from_file(urdf_file, parse_xacro_args(xacro_args)).xml
            except (UrdfError, ValueError) as error:
                msg = f'Failed to load {what} {urdf_file}: {error}'
                raise RobotDescriptionError(msg) from None
            self.set_parameters([_parameter('robot_description', xml)])
        if not xml:
            msg = (
                'robot_description parameter must not be empty (set it, or urdf_file to a '
                'URDF or xacro file)'
            )
            raise RobotDescriptionError(msg)
        self._description_pub = self.create_publisher(
            std_msgs.String, 'robot_description', _LATCHED
        )
        self._model = _load_model(xml)
        self._announce_model(xml)

        frequency = self.declare_parameter('publish_frequency', DEFAULT_PUBLISH_FREQUENCY)
        self._publish_frequency = float(frequency.value)
        if not check_publish_frequency(self._publish_frequency):
            msg = 'publish_frequency must be between 0 (exclusive) and 1000'
            raise RobotDescriptionError(msg)
        self._frame_prefix = str(self.declare_parameter('frame_prefix', '').value)
        self._ignore_timestamp = bool(self.declare_parameter('ignore_timestamp', False).value)

        self._throttle = JointStateThrottle()
        self._dropped_log = DroppedMessageLog()
        self._encoder = TfMessageEncoder(self._frame_prefix)
        self._static: dict[str, geometry_msgs.TransformStamped] = {}
        self._tf_pub = self.create_publisher(
            tf2_msgs.TFMessage,
            '/tf',
            declare_qos_overrides(
                self, '/tf', 'publisher', DynamicBroadcasterQoS(), _TF_OVERRIDABLE
            ),
        )
        self._tf_static_pub = self.create_publisher(
            tf2_msgs.TFMessage,
            '/tf_static',
            declare_qos_overrides(
                self, '/tf_static', 'publisher', _copy_qos(_LATCHED), _TF_STATIC_OVERRIDABLE
            ),
        )
        self.add_on_set_parameters_callback(self._on_set_parameters)
        self.create_subscription(
            sensor_msgs.JointState,
            'joint_states',
            self._on_joint_state,
            declare_qos_overrides(
                self,
                self._resolved('joint_states'),
                'subscription',
                _copy_qos(qos_profile_sensor_data),
                _JOINT_STATES_OVERRIDABLE,
            ),
        )
        self._publish_fixed_transforms()

    # -- QoS overrides (upstream: QosOverridingOptions::with_default_policies) -----------
    def _resolved(self, topic: str) -> str:
        try:
            return str(self.resolve_topic_name(topic))
        except (AttributeError, TypeError):
            namespace = self.get_namespace().rstrip('/')
            return f'{namespace}/{topic}'

    # -- model ---------------------------------------------------------------------------
    def _announce_model(self, xml: str) -> None:
        # upstream's model warnings are kdl_parser's own (RCUTILS_LOG_WARN_NAMED)
        kdl_parser_logger = get_logger('kdl_parser')
        for warning in self._model.warnings:
            kdl_parser_logger.warning(warning)
        for warning in self._model.description.warnings:
            self.get_logger().warning(warning)
        self._description_pub.publish(std_msgs.String(data=xml))
        self.get_logger().info('Robot initialized')

    def _publish_fixed_transforms(self) -> None:
        stamp = self.get_clock().now().to_msg()
        prefix = self._frame_prefix
        for parent, child, translation, rotation in self._model.static_transforms():
            message = _transform_stamped(
                stamp, (prefix + parent, prefix + child, translation, rotation)
            )
            self._static[message.child_frame_id] = message
        self._tf_static_pub.publish(tf2_msgs.TFMessage(transforms=list(self._static.values())))

    # -- parameters ----------------------------------------------------------------------
    def _on_set_parameters(self, parameters: list[Parameter]) -> SetParametersResult:
        new_model: RobotModel | None = None
        new_xml = ''
        updates: dict[str, object] = {}
        new_frequency: float | None = None
        for parameter in parameters:
            if parameter.name == 'robot_description':
                new_xml = str(parameter.value or '')
                try:
                    new_model = _load_model(new_xml)
                except RobotDescriptionError as error:
                    if new_xml:
                        self.get_logger().warning(str(error))
                    return SetParametersResult(successful=False, reason=str(error))
            elif parameter.name == 'publish_frequency':
                if not check_publish_frequency(float(parameter.value)):
                    return SetParametersResult(
                        successful=False,
                        reason='publish_frequency must be between 0.0 (exclusive) and 1000.0',
                    )
                new_frequency = float(parameter.value)
            elif parameter.name in {'frame_prefix', 'ignore_timestamp'}:
                updates[parameter.name] = parameter.value
        # Everything is valid: apply (upstream applies after the set, from parameter events).
        if new_frequency is not None:
            self._publish_frequency = new_frequency
        if 'ignore_timestamp' in updates:
            self._ignore_timestamp = bool(updates['ignore_timestamp'])
        if 'frame_prefix' in updates:
            self._frame_prefix = str(updates['frame_prefix'])
            self._encoder = TfMessageEncoder(self._frame_prefix)
        if new_model is not None:
            self._model = new_model
            self._announce_model(new_xml)
            self._publish_fixed_transforms()
        return SetParametersResult(successful=True)

    # -- joint states --------------------------------------------------------------------
    def _on_joint_state(self, message: sensor_msgs.JointState) -> None:
        names = message.name
        positions = message.position
        problem = joint_state_problem(names, positions, message.velocity, message.effort)
        if problem is not None:
            self._dropped('lengths', *problem)
            return
        now_ns = self.get_clock().now().nanoseconds
        if self._throttle.clock_moved_backwards(now_ns):
            self.get_logger().warning('Moved backwards in time, re-publishing joint transforms!')
        stamp = message.header.stamp
        sec = stamp.sec
        nanosec = stamp.nanosec
        stamp_ns = sec * 1_000_000_000 + nanosec
        if not self._throttle.should_publish(
            names,
            stamp_ns,
            now_ns,
            publish_interval_ns(self._publish_frequency),
            self._ignore_timestamp,
        ):
            return
        try:
            transforms = self._model.joint_transforms(positions_from_joint_state(names, positions))
        except JointPositionError as error:
            text = f'Robot state publisher ignored a JointState message: {error}'
            self._dropped('non-finite', 30, text)
            return
        self._publish_tf(transforms, sec, nanosec)
        self._throttle.record(names, stamp_ns)

    def _dropped(self, kind: str, level: int, text: str) -> None:
        """Log a dropped message, throttled per kind (one call site per severity)."""
        line = self._dropped_log.text(f'{kind}:{level}', text, time.monotonic())
        if line is None:
            return
        if level == 30:
            self.get_logger().warning(line)
        else:
            self.get_logger().error(line)

    def _publish_tf(self, transforms: list[JointTransform], sec: int, nanosec: int) -> None:
        """
        Publish the moving joints' transforms as one serialized TFMessage.

        Both worlds' publishers take CDR bytes as they are (rclpy's ``Publisher.publish``
        hands ``bytes`` to ``publish_raw``; the standalone writer writes them), so no
        message objects are built on the hot path.
        """
        self._tf_pub.publish(self._encoder.encode(transforms, sec, nanosec))


def _copy_qos(profile: QoSProfile) -> QoSProfile:
    """Return an independent copy of a QoS profile (presets must not be modified)."""
    return type(profile)(
        history=profile.history,
        depth=profile.depth,
        reliability=profile.reliability,
        durability=profile.durability,
    )


def _parameter(name: str, value: object) -> Parameter:
    return Parameter(name, value=value)


def _transform_stamped(
    stamp: builtin_interfaces.Time, transform: JointTransform
) -> geometry_msgs.TransformStamped:
    """Build a TransformStamped from ``(parent, child, translation, rotation)``."""
    parent, child, translation, rotation = transform
    message = geometry_msgs.TransformStamped()
    message.header.stamp = stamp
    message.header.frame_id = parent
    message.child_frame_id = child
    t = message.transform.translation
    t.x, t.y, t.z = translation
    r = message.transform.rotation
    r.x, r.y, r.z, r.w = rotation
    return message


def main(args: Sequence[str] | None = None) -> int:
    """Run robot_state_publisher; return the process exit code."""
    argv = list(sys.argv if args is None else args)  # argv[0] is the program
    file_arguments = non_ros_arguments(argv[1:])

    def factory() -> RobotStatePublisher:
        return RobotStatePublisher(file_arguments)

    return int(run_node(factory, argv))


if __name__ == '__main__':
    sys.exit(main())
