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
The standalone world's ``tf2_msgs`` types (``msg/TFMessage``, ``srv/FrameGraph``).

The fields come from :data:`tf_demo.msgs._schema.DEFINITIONS`; see
:class:`tf_demo.msgs._message.Message`.
"""

from __future__ import annotations

from tf_demo.msgs._message import Message
from tf_demo.msgs._message import Service
import tf_demo.msgs.geometry_msgs
import tf_demo.msgs.service_msgs  # noqa: F401 - the services' event messages nest it

__all__ = ['FrameGraph', 'TFMessage']


class TFMessage(Message):
    """tf2_msgs/msg/TFMessage."""


class FrameGraph(Service):
    """tf2_msgs/srv/FrameGraph (what ``view_frames`` asks a tf2_ros Buffer for)."""
