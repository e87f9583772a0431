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
The walk's arithmetic: compose a list of links at one time, and a route of two such lists.

tf2's ``walkToTopParent`` accumulates ``top_T_frame`` up each side of the walk and combines the
two sides at the end; :class:`~tf_demo.core.frame_tree.FrameTree` works out which links make a
route (the full walk, or a remembered :mod:`~tf_demo.core.path_plan`) and this module does the
numbers with :mod:`~tf_demo.core.math3d`'s functions: each link's sample from its cache
(:meth:`~tf_demo.core.time_cache.Link.sample_at_time`, tf2's ``findClosest`` and
``interpolate``), composed as tf2's ``TransformAccum`` does.
"""

from __future__ import annotations

from typing import Final
from typing import TYPE_CHECKING

from tf_demo.core.math3d import compose
from tf_demo.core.math3d import invert
from tf_demo.core.math3d import Quat
from tf_demo.core.math3d import Vec3

if TYPE_CHECKING:
    from collections.abc import Sequence

    from tf_demo.core.time_cache import Link

__all__ = [
    'IDENTITY',
    'ROUTE_ACROSS',
    'ROUTE_DOWN',
    'ROUTE_UP',
    'Route',
    'Transform7',
    'accumulate_links',
    'compose_route',
]

# The shapes of a route (what tf2's walk found).
#: The target is above the source (or is the top): ``top_T_source`` of the source's links.
ROUTE_UP: Final = 0
#: The source is above the target: the inverse of ``top_T_target``.
ROUTE_DOWN: Final = 1
#: Both sides meet at the top: ``(top_T_target)^-1 * top_T_source``.
ROUTE_ACROSS: Final = 2

#: ``(shape, source side links, target side links)``, each side bottom first.
Route = tuple[int, 'Sequence[Link]', 'Sequence[Link]']
#: A transform as seven floats: translation x, y, z, then rotation x, y, z, w.
Transform7 = tuple[float, float, float, float, float, float, float]
#: The identity, one shared object: a lookup tests ``is IDENTITY`` to skip canonicalising.
IDENTITY: Transform7 = (0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0)


def accumulate_links(links: Sequence[Link], time_ns: int) -> Transform7 | None:
    """
    Return ``top_T_bottom`` = ``links[-1] * ... * links[0]`` at ``time_ns``, as 7 floats.

    None when a dynamic link has no data at ``time_ns`` (0: its newest sample).
    """
    t: Vec3 = (0.0, 0.0, 0.0)
    q: Quat = (0.0, 0.0, 0.0, 1.0)
    first = True
    for link in links:
        if not link.covers(time_ns):
            return None
        lx, ly, lz, px, py, pz, pw, _ = link.sample_at_time(time_ns)
        if first:
            t = (lx, ly, lz)
            q = (px, py, pz, pw)
            first = False
        else:  # tf2's TransformAccum: link * accumulated
            t, q = compose((lx, ly, lz), (px, py, pz, pw), t, q)
    return (t[0], t[1], t[2], q[0], q[1], q[2], q[3])


def compose_route(route: Route, time_ns: int) -> Transform7 | None:
    """
    Return ``target_T_source`` along ``route`` at ``time_ns`` (raw rotation, as tf2's).

    Seven floats: the translation, then the rotation.

    None when a link of the route has no data at ``time_ns``.
    """
    shape, source_links, target_links = route
    if shape == ROUTE_UP:
        return accumulate_links(source_links, time_ns)
    target_side = accumulate_links(target_links, time_ns)
    if target_side is None:
        return None
    tx, ty, tz, tqx, tqy, tqz, tqw = target_side
    # tf2's finalize: the inverse of top_T_target, then times top_T_source.
    it, iq = invert((tx, ty, tz), (tqx, tqy, tqz, tqw))
    if shape == ROUTE_DOWN:
        return (it[0], it[1], it[2], iq[0], iq[1], iq[2], iq[3])
    source_side = accumulate_links(source_links, time_ns)
    if source_side is None:
        return None
    sx, sy, sz, sqx, sqy, sqz, sqw = source_side
    rt, rq = compose(it, iq, (sx, sy, sz), (sqx, sqy, sqz, sqw))
    return (rt[0], rt[1], rt[2], rq[0], rq[1], rq[2], rq[3])
