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

"""view_frames as a real process: the upstream DOT and PDF, from the network or a snapshot."""

from __future__ import annotations

import re

import pytest
from tool_runs import run
from tool_runs import static

pytestmark = [pytest.mark.dds]


def test_view_frames_writes_upstream_dot_and_pdf(spawn, tf_peers, tmp_path):
    """view_frames -o writes upstream's DOT for a live static tree and renders the PDF."""
    tf_peers(static('map', 'odom'), static('odom', 'base_link'))
    code, _, err = run(spawn, 'view_frames', '-t', '2', '-o', 'tree')
    assert code == 0, err
    assert 'Listening to tf data for 2.0 seconds...' in err
    dot = (tmp_path / 'tree.gv').read_text()
    label = (
        '[label=" Broadcaster: default_authority\\nAverage rate: 10000.0\\nBuffer length: '
        '0.0\\nMost recent transform: 0.0\\nOldest transform: 0.0\\n"];\n'
    )
    assert re.fullmatch(
        re.escape(
            'digraph G {\n"map" -> "odom"'
            + label
            + '"odom" -> "base_link"'
            + label
            + 'edge [style=invis];\n subgraph cluster_legend { style=bold; color=black; '
            'label ="view_frames Result";\n"Recorded at time: '
        )
        + r'\d+\.\d+'
        + re.escape('"[ shape=plaintext ] ;\n}->"map";\n}'),
        dot,
    )
    assert (tmp_path / 'tree.pdf').read_bytes().startswith(b'%PDF')


def test_view_frames_snapshot_with_two_trees(spawn, tmp_path):
    """--snapshot draws a saved file with two trees without listening."""
    snapshot = tmp_path / 'two.yaml'
    snapshot.write_text(
        'tf_demo_transforms: 1\ntransform_count: 2\ntransforms:\n'
        '  - {parent: map, child: odom, translation: [0, 0, 0], rotation: [0, 0, 0, 1]}\n'
        '  - {parent: base_link, child: laser, translation: [0, 0, 0], rotation: [0, 0, 0, 1]}\n'
    )
    code, _, err = run(spawn, 'view_frames', '--snapshot', str(snapshot), '-o', 'two')
    assert code == 0, err
    assert (tmp_path / 'two.gv').read_text().endswith('}->{"map" "base_link"};\n}')
    assert (tmp_path / 'two.pdf').read_bytes().startswith(b'%PDF')


def test_view_frames_without_data(spawn, tmp_path):
    """With nothing published view_frames writes upstream's placeholder graph, and a PDF."""
    code, _, err = run(spawn, 'view_frames', '-t', '0.5', '-o', 'empty')
    assert code == 0, err
    assert (tmp_path / 'empty.gv').read_text() == 'digraph G { "No tf data received" }'
    assert (tmp_path / 'empty.pdf').read_bytes().startswith(b'%PDF')
