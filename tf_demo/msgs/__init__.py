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
The standalone world's ROS 2 messages and their CDR codec.

One module per ROS package (``builtin_interfaces``, ``std_msgs``, ``geometry_msgs``, ``nav_msgs``,
``sensor_msgs``, ``tf2_msgs``, ``rosgraph_msgs``, ``rmw_dds_common``, ``service_msgs``,
``rcl_interfaces``) with rclpy-compatible classes (services: ``Service`` types with ``Request``
and ``Response``); :mod:`~tf_demo.msgs.cdr` (de)serialises them byte-identically to ROS 2;
:mod:`~tf_demo.msgs.convert` turns them into the core's plain values; :mod:`~tf_demo.msgs.typehash`
gives their RIHS01 hashes. Everything comes from the table in ``_schema.py``: the typed classes
are generated from it into one type store, ``_types.py``, which the package modules re-export
(``python -m tf_demo.msgs._typegen --write``); the codecs are generated from it at run time.
"""
