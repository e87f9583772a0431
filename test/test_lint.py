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

"""Static checks run by `colcon test`: ruff, mypy, licence headers and the layer rule."""

from __future__ import annotations

import ast
from pathlib import Path
import subprocess
import sys

import pytest

REPO_ROOT = Path(__file__).resolve().parent.parent
HEADER = (REPO_ROOT / 'doc' / 'license_header.txt').read_text()
PYTHON_DIRS = tuple(
    name for name in ('tf_demo', 'test', 'bench', 'launch') if (REPO_ROOT / name).is_dir()
)

# design.md §2: dependencies point inward only.
ALLOWED_INTERNAL_IMPORTS = {
    'core': {'core'},
    'urdf': {'core', 'urdf'},
    'msgs': {'core', 'msgs'},
    'transport': {'core', 'msgs', 'transport'},
    'ros': {'core', 'msgs', 'transport', 'ros'},
    'testing': {'core', 'urdf', 'msgs', 'testing'},
}


def _python_files() -> list[Path]:
    files = [REPO_ROOT / 'setup.py']
    for directory in PYTHON_DIRS:
        files.extend(sorted((REPO_ROOT / directory).rglob('*.py')))
    return [path for path in files if '_build' not in path.parts]


def _run(*command: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run(
        [sys.executable, '-m', *command],
        cwd=REPO_ROOT,
        capture_output=True,
        text=True,
        check=False,
    )


@pytest.mark.linter
def test_ruff_check_is_clean() -> None:
    """Ruff finds no lint error in the package, its tests and benchmarks."""
    result = _run('ruff', 'check', '--no-cache', *PYTHON_DIRS, 'setup.py')
    assert result.returncode == 0, result.stdout + result.stderr


@pytest.mark.linter
def test_ruff_format_is_clean() -> None:
    """Every Python file is formatted as `ruff format` would write it."""
    result = _run('ruff', 'format', '--check', '--no-cache', *PYTHON_DIRS, 'setup.py')
    assert result.returncode == 0, result.stdout + result.stderr


@pytest.mark.linter
@pytest.mark.standalone  # the type check needs the standalone world's packages (cyclonedds)
def test_mypy_is_clean() -> None:
    """Mypy (strict for core and urdf, see pyproject.toml) reports no error in the package."""
    result = _run('mypy', '--no-incremental', 'tf_demo')
    assert result.returncode == 0, result.stdout + result.stderr


@pytest.mark.linter
def test_every_source_file_has_the_licence_header() -> None:
    """Each Python file under tf_demo, test, bench and launch starts with the Apache-2.0 header."""
    missing = [
        str(path.relative_to(REPO_ROOT))
        for path in _python_files()
        if path.name != 'setup.py' and not path.read_text().startswith(HEADER)
    ]
    assert missing == []


def _internal_imports(path: Path) -> set[str]:
    layers: set[str] = set()
    for node in ast.walk(ast.parse(path.read_text(), str(path))):
        names: list[str] = []
        if isinstance(node, ast.Import):
            names = [alias.name for alias in node.names]
        elif isinstance(node, ast.ImportFrom) and node.module and node.level == 0:
            names = [node.module]
        elif isinstance(node, ast.ImportFrom) and node.level > 0:
            layer = path.relative_to(REPO_ROOT / 'tf_demo').parts[0]
            base = [layer] if node.level == 1 else []
            names = ['.'.join(['tf_demo', *base, *([node.module] if node.module else [])])]
        for name in names:
            parts = name.split('.')
            if parts[0] == 'tf_demo' and len(parts) > 1:
                layers.add(parts[1])
    return layers


@pytest.mark.linter
def test_layers_import_only_inward() -> None:
    """core <- urdf <- msgs <- transport <- ros <- nodes/cli: no layer imports an outer one."""
    violations = []
    for path in sorted((REPO_ROOT / 'tf_demo').rglob('*.py')):
        relative = path.relative_to(REPO_ROOT / 'tf_demo')
        if len(relative.parts) < 2:
            continue
        layer = relative.parts[0]
        allowed = ALLOWED_INTERNAL_IMPORTS.get(layer)
        if allowed is None:
            continue
        violations.extend(
            f'{relative} imports tf_demo.{outer}'
            for outer in sorted(_internal_imports(path) - allowed)
        )
    assert violations == []
