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
The robot model tf_view draws: a description's visuals as triangle meshes in their links.

Boxes, cylinders (along z, as URDF has them) and spheres are built with trimesh; mesh files are
found as robot_state_publisher's users expect (``package://``, ``file://``, or relative to the
description) and loaded with trimesh. A visual that cannot be built is left out with one line
saying why; the rest of the robot is still drawn. Each mesh is placed in its link; tf_view puts
the link where TF says it is, as rviz2's RobotModel display does.
"""

from __future__ import annotations

from collections.abc import Sequence
import logging
from pathlib import Path
from typing import NamedTuple
from typing import TYPE_CHECKING

from tf_demo.core.lazy_import import lazy_module
from tf_demo.core.math3d import quat_from_rpy
from tf_demo.core.math3d import Vec3
from tf_demo.urdf import resolve_resource
from tf_demo.urdf import Visual

if TYPE_CHECKING:
    import numpy as np
    import numpy.typing as npt
    import trimesh
else:
    np = lazy_module('numpy')
    trimesh = lazy_module('trimesh')

#: rviz2's colour for a visual without a material.
DEFAULT_RGB = (204, 204, 204)
#: Largest mesh file read (a description could name anything).
MAX_MESH_BYTES = 64 * 1024 * 1024


class VisualMesh(NamedTuple):
    """One visual as triangles in its link's frame."""

    link: str
    position: Vec3
    #: Rotation in the link, (w, x, y, z) as viser takes it.
    wxyz: tuple[float, float, float, float]
    vertices: npt.NDArray[np.float32]
    faces: npt.NDArray[np.int32]
    rgb: tuple[int, int, int]
    opacity: float


Triangles = tuple['npt.NDArray[np.float32]', 'npt.NDArray[np.int32]']


def _triangles(mesh: object) -> Triangles:
    """Return a trimesh mesh's vertices and faces as viser takes them."""
    vertices = np.asarray(getattr(mesh, 'vertices', ()), dtype=np.float32).reshape(-1, 3)
    faces = np.asarray(getattr(mesh, 'faces', ()), dtype=np.int32).reshape(-1, 3)
    return vertices, faces


def _shape_triangles(visual: Visual, base_dir: Path | None) -> Triangles:
    """Return the visual's geometry as triangles (a mesh file's own scale applied)."""
    if visual.shape == 'box':
        return _triangles(trimesh.creation.box(extents=visual.size))
    if visual.shape == 'cylinder':
        radius, length = visual.size
        return _triangles(trimesh.creation.cylinder(radius=radius, height=length, sections=32))
    if visual.shape == 'sphere':
        return _triangles(trimesh.creation.icosphere(subdivisions=3, radius=visual.size[0]))
    path = resolve_resource(visual.filename or '', base_dir)
    if not path.is_file():
        msg = f'mesh file {path} does not exist'
        raise ValueError(msg)
    if path.stat().st_size > MAX_MESH_BYTES:
        msg = f'mesh file {path} is larger than {MAX_MESH_BYTES} bytes'
        raise ValueError(msg)
    logging.getLogger('trimesh').setLevel(logging.ERROR)  # its fallbacks are not our users' news
    vertices, faces = _triangles(trimesh.load(path, force='mesh'))
    if len(faces) == 0:
        msg = f'mesh file {path} holds no triangles trimesh can read'
        raise ValueError(msg)
    return vertices * np.asarray(visual.size, dtype=np.float32), faces


def visual_meshes(
    visuals: Sequence[Visual], base_dir: str | Path | None = None
) -> tuple[list[VisualMesh], list[str]]:
    """Return the meshes of ``visuals`` and one line for each visual that could not be built."""
    meshes: list[VisualMesh] = []
    problems: list[str] = []
    folder = Path(base_dir) if base_dir is not None else None
    for visual in visuals:
        try:
            vertices, faces = _shape_triangles(visual, folder)
        except Exception as error:
            problems.append(f"link '{visual.link}' <visual> {visual.shape}: {error}")
            continue
        x, y, z, w = quat_from_rpy(*visual.rpy)
        rgba = visual.rgba or (*(c / 255 for c in DEFAULT_RGB), 1.0)
        rgb = (round(rgba[0] * 255), round(rgba[1] * 255), round(rgba[2] * 255))
        meshes.append(
            VisualMesh(
                visual.link,
                visual.xyz,
                (w, x, y, z),
                vertices,
                faces,
                rgb,
                float(rgba[3]),
            )
        )
    return meshes, problems
