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

"""tf_demo: a pure-Python tf2 for ROS 2 Jazzy and the standalone world."""

from __future__ import annotations

from collections.abc import Sequence

from tf_demo.transport.ros_args import split_ros_args


def non_ros_arguments(args: Sequence[str]) -> list[str]:
    """Return the arguments outside ``--ros-args ... [--]`` sections, in order (rcl's rules)."""
    return split_ros_args(args)[0]
