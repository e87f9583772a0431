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
The standalone world's runtime over Cyclone DDS, one concept per module, as rclpy cuts its own.

``names`` (rcl's name rules), ``context`` (init/shutdown, live nodes), ``graph``
(``ros_discovery_info``), ``endpoints`` (publisher, subscription), ``timers``,
``callback_groups``, ``node`` and ``node_parameters``, ``tasks``, ``executors``,
``multi_threaded_executor`` and ``spin``. :mod:`tf_demo.transport.dds_backend` is the backend
module the world selection imports: it re-exports the public names.
"""
