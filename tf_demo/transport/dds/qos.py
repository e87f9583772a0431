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
Quality-of-service profiles with rclpy's names, values and rules (``rclpy.qos``).

The standalone world's classes; the DDS backend maps them to Cyclone policies as rmw_cyclonedds
does (:mod:`tf_demo.transport.dds.wire_qos`). The rclpy world uses rclpy's own.
"""

from __future__ import annotations

from enum import Enum
from enum import IntEnum
from typing import TYPE_CHECKING
from typing import TypedDict

from tf_demo.transport.dds.time import Duration

if TYPE_CHECKING:  # typing.Unpack is Python 3.11's; only the type checker reads it here
    from typing_extensions import Unpack

__all__ = [
    'DurabilityPolicy',
    'HistoryPolicy',
    'InvalidQoSProfileException',
    'LivelinessPolicy',
    'QoSDurabilityPolicy',
    'QoSHistoryPolicy',
    'QoSLivelinessPolicy',
    'QoSPresetProfiles',
    'QoSProfile',
    'QoSReliabilityPolicy',
    'ReliabilityPolicy',
    'qos_profile_action_status_default',
    'qos_profile_best_available',
    'qos_profile_default',
    'qos_profile_parameter_events',
    'qos_profile_parameters',
    'qos_profile_sensor_data',
    'qos_profile_services_default',
    'qos_profile_system_default',
    'qos_profile_unknown',
]


class QoSPolicyEnum(IntEnum):
    """Base of the policy enumerations (values as in ``rmw/types.h``)."""

    @classmethod
    def short_keys(cls) -> list[str]:
        """Return the lower-case member names (``'reliable'``, ``'best_effort'``, ...)."""
        return [key.lower() for key in cls.__members__]

    @classmethod
    def get_from_short_key(cls, name: str) -> int:
        """Return the value of the member named ``name`` (case-insensitive)."""
        return int(cls[name.upper()].value)

    @property
    def short_key(self) -> str:
        """The lower-case name of this member."""
        return self.name.lower()


class HistoryPolicy(QoSPolicyEnum):
    """History: how many samples are kept."""

    SYSTEM_DEFAULT = 0
    KEEP_LAST = 1
    KEEP_ALL = 2
    UNKNOWN = 3


class ReliabilityPolicy(QoSPolicyEnum):
    """Reliability: whether lost samples are repaired."""

    SYSTEM_DEFAULT = 0
    RELIABLE = 1
    BEST_EFFORT = 2
    UNKNOWN = 3
    BEST_AVAILABLE = 4


class DurabilityPolicy(QoSPolicyEnum):
    """Durability: whether late joiners receive samples written before they appeared."""

    SYSTEM_DEFAULT = 0
    TRANSIENT_LOCAL = 1
    VOLATILE = 2
    UNKNOWN = 3
    BEST_AVAILABLE = 4


class LivelinessPolicy(QoSPolicyEnum):
    """Liveliness: how a writer asserts that it is alive."""

    SYSTEM_DEFAULT = 0
    AUTOMATIC = 1
    MANUAL_BY_TOPIC = 3
    UNKNOWN = 4
    BEST_AVAILABLE = 5


# The names rclpy keeps for backward compatibility.
QoSHistoryPolicy = HistoryPolicy
QoSReliabilityPolicy = ReliabilityPolicy
QoSDurabilityPolicy = DurabilityPolicy
QoSLivelinessPolicy = LivelinessPolicy


class InvalidQoSProfileException(Exception):  # noqa: N818 - rclpy's name
    """Raised when a QoSProfile is constructed with invalid arguments."""

    def __init__(self, *args: object) -> None:
        Exception.__init__(self, 'Invalid QoSProfile', *args)


class _ProfileFields(TypedDict, total=False):
    """The keyword arguments of :class:`QoSProfile` (rclpy's ``**kwargs``), in rclpy's order."""

    history: HistoryPolicy | int
    depth: int
    reliability: ReliabilityPolicy | int
    durability: DurabilityPolicy | int
    lifespan: Duration
    deadline: Duration
    liveliness: LivelinessPolicy | int
    liveliness_lease_duration: Duration
    avoid_ros_namespace_conventions: bool


_PROFILE_FIELDS = tuple(_ProfileFields.__annotations__)


class QoSProfile:
    """
    A set of QoS policies, constructed as rclpy's ``QoSProfile(**kwargs)``.

    ``history`` or ``depth`` is required; ``depth`` alone means KEEP_LAST. Unspecified policies
    take rmw's ``qos_profile_default`` values (RELIABLE, VOLATILE, durations unspecified).
    """

    __slots__ = tuple(f'_{name}' for name in _PROFILE_FIELDS)

    _history: HistoryPolicy
    _depth: int
    _reliability: ReliabilityPolicy
    _durability: DurabilityPolicy
    _lifespan: Duration
    _deadline: Duration
    _liveliness: LivelinessPolicy
    _liveliness_lease_duration: Duration
    _avoid_ros_namespace_conventions: bool

    def __init__(self, **kwargs: Unpack[_ProfileFields]) -> None:
        if set(kwargs) - set(_PROFILE_FIELDS):
            # rclpy Jazzy asserts this (an AssertionError with this text)
            msg = f'Invalid arguments passed to constructor: {kwargs.keys()!r}'
            raise AssertionError(msg)
        if 'history' not in kwargs:
            if 'depth' not in kwargs:
                raise InvalidQoSProfileException('History and/or depth settings are required.')
            kwargs['history'] = HistoryPolicy.KEEP_LAST
        self.history = kwargs['history']
        if self.history == HistoryPolicy.KEEP_LAST and 'depth' not in kwargs:
            raise InvalidQoSProfileException('History set to KEEP_LAST without a depth setting.')
        self.depth = kwargs.get('depth', 10)
        self.reliability = kwargs.get('reliability', ReliabilityPolicy.RELIABLE)
        self.durability = kwargs.get('durability', DurabilityPolicy.VOLATILE)
        self.lifespan = kwargs.get('lifespan', Duration())
        self.deadline = kwargs.get('deadline', Duration())
        self.liveliness = kwargs.get('liveliness', LivelinessPolicy.SYSTEM_DEFAULT)
        self.liveliness_lease_duration = kwargs.get('liveliness_lease_duration', Duration())
        self.avoid_ros_namespace_conventions = kwargs.get('avoid_ros_namespace_conventions', False)

    @property
    def history(self) -> HistoryPolicy:
        """The history policy."""
        return self._history

    @history.setter
    def history(self, value: HistoryPolicy | int) -> None:
        self._history = HistoryPolicy(_policy_value('history', value))

    @property
    def depth(self) -> int:
        """The history depth (used with KEEP_LAST)."""
        return self._depth

    @depth.setter
    def depth(self, value: int) -> None:
        # As rclpy's setter: an int is asserted; a negative depth is refused only when an
        # endpoint is created with it (rmw: "unsupported history depth").
        if not isinstance(value, int):
            msg = f'depth must be an int, not {type(value).__name__}'
            raise AssertionError(msg)
        self._depth = value

    @property
    def reliability(self) -> ReliabilityPolicy:
        """The reliability policy."""
        return self._reliability

    @reliability.setter
    def reliability(self, value: ReliabilityPolicy | int) -> None:
        self._reliability = ReliabilityPolicy(_policy_value('reliability', value))

    @property
    def durability(self) -> DurabilityPolicy:
        """The durability policy."""
        return self._durability

    @durability.setter
    def durability(self, value: DurabilityPolicy | int) -> None:
        self._durability = DurabilityPolicy(_policy_value('durability', value))

    @property
    def lifespan(self) -> Duration:
        """How long a sample stays valid (zero: unspecified, i.e. infinite)."""
        return self._lifespan

    @lifespan.setter
    def lifespan(self, value: Duration) -> None:
        self._lifespan = _duration_value('lifespan', value)

    @property
    def deadline(self) -> Duration:
        """The promised period between samples (zero: unspecified)."""
        return self._deadline

    @deadline.setter
    def deadline(self, value: Duration) -> None:
        self._deadline = _duration_value('deadline', value)

    @property
    def liveliness(self) -> LivelinessPolicy:
        """The liveliness policy."""
        return self._liveliness

    @liveliness.setter
    def liveliness(self, value: LivelinessPolicy | int) -> None:
        self._liveliness = LivelinessPolicy(_policy_value('liveliness', value))

    @property
    def liveliness_lease_duration(self) -> Duration:
        """The liveliness lease (zero: unspecified)."""
        return self._liveliness_lease_duration

    @liveliness_lease_duration.setter
    def liveliness_lease_duration(self, value: Duration) -> None:
        self._liveliness_lease_duration = _duration_value('liveliness_lease_duration', value)

    @property
    def avoid_ros_namespace_conventions(self) -> bool:
        """Whether the topic name is used on the wire as is (no ``rt/`` prefix)."""
        return self._avoid_ros_namespace_conventions

    @avoid_ros_namespace_conventions.setter
    def avoid_ros_namespace_conventions(self, value: bool) -> None:
        if not isinstance(value, bool):
            msg = f'avoid_ros_namespace_conventions must be a bool, not {type(value).__name__}'
            raise TypeError(msg)
        self._avoid_ros_namespace_conventions = value

    def __eq__(self, other: object) -> bool:
        if not isinstance(other, QoSProfile):
            return False
        return all(getattr(self, name) == getattr(other, name) for name in _PROFILE_FIELDS)

    def __hash__(self) -> int:
        return hash(tuple(str(getattr(self, name)) for name in _PROFILE_FIELDS))

    def __str__(self) -> str:
        fields = ', '.join(f'{name}={getattr(self, name)}' for name in _PROFILE_FIELDS)
        return f'{type(self).__name__}({fields})'

    __repr__ = __str__


def _policy_value(field: str, value: object) -> int:
    """Return ``value`` as an int policy value, or raise TypeError naming the field."""
    if isinstance(value, bool) or not isinstance(value, int):
        msg = f'{field} must be a policy enum or int, not {type(value).__name__}'
        raise TypeError(msg)
    return value


def _duration_value(field: str, value: object) -> Duration:
    """Return ``value`` when it is a Duration, else fail as rclpy's setter does (an assert)."""
    if not isinstance(value, Duration):
        msg = f'{field} must be a Duration, not {type(value).__name__}'
        raise AssertionError(msg)
    return value


def validate_qos_or_depth(qos_or_depth: QoSProfile | int) -> QoSProfile:
    """
    Return a profile for what rclpy's ``create_publisher``/``create_subscription`` accept.

    An int is a KEEP_LAST depth (``QoSProfile(depth=n)``), as in rclpy.

    :raises TypeError: for anything else, with rclpy's text.
    :raises ValueError: for a negative depth.
    """
    if isinstance(qos_or_depth, QoSProfile):
        return qos_or_depth
    if isinstance(qos_or_depth, int) and not isinstance(qos_or_depth, bool):
        if qos_or_depth < 0:
            msg = 'history depth must be greater than or equal to zero'
            raise ValueError(msg)
        return QoSProfile(depth=qos_or_depth)
    msg = f'Expected QoSProfile or int, but received {type(qos_or_depth)!r}'
    raise TypeError(msg)


def _keep_last(
    depth: int, reliability: ReliabilityPolicy, durability: DurabilityPolicy
) -> QoSProfile:
    """Return a KEEP_LAST ``depth`` profile (rmw's presets but three)."""
    return QoSProfile(
        history=HistoryPolicy.KEEP_LAST,
        depth=depth,
        reliability=reliability,
        durability=durability,
    )


qos_profile_unknown = QoSProfile(
    history=HistoryPolicy.UNKNOWN,
    depth=0,
    reliability=ReliabilityPolicy.UNKNOWN,
    durability=DurabilityPolicy.UNKNOWN,
    liveliness=LivelinessPolicy.UNKNOWN,
)
qos_profile_default = _keep_last(10, ReliabilityPolicy.RELIABLE, DurabilityPolicy.VOLATILE)
qos_profile_system_default = QoSProfile(
    history=HistoryPolicy.SYSTEM_DEFAULT,
    depth=0,
    reliability=ReliabilityPolicy.SYSTEM_DEFAULT,
    durability=DurabilityPolicy.SYSTEM_DEFAULT,
)
qos_profile_sensor_data = _keep_last(5, ReliabilityPolicy.BEST_EFFORT, DurabilityPolicy.VOLATILE)
qos_profile_services_default = _keep_last(
    10, ReliabilityPolicy.RELIABLE, DurabilityPolicy.VOLATILE
)
qos_profile_parameters = _keep_last(1000, ReliabilityPolicy.RELIABLE, DurabilityPolicy.VOLATILE)
qos_profile_parameter_events = _keep_last(
    1000, ReliabilityPolicy.RELIABLE, DurabilityPolicy.VOLATILE
)
qos_profile_rosout_default = QoSProfile(
    history=HistoryPolicy.KEEP_LAST,
    depth=1000,
    reliability=ReliabilityPolicy.RELIABLE,
    durability=DurabilityPolicy.TRANSIENT_LOCAL,
    lifespan=Duration(seconds=10),
)
qos_profile_action_status_default = _keep_last(
    1, ReliabilityPolicy.RELIABLE, DurabilityPolicy.TRANSIENT_LOCAL
)

# rmw's RMW_QOS_DEADLINE_BEST_AVAILABLE and RMW_QOS_LIVELINESS_LEASE_DURATION_BEST_AVAILABLE.
_BEST_AVAILABLE_DURATION_NS = 2**63 - 2

qos_profile_best_available = QoSProfile(
    history=HistoryPolicy.KEEP_LAST,
    depth=10,
    reliability=ReliabilityPolicy.BEST_AVAILABLE,
    durability=DurabilityPolicy.BEST_AVAILABLE,
    deadline=Duration(nanoseconds=_BEST_AVAILABLE_DURATION_NS),
    liveliness=LivelinessPolicy.BEST_AVAILABLE,
    liveliness_lease_duration=Duration(nanoseconds=_BEST_AVAILABLE_DURATION_NS),
)


class QoSPresetProfiles(Enum):
    """
    The named presets, as rclpy's enum of the same name (same members, same order).

    Equal profiles are aliases, as in rclpy (e.g. ``SERVICES_DEFAULT`` is ``DEFAULT``).
    The standalone backend refuses endpoints with BEST_AVAILABLE policies (a clear error), so
    ``BEST_AVAILABLE`` is a preset to name, not to use, there.
    """

    UNKNOWN = qos_profile_unknown
    DEFAULT = qos_profile_default
    SYSTEM_DEFAULT = qos_profile_system_default
    SENSOR_DATA = qos_profile_sensor_data
    SERVICES_DEFAULT = qos_profile_services_default
    PARAMETERS = qos_profile_parameters
    PARAMETER_EVENTS = qos_profile_parameter_events
    ACTION_STATUS_DEFAULT = qos_profile_action_status_default
    BEST_AVAILABLE = qos_profile_best_available

    @classmethod
    def short_keys(cls) -> list[str]:
        """Return the lower-case preset names."""
        return [key.lower() for key in cls.__members__]

    @classmethod
    def get_from_short_key(cls, name: str) -> QoSProfile:
        """Return the preset named ``name`` (case-insensitive)."""
        profile: QoSProfile = cls[name.upper()].value
        return profile
