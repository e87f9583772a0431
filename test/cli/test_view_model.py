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

"""tf_view's model: trees, the fixed frame, poses, staleness, the tree panel and the echo."""

from __future__ import annotations

import math

from tf_demo.cli._view_model import build_scene
from tf_demo.cli._view_model import echo_markdown
from tf_demo.cli._view_model import tree_markdown
from tf_demo.cli.formatting import format_echo_transform
from tf_demo.core import BufferCore
from tf_demo.core import math3d

SECOND = 1_000_000_000
T0 = 1_700_000_000 * SECOND
IDENTITY = (0.0, 0.0, 0.0, 1.0)


def quiet(level: int, text: str) -> None:
    del level, text


def two_frames_and_a_circle() -> BufferCore:
    """world -> frame_1 (static, 1 m up) -> frame_2 (dynamic, 1 m on, 10 Hz for 1 s)."""
    core = BufferCore(10 * SECOND, log=quiet)
    core.set_transform('world', 'frame_1', 0, (0.0, 0.0, 1.0), IDENTITY, 'test', True)
    for k in range(11):
        core.set_transform(
            'frame_1', 'frame_2', T0 + k * SECOND // 10, (1.0, 0.0, 0.0), IDENTITY, 'test', False
        )
    return core


def test_frames_are_placed_in_the_root_of_the_largest_tree_by_default():
    """No fixed frame: world (the only root); frame_2 sits 1 m on from frame_1, 1 m above."""
    scene = build_scene(two_frames_and_a_circle(), None, T0 + SECOND)
    assert scene.fixed_frame == 'world'
    assert [(f.name, f.parent, f.depth) for f in scene.frames] == [
        ('world', None, 0),
        ('frame_1', 'world', 1),
        ('frame_2', 'frame_1', 2),
    ]
    poses = {f.name: f.translation for f in scene.frames}
    assert poses == {
        'world': (0.0, 0.0, 0.0),
        'frame_1': (0.0, 0.0, 1.0),
        'frame_2': (1.0, 0.0, 1.0),
    }
    assert scene.warnings == ()


def test_a_chosen_fixed_frame_matches_tf2_lookups():
    """From frame_2, every pose is lookup_transform(frame_2, frame, latest)."""
    core = BufferCore(10 * SECOND, log=quiet)
    core.set_transform('map', 'odom', 0, (1.0, 2.0, 0.0), (0.0, 0.0, 0.6, 0.8), 'test', True)
    core.set_transform('odom', 'base', T0, (0.5, 0.0, 0.1), (0.1, 0.2, 0.3, 0.9), 'test', False)
    scene = build_scene(core, 'base', T0)
    assert scene.fixed_frame == 'base'
    for frame in scene.frames:
        expected = core.lookup_transform('base', frame.name, 0)
        assert frame.translation is not None
        assert frame.rotation is not None
        assert math.dist(frame.translation, expected.translation) < 1e-12
        assert math.dist(frame.rotation, math3d.canonical_quat(expected.rotation)) < 1e-12


def test_a_split_tree_warns_and_draws_islands_from_their_own_root():
    """map -> odom and a separate base_link -> laser: two roots, a warning naming both."""
    core = BufferCore(10 * SECOND, log=quiet)
    core.set_transform('map', 'odom', 0, (1.0, 0.0, 0.0), IDENTITY, 'test', True)
    core.set_transform('odom', 'base', 0, (1.0, 0.0, 0.0), IDENTITY, 'test', True)
    core.set_transform('base_link', 'laser', 0, (0.0, 0.0, 0.5), IDENTITY, 'test', True)
    scene = build_scene(core, None, T0)
    assert scene.roots == ('map', 'base_link')
    assert any('split into 2 trees' in w and '[base_link]' in w for w in scene.warnings)
    laser = next(f for f in scene.frames if f.name == 'laser')
    assert laser.root == 'base_link'
    assert laser.translation == (0.0, 0.0, 0.5)
    fixed_on_island = build_scene(core, 'laser', T0)
    assert fixed_on_island.roots == ('base_link', 'map')
    assert next(f for f in fixed_on_island.frames if f.name == 'base_link').translation == (
        0.0,
        0.0,
        -0.5,
    )


def test_an_unknown_fixed_frame_falls_back_with_a_warning():
    scene = build_scene(two_frames_and_a_circle(), 'nowhere', T0)
    assert scene.fixed_frame == 'world'
    assert scene.warnings == (
        'Fixed frame [nowhere] does not exist: drawing from [world], the root of the largest '
        'tree, until it does.',
    )
    assert scene.missing_fixed_frame == scene.warnings[0]


def test_a_missing_map_says_what_is_drawn_instead_and_why():
    """--fixed-frame map on odom→base_link: the warning names odom, the cause and the command."""
    core = BufferCore(10 * SECOND, log=quiet)
    core.set_transform('odom', 'base_link', T0, (1.0, 0.0, 0.0), IDENTITY, 'test', False)
    scene = build_scene(core, 'map', T0)
    assert scene.fixed_frame == 'odom'
    assert scene.missing_fixed_frame is not None
    assert scene.missing_fixed_frame.startswith(
        'Fixed frame [map] does not exist: drawing from [odom]'
    )
    assert 'no localisation' in scene.missing_fixed_frame
    assert (
        'ros2 run tf_demo static_transform_publisher --frame-id map --child-frame-id odom'
        in scene.missing_fixed_frame
    )


def test_stale_rate_and_age():
    """frame_2 (10 Hz) is stale 20 s after its newest sample with the default threshold."""
    core = two_frames_and_a_circle()
    fresh = {f.name: f for f in build_scene(core, None, T0 + SECOND).frames}
    assert not fresh['frame_2'].stale
    assert fresh['frame_2'].age_s == 0.0
    assert abs(fresh['frame_2'].rate_hz - 11.0) < 1e-9  # tf2's rate: 11 samples over 1 s
    assert fresh['frame_1'].is_static
    assert fresh['frame_1'].age_s is None
    late = {f.name: f for f in build_scene(core, None, T0 + 21 * SECOND).frames}
    assert late['frame_2'].stale
    assert not late['frame_1'].stale  # static frames never go stale
    assert {f.name: f for f in build_scene(core, None, T0 + 3 * SECOND, 1.0).frames}[
        'frame_2'
    ].stale


def test_tree_panel_lists_every_frame_with_its_rate_and_age():
    text = tree_markdown(build_scene(two_frames_and_a_circle(), None, T0 + 2 * SECOND, 0.5))
    assert text.splitlines() == [
        '- `world`: root',
        '  - `frame_1`: static',
        '    - `frame_2`: **stale**, 11.0 Hz, 1.00 s old',
    ]
    assert 'waiting' in tree_markdown(build_scene(BufferCore(log=quiet), None, T0))


def test_echo_is_tf_echos_block_or_tf2s_error():
    core = two_frames_and_a_circle()
    latest = core.lookup_transform('world', 'frame_2', 0)
    block = format_echo_transform(
        latest.stamp_ns // SECOND, latest.stamp_ns % SECOND, latest.translation, latest.rotation
    )
    assert block in echo_markdown(core, 'world', 'frame_2')
    assert '"nowhere" passed to lookupTransform argument source_frame does not exist' in (
        echo_markdown(core, 'world', 'nowhere')
    )
    assert echo_markdown(core, 'world', None) == ''
