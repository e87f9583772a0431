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
The one declarative table of ROS message definitions, and its parsed form.

Every message class, every CDR codec and every RIHS01 type hash in :mod:`tf_demo.msgs` is
generated from :data:`DEFINITIONS` (the package modules, ``geometry_msgs.py`` etc., are source
files that :mod:`tf_demo.msgs._typegen` writes from it). Each entry is the ``.msg`` text of ROS 2
Jazzy (comments dropped), with ``;`` between fields and constants. A field may carry a default as
a Python literal after its name, e.g. ``float64 w 1.0``; a constant is ``uint8 NAME=value``.
"""

from __future__ import annotations

import ast
from dataclasses import dataclass
import re
from typing import Literal

#: ``.msg`` definitions of ROS 2 Jazzy, one entry per type, in dependency order.
DEFINITIONS: dict[str, str] = {
    'builtin_interfaces/msg/Time': 'int32 sec; uint32 nanosec',
    'builtin_interfaces/msg/Duration': 'int32 sec; uint32 nanosec',
    'std_msgs/msg/Header': 'builtin_interfaces/Time stamp; string frame_id',
    'std_msgs/msg/String': 'string data',
    'geometry_msgs/msg/Vector3': 'float64 x; float64 y; float64 z',
    'geometry_msgs/msg/Quaternion': 'float64 x 0.0; float64 y 0.0; float64 z 0.0; float64 w 1.0',
    'geometry_msgs/msg/Point': 'float64 x; float64 y; float64 z',
    'geometry_msgs/msg/Point32': 'float32 x; float32 y; float32 z',
    'geometry_msgs/msg/Pose': 'Point position; Quaternion orientation',
    'geometry_msgs/msg/Transform': 'Vector3 translation; Quaternion rotation',
    'geometry_msgs/msg/TransformStamped': (
        'std_msgs/Header header; string child_frame_id; Transform transform'
    ),
    'geometry_msgs/msg/PointStamped': 'std_msgs/Header header; Point point',
    'geometry_msgs/msg/Vector3Stamped': 'std_msgs/Header header; Vector3 vector',
    'geometry_msgs/msg/PoseStamped': 'std_msgs/Header header; Pose pose',
    'geometry_msgs/msg/PoseWithCovariance': 'Pose pose; float64[36] covariance',
    'geometry_msgs/msg/PoseWithCovarianceStamped': (
        'std_msgs/Header header; PoseWithCovariance pose'
    ),
    'geometry_msgs/msg/Twist': 'Vector3 linear; Vector3 angular',
    'geometry_msgs/msg/TwistWithCovariance': 'Twist twist; float64[36] covariance',
    'geometry_msgs/msg/Polygon': 'Point32[] points',
    'geometry_msgs/msg/PolygonStamped': 'std_msgs/Header header; Polygon polygon',
    'nav_msgs/msg/Odometry': (
        'std_msgs/Header header; string child_frame_id; '
        'geometry_msgs/PoseWithCovariance pose; geometry_msgs/TwistWithCovariance twist'
    ),
    'sensor_msgs/msg/JointState': (
        'std_msgs/Header header; string[] name; float64[] position; float64[] velocity; '
        'float64[] effort'
    ),
    'tf2_msgs/msg/TFMessage': 'geometry_msgs/TransformStamped[] transforms',
    'rosgraph_msgs/msg/Clock': 'builtin_interfaces/Time clock',
    'rmw_dds_common/msg/Gid': 'char[16] data',
    'rmw_dds_common/msg/NodeEntitiesInfo': (
        'string<=256 node_namespace; string<=256 node_name; Gid[] reader_gid_seq; '
        'Gid[] writer_gid_seq'
    ),
    'rmw_dds_common/msg/ParticipantEntitiesInfo': (
        'Gid gid; NodeEntitiesInfo[] node_entities_info_seq'
    ),
    'service_msgs/msg/ServiceEventInfo': (
        'uint8 REQUEST_SENT=0; uint8 REQUEST_RECEIVED=1; uint8 RESPONSE_SENT=2; '
        'uint8 RESPONSE_RECEIVED=3; uint8 event_type; builtin_interfaces/Time stamp; '
        'char[16] client_gid; int64 sequence_number'
    ),
    'rcl_interfaces/msg/ParameterType': (
        'uint8 PARAMETER_NOT_SET=0; uint8 PARAMETER_BOOL=1; uint8 PARAMETER_INTEGER=2; '
        'uint8 PARAMETER_DOUBLE=3; uint8 PARAMETER_STRING=4; uint8 PARAMETER_BYTE_ARRAY=5; '
        'uint8 PARAMETER_BOOL_ARRAY=6; uint8 PARAMETER_INTEGER_ARRAY=7; '
        'uint8 PARAMETER_DOUBLE_ARRAY=8; uint8 PARAMETER_STRING_ARRAY=9'
    ),
    'rcl_interfaces/msg/ParameterValue': (
        'uint8 type; bool bool_value; int64 integer_value; float64 double_value; '
        'string string_value; byte[] byte_array_value; bool[] bool_array_value; '
        'int64[] integer_array_value; float64[] double_array_value; string[] string_array_value'
    ),
    'rcl_interfaces/msg/Parameter': 'string name; ParameterValue value',
    'rcl_interfaces/msg/FloatingPointRange': 'float64 from_value; float64 to_value; float64 step',
    'rcl_interfaces/msg/IntegerRange': 'int64 from_value; int64 to_value; uint64 step',
    'rcl_interfaces/msg/ParameterDescriptor': (
        'string name; uint8 type; string description; string additional_constraints; '
        'bool read_only False; bool dynamic_typing False; '
        'FloatingPointRange[<=1] floating_point_range; IntegerRange[<=1] integer_range'
    ),
    'rcl_interfaces/msg/SetParametersResult': 'bool successful; string reason',
    'rcl_interfaces/msg/ListParametersResult': 'string[] names; string[] prefixes',
    'rcl_interfaces/msg/ParameterEvent': (
        'builtin_interfaces/Time stamp; string node; Parameter[] new_parameters; '
        'Parameter[] changed_parameters; Parameter[] deleted_parameters'
    ),
    'rcl_interfaces/msg/Log': (
        'uint8 DEBUG=10; uint8 INFO=20; uint8 WARN=30; uint8 ERROR=40; uint8 FATAL=50; '
        'builtin_interfaces/Time stamp; uint8 level; string name; string msg; string file; '
        'string function; uint32 line'
    ),
}

#: ``.srv`` definitions of ROS 2 Jazzy: (request fields, response fields), as in
#: :data:`DEFINITIONS`. Each adds ``<srv>_Request``, ``<srv>_Response`` and ``<srv>_Event``
#: (rosidl's service event message) to :data:`DEFINITIONS`.
SERVICE_DEFINITIONS: dict[str, tuple[str, str]] = {
    'rcl_interfaces/srv/ListParameters': (
        'uint64 DEPTH_RECURSIVE=0; string[] prefixes; uint64 depth',
        'ListParametersResult result',
    ),
    'rcl_interfaces/srv/GetParameters': ('string[] names', 'ParameterValue[] values'),
    'rcl_interfaces/srv/SetParameters': (
        'Parameter[] parameters',
        'SetParametersResult[] results',
    ),
    'rcl_interfaces/srv/SetParametersAtomically': (
        'Parameter[] parameters',
        'SetParametersResult result',
    ),
    'rcl_interfaces/srv/DescribeParameters': (
        'string[] names',
        'ParameterDescriptor[] descriptors',
    ),
    'rcl_interfaces/srv/GetParameterTypes': ('string[] names', 'uint8[] types'),
    'tf2_msgs/srv/FrameGraph': ('', 'string frame_yaml'),
}

#: What rosidl puts in a message that has no fields.
EMPTY_STRUCTURE = 'uint8 structure_needs_at_least_one_member'

for _srvtype, (_request, _response) in SERVICE_DEFINITIONS.items():
    DEFINITIONS[f'{_srvtype}_Request'] = _request
    DEFINITIONS[f'{_srvtype}_Response'] = _response
    DEFINITIONS[f'{_srvtype}_Event'] = (
        f'service_msgs/ServiceEventInfo info; {_srvtype}_Request[<=1] request; '
        f'{_srvtype}_Response[<=1] response'
    )


@dataclass(frozen=True)
class Primitive:
    """
    How one ROS primitive type is named, laid out on the wire and held in Python.

    :ivar idl: the rosidl (IDL) name, as rclpy and the type description use it.
    :ivar code: the :mod:`struct` format character.
    :ivar size: the wire size in bytes, which is also its CDR alignment.
    :ivar array_code: the :mod:`array` typecode rclpy uses for a sequence of it ('' for a list).
    :ivar numpy_dtype: the numpy dtype rclpy uses for a fixed array of it ('' for a list).
    :ivar default: the Python default value (``byte`` is a 1-byte ``bytes``, as in rclpy).
    """

    idl: str
    code: str
    size: int
    array_code: str
    numpy_dtype: str
    default: bool | int | float | bytes


#: The ROS ``.msg`` primitive types (``wstring`` is not supported).
PRIMITIVES: dict[str, Primitive] = {
    'bool': Primitive('boolean', '?', 1, '', '', False),
    'int8': Primitive('int8', 'b', 1, 'b', 'int8', 0),
    'uint8': Primitive('uint8', 'B', 1, 'B', 'uint8', 0),
    'char': Primitive('uint8', 'B', 1, 'B', 'uint8', 0),
    'byte': Primitive('octet', 'c', 1, '', '', b'\x00'),
    'int16': Primitive('int16', 'h', 2, 'h', 'int16', 0),
    'uint16': Primitive('uint16', 'H', 2, 'H', 'uint16', 0),
    'int32': Primitive('int32', 'i', 4, 'i', 'int32', 0),
    'uint32': Primitive('uint32', 'I', 4, 'I', 'uint32', 0),
    'int64': Primitive('int64', 'q', 8, 'q', 'int64', 0),
    'uint64': Primitive('uint64', 'Q', 8, 'Q', 'uint64', 0),
    'float32': Primitive('float', 'f', 4, 'f', 'float32', 0.0),
    'float64': Primitive('double', 'd', 8, 'd', 'float64', 0.0),
}

Kind = Literal['single', 'sequence', 'array']


@dataclass(frozen=True)
class FieldSpec:
    """
    One field of a message.

    :ivar name: the field name.
    :ivar base: a primitive name from :data:`PRIMITIVES`, ``'string'``, or a nested message
        type ``'pkg/msg/Name'``.
    :ivar kind: ``'single'``, ``'sequence'`` (``T[]``, ``T[<=N]``) or ``'array'`` (``T[N]``).
    :ivar size: the array length, the sequence bound, or 0.
    :ivar string_bound: N of ``string<=N``, else 0.
    :ivar default: the default of a primitive single field, or None for the type's default.
    """

    name: str
    base: str
    kind: Kind
    size: int
    string_bound: int
    default: bool | int | float | str | bytes | None

    @property
    def is_nested(self) -> bool:
        """Tell whether the element type is a message."""
        return '/' in self.base


@dataclass(frozen=True)
class ConstantSpec:
    """
    One constant of a message (``uint8 DEBUG=10``): a class attribute, not on the wire.

    :ivar name: the constant's name.
    :ivar base: its primitive type name, or ``'string'``.
    :ivar value: its value.
    """

    name: str
    base: str
    value: bool | int | float | str


@dataclass(frozen=True)
class MessageSpec:
    """
    A parsed message definition.

    :ivar msgtype: ``'pkg/msg/Name'``.
    :ivar fields: the fields in wire order.
    :ivar constants: the constants, in definition order.
    """

    msgtype: str
    fields: tuple[FieldSpec, ...]
    constants: tuple[ConstantSpec, ...] = ()

    @property
    def package(self) -> str:
        """Return the ROS package name."""
        return self.msgtype.split('/', 1)[0]

    @property
    def name(self) -> str:
        """Return the bare type name."""
        return self.msgtype.rsplit('/', 1)[1]

    @property
    def interface(self) -> str:
        """Return ``'msg'``, or ``'srv'`` for a service's request, response and event."""
        return self.msgtype.split('/')[1]

    @property
    def dds_typename(self) -> str:
        """Return the DDS type name rmw uses, ``pkg::msg::dds_::Name_`` (``pkg::srv::...``)."""
        return f'{self.package}::{self.interface}::dds_::{self.name}_'


class SchemaError(ValueError):
    """A message definition in the table is malformed."""


_FIELD_RE = re.compile(
    r'^(?P<base>[A-Za-z][\w/]*?)(?:<=(?P<strbound>\d+))?'
    r'(?:\[(?P<le><=)?(?P<size>\d*)\])?\s+(?P<name>[a-z][a-z0-9_]*)(?:\s+(?P<default>.+))?$'
)

_CONSTANT_RE = re.compile(
    r'^(?P<base>[a-z][a-z0-9]*)\s+(?P<name>[A-Z][A-Z0-9_]*)\s*=\s*(?P<value>.+)$'
)


def _parse_constant(match: re.Match[str]) -> ConstantSpec:
    """Parse one ``.msg`` constant line (``uint8 NAME=value``)."""
    base = match['base']
    value = ast.literal_eval(match['value'].strip())
    if base == 'string':
        expected: type = str
    elif base in PRIMITIVES and base != 'byte':
        expected = type(PRIMITIVES[base].default)  # bool, int or float
    else:
        msg = f'constants of type {base!r} are not supported: {match.string!r}'
        raise SchemaError(msg)
    if not isinstance(value, bool | int | float | str) or type(value) is not expected:
        msg = f'cannot parse constant definition {match.string!r}'
        raise SchemaError(msg)
    return ConstantSpec(match['name'], match['base'], value)


def _parse_field(package: str, text: str) -> FieldSpec:
    """Parse one ``.msg`` field line of package ``package``."""
    match = _FIELD_RE.match(text.strip())
    if match is None:
        msg = f'cannot parse field definition {text!r}'
        raise SchemaError(msg)
    base = match['base']
    if base not in PRIMITIVES and base != 'string':
        if base == 'wstring':
            msg = f'field type {base!r} is not supported'
            raise SchemaError(msg)
        if base.count('/') < 2:  # 'Name' or 'pkg/Name'; 'pkg/srv/Name' is kept
            pkg, _, name = base.rpartition('/')
            base = f'{pkg or package}/msg/{name}'
    string_bound = int(match['strbound'] or 0)
    if string_bound and base != 'string':
        msg = f'only strings take a <=N bound: {text!r}'
        raise SchemaError(msg)
    kind: Kind = 'single'
    size = 0
    if match['size'] is not None:
        kind = 'sequence' if match['le'] or not match['size'] else 'array'
        size = int(match['size'] or 0)
    default: bool | int | float | str | bytes | None = None
    if match['default'] is not None:
        default = ast.literal_eval(match['default'])
    return FieldSpec(match['name'], base, kind, size, string_bound, default)


def parse_definition(msgtype: str, text: str) -> MessageSpec:
    """Parse the ``;``-separated ``.msg`` text of ``msgtype``."""
    package = msgtype.split('/', 1)[0]
    parts = [part.strip() for part in text.split(';') if part.strip()]
    constants = [_CONSTANT_RE.match(part) for part in parts]
    fields = [part for part, constant in zip(parts, constants, strict=True) if not constant]
    return MessageSpec(
        msgtype,
        tuple(_parse_field(package, part) for part in fields or [EMPTY_STRUCTURE]),
        tuple(_parse_constant(constant) for constant in constants if constant),
    )


#: Every message type of :data:`DEFINITIONS`, parsed.
SPECS: dict[str, MessageSpec] = {
    msgtype: parse_definition(msgtype, text) for msgtype, text in DEFINITIONS.items()
}


#: The service types themselves (for their type hashes): rosidl's three nested messages.
SERVICE_SPECS: dict[str, MessageSpec] = {
    srvtype: parse_definition(
        srvtype,
        f'{srvtype}_Request request_message; {srvtype}_Response response_message; '
        f'{srvtype}_Event event_message',
    )
    for srvtype in SERVICE_DEFINITIONS
}


def spec_for(msgtype: str) -> MessageSpec:
    """
    Return the parsed definition of ``msgtype`` (``pkg/msg/Name`` or ``pkg/Name``).

    :raises KeyError: the type is not in the table.
    """
    if msgtype.count('/') == 1:
        pkg, name = msgtype.split('/')
        msgtype = f'{pkg}/msg/{name}'
    try:
        return SPECS[msgtype]
    except KeyError:
        msg = f'unknown message type {msgtype!r}'
        raise KeyError(msg) from None


def rclpy_field_type(field: FieldSpec) -> str:
    """Return the type string rclpy's ``get_fields_and_field_types()`` gives for ``field``."""
    if field.is_nested:
        pkg, _, name = field.base.split('/')
        element = f'{pkg}/{name}'
    elif field.base == 'string':
        element = f'string<{field.string_bound}>' if field.string_bound else 'string'
    else:
        element = PRIMITIVES[field.base].idl
    if field.kind == 'array':
        return f'{element}[{field.size}]'
    if field.kind == 'sequence':
        return f'sequence<{element}, {field.size}>' if field.size else f'sequence<{element}>'
    return element
