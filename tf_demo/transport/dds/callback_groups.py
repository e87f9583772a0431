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

"""Callback groups (rclpy's): reentrant and mutually exclusive permission to run callbacks."""

from __future__ import annotations

import threading
import weakref

__all__ = ['CallbackGroup', 'MutuallyExclusiveCallbackGroup', 'ReentrantCallbackGroup']


class CallbackGroup:
    """
    rclpy's callback group: decides when the callbacks of its entities may run.

    Entities (subscriptions, timers) are added with :meth:`add_entity` when they are created;
    an executor asks :meth:`can_execute` before handing an entity out, takes permission with
    :meth:`beginning_execution` and returns it with :meth:`ending_execution`. Subclasses
    implement those three, as in rclpy.
    """

    def __init__(self) -> None:
        self.entities: set[weakref.ref[object]] = set()

    def add_entity(self, entity: object) -> None:
        """Add ``entity`` (a subscription or timer) to the group."""
        self.entities.add(weakref.ref(entity))

    def has_entity(self, entity: object) -> bool:
        """Return whether ``entity`` was added to the group."""
        return weakref.ref(entity) in self.entities

    def can_execute(self, entity: object) -> bool:
        """Return whether a callback of ``entity`` may start now."""
        raise NotImplementedError

    def beginning_execution(self, entity: object) -> bool:
        """Ask to start a callback of ``entity``; True obliges to call :meth:`ending_execution`."""
        raise NotImplementedError

    def ending_execution(self, entity: object) -> None:
        """Tell the group that a callback of ``entity`` finished."""
        raise NotImplementedError


class ReentrantCallbackGroup(CallbackGroup):
    """Callbacks of the group may run concurrently, even the same entity's."""

    def can_execute(self, entity: object) -> bool:
        """Return True: the group never holds a callback back."""
        del entity
        return True

    def beginning_execution(self, entity: object) -> bool:
        """Return True: permission is always given."""
        del entity
        return True

    def ending_execution(self, entity: object) -> None:
        """Nothing to release."""
        del entity


class MutuallyExclusiveCallbackGroup(CallbackGroup):
    """At most one callback of the group runs at a time (a node's default group is one)."""

    def __init__(self) -> None:
        super().__init__()
        self._active_entity: object = None
        self._lock = threading.Lock()

    def _check_member(self, entity: object) -> None:
        if not self.has_entity(entity):
            msg = f'{entity!r} is not an entity of this callback group'
            raise AssertionError(msg)

    def can_execute(self, entity: object) -> bool:
        """Return whether no callback of the group is running."""
        with self._lock:
            self._check_member(entity)
            return self._active_entity is None

    def beginning_execution(self, entity: object) -> bool:
        """Take the group for ``entity`` unless a callback of the group is running."""
        with self._lock:
            self._check_member(entity)
            if self._active_entity is None:
                self._active_entity = entity
                return True
        return False

    def ending_execution(self, entity: object) -> None:
        """Release the group taken for ``entity``."""
        with self._lock:
            if self._active_entity is not entity:
                msg = f'{entity!r} is not the entity running in this callback group'
                raise AssertionError(msg)
            self._active_entity = None
