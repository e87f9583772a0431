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
The documentation site (doc/): built as CI and a user build it, then read in a real browser.

One Sphinx run writes the HTML with warnings as errors and nitpicky references (a broken link to
tf_demo's own API fails), then the doctest builder runs every example on the site from the same
doctrees; headless chromium opens the index and the page of ``tf_demo.core.buffer_core`` and
keeps screenshots of both as test artifacts.
"""

from __future__ import annotations

from pathlib import Path
import subprocess
import sys
import time
from typing import Any

from conftest import REPO_ROOT
from conftest import save_artifact
import pytest

pytest.importorskip('sphinx', reason="the site needs the 'docs' extra (sphinx, furo, myst)")
pytest.importorskip('furo', reason="the site needs the 'docs' extra (furo)")
pytest.importorskip('myst_parser', reason="the site needs the 'docs' extra (myst-parser)")

pytestmark = pytest.mark.timeout(300)


def _sphinx(builder: str, doctrees: Path, out: Path) -> subprocess.CompletedProcess[str]:
    command = [sys.executable, '-m', 'sphinx', '-W', '--keep-going', '-n', '-q']
    command += ['-b', builder, '-d', str(doctrees), str(REPO_ROOT / 'doc'), str(out)]
    return subprocess.run(command, capture_output=True, text=True, check=False, timeout=600)


@pytest.fixture(scope='module')
def site(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """The site built into a temporary folder (HTML, then the doctests from the same doctrees)."""
    root = tmp_path_factory.mktemp('site')
    start = time.monotonic()
    html = _sphinx('html', root / 'doctrees', root / 'html')
    assert html.returncode == 0, html.stdout + html.stderr
    doctest = _sphinx('doctest', root / 'doctrees', root / 'doctest')
    assert doctest.returncode == 0, doctest.stdout + doctest.stderr
    elapsed = time.monotonic() - start
    print(f'documentation site built in {elapsed:.1f} s')  # printed, never asserted
    return root


def test_the_site_builds_without_a_warning_and_its_examples_run(site: Path) -> None:
    """Every page is there (one per executable of setup.py) and the doctests ran, none failed."""
    html = site / 'html'
    for page in ('index', 'getting_started', 'coming_from_tf2_ros', 'architecture',
                 'tf_snapshot_format', 'benchmarks', 'api/index'):  # fmt: skip
        assert (html / f'{page}.html').is_file(), page
    for executable in ('tf_echo', 'static_transform_publisher', 'robot_state_publisher'):
        assert (html / 'executables' / f'{executable}.html').is_file(), executable
    report = (site / 'doctest' / 'output.txt').read_text(encoding='utf-8')
    assert '0 failures in tests' in report, report
    assert '0 tests' not in report.splitlines()[-1], report


def _open(browser: Any, page: Path, name: str) -> str:
    """Open ``page``, keep its screenshot as the artifact ``name``; return its visible text."""
    browser.get(page.as_uri())
    save_artifact(name, browser.get_screenshot_as_png())
    return str(browser.execute_script('return document.body.innerText'))


def test_a_user_reads_the_index_and_the_api_page_in_a_browser(site: Path, browser: Any) -> None:
    """The index shows the intro and contents; the API page has lookup_transform's signature."""
    index = _open(browser, site / 'html' / 'index.html', 'docs_index.png')
    assert 'tf_demo — tf2 in typed Python' in index
    for entry in ('Getting started', 'Coming from tf2_ros and rclpy', 'API reference'):
        assert entry in index, entry
    api = _open(browser, site / 'html' / 'api' / 'tf_demo.core.buffer_core.html', 'docs_api.png')
    assert 'class tf_demo.core.buffer_core.BufferCore' in api
    assert 'lookup_transform(target: str, source: str, time_ns: int)' in api
