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
What ``tf_view`` shows, computed from a buffer: the functional core of the live view.

:func:`build_scene` turns the buffer's frames into a :class:`SceneView`: every frame's pose
relative to the fixed frame (frames of another tree relative to that tree's root, drawn at the
origin), the line to its parent, whether it is static or stale, its publishing rate and age as
tf_monitor reports them, and warnings for a split tree. :func:`tree_markdown` and
:func:`echo_markdown` write the page's tree panel and the selected frame's tf_echo numbers. The
viser shell (:mod:`tf_demo.cli.tf_view`) only draws what these return.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import NamedTuple

from tf_demo.cli._doctor_expected import rep105_advice
from tf_demo.cli._doctor_tree import islands_of
from tf_demo.cli._doctor_tree import root_of
from tf_demo.cli.formatting import format_echo_transform
from tf_demo.core.buffer_core import BufferCore
from tf_demo.core.exceptions import TransformException
from tf_demo.core.frames_format import FrameInfo
from tf_demo.core.frames_format import rate_hz
from tf_demo.core.math3d import Quat
from tf_demo.core.math3d import Vec3

#: rviz2's TF display hides frames after 15 s without data ("Frame Timeout").
DEFAULT_STALE_AFTER_S = 15.0


class FrameView(NamedTuple):
    """One frame as the view draws it."""

    name: str
    #: The parent frame, or None for a root.
    parent: str | None
    #: The root of the tree the frame belongs to.
    root: str
    #: Depth below the root (0 for a root): the tree panel's indentation.
    depth: int
    #: Pose in the fixed frame (or in ``root`` for another tree); None when tf2 has no answer.
    translation: Vec3 | None
    rotation: Quat | None
    is_static: bool
    #: Dynamic frame whose newest sample is older than the stale threshold.
    stale: bool
    #: Publishing rate (tf2's average over the cache), 0 for roots and static frames.
    rate_hz: float
    #: Seconds since the newest sample (None for roots and static frames).
    age_s: float | None


class SceneView(NamedTuple):
    """The whole view at one instant."""

    fixed_frame: str | None
    #: Frames in tree order: the fixed frame's tree first, each tree depth first by name.
    frames: tuple[FrameView, ...]
    #: The roots of the trees, the fixed frame's tree first.
    roots: tuple[str, ...]
    warnings: tuple[str, ...]
    #: The warning that the fixed frame asked for does not exist (also in ``warnings``).
    missing_fixed_frame: str | None = None


def parents_of(infos: Sequence[FrameInfo]) -> dict[str, str]:
    """Return every child frame's parent (a frame cleared of data has none)."""
    return {info.child: info.parent for info in infos if info.parent is not None}


def tree_roots(parent_of: dict[str, str], frames: Sequence[str] = ()) -> list[str]:
    """
    Return the root of every tree (island), the largest tree first (then by name).

    ``frames`` adds frames that have no parent link (each its own tree when not in another).
    """
    islands = islands_of(parent_of)
    linked = {frame for members in islands for frame in members}
    islands += [[frame] for frame in sorted(set(frames) - linked)]
    return [root_of(members[0], parent_of) for members in islands]


def _tree_order(root: str, parent_of: dict[str, str]) -> list[tuple[str, int]]:
    """Return ``(frame, depth)`` of ``root``'s tree, depth first, children by name."""
    children: dict[str, list[str]] = {}
    for frame, parent in parent_of.items():
        if frame != root:
            children.setdefault(parent, []).append(frame)
    order: list[tuple[str, int]] = []
    stack = [(root, 0)]
    seen: set[str] = set()
    while stack:
        frame, depth = stack.pop()
        if frame in seen:  # a parent loop
            continue
        seen.add(frame)
        order.append((frame, depth))
        stack.extend((child, depth + 1) for child in sorted(children.get(frame, ()), reverse=True))
    return order


def _pose(core: BufferCore, base: str, frame: str) -> tuple[Vec3 | None, Quat | None]:
    """Return ``frame``'s latest pose in ``base`` (None, None when tf2 cannot answer)."""
    if frame == base:
        return (0.0, 0.0, 0.0), (0.0, 0.0, 0.0, 1.0)
    try:
        result = core.lookup_transform(base, frame, 0)
    except TransformException:
        return None, None
    return result.translation, result.rotation


def build_scene(
    core: BufferCore,
    fixed_frame: str | None,
    now_ns: int,
    stale_after_s: float = DEFAULT_STALE_AFTER_S,
) -> SceneView:
    """
    Return the view of ``core`` at ``now_ns`` (the node's clock) from ``fixed_frame``.

    ``fixed_frame`` None or unknown picks the root of the largest tree. A frame of another tree
    is placed relative to its own root; a warning then says the tree is split.
    """
    infos = {info.child: info for info in core.frames_info()}
    parent_of = parents_of(list(infos.values()))
    roots = tree_roots(parent_of, list(infos))
    known = set(parent_of) | set(parent_of.values()) | set(infos)
    warnings: list[str] = []
    missing = None
    if fixed_frame is not None and fixed_frame not in known:
        if roots:
            missing = (
                f'Fixed frame [{fixed_frame}] does not exist: drawing from [{roots[0]}], the '
                'root of the largest tree, until it does.'
            )
            advice = rep105_advice(fixed_frame, parent_of)
            missing += f' {advice}' if advice else ''
            warnings.append(missing)
        fixed_frame = None
    if fixed_frame is None and roots:
        fixed_frame = roots[0]
    if fixed_frame is not None:
        fixed_root = root_of(fixed_frame, parent_of)
        roots.sort(key=lambda root: root != fixed_root)  # stable: the fixed frame's tree first
    if len(roots) > 1:
        warnings.append(
            f'The TF tree is split into {len(roots)} trees (islands) with roots '
            + ', '.join(f'[{root}]' for root in roots)
            + ': frames not connected to the fixed frame are drawn from their own root.'
        )
    frames: list[FrameView] = []
    for root in roots:
        base = fixed_frame if fixed_frame is not None and root == roots[0] else root
        for frame, depth in _tree_order(root, parent_of):
            translation, rotation = _pose(core, base, frame)
            timing = _timing(infos.get(frame), now_ns, stale_after_s)
            parent = parent_of.get(frame)
            frames.append(FrameView(frame, parent, root, depth, translation, rotation, *timing))
    return SceneView(fixed_frame, tuple(frames), tuple(roots), tuple(warnings), missing)


def _timing(
    info: FrameInfo | None, now_ns: int, stale_after_s: float
) -> tuple[bool, bool, float, float | None]:
    """Return ``(is_static, stale, rate_hz, age_s)`` of a frame (a root has no cache)."""
    if info is None:
        return False, False, 0.0, None
    if info.is_static:
        return True, False, 0.0, None
    age_s = (now_ns - info.newest_ns) / 1e9
    return False, age_s > stale_after_s, rate_hz(info), age_s


def _describe(frame: FrameView) -> str:
    """Return the tree panel's words after a frame's name."""
    if frame.parent is None:
        return 'root'
    if frame.is_static:
        return 'static'
    words = f'{frame.rate_hz:.1f} Hz, {frame.age_s:.2f} s old'
    return f'**stale**, {words}' if frame.stale else words


def tree_markdown(scene: SceneView) -> str:
    """Return the tree panel: the hierarchy with each frame's rate and age, as Markdown."""
    if not scene.frames:
        return 'No frames yet: waiting for /tf and /tf_static.'
    lines = [f'{"  " * frame.depth}- `{frame.name}`: {_describe(frame)}' for frame in scene.frames]
    return '\n'.join(lines)


def echo_markdown(core: BufferCore, fixed_frame: str | None, frame: str | None) -> str:
    """Return tf_echo's block for ``frame`` in ``fixed_frame`` (latest), or tf2's error."""
    if fixed_frame is None or not frame:
        return ''
    try:
        result = core.lookup_transform(fixed_frame, frame, 0)
    except TransformException as error:
        return f'`{fixed_frame}` → `{frame}`: {error}'
    sec, nanosec = divmod(result.stamp_ns, 1_000_000_000)
    block = format_echo_transform(sec, nanosec, result.translation, result.rotation)
    return f'`{fixed_frame}` → `{frame}`\n\n```\n{block}```'
