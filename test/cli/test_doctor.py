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

"""Tests of tf_doctor's diagnosis: parents, publishers, QoS, lookups, and a healthy tree."""

from doctor_cases import healthy
from doctor_cases import kinds
from doctor_cases import later
from doctor_cases import S
from doctor_cases import static
from doctor_cases import stream
from tf_demo.cli._doctor import diagnose
from tf_demo.cli._doctor_report import exit_code
from tf_demo.cli._doctor_report import format_report
from tf_demo.cli._doctor_report import summarize


def test_healthy_tree_has_no_findings():
    """A REP-105 tree with steady data is healthy and exits 0."""
    findings = diagnose(healthy(), listen_ns=2 * S, frames=['map', 'laser'])
    assert findings == []
    assert exit_code(findings) == 0
    report = format_report(findings, summarize(healthy()), 'listened 2.0 s')
    assert report.endswith('Healthy: no problems found.\n')
    assert '5 frames, 1 tree.' in report


def test_no_data():
    """Nothing received is an error that names both topics."""
    findings = diagnose([], listen_ns=3 * S)
    assert kinds(findings) == ['no_data']
    assert '/tf or /tf_static in 3.000 s' in findings[0].message
    assert exit_code(findings) == 1


def test_two_parents():
    """A child published under two parents is reported with both parents and topics."""
    observations = [*healthy(), static('map', 'laser')]
    findings = diagnose(observations)
    finding = next(f for f in findings if f.kind == 'two_parents')
    assert finding.frames == ('laser', 'base_link', 'map')
    assert "'base_link' (1 message on /tf_static)" in finding.message


def test_static_and_dynamic():
    """A frame on both /tf and /tf_static is an error."""
    observations = [*healthy(), static('odom', 'base_link')]
    assert 'static_and_dynamic' in kinds(diagnose(observations))


def test_conflicting_static_values():
    """Two different static transforms for one child are a fight."""
    observations = [*healthy(), static('base_link', 'laser', (1.0, 0.0, 0.0))]
    finding = next(f for f in diagnose(observations) if f.kind == 'publishers_fighting')
    assert '2 different static transforms' in finding.message


def test_dynamic_fight_from_flipping_values_and_publishers():
    """Values jumping back and forth, or two publisher ids, reveal two publishers on /tf."""
    flipping = stream('odom', 'base_link', values=[(0.0, 0.0, 0.0), (5.0, 0.0, 0.0)])
    findings = diagnose([static('map', 'odom'), *flipping])
    finding = next(f for f in findings if f.kind == 'publishers_fighting')
    assert 'jumped back and forth' in finding.message
    two = stream('odom', 'base_link', pub='p1')[::2] + stream('odom', 'base_link', pub='p2')[1::2]
    finding = next(f for f in diagnose(two) if f.kind == 'publishers_fighting')
    assert '2 different publishers' in finding.message


def test_publisher_restart_is_not_a_fight():
    """One publisher replaced by another (a restart) is not reported as fighting."""
    first = stream('odom', 'base_link', pub='p1')
    second = later(stream('odom', 'base_link', pub='p2'), 3)
    assert diagnose([static('map', 'odom'), *first, *second]) == []


def test_qos_mismatch_is_reported_even_without_data():
    """Publishers that never matched the listener are named with tf2's QoS as the fix."""
    findings = diagnose([], unmatched_publishers={'/tf_static': 2})
    assert kinds(findings) == ['no_data', 'qos_mismatch']
    finding = next(f for f in findings if f.kind == 'qos_mismatch')
    assert finding.message.startswith('2 publishers on /tf_static do not match')
    assert 'TRANSIENT_LOCAL' in finding.fix


def test_lookup_without_common_time_fails():
    """Two dynamic links whose data never overlap give tf2's extrapolation error for --frames."""
    early = stream('map', 'odom', seconds=1.0)
    late = later(stream('odom', 'base_link', seconds=1.0), 20)
    findings = diagnose(early + late, frames=['map', 'base_link'])
    finding = next(f for f in findings if f.kind == 'lookup_fails')
    assert 'extrapolation into the past' in finding.message
    assert diagnose(healthy(), frames=['map', 'laser', 'camera']) == []
