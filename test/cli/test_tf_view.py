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
tf_view in a real browser: Debian's chromium, headless, driven by selenium and chromedriver.

Real publisher processes feed a real ``tf_view`` process; the tests read the page as a user
sees it (its text, and screenshots of the WebGL canvas). Screenshots are saved under
``$TF_DEMO_ARTIFACTS`` (default ``test-artifacts/`` in the repository) for a person to look at.
"""

from __future__ import annotations

from collections.abc import Iterator
import io
import os
from pathlib import Path
import re
import time
from typing import Any

from conftest import eventually
from conftest import Processes
from conftest import ProcessOutput
import pytest

pytest.importorskip('viser', reason="tf_view needs the 'view' extra (viser)")
webdriver = pytest.importorskip('selenium.webdriver', reason='the browser tests use selenium')
Image = pytest.importorskip('PIL.Image', reason='screenshots are read with Pillow')

CHROMIUM = '/usr/bin/chromium'
CHROMEDRIVER = '/usr/bin/chromedriver'
pytestmark = [
    pytest.mark.skipif(
        not (os.path.exists(CHROMIUM) and os.path.exists(CHROMEDRIVER)),
        reason="needs Debian's chromium and chromium-driver",
    ),
    pytest.mark.timeout(180),
]
ARTIFACTS = Path(
    os.environ.get('TF_DEMO_ARTIFACTS', Path(__file__).resolve().parents[2] / 'test-artifacts')
)
# Chromium as root in a container: no sandbox, no GPU (WebGL through SwiftShader), and none
# of the background connections this machine's closed network refuses.
CHROMIUM_FLAGS = (
    '--headless=new',
    '--no-sandbox',
    '--disable-gpu',
    '--enable-unsafe-swiftshader',
    '--disable-quic',
    '--no-first-run',
    '--disable-background-networking',
    '--disable-component-update',
    '--disable-sync',
    '--window-size=1280,800',
)


@pytest.fixture
def browser(tmp_path: Path) -> Iterator[Any]:
    """A headless chromium with its own empty profile."""
    from selenium.webdriver.chrome.options import Options
    from selenium.webdriver.chrome.service import Service

    options = Options()
    options.binary_location = CHROMIUM
    for flag in (*CHROMIUM_FLAGS, f'--user-data-dir={tmp_path / "chromium"}'):
        options.add_argument(flag)
    driver = webdriver.Chrome(service=Service(CHROMEDRIVER), options=options)
    try:
        yield driver
    finally:
        driver.quit()


def start_view(spawn: Processes, *args: str) -> tuple[ProcessOutput, str]:
    """Start tf_view on a free port; return its output and the page's URL."""
    output = ProcessOutput(spawn.start('tf_view', '--port', '0', *args))
    line = output.wait_for_line('tf_view: serving on ', timeout=60)
    url = line.split()[-1]
    assert re.fullmatch(r'http://127\.0\.0\.1:\d+', url), line
    return output, url


def page_text(browser: Any) -> str:
    return str(browser.execute_script('return document.body.innerText'))


def wait_for_text(browser: Any, *needles: str, timeout: float = 30.0) -> str:
    """Return the page text once it holds every needle, else fail showing the text."""
    text = eventually(lambda: all(n in page_text(browser) for n in needles), timeout)
    current = page_text(browser)
    assert text, f'{needles} not all on the page within {timeout} s; page text: {current!r}'
    return current


def frame_line(text: str, frame: str) -> str:
    """The tree panel's line for ``frame``."""
    return next(line for line in text.splitlines() if line.strip().startswith(frame + ':'))


def choose(browser: Any, label: str, option: str) -> None:
    """Pick ``option`` in the page's dropdown called ``label`` as a user does: click, click."""
    from selenium.webdriver.common.by import By

    box = browser.find_element(
        By.XPATH, f'//label[normalize-space()="{label}"]/following::input[@role="combobox"][1]'
    )
    box.click()
    item = eventually(
        lambda: next(
            (
                e
                for e in browser.find_elements(By.CSS_SELECTOR, '[role=option]')
                if e.text == option
            ),
            None,
        ),
        10,
    )
    assert item is not None, f'no option {option!r} in the {label!r} dropdown'
    item.click()


def screenshot(browser: Any, name: str) -> Any:
    """Take a screenshot, save it as a test artifact and return it as an RGB image."""
    ARTIFACTS.mkdir(parents=True, exist_ok=True)
    data = browser.get_screenshot_as_png()
    (ARTIFACTS / f'tf_view_{name}.png').write_bytes(data)
    return Image.open(io.BytesIO(data)).convert('RGB')


def scene_region(image: Any) -> Any:
    """The 3D canvas left of the side panel (viser puts the panel at the right)."""
    width, height = image.size
    return image.crop((0, 0, int(width * 0.7), height))


def distinct_colours(image: Any) -> int:
    return len(set(image.getdata()))


def test_every_frame_is_drawn_and_camera_link_moves(spawn: Processes, browser: Any) -> None:
    """The seed's publishers: every frame named on the page, the circle moves between shots."""
    spawn.start('static_tf_pub')
    spawn.start('dynamic_tf_pub')
    _, url = start_view(spawn)
    browser.get(url)
    text = wait_for_text(browser, 'odom', 'base_link', 'camera_link', 'Hz')
    assert 'Fixed frame: odom' in text
    assert 'static' in frame_line(text, 'camera_link')
    assert 'Hz' in frame_line(text, 'base_link')
    time.sleep(2.0)  # the page has drawn a few updates
    first = scene_region(screenshot(browser, 'circle_1'))
    time.sleep(1.5)
    second = scene_region(screenshot(browser, 'circle_2'))
    assert distinct_colours(first) > 20, 'the scene is blank'
    changed = sum(1 for a, b in zip(first.getdata(), second.getdata(), strict=False) if a != b)
    assert changed > 200, f'only {changed} pixels changed while camera_link circles'


def test_a_selected_frame_shows_tf_echo_numbers(spawn: Processes, browser: Any) -> None:
    """--fixed-frame odom, camera_link static 1 m up: the echo panel prints its translation."""
    spawn.start(
        'static_transform_publisher',
        '--frame-id',
        'odom',
        '--child-frame-id',
        'camera_link',
        '--z',
        '1',
    )
    _, url = start_view(spawn, '--fixed-frame', 'odom')
    browser.get(url)
    wait_for_text(browser, 'camera_link')
    choose(browser, 'Frame', 'camera_link')
    text = wait_for_text(browser, '- Translation: [0.000, 0.000, 1.000]')
    assert '- Rotation: in Quaternion [0.000, 0.000, 0.000, 1.000]' in text


def test_a_split_tree_is_shown_with_a_warning(spawn: Processes, browser: Any) -> None:
    """Two unconnected static trees: both drawn, and the page warns that the tree is split."""
    spawn.start('static_transform_publisher', '--frame-id', 'map', '--child-frame-id', 'odom')
    spawn.start(
        'static_transform_publisher', '--frame-id', 'base_link', '--child-frame-id', 'laser'
    )
    _, url = start_view(spawn)
    browser.get(url)
    text = wait_for_text(browser, 'split into 2 trees', 'laser', 'odom')
    assert '[base_link]' in text
    assert '[map]' in text
    screenshot(browser, 'split_tree')


def test_killing_a_publisher_turns_its_frames_stale(spawn: Processes, browser: Any) -> None:
    """dynamic_tf_pub stops: base_link is marked stale after --stale-after seconds."""
    spawn.start('static_tf_pub')
    dynamic = spawn.start('dynamic_tf_pub')
    _, url = start_view(spawn, '--stale-after', '1.0')
    browser.get(url)
    text = wait_for_text(browser, 'base_link', 'Hz')
    assert 'stale' not in frame_line(text, 'base_link')
    dynamic.kill()
    dynamic.wait()
    stale = eventually(lambda: 'stale' in frame_line(page_text(browser), 'base_link'), 30)
    assert stale, page_text(browser)
    assert 'stale' not in frame_line(page_text(browser), 'camera_link')  # static stays
    screenshot(browser, 'stale')


def test_refuses_bad_options_with_one_line(spawn: Processes) -> None:
    """A rate that is not positive: one line naming the option, exit code 2."""
    process = spawn.start('tf_view', '--rate', '0')
    _, err = process.communicate(timeout=60)
    assert process.returncode == 2
    assert err.strip().endswith(
        '--rate must be a number of updates per second in (0, 1000], got 0.0'
    )
