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

import io
import os
from pathlib import Path
import re
import time
from typing import Any

from conftest import CHROMEDRIVER
from conftest import CHROMIUM
from conftest import eventually
from conftest import Processes
from conftest import ProcessOutput
from conftest import save_artifact
import numpy as np
import pytest

pytest.importorskip('viser', reason="tf_view needs the 'view' extra (viser)")
webdriver = pytest.importorskip('selenium.webdriver', reason='the browser tests use selenium')
Image = pytest.importorskip('PIL.Image', reason='screenshots are read with Pillow')

pytestmark = [
    pytest.mark.skipif(
        not (os.path.exists(CHROMIUM) and os.path.exists(CHROMEDRIVER)),
        reason="needs Debian's chromium and chromium-driver",
    ),
    pytest.mark.timeout(180),
]
URDF = Path(__file__).resolve().parents[2] / 'urdf'


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
    data = browser.get_screenshot_as_png()
    save_artifact(f'tf_view_{name}.png', data)
    return Image.open(io.BytesIO(data)).convert('RGB')


def scene_region(image: Any) -> Any:
    """The 3D canvas left of the side panel (viser puts the panel at the right)."""
    width, height = image.size
    return image.crop((0, 0, int(width * 0.7), height))


def distinct_colours(image: Any) -> int:
    return len(np.unique(np.asarray(image).reshape(-1, 3), axis=0))


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
    changed = int((np.asarray(first) != np.asarray(second)).any(axis=2).sum())
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


def test_a_missing_fixed_frame_is_named_on_the_page_and_in_the_log(
    spawn: Processes, browser: Any
) -> None:
    """--fixed-frame map on odom→base_link: the page and the log say odom is drawn, and why."""
    spawn.start(
        'static_transform_publisher', '--frame-id', 'odom', '--child-frame-id', 'base_link'
    )
    output, url = start_view(spawn, '--fixed-frame', 'map')
    line = output.wait_for_line('Fixed frame [map] does not exist', anywhere=True)
    assert 'drawing from [odom]' in line
    assert '--frame-id map --child-frame-id odom' in line
    browser.get(url)
    text = wait_for_text(browser, 'Fixed frame [map] does not exist: drawing from [odom]')
    assert 'no localisation' in text
    assert 'Fixed frame: odom' in text


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


def set_number(browser: Any, label: str, value: float) -> None:
    """Type ``value`` into the number box of the slider called ``label`` and press Enter."""
    from selenium.webdriver.common.by import By
    from selenium.webdriver.common.keys import Keys

    box = browser.find_element(
        By.XPATH,
        f'//*[normalize-space()="{label}"]/following::input[@inputmode="decimal" or '
        '@type="number" or contains(@class, "NumberInput")][1]',
    )
    box.click()
    box.send_keys(Keys.CONTROL, 'a')
    box.send_keys(str(value), Keys.ENTER)


def echoed(echo: ProcessOutput, prefix: str, after: int = 0) -> str | None:
    """The newest tf_echo line starting with ``prefix`` among lines after index ``after``."""
    found = [line for line in echo.stdout[after:] if line.startswith(prefix)]
    return found[-1] if found else None


def test_the_fixed_urdf_puts_frame_1_one_metre_above_world(spawn: Processes, browser: Any) -> None:
    """example_fixed.urdf through robot_state_publisher: the page echoes frame_1 at z = 1."""
    spawn.start('robot_state_publisher', str(URDF / 'example_fixed.urdf'))
    _, url = start_view(spawn, '--fixed-frame', 'world')
    browser.get(url)
    wait_for_text(browser, 'frame_1', 'Robot example_fixed')
    choose(browser, 'Frame', 'frame_1')
    wait_for_text(browser, '- Translation: [0.000, 0.000, 1.000]')
    screenshot(browser, 'example_fixed')
    choose(browser, 'Fixed frame', 'frame_1')  # chosen in the page: world is now 1 m below
    text = wait_for_text(browser, 'Fixed frame: frame_1')
    choose(browser, 'Frame', 'world')
    text = wait_for_text(browser, '- Translation: [0.000, 0.000, -1.000]')
    assert '`frame_1` → `world`' in text or 'frame_1 → world' in text


def test_a_slider_moves_the_joint_for_every_listener(spawn: Processes, browser: Any) -> None:
    """
    example_revolute.urdf: frame_2 sits 1 m on from frame_1 (so at 1, 0, 1 in world); moving
    the joint's slider in the page publishes /joint_states, robot_state_publisher turns frame_2,
    and a separate tf_echo process sees the new rotation.
    """
    urdf = str(URDF / 'example_revolute.urdf')
    spawn.start('robot_state_publisher', urdf)
    _, url = start_view(spawn, '--urdf', urdf, '--publish-joint-states', '--fixed-frame', 'world')
    echo = ProcessOutput(spawn.start('tf_echo', 'world', 'frame_2', '10'))
    echo.wait_for_line('- Translation: [1.000, 0.000, 1.000]', timeout=60)
    assert echoed(echo, '- Rotation: in Quaternion') == (
        '- Rotation: in Quaternion [0.000, 0.000, 0.000, 1.000]'
    )
    browser.get(url)
    wait_for_text(browser, 'frame_1_to_frame_2', 'frame_2')
    choose(browser, 'Frame', 'frame_2')  # the page shows frame_2 one metre on, one metre up
    wait_for_text(browser, '- Translation: [1.000, 0.000, 1.000]')
    screenshot(browser, 'revolute_0')
    before = len(echo.stdout)
    set_number(browser, 'frame_1_to_frame_2', 1.5708)
    turned = eventually(
        lambda: (
            echoed(echo, '- Rotation: in Quaternion', before)
            == '- Rotation: in Quaternion [0.000, 0.000, 0.707, 0.707]'
        ),
        30,
    )
    assert turned, echo.stdout[before:][-8:]
    assert echoed(echo, '- Translation:', before) == '- Translation: [1.000, 0.000, 1.000]'
    screenshot(browser, 'revolute_90')


def test_center_and_randomize_buttons_move_every_joint(spawn: Processes, browser: Any) -> None:
    """Randomize turns frame_2 for a separate listener; Center brings it back to 0."""
    from selenium.webdriver.common.by import By

    urdf = str(URDF / 'example_revolute.urdf')
    spawn.start('robot_state_publisher', urdf)
    _, url = start_view(spawn, '--urdf', urdf, '--publish-joint-states')
    echo = ProcessOutput(spawn.start('tf_echo', 'world', 'frame_2', '10'))
    identity = '- Rotation: in Quaternion [0.000, 0.000, 0.000, 1.000]'
    echo.wait_for_line(identity, timeout=60)
    browser.get(url)
    wait_for_text(browser, 'Randomize')

    def click(text: str) -> None:
        browser.find_element(By.XPATH, f'//button[normalize-space()="{text}"]').click()

    before = len(echo.stdout)
    click('Randomize')
    moved = eventually(
        lambda: echoed(echo, '- Rotation: in Quaternion', before) not in (None, identity), 30
    )
    assert moved, echo.stdout[before:][-8:]
    before = len(echo.stdout)
    click('Center')
    assert eventually(lambda: echoed(echo, '- Rotation: in Quaternion', before) == identity, 30)


def test_mimic_joints_follow_their_leader_without_a_slider() -> None:
    """A mimic joint gets no slider; /joint_states carries it as multiplier * leader + offset."""
    from tf_demo.cli.tf_view import RobotPanel
    from tf_demo.urdf import RobotModel
    import viser

    limit = '<limit lower="-1" upper="1" effort="1" velocity="1"/>'
    model = RobotModel.from_string(
        '<robot name="m"><link name="a"/><link name="b"/><link name="c"/>'
        f'<joint name="lead" type="revolute"><parent link="a"/><child link="b"/>{limit}</joint>'
        '<joint name="follow" type="revolute"><parent link="b"/><child link="c"/>'
        f'{limit}<mimic joint="lead" multiplier="2" offset="0.5"/></joint></robot>'
    )
    server = viser.ViserServer(host='127.0.0.1', port=0, verbose=False)
    try:
        panel = RobotPanel(server, publish=True)
        panel.set_robot(model, None)
        assert panel.table is not None
        assert list(panel.table.free_joints) == ['lead']
        panel.table.free_joints['lead'].position = 0.25
        names, positions, _, _ = panel.table.message_fields() or ([], [], [], [])
        assert dict(zip(names, positions, strict=True)) == {'lead': 0.25, 'follow': 1.0}
        panel.randomize()
        lead = panel.table.free_joints['lead'].position
        assert lead is not None
        assert -1.0 <= lead <= 1.0
        panel.center()
        assert panel.table.free_joints['lead'].position == 0.0
    finally:
        server.stop()


def test_refuses_bad_options_with_one_line(spawn: Processes) -> None:
    """A rate that is not positive: one line naming the option, exit code 2."""
    process = spawn.start('tf_view', '--update-rate', '0')
    _, err = process.communicate(timeout=60)
    assert process.returncode == 2
    assert err.strip().endswith(
        '--update-rate must be a number of updates per second in (0, 1000], got 0.0'
    )
