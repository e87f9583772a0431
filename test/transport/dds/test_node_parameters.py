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

"""A node's parameter callbacks (on-set, pre-set, post-set), as rclpy's."""

from __future__ import annotations

from conftest import STANDALONE_ONLY
import pytest

pytest.importorskip('cyclonedds', reason=STANDALONE_ONLY)

from tf_demo.transport import dds_backend
from tf_demo.transport.parameters import Parameter


@pytest.mark.dds
def test_parameter_callbacks_validate_and_observe_changes(dds_world):
    """On-set callbacks can reject a value; pre-set may add parameters; post-set sees results."""
    from tf_demo.transport.parameters import SetParametersResult

    node = dds_backend.DdsNode('params')
    node.declare_parameter('rate', 10.0)
    node.declare_parameter('unit', 'Hz')
    seen: list[list[str]] = []
    node.add_on_set_parameters_callback(
        lambda params: SetParametersResult(
            successful=all(p.name != 'rate' or p.value > 0 for p in params), reason='rate <= 0'
        )
    )
    node.add_pre_set_parameters_callback(
        lambda params: (
            [*params, Parameter('unit', value='kHz')]
            if any(p.name == 'rate' for p in params)
            else params
        )
    )
    node.add_post_set_parameters_callback(lambda params: seen.append([p.name for p in params]))
    (rejected,) = node.set_parameters([Parameter('rate', value=-1.0)])
    assert not rejected.successful
    assert rejected.reason == 'rate <= 0'
    assert node.get_parameter('rate').value == 10.0
    assert all(result.successful for result in node.set_parameters([Parameter('rate', value=2.0)]))
    assert node.get_parameter('rate').value == 2.0
    assert node.get_parameter('unit').value == 'kHz'
    assert seen == [['rate', 'unit']]
