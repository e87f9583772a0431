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
``tf_saver``: save the live tf tree (or the part between chosen frames) to a snapshot file.

Usage::

    tf_saver [-t SECONDS] [-o FILE] [FRAME ...] [--flatten]

Without frames it saves every transform of the tree (the newest value of each parent→child
link). With frames it saves the links that connect them (the chains from the first frame to each
other one). ``--flatten`` instead saves each further frame directly relative to the first one
(one composed transform per frame, looked up at the latest common time). The file format is
documented in :mod:`tf_demo.cli._snapshot` and ``doc/tf_snapshot_format.md``; ``tf_loader``
republishes it. The file is written atomically and only when everything asked for was found.
"""

from __future__ import annotations

import argparse
from collections.abc import Sequence
import math
import sys

from tf_demo.cli._args import wait_time_error
from tf_demo.cli._live import listen
from tf_demo.cli._live import TfRecorder
from tf_demo.cli._live import tool_main
from tf_demo.cli._live import ToolError
from tf_demo.cli._observations import buffer_from_observations
from tf_demo.cli._observations import Observation
from tf_demo.cli._observations import TF_STATIC_TOPIC
from tf_demo.cli._snapshot import Snapshot
from tf_demo.cli._snapshot import SnapshotTransform
from tf_demo.cli._snapshot import write_snapshot
from tf_demo.core.files import output_path_error
from tf_demo.core.files import OutputFileError
from tf_demo.core.math3d import quat_normalize

TOOL = 'tf_saver'


def build_parser() -> argparse.ArgumentParser:
    """Return tf_saver's argument parser."""
    parser = argparse.ArgumentParser(
        prog=TOOL, description='Save tf transforms from a live system into a YAML snapshot.'
    )
    parser.add_argument('frames', nargs='*', metavar='FRAME', help='frames to save (default all)')
    parser.add_argument('-t', '--wait-time', type=float, default=2.0, help='seconds to listen')
    parser.add_argument('-o', '--output', default='tf_snapshot.yaml', help='file to write')
    parser.add_argument(
        '--flatten',
        action='store_true',
        help='save each frame directly relative to the first frame',
    )
    return parser


def latest_links(observations: Sequence[Observation]) -> dict[str, SnapshotTransform]:
    """
    Return the newest parent→child link per child, with its rate and sample count.

    Quaternions are normalized, as tf2 does on insert; transforms tf2 would ignore (NaN, empty
    or equal frame ids, zero quaternion) are skipped, so the file always loads again.
    """
    newest: dict[str, tuple[int, SnapshotTransform]] = {}
    stamps: dict[str, set[int]] = {}
    for observation in sorted(observations, key=lambda o: o.receive_ns):
        is_static = observation.topic == TF_STATIC_TOPIC
        for t in observation.transforms:
            usable = all(math.isfinite(v) for v in (*t.translation, *t.rotation))
            if not usable or not t.parent or not t.child or t.parent == t.child:
                continue  # tf2 ignores these too (TF_NAN_INPUT, TF_SELF_TRANSFORM, ...)
            try:
                rotation = quat_normalize(t.rotation)
            except ValueError:
                continue
            stamps.setdefault(t.child, set()).add(t.stamp_ns)
            previous = newest.get(t.child)
            if previous is not None and not is_static and t.stamp_ns < previous[0]:
                continue
            newest[t.child] = (
                t.stamp_ns,
                SnapshotTransform(
                    t.parent, t.child, t.translation, rotation, is_static, t.stamp_ns
                ),
            )
    links: dict[str, SnapshotTransform] = {}
    for child, (_, link) in newest.items():
        seen = sorted(stamps[child])
        rate = None
        if not link.is_static and len(seen) > 1 and seen[-1] > seen[0]:
            rate = round((len(seen) - 1) / ((seen[-1] - seen[0]) / 1e9), 3)
        links[child] = SnapshotTransform(
            link.parent,
            link.child,
            link.translation,
            link.rotation,
            link.is_static,
            None if link.is_static else link.stamp_ns,
            None,
            rate,
            len(seen) if not link.is_static else None,
        )
    return links


def _ancestors(frame: str, links: dict[str, SnapshotTransform]) -> list[str]:
    chain = [frame]
    while chain[-1] in links and links[chain[-1]].parent not in chain:
        chain.append(links[chain[-1]].parent)
    return chain


def select_links(
    links: dict[str, SnapshotTransform], frames: Sequence[str]
) -> list[SnapshotTransform]:
    """Return the links joining ``frames`` (all links when empty), parents before children."""
    known = set(links) | {link.parent for link in links.values()}
    missing = [f for f in frames if f not in known]
    if missing:
        msg = f'no transforms for frame(s) {", ".join(missing)} were received'
        raise ToolError(msg)
    chosen: set[str] = set(links) if not frames else set()
    if frames:
        first_chain = _ancestors(frames[0], links)
        for frame in frames[1:]:
            chain = _ancestors(frame, links)
            common = next((f for f in chain if f in first_chain), None)
            if common is None:
                msg = f"frames '{frames[0]}' and '{frame}' are not connected"
                raise ToolError(msg)
            chosen.update(chain[: chain.index(common)])
            chosen.update(first_chain[: first_chain.index(common)])
    depth = {child: len(_ancestors(child, links)) for child in chosen}
    return [links[child] for child in sorted(chosen, key=lambda c: (depth[c], c))]


def flatten(observations: Sequence[Observation], frames: Sequence[str]) -> list[SnapshotTransform]:
    """Return each of ``frames[1:]`` composed directly relative to ``frames[0]``."""
    from tf_demo.core.exceptions import TransformException

    if len(frames) < 2:
        msg = '--flatten needs at least two frames: the reference frame and one more'
        raise ToolError(msg)
    core = buffer_from_observations(observations)
    result = []
    for frame in frames[1:]:
        try:
            found = core.lookup_transform(frames[0], frame, 0)
        except TransformException as error:
            msg = f'cannot save {frames[0]}→{frame}: {error}'
            raise ToolError(msg) from None
        result.append(
            SnapshotTransform(
                frames[0], frame, found.translation, found.rotation, True, found.stamp_ns or None
            )
        )
    return result


def _record_and_save(options: argparse.Namespace) -> int:
    from tf_demo import transport

    node = transport.create_node(TOOL)
    try:
        recorder = TfRecorder(node)
        listen(node, options.wait_time)
        observations = recorder.observations()
        if not any(o.transforms for o in observations):
            msg = f'no transforms received on /tf or /tf_static in {options.wait_time:g} s'
            raise ToolError(msg)
        if options.flatten:
            entries = flatten(observations, options.frames)
        else:
            entries = select_links(latest_links(observations), options.frames)
        snapshot = Snapshot(
            transforms=tuple(entries), recorded_at_ns=node.get_clock().now().nanoseconds
        )
        try:
            write_snapshot(options.output, snapshot)
        except OutputFileError as error:
            raise ToolError(str(error)) from None
        node.get_logger().info(f'Saved {len(entries)} transforms to {options.output}')
        return 0
    finally:
        node.destroy_node()


def options_error(options: argparse.Namespace) -> str | None:
    """Return why parsed ``options`` cannot run (checked before listening), else None."""
    return wait_time_error(options.wait_time) or output_path_error(options.output)


def main(args: list[str] | None = None) -> int:
    """Run tf_saver with ``args`` (default: ``sys.argv[1:]``)."""
    return tool_main(
        TOOL, args, build_parser(), options_error=options_error, live=_record_and_save
    )


if __name__ == '__main__':
    sys.exit(main())
