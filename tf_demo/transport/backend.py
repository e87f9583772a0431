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
Backend selection: which world this process runs in, decided once.

``TF_DEMO_BACKEND=rclpy|dds`` when set; otherwise ``rclpy`` when it imports, otherwise ``dds``.
"""

from __future__ import annotations

import functools
import importlib.util
import os
from typing import Literal

BackendName = Literal['rclpy', 'dds']

BACKEND_ENV_VAR = 'TF_DEMO_BACKEND'
KNOWN_BACKENDS: tuple[BackendName, ...] = ('rclpy', 'dds')


class BackendError(RuntimeError):
    """The requested backend is unknown or cannot be loaded."""


def choose_backend(requested: str | None, rclpy_importable: bool) -> BackendName:
    """
    Pick the backend from the environment value and whether rclpy imports.

    :param requested: the value of ``TF_DEMO_BACKEND`` (``None`` or empty when unset).
    :param rclpy_importable: whether ``import rclpy`` would succeed.
    :raises BackendError: for a value that is not ``rclpy`` or ``dds``, or ``rclpy`` requested
        where it is not installed.
    """
    if requested:
        value = requested.strip().lower()
        if value == 'rclpy':
            if not rclpy_importable:
                msg = (
                    f'{BACKEND_ENV_VAR}=rclpy but rclpy cannot be imported '
                    '(source a ROS 2 installation or use TF_DEMO_BACKEND=dds)'
                )
                raise BackendError(msg)
            return 'rclpy'
        if value == 'dds':
            return 'dds'
        msg = f'{BACKEND_ENV_VAR}={requested!r} is not a known backend (expected rclpy or dds)'
        raise BackendError(msg)
    return 'rclpy' if rclpy_importable else 'dds'


def _rclpy_importable() -> bool:
    """Whether rclpy imports in this process (an installed but broken rclpy counts as absent)."""
    if importlib.util.find_spec('rclpy') is None:
        return False
    try:
        importlib.import_module('rclpy')
    except Exception:  # any failure to import means "not usable"
        return False
    return True


@functools.lru_cache(maxsize=1)
def backend_name() -> BackendName:
    """Return the backend of this process: ``'rclpy'`` or ``'dds'`` (resolved once)."""
    requested = os.environ.get(BACKEND_ENV_VAR)
    if requested and requested.strip().lower() == 'dds':
        return 'dds'
    return choose_backend(requested, _rclpy_importable())


def is_rclpy() -> bool:
    """Whether this process runs on rclpy."""
    return backend_name() == 'rclpy'


class NodeConfigError(ValueError):
    """A node cannot start because of its configuration; ``run_node`` prints it on one line."""


def rclpy_world() -> bool:
    """
    Whether module-level names should be rclpy's (a bad ``TF_DEMO_BACKEND`` counts as no).

    Used at import time, where an error would become a traceback; the bad value is reported
    cleanly when the backend is used (``init``/``run_node``).
    """
    try:
        return backend_name() == 'rclpy'
    except BackendError:
        return False
