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

"""tf_view's robot model: URDF visuals as triangle meshes, in the right size, place and colour."""

from __future__ import annotations

import math
from pathlib import Path

import pytest
from tf_demo.cli._view_robot import DEFAULT_RGB
from tf_demo.cli._view_robot import visual_meshes
from tf_demo.urdf import parse_robot
from tf_demo.urdf import Visual

pytest.importorskip('trimesh', reason="tf_view's robot model needs the 'view' extra (trimesh)")

REPO = Path(__file__).resolve().parents[2]


def extents(vertices) -> tuple[float, ...]:
    return tuple(
        round(float(hi - lo), 6) for lo, hi in zip(vertices.min(0), vertices.max(0), strict=True)
    )


def test_primitives_have_urdf_sizes_and_axes():
    """A box is size x y z; a cylinder's length runs along z, as URDF's do; a sphere 2r across."""
    visuals = [
        Visual('a', (0.1, 0.2, 0.3), (0.0, 0.0, math.pi / 2), 'box', (0.4, 0.25, 0.1)),
        Visual(
            'b', (0.0, 0.0, 0.0), (0.0, 0.0, 0.0), 'cylinder', (0.05, 0.5), rgba=(1, 0, 0, 0.5)
        ),
        Visual('c', (0.0, 0.0, 0.0), (0.0, 0.0, 0.0), 'sphere', (0.2,)),
    ]
    meshes, problems = visual_meshes(visuals)
    assert problems == []
    box, cylinder, sphere = meshes
    assert extents(box.vertices) == (0.4, 0.25, 0.1)
    assert box.position == (0.1, 0.2, 0.3)
    w, x, y, z = box.wxyz
    assert (round(w, 12), x, y, round(z, 12)) == (
        round(math.sqrt(0.5), 12),
        0.0,
        0.0,
        round(math.sqrt(0.5), 12),
    )
    assert box.rgb == DEFAULT_RGB
    assert extents(cylinder.vertices)[2] == 0.5
    assert abs(extents(cylinder.vertices)[0] - 0.1) < 1e-6
    assert (cylinder.rgb, cylinder.opacity) == ((255, 0, 0), 0.5)
    assert all(abs(e - 0.4) < 1e-6 for e in extents(sphere.vertices))
    assert sphere.faces.max() < len(sphere.vertices)


def test_mesh_files_resolve_relative_package_and_file(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
):
    """An STL is found next to the description, through package:// and file://, and scaled."""
    trimesh = pytest.importorskip('trimesh')
    share = tmp_path / 'my_robot' / 'meshes'
    share.mkdir(parents=True)
    trimesh.creation.box(extents=(1.0, 2.0, 3.0)).export(share / 'part.stl')
    monkeypatch.setenv('TF_DEMO_PACKAGE_PATH', str(tmp_path))
    names = [
        'meshes/part.stl',
        'package://my_robot/meshes/part.stl',
        f'file://{share / "part.stl"}',
    ]
    visuals = [Visual('l', (0, 0, 0), (0, 0, 0), 'mesh', (0.5, 0.5, 0.5), n) for n in names]
    meshes, problems = visual_meshes(visuals, tmp_path / 'my_robot')
    assert problems == []
    assert [extents(m.vertices) for m in meshes] == [(0.5, 1.0, 1.5)] * 3


def test_collada_meshes_load(tmp_path: Path):
    """A .dae (the format of most ROS robots' visual meshes) is read through pycollada."""
    trimesh = pytest.importorskip('trimesh')
    pytest.importorskip('collada', reason="pycollada comes with the 'view' extra")
    trimesh.creation.box(extents=(1.0, 2.0, 3.0)).export(tmp_path / 'part.dae')
    meshes, problems = visual_meshes(
        [Visual('l', (0, 0, 0), (0, 0, 0), 'mesh', (1, 1, 1), 'part.dae')], tmp_path
    )
    assert problems == []
    assert extents(meshes[0].vertices) == (1.0, 2.0, 3.0)


def test_unreadable_meshes_are_named_and_the_rest_is_drawn(tmp_path: Path):
    """Missing, corrupt and unknown-scheme meshes: one line each; the box is still drawn."""
    (tmp_path / 'corrupt.stl').write_bytes(b'solid nothing\n\x00\xff garbage')
    visuals = [
        Visual('gone', (0, 0, 0), (0, 0, 0), 'mesh', (1, 1, 1), 'missing.dae'),
        Visual('bad', (0, 0, 0), (0, 0, 0), 'mesh', (1, 1, 1), 'corrupt.stl'),
        Visual('web', (0, 0, 0), (0, 0, 0), 'mesh', (1, 1, 1), 'http://example.com/x.stl'),
        Visual('nopkg', (0, 0, 0), (0, 0, 0), 'mesh', (1, 1, 1), 'package://no_such_pkg/x.stl'),
        Visual('ok', (0, 0, 0), (0, 0, 0), 'box', (1, 1, 1)),
    ]
    meshes, problems = visual_meshes(visuals, tmp_path)
    assert [m.link for m in meshes] == ['ok']
    assert len(problems) == 4
    assert problems[0].startswith("link 'gone' <visual> mesh: mesh file ")
    assert 'missing.dae does not exist' in problems[0]
    assert problems[1].startswith("link 'bad' <visual> mesh: ")
    assert 'only package://, file:// and plain paths' in problems[2]
    assert "package 'no_such_pkg' not found" in problems[3]


def test_the_course_robot_is_drawn_from_its_xacro():
    """mobile_robot.urdf.xacro: a body box, two wheels, a lidar and a camera."""
    from tf_demo.urdf import read_description

    description = parse_robot(read_description(str(REPO / 'urdf' / 'mobile_robot.urdf.xacro')))
    meshes, problems = visual_meshes(description.visuals)
    assert problems == []
    assert [m.link for m in meshes] == [
        'base_link',
        'left_wheel_link',
        'right_wheel_link',
        'lidar_link',
        'camera_link',
    ]
