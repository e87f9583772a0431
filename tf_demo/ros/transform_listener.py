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
  internal node served by a daemon thread (as C++ does with its hidden node: under rclpy a
  wait-set loop of its own, ``serve_subscriptions``, at under a third of the CPU of rclpy's
  executor; standalone a private single-threaded executor), so the user's node keeps its own
  executor and callbacks, and the buffer is marked as fed by a dedicated thread, which makes
  blocking waits safe everywhere.
- a transform the buffer rejects (NaN, empty frame id, ...) is logged and skipped; the rest of
  the message is still used;
- bad samples cannot flood the log: the first malformed sample or rejected transform of each
  writer is logged in full, the following ones as a count every few seconds (see
  :mod:`tf_demo.msgs.log_throttle`). The standalone world names the writer by its GUID; rclpy
  (Jazzy) does not tell a subscription who wrote a sample, so there the count is per topic;
- feeding one of our :class:`Buffer` s, the subscriptions are raw in both worlds (rclpy's
  ``raw=True``): they take the serialised bytes and decode them straight into the buffer's core
  (no message objects) through :meth:`Buffer.insert_decoded
  <tf_demo.ros.Buffer.insert_decoded>`, the listener's hot path. Another buffer (tf2_ros's)
  gets messages through its ``set_transform``.

The authority recorded for each transform is ``'default_authority'``, as in tf2_ros Python.
"""

from __future__ import annotations

from collections.abc import Callable
from collections.abc import Mapping
import contextlib
import threading
from typing import Protocol
from typing import TYPE_CHECKING

from tf_demo.msgs import cdr
from tf_demo.msgs import tf2_msgs as standalone_tf2_msgs
from tf_demo.msgs.log_throttle import PerWriterThrottle
from tf_demo.ros.buffer import Buffer
from tf_demo.transport import create_internal_node
from tf_demo.transport import SubscriptionServer
from tf_demo.transport.callback_groups import ReentrantCallbackGroup
from tf_demo.transport.messages import tf2_msgs
from tf_demo.transport.qos import DynamicListenerQoS
from tf_demo.transport.qos import StaticListenerQoS

if TYPE_CHECKING:
    from tf_demo.msgs.convert import TransformStampedLike
    from tf_demo.msgs.log_throttle import Writer
    from tf_demo.msgs.tf2_msgs import TFMessage
    from tf_demo.transport.dds.endpoints import DdsSubscription
    from tf_demo.transport.node import Node
    from tf_demo.transport.qos import QoSProfile

DEFAULT_TF_TOPIC = '/tf'
DEFAULT_STATIC_TF_TOPIC = '/tf_static'
DEFAULT_AUTHORITY = 'default_authority'
SPIN_STOP_CHECK_S = 0.1
"""How long the private executor blocks per ``spin_once`` before checking for shutdown."""


class TransformSink(Protocol):
    """What the listener needs of a buffer: tf2_ros's two inserts (a tf2_ros ``Buffer`` too)."""

    def set_transform(self, transform: TransformStampedLike, authority: str) -> None: ...

    def set_transform_static(self, transform: TransformStampedLike, authority: str) -> None: ...


class TransformListener:
    """Feeds a buffer from ``/tf`` and ``/tf_static``."""

    def __init__(
        self,
        buffer: TransformSink,
        node: Node,
        *,
        spin_thread: bool = False,
        qos: QoSProfile | int | None = None,
        static_qos: QoSProfile | int | None = None,
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
        self._server: SubscriptionServer | None = None
        self._private_node: Node | None = None
        self.dedicated_listener_thread: threading.Thread | None = None
        self._malformed = PerWriterThrottle('malformed samples')
        self._tf_topic = tf_topic
        self._tf_static_topic = tf_static_topic
        host = node
        if spin_thread:
            host = self._private_node = create_internal_node(
                f'transform_listener_impl_{id(self):x}'
            )
        #: Whether the subscriptions take serialised bytes (feeding one of our buffers).
        self.raw_decoding = raw = isinstance(buffer, Buffer)
        group = ReentrantCallbackGroup()

        def subscribe(
            topic: str, callback: Callable[..., object], profile: QoSProfile | int
        ) -> DdsSubscription:
            # The callback takes (bytes, message info) or a message: rclpy's rule, by arity.
            return host.create_subscription(
                tf2_msgs.TFMessage, topic, callback, profile, callback_group=group, raw=raw
            )

        self.tf_sub: DdsSubscription | None = None
        if not static_only:
            self.tf_sub = subscribe(
                tf_topic,
                self._raw_callback if raw else self.callback,
                DynamicListenerQoS() if qos is None else qos,
            )
        self.tf_static_sub: DdsSubscription | None = subscribe(
            tf_static_topic,
            self._raw_static_callback if raw else self.static_callback,
            StaticListenerQoS() if static_qos is None else static_qos,
        )
        if spin_thread:
            self._start_spin_thread(host)

    def _start_spin_thread(self, host: Node) -> None:
        setter = getattr(self.buffer, 'set_using_dedicated_thread', None)
        if setter is not None:
            setter(True)
        subscriptions = [sub for sub in (self.tf_sub, self.tf_static_sub) if sub is not None]
        self._server = SubscriptionServer(
            host, subscriptions, 'tf_demo_transform_listener', SPIN_STOP_CHECK_S
        )
        self.dedicated_listener_thread = self._server.thread

    def callback(self, data: TFMessage) -> None:
        """Insert every transform of a ``/tf`` message."""
        self._insert_all(data, f"a writer on '{self._tf_topic}'", is_static=False)

    def static_callback(self, data: TFMessage) -> None:
        """Insert every transform of a ``/tf_static`` message."""
        self._insert_all(data, f"a writer on '{self._tf_static_topic}'", is_static=True)

    def _raw_callback(self, data: bytes, info: Mapping[str, object]) -> None:
        self._insert_raw(data, _writer(info, self._tf_topic), is_static=False)

    def _raw_static_callback(self, data: bytes, info: Mapping[str, object]) -> None:
        self._insert_raw(data, _writer(info, self._tf_static_topic), is_static=True)

    def _insert_raw(self, data: bytes, writer: Writer, *, is_static: bool) -> None:
        """Decode serialised TFMessage bytes into the buffer (:meth:`Buffer.insert_decoded`)."""
        buffer = self.buffer
        try:
            if not isinstance(buffer, Buffer):  # replaced after construction, as tf2_ros allows
                message = cdr.deserialize(standalone_tf2_msgs.TFMessage, data)
                self._insert_all(message, writer, is_static=is_static)
                return
            transforms = cdr.decode_tf_message_transforms(data)
        except cdr.CdrError as error:
            self._log_throttled(writer, f'Dropping a malformed TFMessage: {error}')
            return
        buffer.note_feeder_thread()
        for parent, child, failure in buffer.insert_decoded(
            transforms, DEFAULT_AUTHORITY, writer, is_static
        ):
            self._log_insert_failure(writer, parent, child, failure)

    def _insert_all(self, data: TFMessage, writer: Writer, *, is_static: bool) -> None:
        note = getattr(self.buffer, 'note_feeder_thread', None)
        if note is not None:
            note()
        insert = self.buffer.set_transform_static if is_static else self.buffer.set_transform
        set_source: Callable[[Writer | None], None] | None = getattr(
            self.buffer, 'set_log_source', None
        )  # this buffer's: tf2_ros lets a user replace the listener's buffer at any time
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
        self, writer: Writer, parent: str, child: str, error: Exception
    ) -> None:
        self._log_throttled(
            writer,
            f'Failure to set received transform from {child} to {parent} with error: {error}',
            'set_transform',
        )

    def _log_throttled(self, writer: Writer, text: str, kind: str = '') -> None:
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
            with contextlib.suppress(Exception):  # teardown is best effort
                self.node.get_logger().error(line)

    def unregister(self) -> None:
        """Stop the private thread (if any) and destroy the subscriptions."""
        if self._server is not None:
            self._server.stop(destroy_node=False)  # the node goes below, after its subscriptions
            self._server = None
        self.dedicated_listener_thread = None
        self._log_pending()
        host = self._private_node if self._private_node is not None else self.node
        for sub in (self.tf_sub, self.tf_static_sub):
            if sub is not None:
                host.destroy_subscription(sub)
        self.tf_sub = None
        self.tf_static_sub = None
        if self._private_node is not None:
            _quietly(self._private_node.destroy_node)
            self._private_node = None


def _writer(info: Mapping[str, object], topic: str) -> Writer:
    """
    Name the writer of a sample from its message info, for the throttled error log.

    The standalone world's info carries the writer's GUID (``publisher_gid``); rclpy's (Jazzy:
    timestamps and sequence numbers only) does not, so there a topic's writers share one name.
    """
    gid = info.get('publisher_gid')
    return gid if isinstance(gid, bytes) else f"a writer on '{topic}'"


def _quietly(action: Callable[[], object]) -> None:
    with contextlib.suppress(Exception):  # teardown is best effort
        action()
