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
Robot descriptions: URDF and xacro loading, strict validation, KDL-semantics kinematics.

``RobotModel.from_file(path, mappings)`` / ``RobotModel.from_string(xml)`` are the entry points
(design.md section 3.2); every problem is a :class:`UrdfError` subclass whose message names the
file, the element and the reason.
"""

from tf_demo.urdf.description import JointDescription
from tf_demo.urdf.description import Limit
from tf_demo.urdf.description import Mimic
from tf_demo.urdf.description import parse_robot
from tf_demo.urdf.description import RobotDescription
from tf_demo.urdf.description import Visual
from tf_demo.urdf.errors import UrdfBrokenRefError
from tf_demo.urdf.errors import UrdfError
from tf_demo.urdf.errors import UrdfMalformedError
from tf_demo.urdf.errors import UrdfUnsupportedError
from tf_demo.urdf.loading import expand_xacro
from tf_demo.urdf.loading import find_package_share
from tf_demo.urdf.loading import parse_xacro_args
from tf_demo.urdf.loading import read_description
from tf_demo.urdf.loading import resolve_resource
from tf_demo.urdf.model import JointPositionError
from tf_demo.urdf.model import JointTransform
from tf_demo.urdf.model import kdl_quaternion
from tf_demo.urdf.model import RobotModel

__all__ = [
    'JointDescription',
    'JointPositionError',
    'JointTransform',
    'Limit',
    'Mimic',
    'RobotDescription',
    'RobotModel',
    'UrdfBrokenRefError',
    'UrdfError',
    'UrdfMalformedError',
    'UrdfUnsupportedError',
    'Visual',
    'expand_xacro',
    'find_package_share',
    'kdl_quaternion',
    'parse_robot',
    'parse_xacro_args',
    'read_description',
    'resolve_resource',
]
