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
The rules of ``tf_relay`` (pure): which namespaces, how frame names are prefixed, the statics kept.

A namespace ``/fleet/robot1`` is relayed from ``/fleet/robot1/tf`` and ``/fleet/robot1/tf_static``
with its frames named ``fleet/robot1/<frame>`` (robot_state_publisher's ``frame_prefix``
convention), except a frame already so named and the shared frames (``map``, ``world``, ``earth``
by default), which every robot uses as they are. The global namespace ``/`` is refused: its
topics are the relay's own output. :class:`StaticUnion` keeps every robot's static transforms as
tf2's ``StaticTransformBroadcaster`` keeps a node's: one per child frame, the latest replacing.
"""

from __future__ import annotations

from collections.abc import Iterable
from collections.abc import Sequence

__all__ = [
    'DEFAULT_SHARED_FRAMES',
    'FramePrefixer',
    'RelayConfigError',
    'StaticUnion',
    'check_shared_frames',
    'frame_prefix',
    'relay_namespaces',
]

#: Frames every robot shares, left unprefixed: REP-105's world-fixed frames.
DEFAULT_SHARED_FRAMES = ('map', 'world', 'earth')

#: ``(parent, child, stamp_ns, translation, rotation)``, as :mod:`tf_demo.msgs.cdr` decodes.
Transform = tuple[str, str, int, tuple[float, float, float], tuple[float, float, float, float]]


class RelayConfigError(ValueError):
    """A namespace or shared frame ``tf_relay`` cannot use; the message is one line."""


def relay_namespaces(given: Iterable[str]) -> tuple[str, ...]:
    """
    Return the absolute namespaces to relay (``robot1`` is ``/robot1``), in the order given.

    The names' characters are rmw's to check (``validate_namespace`` of the transport).

    :raises RelayConfigError: none given, one given twice, or the global namespace ``/``
        (whose ``/tf`` is the relay's own output: relaying it would loop).
    """
    result: list[str] = []
    for text in given:
        namespace = text if text.startswith('/') else '/' + text
        if namespace == '/':
            msg = (
                f'namespace {text!r} is the global one: /tf and /tf_static are where tf_relay '
                'publishes, so relaying them would loop'
            )
            raise RelayConfigError(msg)
        if namespace in result:
            msg = f'namespace {namespace} is given twice'
            raise RelayConfigError(msg)
        result.append(namespace)
    if not result:
        msg = 'no namespace to relay: give them as arguments (tf_relay /robot1 /robot2 ...)'
        raise RelayConfigError(msg + " or in the 'namespaces' parameter")
    return tuple(result)


def check_shared_frames(frames: Iterable[str]) -> frozenset[str]:
    """
    Return the shared frames as a set.

    :raises RelayConfigError: an empty name or one starting with ``/`` (tf2 refuses both).
    """
    result = set()
    for frame in frames:
        if not frame or frame.startswith('/'):
            msg = f'shared frame {frame!r} is not a tf2 frame name (empty or starting with /)'
            raise RelayConfigError(msg)
        result.add(frame)
    return frozenset(result)


def frame_prefix(namespace: str) -> str:
    """Return the frame prefix of an absolute namespace: ``/fleet/robot1`` -> ``fleet/robot1/``."""
    return namespace.strip('/') + '/'


class FramePrefixer:
    """Name one namespace's frames in the merged tree (results remembered: names repeat)."""

    #: Names remembered, then all forgotten (a bound on what a hostile writer can make us keep).
    MAX_NAMES = 4096

    def __init__(self, namespace: str, shared_frames: Iterable[str]) -> None:
        """Prefix frames of ``namespace`` with :func:`frame_prefix` except ``shared_frames``."""
        self.prefix = frame_prefix(namespace)
        self.shared = frozenset(shared_frames)
        self._names: dict[str, str] = {}

    def __call__(self, frame: str) -> str:
        """Return ``frame`` as the merged tree names it."""
        name = self._names.get(frame)
        if name is None:
            if frame in self.shared or frame.startswith(self.prefix):
                name = frame
            else:
                name = self.prefix + frame
            if len(self._names) >= self.MAX_NAMES:
                self._names.clear()
            self._names[frame] = name
        return name


class StaticUnion:
    """Every static transform relayed so far, one per child frame (tf2's static broadcaster)."""

    def __init__(self) -> None:
        """Start empty."""
        self._by_child: dict[str, Transform] = {}

    def update(self, transforms: Sequence[Transform]) -> bool:
        """Add ``transforms``, each replacing its child frame's; return whether any changed."""
        changed = False
        by_child = self._by_child
        for transform in transforms:
            if by_child.get(transform[1]) != transform:
                by_child[transform[1]] = transform
                changed = True
        return changed

    def transforms(self) -> list[Transform]:
        """Return the union, in the order child frames first arrived."""
        return list(self._by_child.values())

    def __len__(self) -> int:
        """Return how many child frames the union holds."""
        return len(self._by_child)
