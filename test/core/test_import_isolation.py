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

"""tf_demo.core imports and works with rclpy and cyclonedds made unimportable."""

from __future__ import annotations

import json
import sys

from conftest import REPO_ROOT
from conftest import run_captured

_CHILD = r"""
import importlib.abc
import json
import sys

BLOCKED = ('rclpy', 'cyclonedds', 'geometry_msgs', 'tf2_msgs', 'tf2_py', 'yaml', 'lxml')


class Blocker(importlib.abc.MetaPathFinder):
    def find_spec(self, name, path=None, target=None):
        if name.split('.')[0] in BLOCKED:
            raise ImportError(f'{name} is blocked for this test')
        return None


sys.meta_path.insert(0, Blocker())
import tf_demo.core as core

buffer = core.BufferCore()
buffer.set_transform('map', 'odom', 0, (1.0, 0.0, 0.0), (0.0, 0.0, 0.0, 1.0), 'x', True)
buffer.set_transform('odom', 'base', 10**9, (0.0, 2.0, 0.0), (0.0, 0.0, 0.0, 1.0), 'x')
result = buffer.lookup_transform('map', 'base', 0)
loaded = sorted(
    name for name in sys.modules if name.split('.')[0] in BLOCKED or name.startswith('tf_demo.')
)
print(json.dumps({'translation': result.translation, 'modules': loaded}))
"""


def test_core_imports_without_ros_or_dds():
    """With rclpy/cyclonedds/yaml blocked, tf_demo.core imports, works and loads only itself."""
    completed = run_captured([sys.executable, '-c', _CHILD], cwd=REPO_ROOT)
    assert completed.returncode == 0, completed.stderr
    report = json.loads(completed.stdout)
    assert report['translation'] == [1.0, 2.0, 0.0]
    # tf_demo itself says which build runs (build_info) and holds mypyc's shared runtime.
    package = {'tf_demo', 'tf_demo.build_info', 'tf_demo.compiled__mypyc'}
    assert all(name.startswith('tf_demo.core') or name in package for name in report['modules'])
