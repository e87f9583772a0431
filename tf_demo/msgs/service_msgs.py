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
The standalone world's ``service_msgs/msg`` types (rclpy-compatible fields and defaults).

The fields come from :data:`tf_demo.msgs._schema.DEFINITIONS`; see
:class:`tf_demo.msgs._message.Message`.
"""

from __future__ import annotations

from tf_demo.msgs._message import Message
import tf_demo.msgs.builtin_interfaces  # noqa: F401 - defines the nested types first

__all__ = ['ServiceEventInfo']


class ServiceEventInfo(Message):
    """service_msgs/msg/ServiceEventInfo."""

    REQUEST_SENT = 0
    REQUEST_RECEIVED = 1
    RESPONSE_SENT = 2
    RESPONSE_RECEIVED = 3
