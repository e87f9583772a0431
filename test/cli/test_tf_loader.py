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

"""tf_loader as a real process: a bad or missing snapshot file publishes nothing."""

from __future__ import annotations

import pytest
from tool_runs import run

pytestmark = [pytest.mark.dds]


def test_loader_refuses_bad_file_and_publishes_nothing(spawn, tmp_path):
    """A hostile file is refused with its line, exit 1, before anything is published."""
    bad = tmp_path / 'bad.yaml'
    bad.write_text(
        'tf_demo_transforms: 1\ntransform_count: 1\ntransforms:\n'
        '  - {parent: a, child: b, translation: [0, .nan, 0], rotation: [0, 0, 0, 1]}\n'
    )
    code, out, err = run(spawn, 'tf_loader', str(bad))
    assert code == 1
    assert out == ''
    assert err == (
        f'tf_loader: error: {bad}:4: transforms[0].translation[1] must be finite, got nan\n'
    )
    code, _, err = run(spawn, 'tf_loader', str(tmp_path / 'missing.yaml'))
    assert code == 1
    assert 'missing.yaml: no such file' in err
