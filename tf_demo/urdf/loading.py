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
the same way. Files are read through :mod:`tf_demo.core.files` (bounded, regular files only), and a
xacro expansion runs in a child process with time, memory and nesting limits (xacro is code).
"""

from __future__ import annotations

from collections.abc import Mapping
from collections.abc import Sequence
import contextlib
import json
import os
from pathlib import Path
import signal
import site
import subprocess
import sys
import tempfile
from typing import IO

from tf_demo.core.files import InputFileError
from tf_demo.core.files import MAX_TEXT_FILE_BYTES
from tf_demo.core.files import read_text_file
from tf_demo.core.python_child import python_child_command
from tf_demo.urdf.errors import UrdfBrokenRefError
from tf_demo.urdf.errors import UrdfError
from tf_demo.urdf.errors import UrdfMalformedError
from tf_demo.urdf.errors import UrdfUnsupportedError

__all__ = [
    'PACKAGE_PATH_VARIABLE',
    'XACRO_TIMEOUT_S',
    'PackageNotFoundError',
    'expand_xacro',
    'find_package_share',
    'is_xacro_path',
    'parse_xacro_args',
    'read_description',
]

PACKAGE_PATH_VARIABLE = 'TF_DEMO_PACKAGE_PATH'
#: The longest a xacro expansion may take before it is stopped.
XACRO_TIMEOUT_S = 30.0


class PackageNotFoundError(LookupError):
    """A ``$(find pkg)`` or ``package://pkg`` names a package found nowhere on the search path."""


def _search_roots(package_paths: Sequence[str | Path] | None) -> list[Path]:
    roots = [Path(p) for p in package_paths or ()]
    roots += [Path(p) for p in os.environ.get(PACKAGE_PATH_VARIABLE, '').split(os.pathsep) if p]
    return roots


def _pip_data_prefixes() -> list[str]:
    """Where pip puts a wheel's data files (``share/<package>``): the environment, the user."""
    return list(dict.fromkeys((sys.prefix, site.getuserbase())))


def find_package_share(package: str, package_paths: Sequence[str | Path] | None = None) -> Path:
    """
    Return the share directory of ``package`` without ROS.

    Searched in order: ``package_paths``, ``TF_DEMO_PACKAGE_PATH``, ``AMENT_PREFIX_PATH`` (a
    sourced ROS 2 or colcon workspace), then where pip installs a wheel's data files (this
    environment's ``share/``, then the user's), where a ``package.xml`` marks the package.

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
    for prefix in _pip_data_prefixes():
        share = Path(prefix, 'share', package)
        if Path(share, 'package.xml').is_file():
            return share
    searched = [str(r) for r in _search_roots(package_paths)]
    msg = (
        f"package '{package}' not found (searched {PACKAGE_PATH_VARIABLE} / package_paths "
        f'{searched}, AMENT_PREFIX_PATH and {", ".join(_pip_data_prefixes())})'
    )
    raise PackageNotFoundError(msg)


def resolve_resource(
    uri: str, base_dir: str | Path | None = None, package_paths: Sequence[str | Path] | None = None
) -> Path:
    """
    Return the file a URDF resource names, as resource_retriever resolves it.

    ``package://pkg/rel`` is ``rel`` in ``pkg``'s share directory (:func:`find_package_share`),
    ``file:///abs`` the absolute path; a plain path is taken relative to ``base_dir`` (the
    description's folder). The file need not exist.

    :raises PackageNotFoundError: for a package found nowhere.
    :raises ValueError: for another URL scheme or an empty path.
    """
    if uri.startswith('package://'):
        package, _, relative = uri[len('package://') :].partition('/')
        if not package or not relative:
            msg = f'resource {uri!r} does not name a package and a file in it'
            raise ValueError(msg)
        return find_package_share(package, package_paths) / relative
    if uri.startswith('file://'):
        return Path(uri[len('file://') :])
    if '://' in uri or not uri:
        msg = f'resource {uri!r}: only package://, file:// and plain paths are supported'
        raise ValueError(msg)
    path = Path(uri)
    return path if path.is_absolute() or base_dir is None else Path(base_dir) / path


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


_WORKER_BOOTSTRAP = (
    'import json, sys\n'
    'request = json.loads(sys.stdin.buffer.read(1 << 20))\n'
    "sys.path[:0] = request['sys_path']\n"
    'from tf_demo.urdf.xacro_worker import child_main\n'
    'child_main(request)\n'
)
_STDERR_TAIL_BYTES = 64 * 1024
_ERROR_CLASSES: dict[str, type[UrdfError]] = {
    cls.__name__: cls
    for cls in (UrdfError, UrdfMalformedError, UrdfBrokenRefError, UrdfUnsupportedError)
}


def _kill_group(process: subprocess.Popen[bytes]) -> None:
    """Kill the child and anything it started (its own session), then reap it."""
    if process.poll() is None:
        with contextlib.suppress(OSError):
            os.killpg(process.pid, signal.SIGKILL)
        with contextlib.suppress(OSError):
            process.kill()
    process.wait()


def _tail(handle: IO[bytes], limit: int) -> str:
    size = handle.seek(0, os.SEEK_END)
    handle.seek(max(0, size - limit))
    return handle.read().decode('utf-8', 'replace')


def expand_xacro(
    path: str | Path,
    mappings: Mapping[str, str] | None = None,
    package_paths: Sequence[str | Path] | None = None,
    *,
    timeout_s: float = XACRO_TIMEOUT_S,
) -> str:
    """
    Expand a xacro file to URDF text, as ``xacro file name:=value`` does.

    xacro evaluates Python expressions, so the expansion runs in a child process with a time
    limit (killed when it runs out), a memory limit, bounded file reads and a limit on macro and
    include nesting (:mod:`tf_demo.urdf.xacro_worker`). It is not a sandbox: expand only files
    you trust, as with upstream xacro.

    :param path: the ``.xacro`` file.
    :param mappings: xacro arguments (values are converted to ``str``).
    :param package_paths: where ``$(find pkg)`` and ``package://pkg`` look first.
    :param timeout_s: the longest the expansion may take.
    :raises UrdfError: naming the file and what xacro reported, or that time ran out.
    """
    source = str(path)
    request = {
        'path': source,
        'mappings': {str(k): str(v) for k, v in (mappings or {}).items()},
        'package_paths': [str(p) for p in package_paths or ()],
        'sys_path': [p for p in sys.path if isinstance(p, str) and p],  # '' is the cwd
        'timeout_s': timeout_s,
    }
    with tempfile.TemporaryFile() as out, tempfile.TemporaryFile() as err:
        process = subprocess.Popen(  # our own interpreter and bootstrap
            python_child_command(_WORKER_BOOTSTRAP),
            stdin=subprocess.PIPE,
            stdout=out,
            stderr=err,
            start_new_session=True,  # killed as a group; a terminal's Ctrl-C is the parent's
        )
        try:
            try:
                if process.stdin is not None:
                    process.stdin.write(json.dumps(request).encode('utf-8'))
                    process.stdin.close()
            except BrokenPipeError:
                pass  # the child died at once; its exit status tells why below
            try:
                returncode = process.wait(timeout=timeout_s)
            except subprocess.TimeoutExpired:
                msg = (
                    f'expansion did not finish within {timeout_s:g} s and was stopped (xacro '
                    'evaluates expressions: an endless macro or a huge number such as '
                    '${9**9**9}?)'
                )
                raise UrdfMalformedError(source, 'xacro', msg) from None
        finally:
            _kill_group(process)
        size = out.seek(0, os.SEEK_END)
        answer: object = None
        if 0 < size <= 4 * MAX_TEXT_FILE_BYTES:
            out.seek(0)
            with contextlib.suppress(ValueError):
                answer = json.loads(out.read().decode('utf-8'))
        stderr = _tail(err, _STDERR_TAIL_BYTES)
    return _answer_to_text(source, answer, returncode, stderr)


def _answer_to_text(source: str, answer: object, returncode: int, stderr: str) -> str:
    """Return the child's URDF text, or raise the UrdfError it reported (or its death)."""
    if isinstance(answer, dict) and isinstance(answer.get('xml'), str):
        if stderr.strip():
            sys.stderr.write(stderr if stderr.endswith('\n') else stderr + '\n')
        text: str = answer['xml']
        return text
    error = answer.get('error') if isinstance(answer, dict) else None
    if isinstance(error, dict):
        cls = _ERROR_CLASSES.get(str(error.get('kind')), UrdfMalformedError)
        line = error.get('line')
        raise cls(
            str(error.get('source', source)),
            str(error.get('element', 'xacro')),
            str(error.get('reason', '')),
            line if isinstance(line, int) else None,
        )
    if returncode < 0:
        try:
            name = signal.Signals(-returncode).name
        except ValueError:
            name = f'signal {-returncode}'
        reason = f'the expansion was killed by {name} (out of memory, CPU time or output size?)'
    else:
        last = [line for line in stderr.splitlines() if line.strip()]
        reason = f'the expansion failed (exit code {returncode})' + (
            f': {last[-1].strip()}' if last else ''
        )
    raise UrdfMalformedError(source, 'xacro', reason)


def read_description(
    path: str | Path,
    mappings: Mapping[str, str] | None = None,
    package_paths: Sequence[str | Path] | None = None,
) -> str:
    """Read a URDF file (bounded, regular files only), or expand a ``.xacro`` file."""
    if is_xacro_path(path):
        return expand_xacro(path, mappings, package_paths)
    try:
        return read_text_file(path)
    except InputFileError as error:
        raise _file_error(str(path), error) from None


def _file_error(source: str, error: InputFileError) -> UrdfError:
    """Turn the bounded reader's error (``<path>[:line]: reason``) into a UrdfError."""
    text = str(error)
    rest = text[len(source) :] if text.startswith(source) else f': {text}'
    line_text, _, reason = rest.lstrip(':').partition(': ')
    line = int(line_text) if line_text.isdigit() else None
    if line is None:
        reason = rest.lstrip(':').strip()
    if reason == 'no such file':
        return UrdfBrokenRefError(source, 'file', reason, line)
    return UrdfError(source, 'file', reason, line)
