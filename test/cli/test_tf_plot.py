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
tf_plot: plot files that show the data, from bags written with rosbags and from a live network.

The pictures are checked by their pixels (PNG, read back with Pillow) and their text (SVG keeps
its text as text): the curves' colours where the data is, the failure shading where tf2 failed
and nowhere else, and tf2's error in the legend.
"""

from __future__ import annotations

import math
from pathlib import Path
import subprocess
import sys
from typing import Any
from xml.etree import ElementTree

from conftest import save_artifact
import numpy as np
import pytest
from tf_demo.cli import tf_plot
from tf_demo.nodes.dynamic_tf_pub import circle_transform
from tf_demo.testing.bags import SECOND
from tf_demo.testing.bags import tf_bytes
from tf_demo.testing.bags import transform
from tf_demo.testing.bags import write_bag

pytest.importorskip('rosbags.rosbag2', reason="tf_plot needs the 'bag' extra")
pytest.importorskip('matplotlib', reason="tf_plot needs the 'bag' extra")
Image = pytest.importorskip('PIL.Image', reason='the pixel checks need pillow')

T0 = 1_700_000_000 * SECOND
X_BLUE = (0x1F, 0x77, 0xB4)  # the x curve and the path
FAILURE_RED_ON_WHITE = (247, 214, 215)  # #d62728 at alpha 0.18 over white


def circle_bag(path: Path, storage: str = 'mcap', seconds: int = 5, end_s: int = 8) -> Path:
    """The seed's circle for ``seconds`` s at 20 Hz, and a static recorded at ``end_s``."""
    messages = []
    for k in range(seconds * 20 + 1):
        stamp = T0 + k * SECOND // 20
        (x, y, z), q = circle_transform(1.0, stamp)
        yaw = 2.0 * math.atan2(q[2], q[3])
        messages.append(
            ('/tf', stamp, tf_bytes(transform('odom', 'base_link', stamp, (x, y, z), yaw)))
        )
    static = transform('map', 'odom', T0, (1.0, 2.0, 0.0))
    messages.append(('/tf_static', T0 + end_s * SECOND, tf_bytes(static)))
    return write_bag(path, storage, messages)


def pixels_near(image: Any, colour: tuple[int, int, int], box: tuple[int, int, int, int]) -> int:
    """Count the pixels in ``box`` (left, top, right, bottom) within 12 of ``colour``."""
    region = np.asarray(image.convert('RGB').crop(box), dtype=np.int16)
    return int((np.abs(region - np.array(colour)).max(axis=2) <= 12).sum())


def run(*args: str) -> int:
    return tf_plot.main(list(args))


def test_a_png_shows_the_circle_and_shades_where_the_publisher_stopped(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    bag = circle_bag(tmp_path / 'circle')
    output = tmp_path / 'plot.png'
    assert run('map', 'base_link', '--bag', str(bag), '-o', str(output)) == 0
    out = capsys.readouterr().out
    assert f'wrote {output}: 401 samples of map -> base_link, 150 failed in 1 span(s)' in out
    assert '5.020 s to 8.000 s: ExtrapolationException: Lookup would require extrapolation' in out
    save_artifact('tf_plot_circle_stopped.png', output.read_bytes())
    image = Image.open(output)
    width, height = image.size
    assert (width, height) == (1300, 750)
    time_plots = (0, 0, int(width * 0.62), height)
    path_plot = (int(width * 0.63), 0, width, height)
    assert pixels_near(image, X_BLUE, path_plot) > 300  # the circle
    assert pixels_near(image, X_BLUE, time_plots) > 300  # x over time
    shaded = pixels_near(image, FAILURE_RED_ON_WHITE, time_plots)
    assert shaded > 10_000  # 3 of the 8 seconds, in both time plots
    assert pixels_near(image, FAILURE_RED_ON_WHITE, path_plot) < 100  # legend swatch at most


def test_a_recording_without_failures_has_no_shading(tmp_path: Path) -> None:
    bag = circle_bag(tmp_path / 'circle', 'sqlite3', seconds=5, end_s=5)
    output = tmp_path / 'plot.png'
    assert run('map', 'base_link', '--bag', str(bag), '-o', str(output)) == 0
    image = Image.open(output)
    # only the antialiased rim of the red 'last pose' marker comes near the shading's colour
    assert pixels_near(image, FAILURE_RED_ON_WHITE, (0, 0, *image.size)) < 150
    assert pixels_near(image, X_BLUE, (0, 0, *image.size)) > 600


def test_an_svg_names_tf2s_error_and_the_frames(tmp_path: Path) -> None:
    bag = circle_bag(tmp_path / 'circle')
    output = tmp_path / 'plot.svg'
    assert run('map', 'base_link', '--bag', str(bag), '-o', str(output), '--rate', '10') == 0
    root = ElementTree.parse(output).getroot()
    texts = {
        ''.join(element.itertext()) for element in root.iter('{http://www.w3.org/2000/svg}text')
    }
    assert 'ExtrapolationException: Lookup would require extrapolation into the future' in texts
    assert 'base_link in map: position' in texts
    assert any(
        text.startswith('tf_plot map base_link') and '10 samples/s' in text for text in texts
    )


@pytest.mark.parametrize(
    ('arguments', 'error'),
    [
        (['a', 'b', '-o', 'p.png'], 'give either --bag PATH or --duration S'),
        (['a', 'b', '--bag', 'x', '--duration', '1', '-o', 'p.png'], 'give either'),
        (['a', 'b', '--bag', 'x', '-o', 'p.jpg'], 'p.jpg: the plot file must end in .png or .svg'),
        (['a', 'b', '--bag', 'x', '-o', '/'], '/: the plot file must end in .png or .svg'),
        (['a', 'b', '--duration', '-1', '-o', 'p.png'], '--duration must be a positive number'),
        (['a', 'b', '--duration', 'nan', '-o', 'p.png'], '--duration must be a positive number'),
        (['a', 'b', '--bag', 'x', '--rate', '0', '-o', 'p.png'], '--rate must be a positive'),
    ],
)
def test_wrong_arguments_give_one_line_and_exit_2(
    arguments: list[str], error: str, capsys: pytest.CaptureFixture[str]
) -> None:
    assert run(*arguments) == 2
    stderr = capsys.readouterr().err
    assert stderr.startswith('tf_plot: error: ')
    assert error in stderr
    assert stderr.count('\n') == 1


def test_bad_bags_and_outputs_give_one_line_and_exit_1(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    garbage = tmp_path / 'garbage.mcap'
    garbage.write_bytes(b'\x89MCAP0\r\n' + b'\xff' * 64)
    bag = circle_bag(tmp_path / 'circle')
    png = str(tmp_path / 'p.png')
    cases = [
        (['--bag', str(tmp_path / 'none'), '-o', png], 'no such bag'),
        (['--bag', str(garbage), '-o', png], str(garbage)),
        (['--bag', str(bag), '-o', str(tmp_path / 'no' / 'p.png')], 'cannot write'),
        (['--bag', str(bag), '--rate', '1e9', '-o', png], 'ask for a lower rate'),
    ]
    for arguments, error in cases:
        assert run('a', 'b', *arguments) == 1, arguments
        stderr = capsys.readouterr().err
        assert error in stderr, stderr
        assert stderr.count('\n') == 1, stderr
    assert not (tmp_path / 'p.png').exists()


@pytest.mark.dds
@pytest.mark.usefixtures('ros')
def test_live_plot_of_dynamic_tf_pub(spawn: Any, tmp_path: Path) -> None:
    """Three seconds of the running circle (both worlds): exit 0 and the curve in the PNG."""
    spawn.start('static_tf_pub')
    spawn.start('dynamic_tf_pub')
    output = tmp_path / 'live.png'
    process = spawn.start('tf_plot', 'odom', 'base_link', '--duration', '3', '-o', str(output))
    stdout, stderr = process.communicate(timeout=120)
    assert process.returncode == 0, stderr
    assert f'tf_plot: wrote {output}: ' in stdout
    samples = int(stdout.split(': ')[2].split()[0])
    assert samples >= 140  # 3 s at 50 per second
    save_artifact('tf_plot_live.png', output.read_bytes())
    image = Image.open(output)
    assert pixels_near(image, X_BLUE, (int(image.size[0] * 0.63), 0, *image.size)) > 100


def test_the_executable_is_installed() -> None:
    """``tf_plot --help`` runs as an installed console script would."""
    completed = subprocess.run(
        [sys.executable, '-m', 'tf_demo.cli.tf_plot', '--help'],
        capture_output=True, text=True, check=False, timeout=60,
    )  # fmt: skip
    assert completed.returncode == 0
    assert completed.stdout.startswith('usage: tf_plot [-h] -o OUTPUT')


@pytest.mark.dds
@pytest.mark.usefixtures('ros')
def test_live_plot_in_sim_time_samples_the_played_bags_clock(spawn: Any, tmp_path: Path) -> None:
    """``tf_play --clock`` + ``use_sim_time:=true``: the span is the bag's time, not 0 to now."""
    bag = circle_bag(tmp_path / 'circle.mcap', seconds=60, end_s=61)
    spawn.start('tf_play', str(bag), '--clock')
    output = tmp_path / 'sim.png'
    process = spawn.start(
        'tf_plot', 'odom', 'base_link', '--duration', '3', '-o', str(output),
        '--ros-args', '-p', 'use_sim_time:=true',
    )  # fmt: skip
    stdout, stderr = process.communicate(timeout=120)
    assert process.returncode == 0, stderr
    samples, failed = (int(stdout.split(': ')[2].split()[i]) for i in (0, 6))
    assert 50 <= samples <= 160, stdout  # about 3 s of the bag's clock at 50 per second
    assert failed <= samples // 4, stdout
    assert 'hint' not in stdout, stdout


@pytest.mark.dds
@pytest.mark.usefixtures('ros')
def test_live_plot_of_a_bag_played_without_clock_says_why(spawn: Any, tmp_path: Path) -> None:
    """Old stamps and the wall clock: every sample fails, and tf_plot says why and what to do."""
    bag = circle_bag(tmp_path / 'circle.mcap', seconds=60, end_s=61)
    spawn.start('tf_play', str(bag))
    output = tmp_path / 'wall.png'
    process = spawn.start('tf_plot', 'odom', 'base_link', '--duration', '3', '-o', str(output))
    stdout, stderr = process.communicate(timeout=120)
    assert process.returncode == 0, stderr
    assert 'tf_plot: hint: every lookup asked for a time later than the newest data' in stdout
    assert 'tf_play --clock' in stdout
    assert 'use_sim_time:=true' in stdout
