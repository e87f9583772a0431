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

"""Tests of tf_demo/core/lazy_import.py: numpy stays unimported until an array is needed."""

from __future__ import annotations

import json
import subprocess
import sys

from conftest import REPO_ROOT
import pytest
from tf_demo.core.lazy_import import lazy_module

_PROBE = """
import json, sys
import {module}
before = type(sys.modules.get('numpy')).__name__
from tf_demo.core import BufferCore
core = BufferCore()
core.set_transform('a', 'b', 10**9, (1.0, 0.0, 0.0), (0.0, 0.0, 0.0, 1.0))
translations, _ = core.lookup_transforms('a', 'b', [10**9, 10**9])
print(json.dumps([before, type(sys.modules['numpy']).__name__, translations[:, 0].tolist()]))
"""


@pytest.mark.parametrize(
    'module', ['tf_demo.nodes.static_tf_pub', 'tf_demo.cli.tf_echo', 'tf_demo.ros']
)
def test_a_node_starts_without_numpy_and_gets_it_on_first_use(module: str) -> None:
    """Importing a node leaves numpy unimported; a batch lookup then imports and uses it."""
    result = subprocess.run(
        [sys.executable, '-c', _PROBE.format(module=module)],
        capture_output=True,
        text=True,
        cwd=REPO_ROOT,
        timeout=120,
        check=False,
    )
    assert result.returncode == 0, result.stderr
    before, after, xs = json.loads(result.stdout.splitlines()[-1])
    if before == 'module':  # pragma: no cover - the rclpy world's messages import numpy
        pytest.skip(f'numpy was imported by something else on import of {module}')
    assert before == '_LazyModule'
    assert after == 'module'
    assert xs == [1.0, 1.0]


def test_an_imported_module_is_returned_as_it_is() -> None:
    assert lazy_module('json') is json


def test_a_missing_module_is_named_at_once() -> None:
    with pytest.raises(ModuleNotFoundError, match="'no_such_module_tf_demo'"):
        lazy_module('no_such_module_tf_demo')
