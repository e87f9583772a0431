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
The one way the package reads and writes a file a user names.

Reading: bounded, regular files only, UTF-8. ``/dev/zero``, a FIFO or a 10 GB file must not be
read until memory runs out, and a file that is not UTF-8 must not end in a traceback. Every
failure is an :class:`InputFileError` whose message starts with the path (and, for bad text,
the line).

Writing (``tf_saver -o``, ``view_frames -o``), so that ``-o`` can never damage what it points
at; failures are :class:`OutputFileError`, whose message starts with the path the user gave.

- Only regular files are written. A device (``/dev/full``, ``/dev/null``), FIFO, socket or
  directory is refused before anything is written; renaming over it would turn a device node
  into a regular file when run as root.
- A symbolic link is followed: the file it points at is replaced and the link stays a link (as
  shell redirection and editors that preserve links do). A link to something that is not a
  regular file is refused like that thing; a dangling link creates the file it names.
- The new content is written to a temporary file in the target's folder, flushed to disk and
  renamed over the target, so a reader sees the old file or the new one, never half of one. An
  existing file keeps its permission bits (and, where allowed, its owner).
"""

from __future__ import annotations

import contextlib
import os
import secrets
import stat

#: Default size limit for a text file the package reads (URDF, params, snapshot, transforms).
MAX_TEXT_FILE_BYTES = 16 * 1024 * 1024
_CHUNK_BYTES = 64 * 1024


class InputFileError(ValueError):
    """A file that cannot be read as asked; the message names the file and the reason."""


def read_bytes_file(path: str | os.PathLike[str], max_bytes: int = MAX_TEXT_FILE_BYTES) -> bytes:
    """Read at most ``max_bytes`` from the regular file at ``path`` (else InputFileError)."""
    source = os.fspath(path)
    try:
        # O_NONBLOCK: opening a FIFO with no writer must not block before the check below.
        descriptor = os.open(source, os.O_RDONLY | getattr(os, 'O_NONBLOCK', 0))
    except FileNotFoundError:
        raise InputFileError(f'{source}: no such file') from None
    except IsADirectoryError:
        raise InputFileError(f'{source}: is a directory, not a file') from None
    except OSError as error:
        raise InputFileError(f'{source}: cannot open ({error.strerror})') from None
    try:
        status = os.fstat(descriptor)
        if stat.S_ISDIR(status.st_mode):
            raise InputFileError(f'{source}: is a directory, not a file')
        if not stat.S_ISREG(status.st_mode):
            raise InputFileError(f'{source}: not a regular file (a device, FIFO or socket)')
        if status.st_size > max_bytes:
            raise InputFileError(
                f'{source}: file is larger than {max_bytes} bytes ({status.st_size})'
            )
        os.set_blocking(descriptor, True)
        data = _read_at_most(descriptor, max_bytes + 1)
    except OSError as error:
        raise InputFileError(f'{source}: cannot read ({error.strerror})') from None
    finally:
        os.close(descriptor)
    if len(data) > max_bytes:  # grew while being read
        raise InputFileError(f'{source}: file is larger than {max_bytes} bytes')
    return data


def _read_at_most(descriptor: int, limit: int) -> bytes:
    """Read up to ``limit`` bytes in chunks (no ``limit``-sized buffer for a small file)."""
    chunks: list[bytes] = []
    total = 0
    while total < limit:
        chunk = os.read(descriptor, min(_CHUNK_BYTES, limit - total))
        if not chunk:
            break
        chunks.append(chunk)
        total += len(chunk)
    return b''.join(chunks)


def decode_utf8(data: bytes, source: str) -> str:
    """Decode ``data`` as UTF-8, or raise InputFileError naming ``source`` and the bad line."""
    try:
        return data.decode('utf-8')
    except UnicodeDecodeError as error:
        line = data[: error.start].count(b'\n') + 1
        raise InputFileError(f'{source}:{line}: not UTF-8 text') from None


def read_text_file(path: str | os.PathLike[str], max_bytes: int = MAX_TEXT_FILE_BYTES) -> str:
    """Read the UTF-8 text of the regular file at ``path``, at most ``max_bytes`` long."""
    return decode_utf8(read_bytes_file(path, max_bytes), os.fspath(path))


_TEMPORARY_ATTEMPTS = 100


class OutputFileError(Exception):
    """A path that cannot be written as asked; the message names the path and the reason."""


def output_path_error(path: str | os.PathLike[str]) -> str | None:
    """Return why ``path`` cannot be written (see the module rules), or None if it can be."""
    source = os.fspath(path)
    if not source:
        return 'the output path is empty'
    try:
        _existing_status(source, os.path.realpath(source))
    except OutputFileError as error:
        return str(error)
    return None


def _existing_status(source: str, target: str) -> os.stat_result | None:
    """Stat the resolved ``target``: None if it does not exist, else a regular file's status."""
    try:
        status = os.stat(target)
    except FileNotFoundError:
        return None
    except OSError as error:
        raise OutputFileError(f'{source}: cannot write ({error.strerror})') from None
    if stat.S_ISDIR(status.st_mode):
        raise OutputFileError(f'{source}: is a directory, not a file')
    if not stat.S_ISREG(status.st_mode):
        kind = 'a device, FIFO or socket'
        raise OutputFileError(f'{source}: not a regular file ({kind}); nothing was written')
    return status


def _create_temporary(target: str) -> tuple[int, str]:
    """Create a new, empty temporary file next to ``target``; return (descriptor, path)."""
    directory, name = os.path.split(target)
    flags = os.O_WRONLY | os.O_CREAT | os.O_EXCL | getattr(os, 'O_NOFOLLOW', 0)
    flags |= getattr(os, 'O_CLOEXEC', 0)
    for _ in range(_TEMPORARY_ATTEMPTS):
        temporary = os.path.join(directory, f'.{name}.{secrets.token_hex(6)}.tmp')
        try:
            return os.open(temporary, flags, 0o666), temporary
        except FileExistsError:
            continue
    msg = f'no free temporary file name next to {target}'
    raise FileExistsError(msg)


def write_text_atomically(path: str | os.PathLike[str], text: str) -> None:
    """Replace the regular file at ``path`` (or create it) with UTF-8 ``text``, atomically."""
    write_bytes_atomically(path, text.encode('utf-8'))


def write_bytes_atomically(path: str | os.PathLike[str], data: bytes) -> None:
    """Replace the regular file at ``path`` (or create it) with ``data``, atomically."""
    source = os.fspath(path)
    if not source:
        msg = 'the output path is empty'
        raise OutputFileError(msg)
    target = os.path.realpath(source)
    status = _existing_status(source, target)
    try:
        descriptor, temporary = _create_temporary(target)
    except OSError as error:
        reason = error.strerror or str(error)
        raise OutputFileError(f'{source}: cannot write ({reason})') from None
    try:
        with os.fdopen(descriptor, 'wb') as handle:
            handle.write(data)
            handle.flush()
            if status is not None:
                os.fchmod(handle.fileno(), stat.S_IMODE(status.st_mode))
                with contextlib.suppress(OSError):  # only root may give a file away
                    os.fchown(handle.fileno(), status.st_uid, status.st_gid)
            os.fsync(handle.fileno())
        # Checked again just before the rename: the target may have changed while writing.
        _existing_status(source, target)
        os.replace(temporary, target)
    except BaseException as error:
        with contextlib.suppress(OSError):
            os.unlink(temporary)
        if isinstance(error, OSError):
            reason = error.strerror or str(error)
            raise OutputFileError(f'{source}: cannot write ({reason})') from None
        raise


#: Characters after which a YAML ``[`` or ``{`` opens a flow collection (None: the text's start).
_FLOW_OPENERS_AFTER = frozenset('[{,:-?')


def yaml_flow_too_deep(text: str, limit: int) -> int | None:
    """
    Return the 1-based line where YAML flow collections (``[`` ``{``) nest deeper than ``limit``.

    A character scan, run before any YAML parser sees hostile text (PyYAML's scanner reads a
    whole run of brackets ahead, and since 6.0.4 stops at 1,000 levels with its own words).
    Quoted scalars and comments are skipped; a bracket counts only where a node can start (at
    the start, or after ``[ { , : - ?``), so ``a[b`` stays a plain scalar. None when within.
    """
    depth = 0
    line = 1
    previous: str | None = None
    quote: str | None = None
    comment = False
    index = 0
    length = len(text)
    while index < length:
        char = text[index]
        index += 1
        if char == '\n':
            line += 1
            comment = False
            continue
        if comment:
            continue
        if quote is not None:
            if quote == '"' and char == '\\':
                index += 1  # an escaped character
            elif char == quote:
                if quote == "'" and text.startswith("'", index):
                    index += 1  # '' is a quote inside a single-quoted scalar
                else:
                    quote = None
                    previous = char
            continue
        if char in ' \t\r':
            if text.startswith('#', index):
                comment = True
            continue
        opens = previous is None or previous in _FLOW_OPENERS_AFTER
        if char in '[{' and not opens:
            char = 'a'  # inside a plain scalar: neither this nor what follows opens
        elif char in '[{':
            depth += 1
            if depth > limit:
                return line
        elif char in ']}':
            depth = max(0, depth - 1)
        elif char in '\'"' and opens:
            quote = char
        previous = char
    return None
