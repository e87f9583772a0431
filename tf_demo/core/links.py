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
numbers.  :func:`accumulate_links` inlines :meth:`TimeCache.get_data
<tf_demo.core.time_cache.TimeCache.get_data>` (tf2's ``findClosest`` and ``interpolate``) and the
composition: per link only locals, no tuple per link.  The inlined lerp, slerp and composition are
copies of :mod:`~tf_demo.core.math3d`'s, kept for speed and pinned to it (within 1e-12) by
``test/core/test_math3d_inlined.py``.
"""

from __future__ import annotations

from bisect import bisect_right
import math
from typing import TYPE_CHECKING

from tf_demo.core import math3d

if TYPE_CHECKING:
    from collections.abc import Sequence

    from tf_demo.core.time_cache import StaticCache
    from tf_demo.core.time_cache import TimeCache

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
ROUTE_UP = 0
#: The source is above the target: the inverse of ``top_T_target``.
ROUTE_DOWN = 1
#: Both sides meet at the top: ``(top_T_target)^-1 * top_T_source``.
ROUTE_ACROSS = 2

#: ``(shape, source side links, target side links)``, each side bottom first.
Route = tuple[int, 'Sequence[TimeCache | StaticCache]', 'Sequence[TimeCache | StaticCache]']
#: A transform as seven floats: translation x, y, z, then rotation x, y, z, w.
Transform7 = tuple[float, float, float, float, float, float, float]
#: The identity, one shared object: a lookup tests ``is IDENTITY`` to skip canonicalising.
IDENTITY: Transform7 = (0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0)

_bisect_right = bisect_right
_sin = math.sin
_cos = math.cos


def accumulate_links(links: Sequence[TimeCache | StaticCache], time_ns: int) -> Transform7 | None:
    """
    Return ``top_T_bottom`` = ``links[-1] * ... * links[0]`` at ``time_ns``, as 7 floats.

    None when a dynamic link has no data at ``time_ns`` (0: its newest sample).
    """
    x = y = z = qx = qy = qz = 0.0
    qw = 1.0
    sin = _sin
    cos = _cos
    for depth, cache in enumerate(links):
        if cache.is_static:
            lx, ly, lz, px, py, pz, pw, _ = cache._sample
        else:
            view = cache._view
            if view is None:
                view = cache.view()
            earliest, latest, scale, start, last, stamps, samples, intervals = view
            if not (earliest < time_ns < latest and time_ns):
                # At an end of the history, time 0 (the newest sample), or no data.
                if start > last:
                    return None
                if time_ns == latest or not time_ns:
                    lx, ly, lz, px, py, pz, pw, _ = samples[last] or cache.sample_at(last)
                elif time_ns == earliest:
                    lx, ly, lz, px, py, pz, pw, _ = samples[start] or cache.sample_at(start)
                else:
                    return None
            else:
                # Interior: a linear guess (exact for evenly spaced streams), else bisect.
                index = start + int((time_ns - earliest) * scale)
                if index >= last:
                    index = last - 1
                one_stamp = stamps[index]
                if one_stamp <= time_ns:
                    two_stamp = stamps[index + 1]
                    if two_stamp <= time_ns:
                        index = _bisect_right(stamps, time_ns, index + 2, last + 1) - 1
                        one_stamp = stamps[index]
                        two_stamp = stamps[index + 1]
                else:
                    index = _bisect_right(stamps, time_ns, start, index) - 1
                    one_stamp = stamps[index]
                    two_stamp = stamps[index + 1]
                lx, ly, lz, px, py, pz, pw, _ = samples[index] or cache.sample_at(index)
                theta, dx, dy, dz, bx, by, bz, bw = intervals[index] or cache.interval_at(index)
                if theta >= 0.0:  # negative: a parent change, the older sample as it is
                    # tf2's interpolate: lerp the translation, slerp the rotation.
                    ratio = (time_ns - one_stamp) / (two_stamp - one_stamp)
                    lx += ratio * dx
                    ly += ratio * dy
                    lz += ratio * dz
                    if theta:
                        angle = ratio * theta
                        c = cos(angle)
                        s = sin(angle)
                        px = px * c + bx * s
                        py = py * c + by * s
                        pz = pz * c + bz * s
                        pw = pw * c + bw * s
        if depth:
            # link * acc.  p' = R(q) p + t with v + 2w(u x v) + 2u x (u x v): fewer operations
            # than tf2's q * v * conj(q), equal to about 1e-16.
            ux = 2.0 * (py * z - pz * y)
            uy = 2.0 * (pz * x - px * z)
            uz = 2.0 * (px * y - py * x)
            x, y, z = (
                x + pw * ux + (py * uz - pz * uy) + lx,
                y + pw * uy + (pz * ux - px * uz) + ly,
                z + pw * uz + (px * uy - py * ux) + lz,
            )
            qx, qy, qz, qw = (
                pw * qx + px * qw + py * qz - pz * qy,
                pw * qy + py * qw + pz * qx - px * qz,
                pw * qz + pz * qw + px * qy - py * qx,
                pw * qw - px * qx - py * qy - pz * qz,
            )
        else:
            x, y, z, qx, qy, qz, qw = lx, ly, lz, px, py, pz, pw
    return x, y, z, qx, qy, qz, qw


def compose_route(route: Route, time_ns: int) -> Transform7 | None:
    """
    Return ``target_T_source`` along ``route`` at ``time_ns`` (raw rotation, as tf2's).

    Seven floats: the translation, then the rotation.

    None when a link of the route has no data at ``time_ns``.
    """
    shape, source_links, target_links = route
    if shape != ROUTE_UP:
        target_side = accumulate_links(target_links, time_ns)
        if target_side is None:
            return None
        tx, ty, tz, tqx, tqy, tqz, tqw = target_side
    if shape == ROUTE_UP:
        return accumulate_links(source_links, time_ns)
    iq = (-tqx, -tqy, -tqz, tqw)
    ix, iy, iz = math3d.rotate_vector(iq, (-tx, -ty, -tz))
    if shape == ROUTE_DOWN:
        return ix, iy, iz, -tqx, -tqy, -tqz, tqw
    source_side = accumulate_links(source_links, time_ns)
    if source_side is None:
        return None
    sx, sy, sz, sqx, sqy, sqz, sqw = source_side
    rx, ry, rz = math3d.rotate_vector(iq, (sx, sy, sz))
    return (rx + ix, ry + iy, rz + iz, *math3d.quat_multiply(iq, (sqx, sqy, sqz, sqw)))
