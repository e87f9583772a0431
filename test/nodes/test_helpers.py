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

"""Node helpers: timer rates and periods a timer cannot hold are one-line errors."""

from __future__ import annotations

import math
import re

from conftest import executable_command
from conftest import run_captured
import pytest
from tf_demo.nodes.helpers import NodeConfigError


@pytest.mark.parametrize(
    ('name', 'value', 'problem'),
    [
        ('rate', 1e-300, 'is too small: the period 1/rate must be at most 9223372036 s'),
        ('rate', 0.0, 'must be a positive finite number of Hz'),
        ('rate', math.inf, 'must be finite'),
        ('period', 1e300, 'must be at most 9223372036 s'),
        ('period', -1.0, 'must be > 0'),
    ],
)
def test_timer_rates_and_periods_a_timer_cannot_hold_are_one_line(
    name: str, value: float, problem: str
) -> None:
    """A rate of 1e-300 Hz (a period beyond int64 ns) is refused before a timer is made."""
    from tf_demo.nodes.helpers import as_period_s
    from tf_demo.nodes.helpers import as_rate_hz

    check = as_rate_hz if name == 'rate' else as_period_s
    with pytest.raises(NodeConfigError, match=re.escape(problem)):
        check(name, value)


@pytest.mark.parametrize('node', ['dynamic_tf_pub', 'tf_listener', 'joint_state_publisher'])
def test_a_node_given_a_timer_it_cannot_run_exits_1_with_one_line(
    node: str, world_env: dict[str, str]
) -> None:
    """``-p rate:=1e-300`` (or ``period:=1e300``): exit 1, one line naming it, no traceback."""
    parameter = 'period:=1e300' if node == 'tf_listener' else 'rate:=1e-300'
    completed = run_captured(executable_command(node, '--ros-args', '-p', parameter), world_env)
    assert completed.returncode == 1, completed.stderr
    assert 'Traceback' not in completed.stderr, completed.stderr
    assert completed.stderr.strip().count('\n') == 0, completed.stderr
    assert parameter.split(':=')[0] in completed.stderr
