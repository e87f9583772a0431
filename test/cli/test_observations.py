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

"""Tests of the tools' observations: a snapshot read back as observations."""

from doctor_cases import kinds
from tf_demo.cli._doctor import diagnose
from tf_demo.cli._observations import observations_from_snapshot
from tf_demo.cli._snapshot import parse_snapshot


def test_snapshot_observations():
    """A snapshot is diagnosed structurally (no timing checks)."""
    snapshot = parse_snapshot(
        'tf_demo_transforms: 1\ntransform_count: 2\ntransforms:\n'
        '  - {parent: map, child: odom, translation: [0, 0, 0], rotation: [0, 0, 0, 1]}\n'
        '  - {parent: base_link, child: laser, translation: [0, 0, 0], rotation: [0, 0, 0, 1],'
        ' static: false, stamp: {sec: 1, nanosec: 0}}\n'
    )
    findings = diagnose(observations_from_snapshot(snapshot), check_timing=False)
    assert kinds(findings) == ['disconnected']
