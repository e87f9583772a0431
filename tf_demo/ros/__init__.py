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
The tf2_ros-compatible API: buffer, listener, broadcasters and ``do_transform_*``.

``from tf_demo import ros as tf2_ros`` gives code written for tf2_ros the names it expects.
"""

from tf_demo.core.exceptions import BackwardExtrapolationException
from tf_demo.core.exceptions import ConnectivityException
from tf_demo.core.exceptions import ExtrapolationException
from tf_demo.core.exceptions import ForwardExtrapolationException
from tf_demo.core.exceptions import InvalidArgumentException
from tf_demo.core.exceptions import LookupException
from tf_demo.core.exceptions import NoDataForExtrapolationException
from tf_demo.core.exceptions import TimeoutException
from tf_demo.core.exceptions import TransformException
from tf_demo.ros.buffer import Buffer
from tf_demo.ros.buffer import ns_from_duration
from tf_demo.ros.buffer import ns_from_time
from tf_demo.ros.buffer import TypeException
from tf_demo.ros.geometry import do_transform_point
from tf_demo.ros.geometry import do_transform_polygon_stamped
from tf_demo.ros.geometry import do_transform_pose
from tf_demo.ros.geometry import do_transform_pose_stamped
from tf_demo.ros.geometry import do_transform_pose_with_covariance_stamped
from tf_demo.ros.geometry import do_transform_quaternion_stamped
from tf_demo.ros.geometry import do_transform_vector3
from tf_demo.ros.geometry import do_transform_wrench_stamped
from tf_demo.ros.geometry import transform_covariance
from tf_demo.ros.geometry import TRANSFORM_FUNCTIONS
from tf_demo.ros.static_transform_broadcaster import StaticTransformBroadcaster
from tf_demo.ros.transform_broadcaster import TransformBroadcaster
from tf_demo.ros.transform_listener import TransformListener
from tf_demo.transport.future import Future

__all__ = [
    'TRANSFORM_FUNCTIONS',
    'BackwardExtrapolationException',
    'Buffer',
    'ConnectivityException',
    'ExtrapolationException',
    'ForwardExtrapolationException',
    'Future',
    'InvalidArgumentException',
    'LookupException',
    'NoDataForExtrapolationException',
    'StaticTransformBroadcaster',
    'TimeoutException',
    'TransformBroadcaster',
    'TransformException',
    'TransformListener',
    'TypeException',
    'do_transform_point',
    'do_transform_polygon_stamped',
    'do_transform_pose',
    'do_transform_pose_stamped',
    'do_transform_pose_with_covariance_stamped',
    'do_transform_quaternion_stamped',
    'do_transform_vector3',
    'do_transform_wrench_stamped',
    'ns_from_duration',
    'ns_from_time',
    'transform_covariance',
]
