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
    name for name in ('tf_demo', 'test', 'bench', 'launch', 'doc') if (REPO_ROOT / name).is_dir()
)

# design.md §2: dependencies point inward only.
ALLOWED_INTERNAL_IMPORTS = {
    'core': {'core'},
    'urdf': {'core', 'urdf'},
    'msgs': {'core', 'msgs'},
    'transport': {'core', 'msgs', 'transport'},
    'ros': {'core', 'msgs', 'transport', 'ros'},
    'testing': {'core', 'urdf', 'msgs', 'testing'},
    'bag': {'core', 'msgs', 'bag'},
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
    violations: list[str] = []
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


def _module_name(path: Path) -> str:
    parts = path.relative_to(REPO_ROOT).with_suffix('').parts
    return '.'.join(parts[:-1] if parts[-1] == '__init__' else parts)


def _runs_when_type_checking_only(test: ast.expr) -> bool:
    return isinstance(test, ast.Name) and test.id == 'TYPE_CHECKING'


def _imported_modules(path: Path, known: set[str]) -> set[str]:
    """The tf_demo modules ``path`` imports anywhere (functions too), but for type checking."""
    found: set[str] = set()
    pending: list[ast.AST] = [ast.parse(path.read_text(), str(path))]
    while pending:
        node = pending.pop()
        if isinstance(node, ast.If) and _runs_when_type_checking_only(node.test):
            pending.extend(node.orelse)
            continue
        pending.extend(ast.iter_child_nodes(node))
        if isinstance(node, ast.Import):
            found.update(alias.name for alias in node.names if alias.name in known)
        elif isinstance(node, ast.ImportFrom) and node.module and node.level == 0:
            for alias in node.names:
                submodule = f'{node.module}.{alias.name}'
                found.add(submodule if submodule in known else node.module)
    return found & known


def _import_graph() -> dict[str, set[str]]:
    paths = {_module_name(path): path for path in (REPO_ROOT / 'tf_demo').rglob('*.py')}
    known = set(paths)
    return {name: _imported_modules(path, known) - {name} for name, path in paths.items()}


def _cycles(graph: dict[str, set[str]]) -> list[list[str]]:
    """The strongly connected components with more than one module (Tarjan, iterative)."""
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    stack: list[str] = []
    on_stack: set[str] = set()
    components: list[list[str]] = []
    for root in sorted(graph):
        if root in index:
            continue
        work = [(root, iter(sorted(graph[root])))]
        index[root] = low[root] = len(index)
        stack.append(root)
        on_stack.add(root)
        while work:
            node, children = work[-1]
            child = next(children, None)
            if child is not None:
                if child not in index:
                    index[child] = low[child] = len(index)
                    stack.append(child)
                    on_stack.add(child)
                    work.append((child, iter(sorted(graph[child]))))
                elif child in on_stack:
                    low[node] = min(low[node], index[child])
                continue
            work.pop()
            if work:
                low[work[-1][0]] = min(low[work[-1][0]], low[node])
            if low[node] == index[node]:
                component = []
                while True:
                    member = stack.pop()
                    on_stack.discard(member)
                    component.append(member)
                    if member == node:
                        break
                if len(component) > 1:
                    components.append(sorted(component))
    return components


@pytest.mark.linter
def test_the_cycle_finder_finds_a_cycle() -> None:
    """The import-cycle check below can fail: a two-module and a three-module circle are found."""
    graph = {'a': {'b'}, 'b': {'a'}, 'c': {'d'}, 'd': {'e'}, 'e': {'c', 'a'}, 'f': set()}
    assert sorted(_cycles(graph)) == [['a', 'b'], ['c', 'd', 'e']]


@pytest.mark.linter
def test_no_import_cycles() -> None:
    """No tf_demo module imports itself round a circle, not even from inside a function."""
    assert _cycles(_import_graph()) == []


#: Files written by a generator (exempt from the size limit).
GENERATED_MARK = 'generated by'
SIZE_LIMITS = ((('tf_demo', 'transport'), 500), (('tf_demo',), 800))


@pytest.mark.linter
def test_no_module_is_too_long() -> None:
    """No module over 800 lines in tf_demo (500 in transport), generated files aside."""
    too_long = []
    for path in sorted((REPO_ROOT / 'tf_demo').rglob('*.py')):
        text = path.read_text()
        if GENERATED_MARK in text[:2000]:
            continue
        parts = path.relative_to(REPO_ROOT).parts
        limit = next(limit for prefix, limit in SIZE_LIMITS if parts[: len(prefix)] == prefix)
        lines = text.count('\n')
        if lines > limit:
            too_long.append(f'{"/".join(parts)}: {lines} lines (limit {limit})')
    assert too_long == []


@pytest.mark.linter
def test_the_world_is_not_chosen_by_rewriting_namespaces() -> None:
    """No ``globals()`` rewriting and no module ``__getattr__`` in the package."""
    found: list[str] = []
    for path in sorted((REPO_ROOT / 'tf_demo').rglob('*.py')):
        tree = ast.parse(path.read_text(), str(path))
        relative = path.relative_to(REPO_ROOT)
        found.extend(
            f'{relative}: module __getattr__'
            for node in tree.body
            if isinstance(node, ast.FunctionDef) and node.name == '__getattr__'
        )
        found.extend(
            f'{relative}:{node.lineno}: globals()'
            for node in ast.walk(tree)
            if isinstance(node, ast.Call)
            and isinstance(node.func, ast.Name)
            and node.func.id == 'globals'
        )
    assert found == []


@pytest.mark.linter
@pytest.mark.standalone  # the type check needs the standalone world's packages (cyclonedds)
def test_mypy_is_clean_on_tests_and_benchmarks() -> None:
    """Mypy passes on test/ and bench/ (as strict as the package; test functions may be bare)."""
    result = _run('mypy', '--no-incremental', 'test', 'bench')
    assert result.returncode == 0, result.stdout + result.stderr


_GENERATED_MESSAGES = (
    'builtin_interfaces', 'geometry_msgs', 'nav_msgs', 'rcl_interfaces', 'rmw_dds_common',
    'rosgraph_msgs', 'sensor_msgs', 'service_msgs', 'std_msgs', 'tf2_msgs',
)  # fmt: skip
_WORLD_FACADES = ('callback_groups', 'clock', 'executors', 'logging', 'node', 'parameters')
#: The modules that have no test file named after them, and where they are tested instead.
TESTED_ELSEWHERE = {
    'tf_demo/__main__.py': '`python -m tf_demo`: test/test_build_info.py runs it',
    **{
        f'tf_demo/msgs/{name}.py': 'generated from the schema table: test/msgs/test_typegen.py '
        "checks it is the generator's output, test/msgs/test_message.py its classes"
        for name in (*_GENERATED_MESSAGES, '_types')
    },
    **{
        f'tf_demo/transport/{name}.py': 'a world facade (star imports only): the rclpy '
        "backend's test_each_facade_* check which world's names it holds; the behaviour is "
        f'tested in both worlds by test/transport/dds/test_{name}*.py'
        for name in _WORLD_FACADES
    },
    **{
        f'tf_demo/transport/{name}.py': "rclpy's module name for another facade's names: "
        'test/test_course_code.py checks that each answers its README row'
        for name in ('duration', 'parameter', 'time')
    },
    'tf_demo/transport/dds_backend.py': "re-exports transport/dds/'s public names as the "
    'standalone backend: test/transport/test_backend.py checks the world takes it, and the '
    'tests under test/transport/dds/ reach the runtime through it',
}


def _test_stems(module: Path) -> list[str]:
    """The stems of the test files named after ``module``, in the folder mirroring its own."""
    relative = module.relative_to(REPO_ROOT / 'tf_demo')
    folder = REPO_ROOT / 'test' / relative.parent
    name = module.stem.lstrip('_')
    if (folder / name).is_dir():  # a folder of tests named after the module
        return [path.stem for path in (folder / name).glob('test_*.py')]
    return [
        path.stem
        for path in folder.glob(f'test_{name}*.py')
        if path.stem == f'test_{name}' or path.stem.startswith(f'test_{name}_')
    ]


@pytest.mark.linter
def test_every_module_has_a_test_named_after_it() -> None:
    """Tests mirror the package: tf_demo/a/b/m.py has test/a/b/test_m.py (or test_m_*.py, m/).

    ``__init__`` modules aside; the few modules tested elsewhere say where (TESTED_ELSEWHERE).
    """
    missing = []
    for path in sorted((REPO_ROOT / 'tf_demo').rglob('*.py')):
        relative = path.relative_to(REPO_ROOT).as_posix()
        if path.stem == '__init__' or relative in TESTED_ELSEWHERE:
            continue
        if not _test_stems(path):
            missing.append(relative)
    assert missing == []
    stale = [relative for relative in TESTED_ELSEWHERE if not (REPO_ROOT / relative).is_file()]
    assert stale == [], 'TESTED_ELSEWHERE names modules that are gone'
    tested_anyway = [
        relative for relative in TESTED_ELSEWHERE if _test_stems(REPO_ROOT / relative)
    ]
    assert tested_anyway == [], 'these now have a test named after them: drop their exemption'
