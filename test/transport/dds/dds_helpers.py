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

"""What the standalone-only tests of tf_demo.transport.dds share: spinning, a /tf message."""

from __future__ import annotations

from collections.abc import Callable
import time

from conftest import STANDALONE_ONLY
import pytest

pytest.importorskip('cyclonedds', reason=STANDALONE_ONLY)

from tf_demo.msgs import geometry_msgs
from tf_demo.msgs import tf2_msgs
from tf_demo.transport import dds_backend


def spin_until(
    executor: dds_backend.DdsExecutor, done: Callable[[], bool], timeout: float = 10.0
) -> bool:
    deadline = time.monotonic() + timeout
    while not done() and time.monotonic() < deadline:
        executor.spin_once(timeout_sec=0.05)
    return done()


def one_transform(x: float) -> tf2_msgs.TFMessage:
    transform = geometry_msgs.TransformStamped()
    transform.header.frame_id = 'odom'
    transform.child_frame_id = 'base_link'
    transform.transform.translation.x = x
    transform.transform.rotation.w = 1.0
    return tf2_msgs.TFMessage(transforms=[transform])
