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
Tests of tf_demo/build_info.py (and ``python -m tf_demo``): which build runs, and switching it.

The suite runs on the compiled build where the install compiled (both README worlds) and again,
for the core and the codec, with ``TF_DEMO_INTERPRETED=1``; these tests check that what
:mod:`tf_demo.build_info` says is what Python imported.
"""

from __future__ import annotations

import importlib
from importlib.machinery import EXTENSION_SUFFIXES
import os
from pathlib import Path
import shutil
import sys
import time
import traceback

from conftest import PACKAGE_ROOT
from conftest import run_captured
import pytest
from tf_demo import build_info
from tf_demo.core import BufferCore
from tf_demo.core import InvalidArgumentException

COMPILED_HERE = all(
    (PACKAGE_ROOT / Path(*name.split('.'))).with_suffix(EXTENSION_SUFFIXES[0]).exists()
    for name in build_info.COMPILED_MODULES
)
INTERPRETED_ASKED = os.environ.get(build_info.INTERPRETED_ENVIRONMENT_VARIABLE, '') not in (
    '',
    '0',
)
needs_compiled = pytest.mark.skipif(
    not COMPILED_HERE,
    reason='this install is interpreted (no mypyc extensions beside the sources)',
)


def _python(code: str, **variables: str) -> tuple[str, str]:
    env = dict(os.environ, PYTHONPATH=str(PACKAGE_ROOT), **variables)
    if 'TF_DEMO_INTERPRETED' not in variables:
        env.pop(build_info.INTERPRETED_ENVIRONMENT_VARIABLE, None)
    done = run_captured([sys.executable, '-c', code], env, cwd=Path('/'))
    assert done.returncode == 0, done.stderr
    return done.stdout, done.stderr


def test_what_build_info_says_is_what_was_imported() -> None:
    suffixes = tuple(EXTENSION_SUFFIXES)
    imported = {
        name
        for name in build_info.COMPILED_MODULES
        if str(importlib.import_module(name).__file__).endswith(suffixes)
    }
    assert set(build_info.compiled_modules()) == imported
    if INTERPRETED_ASKED or not COMPILED_HERE:
        assert imported == set()
        assert build_info.build_name() == 'interpreted'
    else:
        assert imported == set(build_info.COMPILED_MODULES)
        assert build_info.build_name() == 'compiled'


@needs_compiled
def test_the_variable_runs_the_sources_of_a_compiled_install() -> None:
    code = (
        'import tf_demo.core.buffer_core as m, tf_demo.build_info as b; '
        'print(m.__file__); print(b.describe())'
    )
    compiled, _ = _python(code)
    interpreted, _ = _python(code, TF_DEMO_INTERPRETED='1')
    count = len(build_info.COMPILED_MODULES)
    assert compiled.splitlines()[0].endswith(EXTENSION_SUFFIXES[0])
    assert compiled.splitlines()[1] == f'compiled (mypyc: {count} of {count} hot modules)'
    assert interpreted.splitlines()[0].endswith('buffer_core.py')
    assert interpreted.splitlines()[1] == f'interpreted (mypyc: 0 of {count} hot modules)'


@needs_compiled
def test_a_source_edited_after_the_build_runs_interpreted_with_a_warning(tmp_path: Path) -> None:
    """An editable install whose source changed: the stale extensions are not used."""
    copy = tmp_path / 'tf_demo'
    shutil.copytree(PACKAGE_ROOT / 'tf_demo', copy, ignore=shutil.ignore_patterns('__pycache__'))
    edited = copy / 'core' / 'links.py'
    later = time.time() + 60  # edited after any build
    os.utime(edited, (later, later))
    env = dict(os.environ, PYTHONPATH=str(tmp_path))
    env.pop(build_info.INTERPRETED_ENVIRONMENT_VARIABLE, None)
    done = run_captured(
        [sys.executable, '-c', 'import tf_demo.core.links as m; print(m.__file__)'],
        env,
        cwd=Path('/'),
    )
    assert done.returncode == 0, done.stderr
    assert done.stdout.strip() == str(edited)
    assert 'tf_demo.core.links changed after it was compiled: running the Python' in done.stderr
    assert 'RuntimeWarning' in done.stderr


@needs_compiled
def test_an_extension_left_beside_a_module_that_is_not_compiled_is_not_used(
    tmp_path: Path,
) -> None:
    """A colcon install folder keeps extensions a newer build no longer makes: sources win."""
    copy = tmp_path / 'tf_demo'
    shutil.copytree(PACKAGE_ROOT / 'tf_demo', copy, ignore=shutil.ignore_patterns('__pycache__'))
    suffix = EXTENSION_SUFFIXES[0]
    stray = copy / 'core' / f'files{suffix}'  # tf_demo.core.files is not compiled
    shutil.copy2(copy / 'core' / f'links{suffix}', stray)
    env = dict(os.environ, PYTHONPATH=str(tmp_path))
    env.pop(build_info.INTERPRETED_ENVIRONMENT_VARIABLE, None)
    code = 'import tf_demo.core.files as f, tf_demo.core.links as l; print(f.__file__, l.__file__)'
    done = run_captured([sys.executable, '-c', code], env, cwd=Path('/'))
    assert done.returncode == 0, done.stderr
    files, links = done.stdout.split()
    assert files == str(copy / 'core' / 'files.py')
    # compiled; a module mypyc's group library initialises itself gets a __file__ one tf_demo/
    # too deep (placed from the library's folder), hence only the end
    assert links.endswith(f'/core/links{suffix}')


def test_python_m_tf_demo_says_version_build_and_python() -> None:
    out, _ = _python('import runpy; runpy.run_module("tf_demo", run_name="__main__")')
    assert out.startswith('tf_demo ')
    assert f'CPython {sys.version.split()[0]}' in out
    assert ('compiled (mypyc' in out) == COMPILED_HERE  # the child runs without the variable


def test_a_traceback_through_compiled_code_names_file_and_line() -> None:
    """mypyc keeps file and line in tracebacks (checked on whichever build runs)."""
    with pytest.raises(InvalidArgumentException) as caught:
        BufferCore().lookup_transform('', 'a', 0)
    frames = traceback.extract_tb(caught.value.__traceback__)
    ours = [(Path(f.filename).name, f.name, f.lineno or 0) for f in frames]
    name, function, line = ours[-1]
    assert (name, function) == ('frame_tree.py', '_validate'), ours
    assert line > 0
    assert any(name == 'buffer_core.py' for name, _, _ in ours)
