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
tf_doctor's checks of the frame graph: separate trees, loops, REP 105 order, leading slashes.

The graph is each child's latest parent (``parent_of``). :func:`islands_of` finds the connected
trees; REP 105's chain (earth → map → odom → base_link) names the link that likely joins two of
them and who should publish it.
"""

from __future__ import annotations

from collections.abc import Sequence

from tf_demo.cli._doctor_model import Finding
from tf_demo.cli._doctor_model import format_members
from tf_demo.cli._snapshot import find_cycle

# REP 105's chain, outermost first; base_footprint may stand in for base_link.
REP105_CHAIN = ('earth', 'map', 'odom', 'base_link')
BASE_FRAMES = ('base_link', 'base_footprint')


_ODOMETRY = 'the odometry source (base driver, diff-drive controller or robot_localization)'
LINK_PUBLISHERS = {
    'map→odom': 'localization or SLAM (AMCL, slam_toolbox, robot_localization)',
    'odom→base_link': _ODOMETRY,
    'odom→base_footprint': _ODOMETRY,
    'earth→map': 'a map server or a static_transform_publisher',
}


def islands_of(parent_of: dict[str, str]) -> list[list[str]]:
    """Return the connected components of the frame graph, biggest first, members sorted."""
    neighbours: dict[str, set[str]] = {}
    for child, parent in parent_of.items():
        neighbours.setdefault(child, set()).add(parent)
        neighbours.setdefault(parent, set()).add(child)
    seen: set[str] = set()
    islands: list[list[str]] = []
    for start in sorted(neighbours):
        if start in seen:
            continue
        stack, members = [start], []
        seen.add(start)
        while stack:
            frame = stack.pop()
            members.append(frame)
            for other in neighbours[frame]:
                if other not in seen:
                    seen.add(other)
                    stack.append(other)
        islands.append(sorted(members))
    islands.sort(key=lambda members: (-len(members), members[0]))
    return islands


def ancestors(frame: str, parent_of: dict[str, str]) -> list[str]:
    """Return the parents of ``frame`` up to its root (stopping at a loop)."""
    chain: list[str] = []
    seen = {frame}
    while frame in parent_of:
        frame = parent_of[frame]
        if frame in seen:
            break
        seen.add(frame)
        chain.append(frame)
    return chain


def root_of(frame: str, parent_of: dict[str, str]) -> str:
    """Return the root of the tree ``frame`` is in."""
    chain = ancestors(frame, parent_of)
    return chain[-1] if chain else frame


def _rep105_rank(frame: str) -> int | None:
    """Return ``frame``'s place in REP 105's chain, or None outside it."""
    if frame in BASE_FRAMES:
        return REP105_CHAIN.index('base_link')
    return REP105_CHAIN.index(frame) if frame in REP105_CHAIN else None


def _missing_link(root: str, island_of: dict[str, int], own: int) -> str | None:
    """Return the REP 105 link that likely joins ``root`` to another tree, as 'a→b'."""
    rank = _rep105_rank(root)
    if rank is None:
        return None
    for candidate in reversed(REP105_CHAIN[:rank]):
        if candidate in island_of and island_of[candidate] != own:
            return f'{candidate}→{root}'
    return None


def loop(parent_of: dict[str, str]) -> list[Finding]:
    """Report a loop of parent links (tf2 cannot walk from its frames to a root)."""
    cycle = find_cycle((parent, child) for child, parent in parent_of.items())
    if cycle is None:
        return []
    return [
        Finding(
            'loop',
            'error',
            tuple(cycle[:-1]),
            f'The parent links form a loop: {" → ".join(cycle)}. tf2 cannot walk from these '
            'frames to a root, so every lookup through them fails.',
            'A loop usually means one link is published the wrong way round (child and '
            'parent swapped). Find the publisher of each link in the loop and invert or '
            'remove one of them.',
        )
    ]


def disconnected(parent_of: dict[str, str], frames: Sequence[str]) -> list[Finding]:
    """Report the separate trees, each with its root, and the likely missing links."""
    islands = islands_of(parent_of)
    if len(islands) < 2:
        return []
    island_of = {frame: index for index, members in enumerate(islands) for frame in members}
    lines = []
    links = []
    for index, members in enumerate(islands):
        root = root_of(members[0], parent_of)
        lines.append(f'tree {index + 1} (root {root}): {format_members(members)}')
        link = _missing_link(root, island_of, index)
        if link is not None:
            links.append(link)
    message = f'The frames form {len(islands)} separate trees; lookups between trees fail:\n'
    message += '\n'.join(lines)
    asked = [f for f in frames if f in island_of]
    if len({island_of[f] for f in asked}) > 1:
        message += '\nThe frames you asked about are in different trees: ' + ', '.join(
            f"'{f}' in tree {island_of[f] + 1}" for f in asked
        )
        message += '.'
    if links:
        fix = 'The likely missing link' + ('s are ' if len(links) > 1 else ' is ')
        fix += ', '.join(
            link + (f', published by {LINK_PUBLISHERS[link]}' if link in LINK_PUBLISHERS else '')
            for link in links
        )
        first_parent, first_child = links[0].split('→')
        fix += (
            '. Start that publisher, or for a fixed offset run static_transform_publisher '
            f'--frame-id {first_parent} --child-frame-id {first_child}'
        )
    else:
        roots = [root_of(members[0], parent_of) for members in islands]
        fix = (
            'Connect each tree to the main one by publishing a transform whose child is its '
            f'root ({", ".join(roots[1:])}) and whose parent is a frame of tree 1.'
        )
    return [
        Finding(
            'disconnected', 'error', tuple(root_of(m[0], parent_of) for m in islands), message, fix
        )
    ]


def rep105(parent_of: dict[str, str]) -> list[Finding]:
    """Report frames in the wrong REP 105 order (map → odom → base_link)."""
    findings = []
    present = [
        f for f in ('map', 'odom', *BASE_FRAMES) if f in parent_of or f in set(parent_of.values())
    ]
    for later in present:
        for earlier in present:
            rank_early, rank_late = _rep105_rank(earlier), _rep105_rank(later)
            if rank_early is None or rank_late is None or rank_early >= rank_late:
                continue
            if later in ancestors(earlier, parent_of):
                findings.append(
                    Finding(
                        'rep105_order',
                        'error',
                        (earlier, later),
                        f"'{earlier}' is below '{later}' in the tree; REP 105 orders them "
                        'map → odom → base_link (each frame the parent of the next).',
                        f'Publish {earlier}→{later} instead of {later}→{earlier}: invert that '
                        "transform, or set the publisher's frame parameters the other way round.",
                    )
                )
    if 'odom' in present and any(b in present for b in BASE_FRAMES) and 'map' in present:
        findings.extend(
            Finding(
                'rep105_order',
                'warning',
                ('map', 'odom', base),
                f"'{base}' hangs directly off 'map' although 'odom' exists; REP 105 "
                f'expects map → odom → {base}.',
                f'Let localization publish map→odom and odometry publish odom→{base}, '
                f'instead of one node publishing map→{base}.',
            )
            for base in BASE_FRAMES
            if parent_of.get(base) == 'map'
        )
    return findings


def leading_slashes(known: set[str]) -> list[Finding]:
    """Report frame ids that start with '/' (tf2 refuses them in lookups)."""
    slashed = sorted(frame for frame in known if frame.startswith('/'))
    if not slashed:
        return []
    return [
        Finding(
            'leading_slash',
            'error',
            tuple(slashed),
            f"Frame ids {', '.join(repr(f) for f in slashed)} start with '/'. tf2 in ROS 2 "
            'refuses such ids in lookups ("frame_ids cannot start with a \'/\'"), so nothing '
            'can be looked up through them.',
            "Drop the leading '/' where these frames are published (a ROS 1 habit): "
            f"'{slashed[0].lstrip('/')}' instead of '{slashed[0]}'.",
        )
    ]
