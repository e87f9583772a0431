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

"""The periodic timer (rclpy ``Timer`` subset) on a node's clock."""

from __future__ import annotations

from collections.abc import Callable
import threading

from tf_demo.transport.dds.callback_groups import CallbackGroup
from tf_demo.transport.dds.callback_groups import MutuallyExclusiveCallbackGroup
from tf_demo.transport.dds.clock import Clock


class DdsTimer:
    """
    A periodic timer (rclpy ``Timer`` subset) on the node's clock.

    ``callback_group`` is the group it was created in (the node's default group unless given).
    Its state is guarded by a lock: a pool thread marks it called while the spinning thread
    asks whether it is ready.
    """

    def __init__(
        self,
        callback: Callable[[], object],
        period_ns: int,
        clock: Clock,
        *,
        autostart: bool = True,
        callback_group: CallbackGroup | None = None,
    ) -> None:
        self.callback = callback
        self.timer_period_ns = period_ns
        self.clock = clock
        self.callback_group: CallbackGroup = (
            MutuallyExclusiveCallbackGroup() if callback_group is None else callback_group
        )
        self._lock = threading.RLock()
        self._canceled = not autostart
        self._next_call_ns = int(clock.now().nanoseconds) + period_ns
        self._last_call_ns: int | None = None
        self._wake: Callable[[], None] | None = None

    def _now_ns(self) -> int:
        now = int(self.clock.now().nanoseconds)
        with self._lock:
            if now < self._next_call_ns - self.timer_period_ns:
                # The clock jumped backwards (e.g. a bag replayed on /clock from the start):
                # restart the period from the new time instead of waiting for the old deadline.
                self._next_call_ns = now + self.timer_period_ns
        return now

    def cancel(self) -> None:
        """Stop calling the callback until :meth:`reset`."""
        self._canceled = True

    def is_canceled(self) -> bool:
        """Return whether the timer is canceled."""
        return self._canceled

    def reset(self) -> None:
        """Restart the period from now (and un-cancel)."""
        with self._lock:
            self._canceled = False
            self._next_call_ns = self._now_ns() + self.timer_period_ns
        if self._wake is not None:
            self._wake()

    def is_ready(self) -> bool:
        """Return whether the timer is due."""
        with self._lock:
            return not self._canceled and self._now_ns() >= self._next_call_ns

    def time_until_next_call(self) -> int | None:
        """Return nanoseconds until the next call (None when canceled)."""
        with self._lock:
            if self._canceled:
                return None
            return max(0, self._next_call_ns - self._now_ns())

    def time_since_last_call(self) -> int:
        """Return nanoseconds since the last call (or since creation)."""
        with self._lock:
            last = self._last_call_ns
            reference = last if last is not None else self._next_call_ns - self.timer_period_ns
            return self._now_ns() - reference

    def _mark_called(self) -> None:
        with self._lock:
            now = self._now_ns()
            self._last_call_ns = now
            self._next_call_ns += self.timer_period_ns
            if self.timer_period_ns == 0:
                self._next_call_ns = now
            elif self._next_call_ns <= now:
                # Fell behind (or the clock jumped): skip missed periods, as rcl does.
                missed = (now - self._next_call_ns) // self.timer_period_ns + 1
                self._next_call_ns += missed * self.timer_period_ns

    def destroy(self) -> None:
        """Cancel the timer for good."""
        self._canceled = True
