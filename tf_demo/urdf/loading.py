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
Reading robot descriptions from files: plain URDF or xacro, without a ROS installation.

xacro's ``$(find pkg)`` normally needs ``ament_index_python``; here a package is found in the
directories of ``package_paths`` (or ``TF_DEMO_PACKAGE_PATH``, ``os.pathsep``-separated), each
holding ``<pkg>/`` folders, and then as ``<prefix>/share/<pkg>`` for every prefix of
``AMENT_PREFIX_PATH`` (the ament index layout). ``package://pkg/rel`` in ``xacro:include`` resolves
the same way. xacro keeps module-global state, so expansion is serialised with a lock.
"""

from __future__ import annotations

from collections.abc import Callable
from collections.abc import Iterator
from collections.abc import Mapping
from collections.abc import Sequence
import contextlib
import os
from pathlib import Path
import threading
from xml.parsers.expat import ExpatError

from tf_demo.urdf.errors import UrdfBrokenRefError
from tf_demo.urdf.errors import UrdfError
from tf_demo.urdf.errors import UrdfMalformedError

__all__ = [
    'PACKAGE_PATH_VARIABLE',
    'expand_xacro',
    'find_package_share',
    'is_xacro_path',
    'parse_xacro_args',
    'read_description',
]

PACKAGE_PATH_VARIABLE = 'TF_DEMO_PACKAGE_PATH'
_XACRO_LOCK = threading.Lock()


class PackageNotFoundError(LookupError):
    """A ``$(find pkg)`` or ``package://pkg`` names a package found nowhere on the search path."""


def _search_roots(package_paths: Sequence[str | Path] | None) -> list[Path]:
    roots = [Path(p) for p in package_paths or ()]
    roots += [Path(p) for p in os.environ.get(PACKAGE_PATH_VARIABLE, '').split(os.pathsep) if p]
    return roots


def find_package_share(package: str, package_paths: Sequence[str | Path] | None = None) -> Path:
    """
    Return the share directory of ``package`` without ROS.

    :param package: the package name.
    :param package_paths: extra directories holding ``<package>/`` folders, searched first.
    :raises PackageNotFoundError: when no candidate exists.
    """
    for root in _search_roots(package_paths):
        for candidate in (root / package, root / 'share' / package):
            if candidate.is_dir():
                return candidate
    for prefix in os.environ.get('AMENT_PREFIX_PATH', '').split(os.pathsep):
        if not prefix:
            continue
        marker = Path(prefix, 'share', 'ament_index', 'resource_index', 'packages', package)
        share = Path(prefix, 'share', package)
        if marker.is_file() or share.is_dir():
            return share
    searched = [str(r) for r in _search_roots(package_paths)]
    msg = (
        f"package '{package}' not found (searched {PACKAGE_PATH_VARIABLE} / package_paths "
        f'{searched} and AMENT_PREFIX_PATH)'
    )
    raise PackageNotFoundError(msg)


def is_xacro_path(path: str | Path) -> bool:
    """Tell whether a file must be expanded with xacro (its name ends in ``.xacro``)."""
    return str(path).endswith('.xacro')


def parse_xacro_args(text: str) -> dict[str, str]:
    """
    Parse xacro arguments written as on xacro's command line: ``'name:=value other:=2'``.

    :raises ValueError: for a word without ``:=``.
    """
    mappings: dict[str, str] = {}
    for word in text.split():
        name, sep, value = word.partition(':=')
        if not sep or not name:
            msg = f"xacro argument '{word}' is not of the form name:=value"
            raise ValueError(msg)
        mappings[name] = value
    return mappings


@contextlib.contextmanager
def _patched_xacro(package_paths: Sequence[str | Path] | None) -> Iterator[None]:
    import xacro
    from xacro import substitution_args

    def find(package: str) -> str:
        return str(find_package_share(package, package_paths))

    original_abs: Callable[[str], str] = xacro.abs_filename_spec

    def abs_filename(filename_spec: str) -> str:
        if filename_spec.startswith('package://'):
            package, _, relative = filename_spec[len('package://') :].partition('/')
            return str(find_package_share(package, package_paths) / relative)
        return original_abs(filename_spec)

    original_find = substitution_args._eval_find
    original_dict_find = substitution_args._eval_dict['find']
    with _XACRO_LOCK:
        xacro.abs_filename_spec = abs_filename
        substitution_args._eval_find = find
        substitution_args._eval_dict['find'] = find
        try:
            yield
        finally:
            xacro.abs_filename_spec = original_abs
            substitution_args._eval_find = original_find
            substitution_args._eval_dict['find'] = original_dict_find


def expand_xacro(
    path: str | Path,
    mappings: Mapping[str, str] | None = None,
    package_paths: Sequence[str | Path] | None = None,
) -> str:
    """
    Expand a xacro file to URDF text, as ``xacro file name:=value`` does.

    :param path: the ``.xacro`` file.
    :param mappings: xacro arguments (values are converted to ``str``).
    :param package_paths: where ``$(find pkg)`` and ``package://pkg`` look first.
    :raises UrdfError: naming the file and what xacro reported.
    """
    source = str(path)
    if not Path(path).is_file():
        raise UrdfBrokenRefError(source, 'file', 'no such file')
    import xacro

    arguments = {str(k): str(v) for k, v in (mappings or {}).items()}
    try:
        with _patched_xacro(package_paths):
            document = xacro.process_file(source, mappings=arguments)
    except PackageNotFoundError as error:
        raise UrdfBrokenRefError(source, 'xacro', str(error)) from None
    except ExpatError as error:
        raise UrdfMalformedError(
            source, 'XML', f'malformed XML: {error}', getattr(error, 'lineno', None)
        ) from None
    except (xacro.XacroException, OSError, KeyError, ValueError, NameError) as error:
        reason = str(error) or type(error).__name__
        cause = getattr(error, 'exc', None)
        if isinstance(cause, PackageNotFoundError):
            raise UrdfBrokenRefError(source, 'xacro', str(cause)) from None
        if isinstance(cause, OSError) and cause.filename:
            raise UrdfBrokenRefError(
                source, 'xacro', f'{cause.strerror}: {cause.filename}'
            ) from None
        if isinstance(error, OSError) and error.filename:
            raise UrdfBrokenRefError(
                source, 'xacro', f'{error.strerror}: {error.filename}'
            ) from None
        raise UrdfMalformedError(source, 'xacro', f'xacro failed: {reason}') from None
    text: str = document.toprettyxml(indent='  ')
    return text


def read_description(
    path: str | Path,
    mappings: Mapping[str, str] | None = None,
    package_paths: Sequence[str | Path] | None = None,
) -> str:
    """Read a URDF file, or expand a ``.xacro`` file; return the URDF text."""
    if is_xacro_path(path):
        return expand_xacro(path, mappings, package_paths)
    try:
        return Path(path).read_text(encoding='utf-8')
    except FileNotFoundError:
        raise UrdfBrokenRefError(str(path), 'file', 'no such file') from None
    except (OSError, UnicodeDecodeError) as error:
        raise UrdfError(str(path), 'file', f'cannot read: {error}') from None
