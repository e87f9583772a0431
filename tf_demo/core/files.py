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
The one way the package reads a file a user names: bounded, regular files only, UTF-8.

``/dev/zero``, a FIFO or a 10 GB file must not be read until memory runs out, and a file
that is not UTF-8 must not end in a traceback. Every failure is an :class:`InputFileError`
whose message starts with the path (and, for bad text, the line).
"""

from __future__ import annotations

import os
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
