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

"""
The distributions: ``python -m build`` makes an sdist and a platform wheel from a clean copy.

The wheel holds every compiled module beside its source, installs into a fresh virtual
environment with nothing built (``--only-binary :all:``), and runs compiled there: ``python -m
tf_demo``, a lookup, and the demo's ``static_tf_pub`` heard by ``tf_echo`` over DDS.
"""

from __future__ import annotations

from importlib.machinery import EXTENSION_SUFFIXES
import os
from pathlib import Path
import shutil
import subprocess
import sys
import tarfile
import zipfile

from conftest import REPO_ROOT
from conftest import run_captured
import pytest
from tf_demo.build_info import COMPILED_MODULES

pytestmark = [pytest.mark.slow, pytest.mark.standalone]

#: What a clean checkout holds (the copy the distributions are built from).
_CHECKOUT_PARTS = (
    'setup.py',
    'setup.cfg',
    'pyproject.toml',
    'package.xml',
    'README.md',
    'tf_demo',
    'resource',
    'launch',
    'config',
    'urdf',
)


def _clean_copy(destination: Path) -> Path:
    """Copy the package's tracked files (no build outputs, no compiled modules) to a folder."""
    listed = run_captured(['git', 'ls-files', *_CHECKOUT_PARTS], cwd=REPO_ROOT)
    if listed.returncode != 0:
        pytest.skip(f'not a git checkout ({listed.stderr.strip()}): no clean copy to build from')
    for name in listed.stdout.split():
        target = destination / name
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copy2(REPO_ROOT / name, target)
    return destination


@pytest.fixture(scope='module')
def distributions(tmp_path_factory: pytest.TempPathFactory) -> tuple[Path, Path]:
    """Build the sdist, then the wheel from it (``python -m build``), once for the module."""
    pytest.importorskip('build', reason='the wheel test needs PyPI build (the [test] extra)')
    source = _clean_copy(tmp_path_factory.mktemp('checkout'))
    out = tmp_path_factory.mktemp('dist')
    built = run_captured(
        [sys.executable, '-m', 'build', '--no-isolation', '--outdir', str(out), str(source)],
        timeout=900,
    )
    assert built.returncode == 0, built.stdout[-3000:] + built.stderr[-3000:]
    assert 'tf_demo: compiled' in built.stdout + built.stderr
    (sdist,) = out.glob('tf_demo-*.tar.gz')
    (wheel,) = out.glob('tf_demo-*.whl')
    return sdist, wheel


def _module_files(names: list[str], module: str) -> set[str]:
    base = module.replace('.', '/')
    return {name for name in names if name.startswith(base + '.')}


def test_the_wheel_holds_each_compiled_module_beside_its_source(
    distributions: tuple[Path, Path],
) -> None:
    _, wheel = distributions
    tag = wheel.name.removesuffix('.whl').split('-')[-1]
    assert tag != 'any', f'{wheel.name} is not a platform wheel'
    with zipfile.ZipFile(wheel) as archive:
        names = archive.namelist()
    suffix = EXTENSION_SUFFIXES[0]
    for module in COMPILED_MODULES:
        files = _module_files(names, module)
        assert files == {module.replace('.', '/') + suffix, module.replace('.', '/') + '.py'}
    assert f'tf_demo/compiled__mypyc{suffix}' in names  # mypyc's shared runtime
    assert 'tf_demo/py.typed' in names


def test_the_sdist_has_the_sources_and_no_compiled_file(distributions: tuple[Path, Path]) -> None:
    sdist, _ = distributions
    with tarfile.open(sdist) as archive:
        names = archive.getnames()
    root = sdist.name.removesuffix('.tar.gz')
    for module in COMPILED_MODULES:
        assert f'{root}/{module.replace(".", "/")}.py' in names
    assert f'{root}/tf_demo/build_info.py' in names
    assert f'{root}/pyproject.toml' in names
    assert not [name for name in names if name.endswith(tuple(EXTENSION_SUFFIXES))]


@pytest.fixture(scope='module')
def installed(distributions: tuple[Path, Path], tmp_path_factory: pytest.TempPathFactory) -> Path:
    """A fresh virtual environment with the wheel and its dependencies, none of them built."""
    _, wheel = distributions
    venv = tmp_path_factory.mktemp('venv')
    created = run_captured([sys.executable, '-m', 'venv', str(venv)], timeout=300)
    assert created.returncode == 0, created.stderr
    pip = run_captured(
        [
            str(venv / 'bin' / 'python'),
            '-m',
            'pip',
            'install',
            '-q',
            '--disable-pip-version-check',
            '--only-binary',
            ':all:',
            f'{wheel}[dds]',
        ],
        timeout=900,
    )
    assert pip.returncode == 0, pip.stdout[-3000:] + pip.stderr[-3000:]
    return venv


def _venv_env(venv: Path, world_env: dict[str, str]) -> dict[str, str]:
    """``world_env`` for the fresh environment: its bin first, nothing of this checkout."""
    env = dict(world_env)
    env.pop('PYTHONPATH', None)
    env.pop('TF_DEMO_INTERPRETED', None)
    env['PATH'] = os.pathsep.join((str(venv / 'bin'), env.get('PATH', '')))
    env['VIRTUAL_ENV'] = str(venv)
    env['TF_DEMO_BACKEND'] = 'dds'
    return env


def test_the_installed_wheel_runs_compiled(
    installed: Path, world_env: dict[str, str], tmp_path: Path
) -> None:
    env = _venv_env(installed, world_env)
    python = str(installed / 'bin' / 'python')
    version = run_captured([python, '-m', 'tf_demo'], env, cwd=tmp_path)
    assert version.returncode == 0, version.stderr
    count = len(COMPILED_MODULES)
    assert f'compiled (mypyc: {count} of {count} hot modules)' in version.stdout
    lookup = run_captured(
        [
            python,
            '-c',
            'import tf_demo.core as c; from tf_demo.core import buffer_core as m; '
            'b = c.BufferCore(); '
            "b.set_transform('map', 'odom', 10, (1.0, 2.0, 3.0), (0.0, 0.0, 0.0, 1.0)); "
            "b.set_transform('map', 'odom', 20, (3.0, 2.0, 1.0), (0.0, 0.0, 0.0, 1.0)); "
            "print(m.__file__.rsplit('.', 1)[1], b.lookup_transform('map', 'odom', 15))",
        ],
        env,
        cwd=tmp_path,
    )
    assert lookup.returncode == 0, lookup.stderr
    assert lookup.stdout.split(' ', 1) == [
        'so',
        'TransformResult(translation=(2.0, 2.0, 2.0), rotation=(0.0, 0.0, 0.0, 1.0), '
        'stamp_ns=15)\n',
    ]


@pytest.mark.dds
def test_the_installed_wheels_nodes_talk_over_dds(
    installed: Path, world_env: dict[str, str], tmp_path: Path
) -> None:
    """The demo's static_tf_pub and tf_echo, as the wheel installed them (console scripts)."""
    env = _venv_env(installed, world_env)
    publisher = subprocess.Popen(
        [str(installed / 'bin' / 'static_tf_pub')],
        env=env,
        cwd=tmp_path,
        stdout=subprocess.DEVNULL,
        stderr=subprocess.PIPE,
        text=True,
    )
    try:
        echo = run_captured(
            [str(installed / 'bin' / 'tf_echo'), 'base_link', 'camera_link', '--limit', '1'],
            env,
            cwd=tmp_path,
            timeout=60,
        )
    finally:
        publisher.terminate()
        publisher.wait(timeout=10)
    assert echo.returncode == 0, echo.stdout + echo.stderr
    assert '- Translation: [' in echo.stdout
