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
How to install an optional extra, said the way that works in the world the tool runs in.

Standalone, ``pip install 'tf_demo[bag]'``. Inside ROS 2 the system Python is externally managed
(PEP 668: pip refuses with ``externally-managed-environment`` on Debian 12 and Ubuntu 24.04), so
the hint is ROS 2's own advice: a virtual environment that sees the system's packages, ignored by
colcon, and colcon run through it (README, "Install"); where the tool already runs in such an
environment, that environment's pip. Every "install the extra" message is made here.
"""

from __future__ import annotations

from collections.abc import Mapping
from collections.abc import Sequence
import importlib.metadata
import os
import re
import shlex
import sys

__all__ = ['extra_hint', 'extra_requirements', 'install_hint']

_EXTRA_MARKER = re.compile(r';.*\bextra\s*==\s*[\'"]([\w-]+)[\'"]')


def extra_requirements(extra: str, requires: Sequence[str]) -> list[str]:
    """Return the requirements (``name>=version``) of ``extra`` in metadata's ``requires``."""
    found = []
    for requirement in requires:
        match = _EXTRA_MARKER.search(requirement)
        if match is not None and match.group(1) == extra:
            found.append(requirement[: match.start()].strip().replace(' ', ''))
    return found


def install_hint(
    extra: str, requirements: Sequence[str], *, inside_ros: bool, venv_python: str | None
) -> str:
    """
    Return the command that installs ``extra`` (its ``requirements``) where the tool runs.

    :param inside_ros: a ROS 2 installation is sourced (its Python refuses a plain pip install).
    :param venv_python: the running Python when it is a virtual environment's, else None.
    """
    if not inside_ros:
        return f"pip install 'tf_demo[{extra}]'"
    packages = ' '.join(shlex.quote(r) for r in requirements) or f"'tf_demo[{extra}]'"
    if venv_python is not None:
        return f'{shlex.quote(venv_python)} -m pip install {packages}'
    return (
        'inside ROS 2, in a virtual environment that sees its packages: python3 -m venv '
        f'--system-site-packages venv && touch venv/COLCON_IGNORE && venv/bin/pip install '
        f'{packages}, then build the workspace with venv/bin/python -m colcon build'
    )


def extra_hint(extra: str, environ: Mapping[str, str] | None = None) -> str:
    """:func:`install_hint` for ``extra`` in this process's world (``environ``: os.environ)."""
    environ = os.environ if environ is None else environ
    try:
        requires = importlib.metadata.requires('tf_demo') or []
    except importlib.metadata.PackageNotFoundError:
        requires = []
    return install_hint(
        extra,
        extra_requirements(extra, requires),
        inside_ros=bool(environ.get('ROS_DISTRO') or environ.get('AMENT_PREFIX_PATH')),
        venv_python=sys.executable if sys.prefix != sys.base_prefix else None,
    )
