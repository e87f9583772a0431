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
``TransformListener``: subscribes to ``/tf`` and ``/tf_static`` and fills a :class:`Buffer`.

Compatible with tf2_ros's Python listener (plus rolling's ``tf_topic``/``tf_static_topic`` and
``static_only``). Two fixes over Jazzy:

- ``spin_thread=True`` spins **only the listener's own subscriptions**: they live on a private
  internal node served by a private single-threaded executor on a daemon thread (as C++ does
  with its hidden node), so the user's node keeps its own executor and callbacks, and the buffer
  is marked as fed by a dedicated thread, which makes blocking waits safe everywhere.
- a transform the buffer rejects (NaN, empty frame id, ...) is logged and skipped; the rest of
  the message is still used;
- bad samples cannot flood the log: the first malformed sample or rejected transform of each
  writer is logged in full, the following ones as a count every few seconds (see
  :mod:`tf_demo.msgs.log_throttle`). The standalone world names the writer by its GUID; rclpy
  (Jazzy) does not tell a subscription who wrote a sample, so there the count is per topic;
- in the standalone world the subscriptions take the serialised bytes and decode them straight
  into the buffer's core (no message objects), which is the listener's hot path.

The authority recorded for each transform is ``'default_authority'``, as in tf2_ros Python.
"""

from __future__ import annotations

import contextlib
import threading
from typing import Any

from tf_demo.msgs.log_throttle import PerWriterThrottle

DEFAULT_TF_TOPIC = '/tf'
DEFAULT_STATIC_TF_TOPIC = '/tf_static'
DEFAULT_AUTHORITY = 'default_authority'
SPIN_STOP_CHECK_S = 0.1
"""How long the private executor blocks per ``spin_once`` before checking for shutdown."""


def _dynamic_listener_qos() -> Any:
    from tf_demo.transport.qos import DynamicListenerQoS

    return DynamicListenerQoS()


def _static_listener_qos() -> Any:
    from tf_demo.transport.qos import StaticListenerQoS

    return StaticListenerQoS()


class TransformListener:
    """Feeds a buffer from ``/tf`` and ``/tf_static``."""

    def __init__(
        self,
        buffer: Any,
        node: Any,
        *,
        spin_thread: bool = False,
        qos: Any = None,
        static_qos: Any = None,
        tf_topic: str = DEFAULT_TF_TOPIC,
        tf_static_topic: str = DEFAULT_STATIC_TF_TOPIC,
        static_only: bool = False,
    ) -> None:
        """
        Create the subscriptions.

        :param buffer: the :class:`~tf_demo.ros.Buffer` to fill.
        :param node: the user's node (rclpy or tf_demo). With ``spin_thread=False`` the
            subscriptions are created on it and its executor delivers the data.
        :param spin_thread: subscribe on a private internal node spun by a private thread
            instead, so data arrives whatever the user's executor is doing.
        :param qos: ``/tf`` QoS profile or depth (default: KEEP_LAST 100, RELIABLE, VOLATILE).
        :param static_qos: ``/tf_static`` QoS profile or depth (default: KEEP_LAST 100,
            RELIABLE, TRANSIENT_LOCAL; an int depth gives a VOLATILE profile, as in rclpy).
        :param tf_topic: topic of dynamic transforms.
        :param tf_static_topic: topic of static transforms.
        :param static_only: subscribe to ``tf_static_topic`` only.
        """
        self.buffer = buffer
        self.node = node
        self._stop = threading.Event()
        self._executor: Any = None
        self._private_node: Any = None
        self.dedicated_listener_thread: threading.Thread | None = None
        self._malformed = PerWriterThrottle('malformed samples')
        self._set_log_source = getattr(buffer, 'set_log_source', None)
        self._tf_topic = tf_topic
        self._tf_static_topic = tf_static_topic
        host = node
        if spin_thread:
            host = self._private_node = _create_private_node(
                f'transform_listener_impl_{id(self):x}'
            )
        group = _reentrant_callback_group()
        extra: dict[str, Any] = {} if group is None else {'callback_group': group}
        self.raw_decoding = _can_decode_raw(host, buffer)
        if self.raw_decoding:
            extra['raw'] = True
            from tf_demo.core.buffer_core import BufferCore
            from tf_demo.msgs import cdr

            self._decode_transforms = cdr.decode_tf_message_transforms
            self._decode_error = cdr.CdrError
            self._core_insert = BufferCore.set_transform
        from tf_demo.transport.messages import tf2_msgs

        self.tf_sub: Any = None
        if not static_only:
            self.tf_sub = host.create_subscription(
                tf2_msgs.TFMessage,
                tf_topic,
                self._raw_callback if self.raw_decoding else self.callback,
                _dynamic_listener_qos() if qos is None else qos,
                **extra,
            )
        self.tf_static_sub: Any = host.create_subscription(
            tf2_msgs.TFMessage,
            tf_static_topic,
            self._raw_static_callback if self.raw_decoding else self.static_callback,
            _static_listener_qos() if static_qos is None else static_qos,
            **extra,
        )
        if spin_thread:
            self._start_spin_thread()

    def _start_spin_thread(self) -> None:
        from tf_demo.transport.executors import SingleThreadedExecutor

        self._executor = SingleThreadedExecutor()
        self._executor.add_node(self._private_node)
        setter = getattr(self.buffer, 'set_using_dedicated_thread', None)
        if setter is not None:
            setter(True)
        self.dedicated_listener_thread = threading.Thread(
            target=self._spin, name='tf_demo_transform_listener', daemon=True
        )
        self.dedicated_listener_thread.start()

    def _spin(self) -> None:
        from tf_demo.transport import ok

        while not self._stop.is_set() and ok():
            try:
                self._executor.spin_once(timeout_sec=SPIN_STOP_CHECK_S)
            except Exception:
                if self._stop.is_set() or not ok():
                    return
                raise

    def callback(self, data: Any) -> None:
        """Insert every transform of a ``/tf`` message."""
        self._insert_all(data, f"a writer on '{self._tf_topic}'", is_static=False)

    def static_callback(self, data: Any) -> None:
        """Insert every transform of a ``/tf_static`` message."""
        self._insert_all(data, f"a writer on '{self._tf_static_topic}'", is_static=True)

    def _raw_callback(self, data: bytes, info: dict[str, Any]) -> None:
        self._insert_raw(data, info['publisher_gid'], is_static=False)

    def _raw_static_callback(self, data: bytes, info: dict[str, Any]) -> None:
        self._insert_raw(data, info['publisher_gid'], is_static=True)

    def _insert_raw(self, data: bytes, writer: bytes, *, is_static: bool) -> None:
        """Decode serialised TFMessage bytes straight into the core (no message objects)."""
        buffer = self.buffer
        buffer.note_feeder_thread()
        try:
            transforms = self._decode_transforms(data)
        except self._decode_error as error:
            self._log_throttled(writer, f'Dropping a malformed TFMessage: {error}')
            return
        insert = self._core_insert
        buffer.set_log_source(writer)
        try:
            for parent, child, stamp_ns, translation, rotation in transforms:
                try:
                    insert(
                        buffer,
                        parent,
                        child,
                        stamp_ns,
                        translation,
                        rotation,
                        DEFAULT_AUTHORITY,
                        is_static,
                    )
                except Exception as error:
                    self._log_insert_failure(writer, parent, child, error)
        finally:
            buffer.set_log_source(None)

    def _insert_all(self, data: Any, writer: str, *, is_static: bool) -> None:
        note = getattr(self.buffer, 'note_feeder_thread', None)
        if note is not None:
            note()
        insert = self.buffer.set_transform_static if is_static else self.buffer.set_transform
        set_source = self._set_log_source
        if set_source is not None:
            set_source(writer)
        try:
            for transform in data.transforms:
                try:
                    insert(transform, DEFAULT_AUTHORITY)
                except Exception as error:
                    self._log_insert_failure(
                        writer,
                        getattr(getattr(transform, 'header', None), 'frame_id', '?'),
                        getattr(transform, 'child_frame_id', '?'),
                        error,
                    )
        finally:
            if set_source is not None:
                set_source(None)

    def _log_insert_failure(
        self, writer: bytes | str, parent: str, child: str, error: Exception
    ) -> None:
        self._log_throttled(
            writer,
            f'Failure to set received transform from {child} to {parent} with error: {error}',
            'set_transform',
        )

    def _log_throttled(self, writer: bytes | str, text: str, kind: str = '') -> None:
        """Log ``text`` if it is the first of its writer (and kind), else count it."""
        line = self._malformed.line(writer, text, kind)
        if line is not None:
            self.node.get_logger().error(line)

    def _log_pending(self) -> None:
        """Log the counts of bad samples not reported yet (at unregister)."""
        lines = self._malformed.pending()
        log_pending = getattr(self.buffer, 'log_pending_rejections', None)
        if log_pending is not None:
            log_pending()
        for line in lines:
            _quietly(lambda text=line: self.node.get_logger().error(text))

    def unregister(self) -> None:
        """Stop the private thread (if any) and destroy the subscriptions."""
        self._stop.set()
        thread = self.dedicated_listener_thread
        if thread is not None and thread is not threading.current_thread():
            thread.join(timeout=5.0)
        self.dedicated_listener_thread = None
        self._log_pending()
        host = self._private_node if self._private_node is not None else self.node
        for sub in (self.tf_sub, self.tf_static_sub):
            if sub is not None:
                host.destroy_subscription(sub)
        self.tf_sub = None
        self.tf_static_sub = None
        if self._executor is not None:
            _quietly(self._executor.shutdown)
            self._executor = None
        if self._private_node is not None:
            _quietly(self._private_node.destroy_node)
            self._private_node = None


def _can_decode_raw(host: Any, buffer: Any) -> bool:
    """
    Whether to take serialised bytes: a tf_demo buffer on a node that declares the capability.

    The standalone node class carries ``supports_raw_subscriptions = True``; rclpy's lacks it.
    """
    from tf_demo.ros.buffer import Buffer

    return isinstance(buffer, Buffer) and (
        getattr(type(host), 'supports_raw_subscriptions', False) is True
    )


def _create_private_node(name: str) -> Any:
    from tf_demo.transport import create_node

    try:
        return create_node(name, start_parameter_services=False, enable_rosout=False)
    except TypeError:
        return create_node(name)


def _reentrant_callback_group() -> Any:
    from tf_demo import transport

    group_type = getattr(transport, 'ReentrantCallbackGroup', None)
    return None if group_type is None else group_type()


def _quietly(action: Any) -> None:
    with contextlib.suppress(Exception):  # teardown is best effort
        action()
