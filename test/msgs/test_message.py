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

"""The message classes behave like rclpy's: fields, defaults, constructor, equality, repr."""

from __future__ import annotations

from array import array
import copy
import pickle

import numpy
import pytest
from tf_demo.msgs import builtin_interfaces
from tf_demo.msgs import cdr
from tf_demo.msgs import geometry_msgs
from tf_demo.msgs import nav_msgs
from tf_demo.msgs import rcl_interfaces
from tf_demo.msgs import rmw_dds_common
from tf_demo.msgs import rosgraph_msgs
from tf_demo.msgs import sensor_msgs
from tf_demo.msgs import service_msgs
from tf_demo.msgs import std_msgs
from tf_demo.msgs import tf2_msgs
from tf_demo.msgs._message import blank_instance_maker
from tf_demo.msgs._message import message_class
from tf_demo.msgs._message import REGISTRY
from tf_demo.msgs._schema import DEFINITIONS

REQUIRED = {
    'builtin_interfaces': ['Time', 'Duration'],
    'std_msgs': ['Header', 'String'],
    'geometry_msgs': [
        'Vector3', 'Quaternion', 'Point', 'Point32', 'Pose', 'Transform', 'TransformStamped',
        'PointStamped', 'Vector3Stamped', 'PoseStamped', 'PoseWithCovariance',
        'PoseWithCovarianceStamped', 'Twist', 'TwistWithCovariance', 'Polygon', 'PolygonStamped',
    ],
    'nav_msgs': ['Odometry'],
    'sensor_msgs': ['JointState'],
    'tf2_msgs': ['TFMessage'],
    'rosgraph_msgs': ['Clock'],
    'rmw_dds_common': ['Gid', 'NodeEntitiesInfo', 'ParticipantEntitiesInfo'],
    'service_msgs': ['ServiceEventInfo'],
    'rcl_interfaces': [
        'ParameterType', 'ParameterValue', 'Parameter', 'FloatingPointRange', 'IntegerRange',
        'ParameterDescriptor', 'SetParametersResult', 'ListParametersResult', 'ParameterEvent',
        'Log',
    ],
}  # fmt: skip
MODULES = {
    module.__name__.rsplit('.', 1)[1]: module
    for module in (
        builtin_interfaces, std_msgs, geometry_msgs, nav_msgs, sensor_msgs, tf2_msgs,
        rosgraph_msgs, rmw_dds_common, service_msgs, rcl_interfaces,
    )
}  # fmt: skip


@pytest.mark.parametrize(
    ('package', 'name'), [(pkg, name) for pkg, names in REQUIRED.items() for name in names]
)
def test_every_required_type_exists_with_ros_names(package: str, name: str) -> None:
    """Each type lives in its package module with rmw's DDS name and an RIHS01 hash."""
    cls = getattr(MODULES[package], name)
    assert cls.__msgtype__ == f'{package}/msg/{name}'
    assert cls.__dds_typename__ == f'{package}::msg::dds_::{name}_'
    assert cls.__typehash__.startswith('RIHS01_')
    assert len(cls.__typehash__) == len('RIHS01_') + 64
    assert message_class(cls.__msgtype__) is cls
    assert cls() == cls()


def test_registry_covers_the_whole_table() -> None:
    """Every definition in the table has a class once the package modules are imported."""
    assert set(REGISTRY) == set(DEFINITIONS)


def test_nested_defaults_follow_rclpy() -> None:
    """Defaults are rclpy's: zeros, empty strings, Quaternion w=1, fresh nested objects."""
    transform = geometry_msgs.TransformStamped()
    assert transform.header.stamp.sec == 0
    assert transform.header.stamp.nanosec == 0
    assert transform.header.frame_id == ''
    assert transform.child_frame_id == ''
    rotation = transform.transform.rotation
    assert (rotation.x, rotation.y, rotation.z, rotation.w) == (0.0, 0.0, 0.0, 1.0)
    assert geometry_msgs.Pose().orientation.w == 1.0
    other = geometry_msgs.TransformStamped()
    assert other.header is not transform.header
    transform.header.frame_id = 'odom'
    assert other.header.frame_id == ''


def test_array_and_sequence_defaults_have_rclpy_container_types() -> None:
    """Fixed arrays are numpy arrays of the right size; numeric sequences are array.array."""
    covariance = geometry_msgs.PoseWithCovariance().covariance
    assert isinstance(covariance, numpy.ndarray)
    assert covariance.dtype == numpy.float64
    assert covariance.shape == (36,)
    assert not covariance.any()
    twist_covariance = nav_msgs.Odometry().twist.covariance
    assert isinstance(twist_covariance, numpy.ndarray)
    assert twist_covariance.shape == (36,)
    gid = rmw_dds_common.Gid().data
    assert isinstance(gid, numpy.ndarray)
    assert gid.dtype == numpy.uint8
    assert gid.shape == (16,)
    joint_state = sensor_msgs.JointState()
    assert joint_state.name == []
    assert isinstance(joint_state.position, array)
    assert joint_state.position.typecode == 'd'
    assert sensor_msgs.JointState().position is not joint_state.position
    assert geometry_msgs.Polygon().points == []
    assert tf2_msgs.TFMessage().transforms == []


def test_keyword_constructor_sets_fields_and_rejects_unknown_names() -> None:
    """Keyword arguments set fields; an unknown name is a TypeError naming the valid fields."""
    point = geometry_msgs.Point(x=1.0, z=3.0)
    assert (point.x, point.y, point.z) == (1.0, 0.0, 3.0)
    clock = rosgraph_msgs.Clock(clock=builtin_interfaces.Time(sec=4, nanosec=5))
    assert clock.clock.nanosec == 5
    with pytest.raises(
        TypeError, match=r'Point\(\) got unknown field\(s\) w; its fields are: x, y, z'
    ):
        geometry_msgs.Point(w=1.0)  # type: ignore[arg-type]  # no field w: the refusal is tested
    with pytest.raises(TypeError, match=r'Point\(\) takes keyword arguments only'):
        geometry_msgs.Point(1.0)  # type: ignore[arg-type]  # rclpy takes keywords only
    assert type(geometry_msgs.Point(x=2.0)) is geometry_msgs.Point
    assert geometry_msgs.Point(x=2.0) == geometry_msgs.Point(x=2.0, y=0.0)


def test_blank_instances_are_the_public_classes_with_no_fields_set() -> None:
    """The decoders' instance maker gives a plain instance: no defaults, no other class."""
    make = blank_instance_maker(geometry_msgs.Vector3)
    blank = make()
    assert type(blank) is geometry_msgs.Vector3
    with pytest.raises(AttributeError):
        _ = blank.x
    blank.x, blank.y, blank.z = 1.0, 2.0, 3.0
    assert blank == geometry_msgs.Vector3(x=1.0, y=2.0, z=3.0)
    assert repr(blank) == 'geometry_msgs.msg.Vector3(x=1.0, y=2.0, z=3.0)'
    decoded = cdr.deserialize(
        tf2_msgs.TFMessage,
        cdr.serialize(tf2_msgs.TFMessage(transforms=[geometry_msgs.TransformStamped()] * 5)),
    )
    stamped = decoded.transforms[4]
    assert type(stamped) is geometry_msgs.TransformStamped
    assert type(stamped.header.stamp) is builtin_interfaces.Time
    assert type(stamped.transform.rotation) is geometry_msgs.Quaternion


def test_slots_reject_attributes_that_are_not_fields() -> None:
    """A typo in a field name fails loudly instead of silently adding an attribute."""
    header = std_msgs.Header()
    assert not hasattr(header, '__dict__')
    with pytest.raises(AttributeError):
        header.frameid = 'map'  # type: ignore[attr-defined]


def test_equality_compares_all_fields_and_types() -> None:
    """Messages are equal when type and every field are equal, sequences by value."""
    assert geometry_msgs.Vector3(x=1.0) == geometry_msgs.Vector3(x=1.0)
    assert geometry_msgs.Vector3(x=1.0) != geometry_msgs.Vector3(x=2.0)
    assert geometry_msgs.Vector3() != geometry_msgs.Point()
    assert sensor_msgs.JointState(position=[1.0]) == sensor_msgs.JointState(
        position=array('d', [1.0])
    )
    assert sensor_msgs.JointState(position=[1.0]) != sensor_msgs.JointState(position=[1.0, 2.0])
    with_cov = geometry_msgs.PoseWithCovariance()
    assert isinstance(with_cov.covariance, numpy.ndarray)
    with_cov.covariance[0] = 1.0
    assert with_cov != geometry_msgs.PoseWithCovariance()
    assert geometry_msgs.Vector3() != (0.0, 0.0, 0.0)


def test_repr_looks_like_rclpy() -> None:
    """repr is rclpy's ``pkg.msg.Name(field=value, ...)`` with arrays shown as lists."""
    assert repr(geometry_msgs.Vector3(x=1.5)) == 'geometry_msgs.msg.Vector3(x=1.5, y=0.0, z=0.0)'
    assert repr(std_msgs.Header(frame_id='map')) == (
        "std_msgs.msg.Header(stamp=builtin_interfaces.msg.Time(sec=0, nanosec=0), frame_id='map')"
    )
    text = repr(sensor_msgs.JointState(name=['j'], position=array('d', [0.5])))
    assert "name=['j'], position=[0.5], velocity=[], effort=[]" in text


def test_fields_and_field_types_match_rclpy_strings() -> None:
    """get_fields_and_field_types gives rosidl's type strings in field order."""
    assert sensor_msgs.JointState.get_fields_and_field_types() == {
        'header': 'std_msgs/Header',
        'name': 'sequence<string>',
        'position': 'sequence<double>',
        'velocity': 'sequence<double>',
        'effort': 'sequence<double>',
    }
    assert geometry_msgs.Point32.get_fields_and_field_types() == {
        'x': 'float', 'y': 'float', 'z': 'float',
    }  # fmt: skip
    assert geometry_msgs.PoseWithCovariance().get_fields_and_field_types()['covariance'] == (
        'double[36]'
    )
    assert rmw_dds_common.NodeEntitiesInfo.get_fields_and_field_types() == {
        'node_namespace': 'string<256>',
        'node_name': 'string<256>',
        'reader_gid_seq': 'sequence<rmw_dds_common/Gid>',
        'writer_gid_seq': 'sequence<rmw_dds_common/Gid>',
    }
    assert rmw_dds_common.Gid.get_fields_and_field_types() == {'data': 'uint8[16]'}


def test_messages_copy_and_pickle_deeply() -> None:
    """deepcopy and pickle give equal, independent messages."""
    original = tf2_msgs.TFMessage(transforms=[geometry_msgs.TransformStamped(child_frame_id='a')])
    for clone in (copy.deepcopy(original), pickle.loads(pickle.dumps(original))):
        assert clone == original
        clone.transforms[0].child_frame_id = 'b'
        assert original.transforms[0].child_frame_id == 'a'
