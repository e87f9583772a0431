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
Which build of tf_demo runs: the hot modules compiled by mypyc, or the same source interpreted.

``setup.py`` compiles :data:`COMPILED_MODULES` with mypyc when mypyc and a C compiler are there;
everything else is always Python.  ``TF_DEMO_INTERPRETED=1`` asks for the interpreted build when
installing, and, in a compiled install's environment, runs the Python sources that sit beside
the extensions (:func:`prefer_sources`; child processes inherit it).  This file is read by
``setup.py`` as well (with no import of the package), so it imports only the standard library.
"""

from __future__ import annotations

import importlib.abc
import importlib.machinery
import importlib.util
import os
import sys
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from collections.abc import Sequence
    from types import ModuleType

__all__ = [
    'COMPILED_MODULES',
    'INTERPRETED_ENVIRONMENT_VARIABLE',
    'build_name',
    'compiled_modules',
    'describe',
    'guard_sources',
    'prefer_sources',
    'stale_modules',
    'version_line',
]

#: The modules mypyc compiles, chosen by measurement (``bench/bench_core.py``,
#: ``bench/bench_codec.py``): the buffer's insert, lookup and walk, its time caches and path
#: plans, and the math they call.  Not the CDR codec: compiled, its TF encoder took 1.7 times as
#: long (it reads 13 attributes of interpreted message objects per transform, which CPython's
#: specialising interpreter caches and compiled code looks up each time) and its TF decoder
#: gained 7 % (its work is ``struct``'s, in C already).
COMPILED_MODULES = (
    'tf_demo.core.math3d',
    'tf_demo.core.time_cache',
    'tf_demo.core.links',
    'tf_demo.core.path_plan',
    'tf_demo.core.frame_tree',
    'tf_demo.core.buffer_core',
    'tf_demo.core.velocity',
)

#: Set to ``1`` when building (``pip install``, ``colcon build``) to install interpreted only.
INTERPRETED_ENVIRONMENT_VARIABLE = 'TF_DEMO_INTERPRETED'


_PACKAGE_DIR = os.path.dirname(os.path.abspath(__file__))


def _files(name: str) -> tuple[str, str | None]:
    """Return the source of module ``name`` and its C extension (None: not there)."""
    base = os.path.join(_PACKAGE_DIR, *name.split('.')[1:])
    for suffix in importlib.machinery.EXTENSION_SUFFIXES:
        if os.path.exists(base + suffix):
            return base + '.py', base + suffix
    return base + '.py', None


def _sources_preferred() -> bool:
    return any(isinstance(f, _SourcesFirst) and f.all_modules for f in sys.meta_path)


def compiled_modules() -> list[str]:
    """Return the modules of :data:`COMPILED_MODULES` that run (or will run) compiled here."""
    suffixes = tuple(importlib.machinery.EXTENSION_SUFFIXES)
    found = []
    for name in COMPILED_MODULES:
        module = sys.modules.get(name)
        if module is not None:
            compiled = str(getattr(module, '__file__', '')).endswith(suffixes)
        else:
            compiled = _files(name)[1] is not None and not _sources_preferred()
        if compiled:
            found.append(name)
    return found


#: A source this much newer than its extension was edited after the build (an install writes
#: both within moments).
_STALE_AFTER_S = 2.0


def stale_modules() -> list[str]:
    """
    Return the compiled modules whose Python source was changed after they were compiled.

    An editable install (``pip install -e .``, ``colcon build --symlink-install``) keeps the
    extensions beside the sources: after an edit, the extension no longer is the source.
    """
    stale = []
    for name in COMPILED_MODULES:
        source, extension = _files(name)
        if extension is None:
            continue
        try:
            if os.stat(source).st_mtime > os.stat(extension).st_mtime + _STALE_AFTER_S:
                stale.append(name)
        except OSError:
            continue
    return stale


def build_name() -> str:
    """Return ``'compiled'``, ``'interpreted'`` or ``'partly compiled'``."""
    return _build_name(len(compiled_modules()))


def _build_name(count: int) -> str:
    if count == len(COMPILED_MODULES):
        return 'compiled'
    return 'partly compiled' if count else 'interpreted'


def version_line() -> str:
    """Return e.g. ``tf_demo 0.1.0, compiled (mypyc: 7 of 7 hot modules), CPython 3.11.7``."""
    from importlib import metadata

    try:
        version = metadata.version('tf_demo')
    except metadata.PackageNotFoundError:
        version = 'unknown version (not installed)'
    python = f'{sys.implementation.name} {sys.version.split()[0]}'
    return f'tf_demo {version}, {describe()}, {python.replace("cpython", "CPython")}'


def describe() -> str:
    """Return one line saying which build runs, e.g. ``compiled (mypyc: 8 of 8 hot modules)``."""
    count = len(compiled_modules())
    return f'{_build_name(count)} (mypyc: {count} of {len(COMPILED_MODULES)} hot modules)'


class _SourcesFirst(importlib.abc.MetaPathFinder):
    """
    Finds a tf_demo module's ``.py`` file before a C extension of the same name.

    For every module but the compiled ones, unless :attr:`all_modules`: an extension beside a
    module that is not compiled is left over from an older install (a colcon install folder
    keeps files a newer build no longer makes) and must not shadow the source.
    """

    def __init__(self) -> None:
        #: The compiled modules from their sources too (the interpreted build).
        self.all_modules = False

    def find_spec(
        self, fullname: str, path: Sequence[str] | None, target: ModuleType | None = None
    ) -> importlib.machinery.ModuleSpec | None:
        del target
        if not path or not fullname.startswith('tf_demo.'):
            return None
        if fullname in COMPILED_MODULES and not self.all_modules:
            return None
        base = fullname.rpartition('.')[2] + '.py'
        for folder in path:
            candidate = os.path.join(folder, base)
            if os.path.isfile(candidate):
                return importlib.util.spec_from_file_location(fullname, candidate)
        return None


def _finder() -> _SourcesFirst:
    """Return the finder of :func:`guard_sources` (installing it first on ``sys.meta_path``)."""
    for finder in sys.meta_path:
        if isinstance(finder, _SourcesFirst):
            return finder
    finder = _SourcesFirst()
    sys.meta_path.insert(0, finder)
    return finder


def guard_sources() -> None:
    """Import every module that is not compiled from its source (tf_demo does on import)."""
    _finder()


def prefer_sources() -> None:
    """Import the hot modules from their Python source from now on (the interpreted build)."""
    _finder().all_modules = True
