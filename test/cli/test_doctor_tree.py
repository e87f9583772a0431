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

"""Tests of tf_doctor's frame-graph checks: separate trees, loops, REP 105 order, slashes."""

from doctor_cases import kinds
from doctor_cases import static
from tf_demo.cli._doctor import diagnose
from tf_demo.cli._doctor_report import exit_code


def test_disconnected_names_islands_and_missing_odom_link():
    """Two trees: each island is named and odom→base_link is suggested."""
    observations = [static('map', 'odom'), static('base_link', 'laser')]
    findings = diagnose(observations, frames=['map', 'laser'])
    assert kinds(findings) == ['disconnected']
    finding = findings[0]
    assert 'tree 1 (root base_link): base_link, laser' in finding.message
    assert 'tree 2 (root map): map, odom' in finding.message
    assert "'map' in tree 2, 'laser' in tree 1" in finding.message
    assert 'odom→base_link' in finding.fix
    assert '--frame-id odom --child-frame-id base_link' in finding.fix


def test_disconnected_without_rep105_names_roots():
    """Islands outside REP 105 get a generic fix naming the roots to connect."""
    findings = diagnose([static('a', 'b'), static('a', 'c'), static('x', 'y')])
    assert kinds(findings) == ['disconnected']
    assert 'root (x)' in findings[0].fix


def test_loop():
    """A cycle of parent links is an error naming the loop."""
    findings = diagnose([static('a', 'b'), static('b', 'c'), static('c', 'a')])
    finding = next(f for f in findings if f.kind == 'loop')
    assert set(finding.frames) == {'a', 'b', 'c'}
    assert '→' in finding.message


def test_rep105_inverted_and_bypassed():
    """odom below base_link is inverted; map→base_link beside odom is a warning."""
    inverted = [static('map', 'base_link'), static('base_link', 'odom')]
    findings = diagnose(inverted)
    assert any(f.kind == 'rep105_order' and f.frames == ('odom', 'base_link') for f in findings)
    bypass = [static('map', 'odom'), static('map', 'base_link')]
    finding = next(f for f in diagnose(bypass) if f.kind == 'rep105_order')
    assert finding.severity == 'warning'
    assert exit_code([finding]) == 1


def test_leading_slash_frames():
    """Frames published with a leading '/' are an error with the fixed name."""
    findings = diagnose([static('map', '/odom')])
    finding = next(f for f in findings if f.kind == 'leading_slash')
    assert finding.frames == ('/odom',)
    assert "'odom' instead of '/odom'" in finding.fix
