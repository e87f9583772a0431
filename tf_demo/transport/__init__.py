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
The node API every executable is written against, on rclpy or on the standalone DDS backend.

``init``, ``shutdown``, ``ok``, ``spin``, ``spin_once`` and ``create_node`` call the backend
chosen by :func:`tf_demo.transport.backend.backend_name` (``TF_DEMO_BACKEND=rclpy|dds``, else
rclpy when it imports, else DDS); the backend is imported on first use, so importing this
package stays cheap. The world's classes have their own modules, each choosing once:
:mod:`~tf_demo.transport.node` (``Node``), :mod:`~tf_demo.transport.executors`,
:mod:`~tf_demo.transport.callback_groups`, :mod:`~tf_demo.transport.clock`,
:mod:`~tf_demo.transport.qos`, :mod:`~tf_demo.transport.parameters` and
:mod:`~tf_demo.transport.logging`. :func:`run_node` is the shared ``main()``.
"""

from __future__ import annotations

import _thread
import atexit
from collections.abc import Callable
from collections.abc import Sequence
import contextlib
import importlib
import os
import signal
import sys
import threading
import time as _time
from types import FrameType
from types import ModuleType
from typing import Any
from typing import TYPE_CHECKING

from tf_demo.transport.backend import backend_name
from tf_demo.transport.backend import BackendError
from tf_demo.transport.backend import NodeConfigError
from tf_demo.transport.ros_args import parse_ros_args
from tf_demo.transport.ros_args import ROS_ARGS_USAGE
from tf_demo.transport.ros_args import RosArgsError

if TYPE_CHECKING:
    # RCLPY_SUBMODULES, attributes of this package at run time once the node API is in use.
    from tf_demo.transport import callback_groups as callback_groups
    from tf_demo.transport import clock as clock
    from tf_demo.transport import duration as duration
    from tf_demo.transport import executors as executors
    from tf_demo.transport import logging as logging
    from tf_demo.transport import node as node
    from tf_demo.transport import parameter as parameter
    from tf_demo.transport import qos as qos
    from tf_demo.transport import time as time
    from tf_demo.transport.executors import Executor
    from tf_demo.transport.future import Future
    from tf_demo.transport.node import Node

__all__ = [
    'RCLPY_SUBMODULES',
    'BackendError',
    'NodeConfigError',
    'RosArgsError',
    'StopRequest',
    'SubscriptionServer',
    'backend_module',
    'backend_name',
    'create_internal_node',
    'create_node',
    'import_rclpy_submodules',
    'init',
    'ok',
    'run_node',
    'shutdown',
    'spin',
    'spin_once',
    'spin_until_future_complete',
    'try_shutdown',
]

#: What ``signal.signal`` returns and takes: a handler, ``SIG_DFL``/``SIG_IGN``, or None (set
#: from C).
SignalHandler = Callable[[int, FrameType | None], object] | int | signal.Handlers | None

#: rclpy's submodules that ``import tf_demo.transport as rclpy`` answers by attribute
#: (``rclpy.time.Time()``, ``rclpy.duration.Duration()``, as the course writes them): this
#: package's modules of the same names, imported once the node API is in use, as rclpy's are.
RCLPY_SUBMODULES = (
    'callback_groups',
    'clock',
    'duration',
    'executors',
    'logging',
    'node',
    'parameter',
    'qos',
    'time',
)

_BACKEND_MODULES = {
    'rclpy': 'tf_demo.transport.rclpy_backend',
    'dds': 'tf_demo.transport.dds_backend',
}


def backend_module() -> ModuleType:
    """Return the selected backend's module (imported on first use)."""
    return importlib.import_module(_BACKEND_MODULES[backend_name()])


def import_rclpy_submodules() -> None:
    """Import :data:`RCLPY_SUBMODULES`, making them attributes of this package (as rclpy.node)."""
    for name in RCLPY_SUBMODULES:
        importlib.import_module(f'{__name__}.{name}')


def _take_back_an_ignored_sigint() -> None:
    """
    Make SIGINT raise ``KeyboardInterrupt`` even when the process inherited it ignored.

    A node started with ``&`` from a non-interactive shell starts with SIGINT ignored, and
    Python then installs no handler; rclpy's ``init`` installs its own regardless, so
    ``kill -INT`` stops an rclpy node: the standalone world does the same.
    """
    if (
        threading.current_thread() is threading.main_thread()
        and signal.getsignal(signal.SIGINT) == signal.SIG_IGN
    ):
        signal.signal(signal.SIGINT, signal.default_int_handler)


def init(args: Sequence[str] | None = None) -> None:
    """
    Initialise the backend with the process arguments (``sys.argv`` when None).

    Bad ``--ros-args`` raise :class:`RosArgsError` with rcl's text in both worlds: the
    standalone world parses them here (and applies ``--log-level``); under rclpy, rcl parses
    them once, in ``rclpy.init``, and its refusal is turned into the same error.
    """
    argv = list(sys.argv if args is None else args)
    if backend_name() == 'dds':
        _take_back_an_ignored_sigint()
        from tf_demo.transport import logging as node_logging

        for logger_name, level in parse_ros_args(argv).log_levels:
            if logger_name is None:
                node_logging.set_default_logger_level(level)
            else:
                node_logging.set_logger_level(logger_name, level)
    backend_module().init(args=argv)
    import_rclpy_submodules()


def shutdown() -> None:
    """Shut the backend down (nodes and executors stop)."""
    backend_module().shutdown()


def try_shutdown() -> None:
    """Shut the backend down unless it already is (``rclpy.try_shutdown``)."""
    backend_module().try_shutdown()


def ok() -> bool:
    """Whether the backend is initialised and not shut down."""
    return bool(backend_module().ok())


def spin(node: Node, executor: Executor | None = None) -> None:
    """Run ``node``'s callbacks until shutdown."""
    backend_module().spin(node, executor=executor)


def spin_once(
    node: Node, *, executor: Executor | None = None, timeout_sec: float | None = None
) -> None:
    """Run at most one of ``node``'s ready callbacks, waiting up to ``timeout_sec``."""
    backend_module().spin_once(node, executor=executor, timeout_sec=timeout_sec)


def spin_until_future_complete(
    node: Node,
    future: Future[Any],
    executor: Executor | None = None,
    timeout_sec: float | None = None,
) -> None:
    """Run ``node``'s callbacks until ``future`` is done or ``timeout_sec`` passed (as rclpy)."""
    backend_module().spin_until_future_complete(
        node, future, executor=executor, timeout_sec=timeout_sec
    )


def create_node(node_name: str, **kwargs: object) -> Node:
    """Create a node of the selected backend (rclpy ``Node`` keyword arguments)."""
    node: Node = backend_module().create_node(node_name, **kwargs)
    return node


def create_internal_node(node_name: str) -> Node:
    """Create a hidden helper node: no parameter services, no ``/rosout`` (as tf2_ros's own)."""
    try:
        return create_node(node_name, start_parameter_services=False, enable_rosout=False)
    except TypeError:  # a backend without those options
        return create_node(node_name)


#: The internal serving threads still running, with the event that stops each.
_serving_threads: dict[threading.Thread, threading.Event] = {}
#: How long stopping a server (or the process's exit) waits for its thread: a hang guard.
SERVER_JOIN_S = 5.0


@atexit.register
def _stop_serving_threads_at_exit() -> None:
    """
    Stop and join every :class:`SubscriptionServer` thread before the interpreter finalises.

    A server not stopped (its owner interrupted between creating it and its ``try``) leaves a
    daemon thread blocked in the middleware with the GIL released. Under rclpy that thread,
    waking while Python finalises, is ended by ``pthread_exit`` inside pybind11's ``noexcept``
    GIL guard: ``terminate called without an active exception`` and exit -6. ``atexit`` runs
    before finalisation, while the thread can still return on its own.
    """
    for thread, stop in list(_serving_threads.items()):
        stop.set()
        if thread.ident is not None:  # registered before start(): a stop may come in between
            thread.join(timeout=SERVER_JOIN_S)
    _serving_threads.clear()


def _serve_subscriptions() -> Callable[..., None]:
    """Return the world's loop that serves an internal node's subscriptions until told to stop."""
    if backend_name() == 'rclpy':
        from tf_demo.transport.rclpy_serve import serve_subscriptions
    else:
        from tf_demo.transport.dds.spin import serve_subscriptions
    return serve_subscriptions


class SubscriptionServer:
    """
    A thread that runs the callbacks of an internal node's subscriptions, and nothing else.

    Under rclpy it waits on rcl's wait set itself (``serve_subscriptions``: about a quarter of
    the CPU per message of rclpy's executor); standalone it is a private executor. The node must
    hold only subscriptions; ``stop`` is checked every ``period_s``.
    """

    def __init__(
        self, node: Node, subscriptions: Sequence[object], name: str, period_s: float = 0.1
    ) -> None:
        """Start serving ``subscriptions`` of ``node`` in a daemon thread called ``name``."""
        self.node = node
        self._stop = threading.Event()
        serve = _serve_subscriptions()
        #: The serving thread (tf2_ros's ``dedicated_listener_thread``).
        self.thread = threading.Thread(
            target=self._serve, args=(serve, list(subscriptions), period_s), name=name, daemon=True
        )
        _serving_threads[self.thread] = self._stop
        self.thread.start()

    def _serve(
        self, serve: Callable[..., None], subscriptions: list[object], period_s: float
    ) -> None:
        try:
            serve(self.node, subscriptions, self._stop, period_s)
        except Exception:
            if not (self._stop.is_set() or not ok()):
                raise

    def stop(self, *, destroy_node: bool = True) -> None:
        """Stop the thread (and destroy the node unless told not to); safe to call twice."""
        self._stop.set()
        if self.thread is not threading.current_thread():
            self.thread.join(timeout=SERVER_JOIN_S)
        _serving_threads.pop(self.thread, None)
        if destroy_node:
            with contextlib.suppress(Exception):  # teardown is best effort
                self.node.destroy_node()


def _program_name(argv: Sequence[str]) -> str:
    return os.path.basename(argv[0]) if argv and argv[0] and argv[0] != '-c' else 'tf_demo'


def _config_error_types() -> tuple[type[BaseException], ...]:
    """Exceptions from a node constructor that mean "bad configuration", not a bug."""
    from tf_demo.transport.parameters import ParameterException

    return (ValueError, OSError, ParameterException)


class StopRequest:
    """
    SIGINT/SIGTERM for an executable's ``main``: the first signal asks to stop, later ones wait.

    The first signal sets ``event`` (and with ``interrupt=True`` also raises
    ``KeyboardInterrupt`` in the main thread, for tools that block in a loop of their own). While
    the shutdown is under way every further SIGINT or SIGTERM is ignored, as rclpy's own C
    handler does (it only requests the same shutdown again), so a quick double Ctrl-C cannot cut
    the clean-up short: nodes are destroyed and publishers flush.

    Installed *before* the backend's ``init``: ``rclpy.init`` then puts its own C handlers on
    top and chains to these (rclpy's ``signal_handler.cpp`` calls the previous handler, then
    triggers the guard conditions that wake every executor), so a stop request wakes the
    executor at once. :meth:`restore` puts the previous handlers back, except after a stop
    request: the process is then on its way out and both signals stay ignored, because Python's
    finalisation resets a Python-level SIGINT handler to ``SIG_DFL`` and a late Ctrl-C there
    would kill the process (exit -2) before the middleware has finished.
    """

    def __init__(self, *, interrupt: bool = False) -> None:
        self.event = threading.Event()
        self.interrupt = interrupt
        self.previous: dict[int, SignalHandler] = {}
        self._previous_unraisable_hook: Callable[[sys.UnraisableHookArgs], object] | None = None
        self._interrupt_owed = False  # a KeyboardInterrupt still to be raised

    def handle(self, signum: int, _frame: FrameType | None) -> None:
        """Signal handler: the first call requests the stop, later calls are ignored."""
        del signum
        if not self.event.is_set():
            self.event.set()
            self._interrupt_owed = self.interrupt
        if self._interrupt_owed:
            self._interrupt_owed = False
            raise KeyboardInterrupt

    def explains(self, error: BaseException) -> bool:
        """
        Whether ``error``, raised by running code, is how a stop reached it rather than a fault.

        True once a stop was requested: under rclpy its signal handler shuts the context down
        from under whatever runs, so executors raise ``ExternalShutdownException`` or, in a
        narrow race, ``RCLError`` (invalid context). And true for rclpy's
        ``ExternalShutdownException`` itself: the context was shut down elsewhere, which
        upstream's nodes treat as a stop too.
        """
        return self.event.is_set() or type(error).__name__ == 'ExternalShutdownException'

    def _unraisable(self, unraisable: sys.UnraisableHookArgs) -> None:
        """
        ``sys.unraisablehook`` while a stop is under way: what the interrupt broke is mended.

        A signal handler's exception is raised wherever the main thread is, and Python cannot
        propagate it out of a weakref callback or a ``__del__`` (an import's module lock has
        one): it would print "Exception ignored" with a traceback and the stop would be lost,
        so it is raised again. And where it cut an rclpy object's constructor short (a
        ``Task`` built by the executor), that object's ``__del__`` fails on the attribute it
        never set: that is the stop's doing, not a fault, and is not printed.
        """
        if self.event.is_set():
            if isinstance(unraisable.exc_value, KeyboardInterrupt):
                self._interrupt_owed = True
                # Not from here: the handler would run at once, inside this hook.
                threading.Thread(target=_interrupt_main_soon, daemon=True).start()
                return
            if isinstance(unraisable.exc_value, AttributeError) and _is_rclpy_finaliser(
                unraisable.object
            ):
                return
        previous = self._previous_unraisable_hook or sys.__unraisablehook__
        previous(unraisable)

    def install(self) -> None:
        """Install :meth:`handle` for SIGINT and SIGTERM (main thread only, else a no-op)."""
        if threading.current_thread() is not threading.main_thread():
            return
        for signum in (signal.SIGINT, signal.SIGTERM):
            self.previous[signum] = signal.signal(signum, self.handle)
        if self.interrupt:
            self._previous_unraisable_hook = sys.unraisablehook
            sys.unraisablehook = self._unraisable

    def restore(self) -> None:
        """Put the previous handlers back; after a stop request, ignore both signals."""
        if self._previous_unraisable_hook is not None:
            sys.unraisablehook = self._previous_unraisable_hook
            self._previous_unraisable_hook = None
        for signum, previous in self.previous.items():
            if self.event.is_set():
                signal.signal(signum, signal.SIG_IGN)
                continue
            # None: the previous handler was installed from C; use Python's default.
            default = signal.default_int_handler if signum == signal.SIGINT else signal.SIG_DFL
            signal.signal(signum, default if previous is None else previous)
        self.previous.clear()


def _is_rclpy_finaliser(function: object) -> bool:
    """Whether ``function`` is a ``__del__`` defined in rclpy's code."""
    module = getattr(function, '__module__', None) or ''
    name = getattr(function, '__name__', None)
    return name == '__del__' and (module == 'rclpy' or module.startswith('rclpy.'))


def _interrupt_main_soon() -> None:
    """Run the main thread's SIGINT handler shortly (after the caller has returned)."""
    _time.sleep(0.001)
    _thread.interrupt_main(signal.SIGINT)


def run_node(factory: Callable[[], Node], args: Sequence[str] | None = None) -> int:
    """
    Run one node as an executable's ``main()`` and return the exit code.

    Parses ``--ros-args`` (bad ones: usage and a one-line error, exit 1), initialises the
    backend, builds the node with ``factory()`` (a ``ValueError``, ``OSError`` or parameter
    error from it — e.g. :class:`NodeConfigError` — prints one line and exits 1), spins until
    Ctrl-C or SIGTERM, then destroys the node (its publishers flush) and shuts down: exit 0,
    no traceback; further Ctrl-Cs are ignored while it shuts down (:class:`StopRequest`).
    Under rclpy the context being shut down elsewhere (``ExternalShutdownException``) also ends
    the loop with exit 0.
    """
    argv = list(sys.argv if args is None else args)
    program = _program_name(argv)
    stop = StopRequest()
    stop.install()
    try:
        return _run_installed(factory, argv, program, stop)
    finally:
        stop.restore()


def _run_installed(
    factory: Callable[[], Node], argv: list[str], program: str, stop: StopRequest
) -> int:
    """Initialise, build, spin and finish one node (:func:`run_node` with its handlers set)."""
    try:
        init(argv)
    except (RosArgsError, BackendError) as error:
        print(ROS_ARGS_USAGE.replace('<executable>', program), file=sys.stderr)
        print(f'{program}: error: {error}', file=sys.stderr)
        return 1
    node: Node | None = None
    executor: Executor | None = None
    try:
        # The executor is made first: under rclpy a Ctrl-C shuts the context down from
        # rclpy's signal thread, and an executor built on a context going away prints
        # rclpy's own "Exception ignored" tracebacks. Building the node is the long window.
        executor = backend_module().SingleThreadedExecutor()
        try:
            node = factory()
        except Exception as error:
            if stop.explains(error) or not ok():
                # Ctrl-C or SIGTERM while the node was being built (under rclpy its handler
                # shuts the context down under the constructor): a stop, not an error.
                return 0
            if not isinstance(error, _config_error_types()):
                raise
            text = ' '.join(str(error).split()) or type(error).__name__
            print(f'{program}: error: {text}', file=sys.stderr)
            return 1
        if stop.event.is_set() or not ok():
            return 0  # stopped while starting: nothing to spin on a context that is gone
        executor.add_node(node)
        while not stop.event.is_set() and ok():
            executor.spin_once(timeout_sec=0.1)
    except KeyboardInterrupt:
        pass
    except Exception as error:
        if ok() and not stop.explains(error):
            raise
    finally:
        _finish(executor, node)
    return 0


def _finish(executor: Executor | None, node: Node | None) -> None:
    """
    Shut the executor down, destroy the node (flushing its publishers) and the backend, quietly.

    Stop signals are ignored while this runs (:class:`StopRequest`); a ``KeyboardInterrupt``
    from elsewhere skips the rest of the clean-up instead of printing a traceback.
    """
    try:
        try:
            if executor is not None:
                executor.shutdown()
            if node is not None:
                node.destroy_node()
        finally:
            if ok():
                shutdown()
    except KeyboardInterrupt:
        pass
    except Exception as error:  # a failed clean-up must not turn exit 0 into a traceback
        print(f'warning: clean shutdown failed: {error}', file=sys.stderr)
