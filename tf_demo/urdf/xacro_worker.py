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
The child side of a xacro expansion: one expansion per process, under resource limits.

xacro is code: it evaluates Python expressions (``${9**9**9}`` never ends), macros may call
themselves and files may include themselves. :func:`tf_demo.urdf.loading.expand_xacro` therefore
runs :func:`serve` in a child process it kills after a time limit; here the child limits its own
memory and CPU time (so an orphan cannot burn CPU for long), reads every file through the bounded
reader, refuses macro and include nesting deeper than a stated limit, and reports the result or
a :class:`~tf_demo.urdf.errors.UrdfError` as one JSON object.

This is not a sandbox: xacro can still read any file and environment variable the user can
(``$(env HOME)``, ``load_yaml``); expand only files you trust, as with upstream xacro.
"""

from __future__ import annotations

from collections.abc import Callable
from collections.abc import Iterator
from collections.abc import Mapping
from collections.abc import Sequence
import contextlib
import io
import json
import os
from pathlib import Path
import sys
from typing import BinaryIO
from xml.parsers.expat import ExpatError

from tf_demo.core.files import InputFileError
from tf_demo.core.files import MAX_TEXT_FILE_BYTES
from tf_demo.core.files import read_bytes_file
from tf_demo.urdf.errors import UrdfBrokenRefError
from tf_demo.urdf.errors import UrdfError
from tf_demo.urdf.errors import UrdfMalformedError
from tf_demo.urdf.loading import find_package_share
from tf_demo.urdf.loading import PackageNotFoundError

__all__ = [
    'MAX_INCLUDE_DEPTH',
    'MAX_MACRO_DEPTH',
    'child_main',
    'expand_in_process',
    'serve',
]

#: Macros instantiated inside each other deeper than this are refused.
MAX_MACRO_DEPTH = 100
#: Files included inside each other deeper than this are refused.
MAX_INCLUDE_DEPTH = 50
#: Address-space limit of the child process.
MEMORY_LIMIT_BYTES = 2 * 1024 * 1024 * 1024
_RECURSION_LIMIT = 10_000
_TOO_DEEP = 'nesting too deep (a macro that calls itself, or a file that includes itself?)'
_TOO_BIG = f'the expansion needs more than {MEMORY_LIMIT_BYTES // (1024 * 1024)} MiB of memory'


def _nesting_error(what: str, limit: int, names: Sequence[str]) -> Exception:
    import xacro

    shown = [*names[:3], '...', *names[-2:]] if len(names) > 6 else list(names)
    error: Exception = xacro.XacroException(
        f'{what} nested deeper than {limit} ({" -> ".join(shown)}): does a macro call itself, '
        'or a file include itself?'
    )
    return error


@contextlib.contextmanager
def _patched_xacro(package_paths: Sequence[str | Path] | None) -> Iterator[None]:
    """Patch xacro: packages found without ROS, bounded file reads, nesting limits."""
    import xacro
    from xacro import substitution_args

    def find(package: str) -> str:
        return str(find_package_share(package, package_paths))

    original_abs: Callable[[str], str] = xacro.abs_filename_spec
    original_parse = xacro.parse
    original_macro_call = xacro.handle_macro_call
    original_include = xacro.process_include

    def abs_filename(filename_spec: str) -> str:
        if filename_spec.startswith('package://'):
            package, _, relative = filename_spec[len('package://') :].partition('/')
            return str(find_package_share(package, package_paths) / relative)
        return original_abs(filename_spec)

    def parse(inp: object, filename: str | None = None) -> object:
        if inp is None and filename is not None:
            # xacro's --root-dir (2.0.11 on); before it, files open from the working directory.
            path = os.path.join(getattr(xacro, 'root_dir', os.curdir), filename)
            if os.path.lexists(path):  # a missing file keeps xacro's own error (optional includes)
                try:
                    inp = io.BytesIO(read_bytes_file(path))
                except InputFileError as error:
                    raise xacro.XacroException(str(error)) from None
        return original_parse(inp, filename)

    def handle_macro_call(node: object, macros: object, symbols: object) -> object:
        stack = xacro.macrostack or []
        if len(stack) >= MAX_MACRO_DEPTH:
            names = [str(m.body.getAttribute('name')) for m in stack]
            raise _nesting_error('macros', MAX_MACRO_DEPTH, names)
        return original_macro_call(node, macros, symbols)

    def process_include(elt: object, macros: object, symbols: object, func: object) -> object:
        stack = xacro.filestack or []
        if len(stack) > MAX_INCLUDE_DEPTH:
            raise _nesting_error('includes', MAX_INCLUDE_DEPTH, [str(f) for f in stack])
        return original_include(elt, macros, symbols, func)

    def install(functions: dict[str, object], finds: tuple[object, object]) -> None:
        for name, function in functions.items():
            setattr(xacro, name, function)
        substitution_args._eval_find, substitution_args._eval_dict['find'] = finds

    patched: dict[str, object] = {
        'abs_filename_spec': abs_filename,
        'parse': parse,
        'handle_macro_call': handle_macro_call,
        'process_include': process_include,
    }
    originals = {name: getattr(xacro, name) for name in patched}
    original_finds = (substitution_args._eval_find, substitution_args._eval_dict['find'])
    install(patched, (find, find))
    try:
        yield
    finally:
        install(originals, original_finds)


def expand_in_process(
    source: str,
    mappings: Mapping[str, str],
    package_paths: Sequence[str | Path] | None = None,
) -> str:
    """
    Expand the xacro file ``source`` here, in this process (the child's work).

    Only for a process of its own: xacro keeps module-global state, and nothing here bounds
    the time an expression may take.

    :raises UrdfError: naming the file and what went wrong.
    """
    import xacro

    try:
        with _patched_xacro(package_paths):
            document = xacro.process_file(source, mappings=dict(mappings))
        text: str = document.toprettyxml(indent='  ')
    except PackageNotFoundError as error:
        raise UrdfBrokenRefError(source, 'xacro', str(error)) from None
    except ExpatError as error:
        raise UrdfMalformedError(
            source, 'XML', f'malformed XML: {error}', getattr(error, 'lineno', None)
        ) from None
    except RecursionError:
        raise UrdfMalformedError(source, 'xacro', _TOO_DEEP) from None
    except MemoryError:
        raise UrdfMalformedError(source, 'xacro', _TOO_BIG) from None
    except Exception as error:  # xacro evaluates user code: any exception is the file's error
        raise _error_from_xacro(source, error) from None
    if len(text) > MAX_TEXT_FILE_BYTES:
        msg = f'the expanded description is larger than {MAX_TEXT_FILE_BYTES} bytes'
        raise UrdfMalformedError(source, 'xacro', msg)
    return text


def _error_from_xacro(source: str, error: Exception) -> UrdfError:
    """Turn what xacro raised into a UrdfError naming the file and the reason."""
    cause = getattr(error, 'exc', None)
    if isinstance(cause, RecursionError):
        return UrdfMalformedError(source, 'xacro', _TOO_DEEP)
    if isinstance(cause, MemoryError):
        return UrdfMalformedError(source, 'xacro', _TOO_BIG)
    if isinstance(cause, PackageNotFoundError):
        return UrdfBrokenRefError(source, 'xacro', str(cause))
    for candidate in (cause, error):
        if isinstance(candidate, OSError) and candidate.filename:
            return UrdfBrokenRefError(
                source, 'xacro', f'{candidate.strerror}: {candidate.filename}'
            )
    lines = [line.strip() for line in str(error).splitlines() if line.strip()]
    reason = '; '.join(lines) or type(error).__name__
    if type(error).__name__ != 'XacroException' and not isinstance(error, OSError):
        reason = f'{type(error).__name__}: {reason}'
    return UrdfMalformedError(source, 'xacro', f'xacro failed: {reason}')


def _limit_resources(cpu_seconds: int) -> None:
    """Bound this process's memory and CPU time (best effort where ``resource`` exists)."""
    try:
        import resource
    except ImportError:  # not POSIX: the parent's time limit still applies
        return
    limits = (
        (resource.RLIMIT_AS, MEMORY_LIMIT_BYTES),
        (resource.RLIMIT_CPU, cpu_seconds),
        (resource.RLIMIT_FSIZE, 4 * MAX_TEXT_FILE_BYTES),
    )
    for kind, value in limits:
        with contextlib.suppress(ValueError, OSError):
            _, hard = resource.getrlimit(kind)
            resource.setrlimit(
                kind, (value if hard == resource.RLIM_INFINITY else min(value, hard), hard)
            )


def serve(request: Mapping[str, object], result: BinaryIO) -> None:
    """Run one expansion from a decoded request; write ``{"xml"}`` or ``{"error"}`` as JSON."""
    source = str(request['path'])
    timeout = request.get('timeout_s', 60)
    _limit_resources(int(timeout if isinstance(timeout, (int, float)) else 60) + 2)
    sys.setrecursionlimit(_RECURSION_LIMIT)
    raw_mappings = request.get('mappings') or {}
    raw_paths = request.get('package_paths') or []
    mappings = (
        {str(k): str(v) for k, v in raw_mappings.items()} if isinstance(raw_mappings, dict) else {}
    )
    paths = [str(p) for p in raw_paths] if isinstance(raw_paths, list) else []
    answer: dict[str, object]
    try:
        answer = {'xml': expand_in_process(source, mappings, paths)}
    except UrdfError as error:
        answer = {
            'error': {
                'kind': type(error).__name__,
                'source': error.source,
                'element': error.element,
                'reason': error.reason,
                'line': error.line,
            }
        }
    result.write(json.dumps(answer).encode('utf-8'))
    result.flush()


def child_main(request: Mapping[str, object]) -> None:
    """Child entry point: answer ``request`` on the original stdout as JSON."""
    result = os.fdopen(os.dup(1), 'wb')
    os.dup2(2, 1)  # whatever xacro or the user's expressions print goes to stderr
    sys.stdout = sys.stderr
    serve(request, result)
    result.close()
