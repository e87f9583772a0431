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
Drive tf2's C++ core through its Python binding ``tf2_py`` over a JSON-lines protocol.

Two flavours of the same core: Debian's ROS 1 Noetic ``tf2_py`` (run this file with
``/usr/bin/python3``, the interpreter that can ``import tf2_py`` and ``rospy``), and ROS 2
Jazzy's own ``tf2_py`` (run it with ``--ros2`` under a sourced Jazzy, where its times are
``builtin_interfaces`` messages).  It is not part of the package and never runs under the
project's standalone virtual environment.

Protocol: every input line is a JSON array of scenarios; for each line exactly one output line is
written, a JSON array with one entry per scenario, each a list with one result per operation.
A scenario is ``{"cache_time_ns": int, "ops": [op, ...]}``; the operations are:

``["set", parent, child, stamp_ns, [tx, ty, tz], [qx, qy, qz, qw], authority, is_static]``
    insert; result ``null`` (``tf2_py`` returns nothing).
``["clear"]``
    result ``null``.
``["lookup", target, source, time_ns]`` and
``["lookup_full", target, target_time_ns, source, source_time_ns, fixed]``
    result ``{"t": [3], "q": [4], "stamp": ns}`` or ``{"exc": class name, "msg": text}``.
``["can", target, source, time_ns]`` and ``["can_full", target, tt, source, st, fixed]``
    result ``{"ok": bool, "msg": text}``; ``can`` adds ``"exists": [bool, bool]`` for its
    target and source (``_frameExists``).
``["velocity", tracking, observation, time_ns, averaging_ns]`` (Jazzy only)
    result ``{"linear": [3], "angular": [3]}`` (``lookupVelocityCore``) or an exception object.
``["lct", target, source]``
    result ``{"stamp": ns}`` or an exception object.
``["chain", target, target_time_ns, source, source_time_ns, fixed]``
    result ``{"frames": [...]}`` or an exception object.
``["dot", current_time_ns]``
    ``{"text": _allFramesAsDot(current_time)}``.
``["string"]``, ``["yaml"]`` and ``["frames"]``
    ``{"text": all_frames_as_string()}``, ``{"text": all_frames_as_yaml()}`` and
    ``{"frames": every frame name in id order}``.
``["time_lookups", target, source, [time_ns, ...]]``
    one simple lookup per stamp, timed; result ``{"seconds": total wall time}`` (benchmarks).

A line ``"quit"`` (the JSON string) ends the process.  tf2's console warnings are discarded.
"""

import json
import os
import sys
import time
from typing import Any

from geometry_msgs.msg import TransformStamped
import tf2_py

_NS_PER_S = 1_000_000_000

if '--ros2' in sys.argv[1:]:
    from builtin_interfaces.msg import Duration as _DurationMsg
    from builtin_interfaces.msg import Time as _TimeMsg

    def _time(ns: int) -> Any:
        """Build a ``builtin_interfaces/Time`` from integer nanoseconds."""
        return _TimeMsg(sec=ns // _NS_PER_S, nanosec=ns % _NS_PER_S)

    def _duration(ns: int) -> Any:
        """Build a ``builtin_interfaces/Duration`` from integer nanoseconds."""
        return _DurationMsg(sec=ns // _NS_PER_S, nanosec=ns % _NS_PER_S)

    def _nanoseconds(stamp: Any) -> int:
        """Return a ``builtin_interfaces/Time`` (or an ``rclpy`` ``Time``) as nanoseconds."""
        if hasattr(stamp, 'nanoseconds'):  # get_latest_common_time answers an rclpy Time
            return int(stamp.nanoseconds)
        return int(stamp.sec) * _NS_PER_S + int(stamp.nanosec)

else:
    import rospy  # type: ignore[import-not-found]

    def _time(ns: int) -> Any:
        """Build a ``rospy.Time`` from integer nanoseconds."""
        return rospy.Time(ns // _NS_PER_S, ns % _NS_PER_S)

    def _duration(ns: int) -> Any:
        """Build a ``rospy.Duration`` from integer nanoseconds."""
        return rospy.Duration(ns // _NS_PER_S, ns % _NS_PER_S)

    def _nanoseconds(stamp: Any) -> int:
        """Return a ``rospy.Time`` as integer nanoseconds."""
        return int(stamp.to_nsec())


def _message(op: list[Any]) -> Any:
    """Build the ``TransformStamped`` of a ``set`` operation."""
    _, parent, child, stamp_ns, translation, rotation, _, _ = op
    msg = TransformStamped()
    msg.header.frame_id = parent
    msg.child_frame_id = child
    msg.header.stamp = _time(stamp_ns)
    msg.transform.translation.x, msg.transform.translation.y, msg.transform.translation.z = (
        translation
    )
    rot = msg.transform.rotation
    rot.x, rot.y, rot.z, rot.w = rotation
    return msg


def _transform_result(msg: Any) -> dict[str, Any]:
    """Encode a looked-up ``TransformStamped``."""
    tr = msg.transform.translation
    rot = msg.transform.rotation
    return {
        't': [tr.x, tr.y, tr.z],
        'q': [rot.x, rot.y, rot.z, rot.w],
        'stamp': _nanoseconds(msg.header.stamp),
    }


def _error(exc: Exception) -> dict[str, str]:
    """Encode an exception raised by ``tf2_py``."""
    return {'exc': type(exc).__name__, 'msg': str(exc)}


def _run_op(buffer: Any, op: list[Any]) -> dict[str, Any] | None:
    """Apply one operation to ``buffer`` and return its encoded result."""
    kind = op[0]
    if kind == 'set':
        msg = _message(op)
        if op[7]:
            buffer.set_transform_static(msg, op[6])
        else:
            buffer.set_transform(msg, op[6])
        return None
    if kind == 'clear':
        buffer.clear()
        return None
    if kind == 'can':
        ok, msg = buffer.can_transform_core(op[1], op[2], _time(op[3]))
        exists = [bool(buffer._frameExists(name)) for name in (op[1], op[2])]
        return {'ok': bool(ok), 'msg': msg, 'exists': exists}
    if kind == 'can_full':
        ok, msg = buffer.can_transform_full_core(op[1], _time(op[2]), op[3], _time(op[4]), op[5])
        return {'ok': bool(ok), 'msg': msg}
    if kind == 'string':
        return {'text': buffer.all_frames_as_string()}
    if kind == 'yaml':
        return {'text': buffer.all_frames_as_yaml()}
    if kind == 'dot':
        return {'text': buffer._allFramesAsDot(_time(op[1]))}
    if kind == 'frames':
        return {'frames': list(buffer._getFrameStrings())}
    if kind == 'time_lookups':
        lookup = buffer.lookup_transform_core
        times = [_time(ns) for ns in op[3]]
        start = time.perf_counter()
        for stamp in times:
            lookup(op[1], op[2], stamp)
        return {'seconds': time.perf_counter() - start}
    try:
        if kind == 'lookup':
            return _transform_result(buffer.lookup_transform_core(op[1], op[2], _time(op[3])))
        if kind == 'lookup_full':
            return _transform_result(
                buffer.lookup_transform_full_core(op[1], _time(op[2]), op[3], _time(op[4]), op[5])
            )
        if kind == 'velocity':
            linear, angular = buffer.lookupVelocityCore(
                op[1], op[2], _time(op[3]), _duration(op[4])
            )
            return {'linear': list(linear), 'angular': list(angular)}
        if kind == 'lct':
            return {'stamp': _nanoseconds(buffer.get_latest_common_time(op[1], op[2]))}
        if kind == 'chain':
            return {'frames': list(buffer._chain(op[1], _time(op[2]), op[3], _time(op[4]), op[5]))}
    except tf2_py.TransformException as exc:
        return _error(exc)
    return {'exc': 'ProtocolError', 'msg': f'unknown operation {kind!r}'}


def run_scenario(scenario: dict[str, Any]) -> list[dict[str, Any] | None]:
    """Run one scenario on a fresh ``BufferCore`` and return the per-operation results."""
    cache_time_ns = scenario.get('cache_time_ns', 10_000_000_000)
    buffer = tf2_py.BufferCore(_duration(cache_time_ns))
    return [_run_op(buffer, op) for op in scenario['ops']]


def main() -> None:
    """Serve scenario batches on stdin/stdout until EOF or ``"quit"``."""
    # tf2's C++ warnings (TF_REPEATED_DATA, ...) are written to file descriptor 2; silence them
    # but keep Python's own tracebacks visible on the original stderr.
    sys.stderr = os.fdopen(os.dup(2), 'w')
    devnull = os.open(os.devnull, os.O_WRONLY)
    os.dup2(devnull, 2)
    out = sys.stdout
    for line in sys.stdin:
        request = json.loads(line)
        if request == 'quit':
            break
        if request == 'ping':
            out.write(json.dumps('pong') + '\n')
        else:
            out.write(json.dumps([run_scenario(scenario) for scenario in request]) + '\n')
        out.flush()


if __name__ == '__main__':
    main()
