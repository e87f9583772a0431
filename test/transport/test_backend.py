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

"""Backend selection: TF_DEMO_BACKEND, else rclpy when it imports, else DDS (in subprocesses)."""

import os
from pathlib import Path
import subprocess
import sys

from conftest import PACKAGE_ROOT
from conftest import run_captured
import pytest
from tf_demo.transport.backend import BackendError
from tf_demo.transport.backend import choose_backend

PROBE = (
    'import sys; import tf_demo.transport as t; '
    'print(t.backend_name()); '
    "print('rclpy' in sys.modules, 'cyclonedds' in sys.modules)"
)


def run_probe(
    code: str, backend: str | None, extra_path: Path | None = None
) -> subprocess.CompletedProcess[str]:
    """Run ``code`` in a fresh Python with ``TF_DEMO_BACKEND`` set to ``backend`` (None: unset)."""
    env = dict(os.environ)
    env.pop('TF_DEMO_BACKEND', None)
    if backend is not None:
        env['TF_DEMO_BACKEND'] = backend
    paths = [str(PACKAGE_ROOT)] + ([str(extra_path)] if extra_path else [])
    env['PYTHONPATH'] = os.pathsep.join(paths)
    return run_captured([sys.executable, '-c', code], env)


def test_choose_backend_rules() -> None:
    """An explicit choice wins; otherwise rclpy if importable; unknown names are errors."""
    assert choose_backend('dds', rclpy_importable=True) == 'dds'
    assert choose_backend('rclpy', rclpy_importable=True) == 'rclpy'
    assert choose_backend(' RCLPY ', rclpy_importable=True) == 'rclpy'
    assert choose_backend(None, rclpy_importable=True) == 'rclpy'
    assert choose_backend('', rclpy_importable=False) == 'dds'
    with pytest.raises(BackendError, match='rclpy cannot be imported'):
        choose_backend('rclpy', rclpy_importable=False)
    with pytest.raises(BackendError, match="TF_DEMO_BACKEND='zenoh' is not a known backend"):
        choose_backend('zenoh', rclpy_importable=True)


def test_explicit_dds_selects_dds_and_imports_neither_middleware_eagerly() -> None:
    """TF_DEMO_BACKEND=dds picks DDS; importing the package loads neither rclpy nor cyclonedds."""
    completed = run_probe(PROBE, 'dds')
    assert completed.returncode == 0, completed.stderr
    assert completed.stdout.split() == ['dds', 'False', 'False']


def test_without_rclpy_the_default_is_dds() -> None:
    """With no TF_DEMO_BACKEND and no rclpy installed, the DDS backend is chosen."""
    completed = run_probe(PROBE, None)
    assert completed.returncode == 0, completed.stderr
    assert completed.stdout.split()[0] == 'dds'


def test_a_broken_rclpy_counts_as_absent(tmp_path: Path) -> None:
    """An rclpy that fails to import (e.g. built for another Python) falls back to DDS."""
    broken = tmp_path / 'rclpy'
    broken.mkdir()
    (broken / '__init__.py').write_text(
        "raise ImportError('rclpy built for another Python')\n", encoding='utf-8'
    )
    completed = run_probe(PROBE, None, extra_path=tmp_path)
    assert completed.returncode == 0, completed.stderr
    assert completed.stdout.split()[0] == 'dds'


def test_requesting_rclpy_without_it_is_a_clear_error() -> None:
    """TF_DEMO_BACKEND=rclpy without rclpy raises BackendError naming the fix."""
    completed = run_probe(PROBE, 'rclpy')
    assert completed.returncode != 0
    assert 'BackendError: TF_DEMO_BACKEND=rclpy but rclpy cannot be imported' in completed.stderr


@pytest.mark.standalone  # runs the DDS backend in a child process
def test_dds_world_node_api_comes_from_the_dds_backend() -> None:
    """In the DDS world Node, executors and message modules are the standalone ones."""
    code = (
        'from tf_demo.transport import executors as e, messages as m, node as n; '
        'print(n.Node.__module__, e.SingleThreadedExecutor.__module__, '
        'm.geometry_msgs.__name__, m.tf2_msgs.TFMessage.__msgtype__)'
    )
    completed = run_probe(code, 'dds')
    assert completed.returncode == 0, completed.stderr
    assert completed.stdout.split() == [
        'tf_demo.transport.dds.node',
        'tf_demo.transport.dds.executors',
        'tf_demo.msgs.geometry_msgs',
        'tf2_msgs/msg/TFMessage',
    ]


def test_run_node_reports_a_bad_backend_choice_without_traceback() -> None:
    """run_node with an unknown TF_DEMO_BACKEND exits 1 with a one-line error."""
    code = 'import sys; from tf_demo.transport import run_node; sys.exit(run_node(object, ["x"]))'
    completed = run_probe(code, 'zenoh')
    assert completed.returncode == 1
    assert "x: error: TF_DEMO_BACKEND='zenoh' is not a known backend" in completed.stderr
    assert 'Traceback' not in completed.stderr


# --------------------------------------------------------------------------------------------
# With an importable rclpy.


@pytest.fixture
def importable_rclpy(tmp_path: Path) -> Path:
    """A directory holding a package named rclpy that imports (its import is recorded)."""
    package = tmp_path / 'rclpy'
    package.mkdir()
    (package / '__init__.py').write_text('IMPORTED = True\n', encoding='utf-8')
    return tmp_path


def test_the_backend_is_resolved_once_per_process(monkeypatch: pytest.MonkeyPatch) -> None:
    """Changing TF_DEMO_BACKEND after the first answer does not switch worlds mid-process."""
    from tf_demo.transport import backend

    monkeypatch.setenv('TF_DEMO_BACKEND', 'dds')
    backend.backend_name.cache_clear()
    try:
        assert backend.backend_name() == 'dds'
        monkeypatch.setenv('TF_DEMO_BACKEND', 'zenoh')
        assert backend.backend_name() == 'dds'
        assert backend.rclpy_world() is False
    finally:
        backend.backend_name.cache_clear()


@pytest.mark.standalone  # runs the DDS backend in a child process
def test_explicit_dds_never_imports_an_installed_rclpy(importable_rclpy: Path) -> None:
    """TF_DEMO_BACKEND=dds keeps rclpy (and its signal handlers) out of the process."""
    code = (
        'import sys; import tf_demo.transport.messages, tf_demo.transport.qos, '
        'tf_demo.transport.clock, tf_demo.transport as t, tf_demo.transport.node as n; '
        "print(t.backend_name(), 'rclpy' in sys.modules, n.Node.__module__)"
    )
    completed = run_probe(code, ' DDS ', importable_rclpy)
    assert completed.returncode == 0, completed.stderr
    assert completed.stdout.split() == ['dds', 'False', 'tf_demo.transport.dds.node']
