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
The node code must run unchanged on real rclpy (Jazzy): checks of everything it calls.

No ROS is installed here, so rclpy's API is written below as data, read from upstream:

- ``ros2/rclpy`` ``rclpy/rclpy/node.py`` at 32e4eae (Jazzy era: ``enable_logger_service``,
  pre/post-set parameter callbacks, ``create_timer(..., autostart)``),
- ``rclpy/rclpy/__init__.py`` at 26a7251 (``init``, ``shutdown``, ``create_node``, ``spin*``),
- ``rclpy/rclpy/executors.py``, ``publisher.py`` (``publish(msg: MsgType | bytes)``) and
  ``subscription.py`` (the ``callback`` setter decides between ``msg`` and ``msg, info``),
- ``rclpy/rclpy/impl/rcutils_logger.py`` (``RcutilsLogger``; one context per call site),
- ``rosidl_generator_py``'s generated message setters (``_idl.py.em``): with
  ``ROS_PYTHON_CHECK_FIELDS=1`` (the default before Iron) they assert the Python type of every
  field value, e.g. ``The 'x' field must be of type 'float'``.

The tests check (1) that the standalone backend (nodes, executors, publishers, subscriptions,
loggers, module functions) offers the same signatures, (2) that every call site in
``tf_demo/ros``, ``tf_demo/nodes`` and ``tf_demo/cli`` binds to rclpy's signatures and never logs
at two severities from one call site, (3) that the messages our node code builds and publishes
would pass rclpy's field checks, (4) that ``rclpy_backend`` stays a pure pass-through that
replaces every rclpy concept of the node API, and (5) standalone behaviour that rclpy specifies
(callback arity, ``publish`` types, ``try_shutdown``, stop signals). The backend selection rules
are tested in test_backend.py.
"""

from __future__ import annotations

import array
import ast
from collections import UserList
from collections import UserString
from collections.abc import Callable
from collections.abc import Iterator
from collections.abc import Sequence
from collections.abc import Set
from dataclasses import dataclass
import inspect
import math
import os
from pathlib import Path
import sys
import time
from typing import Any

from conftest import HAVE_CYCLONEDDS
from conftest import PACKAGE_ROOT
from conftest import run_captured
from conftest import STANDALONE_ONLY
from conftest import WORLD
import numpy as np
import pytest

REPO_ROOT = Path(__file__).resolve().parents[2]
NODE_CODE_DIRS = ('tf_demo/ros', 'tf_demo/nodes', 'tf_demo/cli')

# --------------------------------------------------------------------------------------------
# rclpy Jazzy's signatures, as data.
# A parameter is (name, kind, default); kind: 'pos' (positional or keyword), 'kw' (keyword
# only); default REQUIRED = no default, ANY = has a default that is not a plain literal.

REQUIRED = object()
ANY = object()
Param = tuple[str, str, Any]


def _params(
    *names: str, kw: Sequence[tuple[str, Any]] = (), var_kw: bool = False, **defaults: Any
) -> list[Param]:
    """
    Build a parameter list: ``names`` positional (``defaults`` by name), ``kw`` keyword-only.

    ``var_kw``: the function also takes ``**kwargs`` (kind ``'varkw'``).
    """
    params = [(name, 'pos', defaults.get(name, REQUIRED)) for name in names]
    params += [(name, 'kw', default) for name, default in kw]
    return params + ([('**', 'varkw', REQUIRED)] if var_kw else [])


_NODE_OPTIONS: list[tuple[str, Any]] = [
    ('context', None),
    ('cli_args', None),
    ('namespace', None),
    ('use_global_arguments', True),
    ('enable_rosout', True),
    ('start_parameter_services', True),
    ('parameter_overrides', None),
    ('allow_undeclared_parameters', False),
    ('automatically_declare_parameters_from_overrides', False),
    ('enable_logger_service', False),
]

#: rclpy/rclpy/node.py @32e4eae, class Node (``self`` omitted).
RCLPY_NODE: dict[str, list[Param]] = {
    # def __init__(self, node_name, *, context=None, ..., enable_logger_service=False)
    '__init__': _params('node_name', kw=_NODE_OPTIONS),
    'get_name': _params(),
    'get_namespace': _params(),
    'get_fully_qualified_name': _params(),
    'get_clock': _params(),
    'get_logger': _params(),
    # def declare_parameter(self, name, value=None, descriptor=None, ignore_override=False)
    'declare_parameter': _params(
        'name', 'value', 'descriptor', 'ignore_override',
        value=None, descriptor=None, ignore_override=False,
    ),
    'declare_parameters': _params(
        'namespace', 'parameters', 'ignore_override', ignore_override=False
    ),
    'undeclare_parameter': _params('name'),
    'has_parameter': _params('name'),
    'get_parameters': _params('names'),
    'get_parameter': _params('name'),
    'get_parameter_or': _params('name', 'alternative_value', alternative_value=None),
    'get_parameters_by_prefix': _params('prefix'),
    'set_parameters': _params('parameter_list'),
    'set_parameters_atomically': _params('parameter_list'),
    'add_on_set_parameters_callback': _params('callback'),
    'remove_on_set_parameters_callback': _params('callback'),
    'describe_parameter': _params('name'),
    # def resolve_topic_name(self, topic, *, only_expand=False)
    'resolve_topic_name': _params('topic', kw=[('only_expand', False)]),
    # def create_publisher(self, msg_type, topic, qos_profile, *, callback_group=None,
    #     event_callbacks=None, qos_overriding_options=None, publisher_class=Publisher)
    'create_publisher': _params(
        'msg_type', 'topic', 'qos_profile',
        kw=[
            ('callback_group', None),
            ('event_callbacks', None),
            ('qos_overriding_options', None),
            ('publisher_class', ANY),
        ],
    ),
    # def create_subscription(self, msg_type, topic, callback, qos_profile, *,
    #     callback_group=None, event_callbacks=None, qos_overriding_options=None, raw=False)
    'create_subscription': _params(
        'msg_type', 'topic', 'callback', 'qos_profile',
        kw=[
            ('callback_group', None),
            ('event_callbacks', None),
            ('qos_overriding_options', None),
            ('raw', False),
        ],
    ),
    # def create_timer(self, timer_period_sec, callback, callback_group=None, clock=None,
    #     autostart=True)
    'create_timer': _params(
        'timer_period_sec', 'callback', 'callback_group', 'clock', 'autostart',
        callback_group=None, clock=None, autostart=True,
    ),
    # def create_service(self, srv_type, srv_name, callback, *,
    #     qos_profile=qos_profile_services_default, callback_group=None)
    'create_service': _params(
        'srv_type', 'srv_name', 'callback', kw=[('qos_profile', ANY), ('callback_group', None)]
    ),
    # def create_client(self, srv_type, srv_name, *, qos_profile=qos_profile_services_default,
    #     callback_group=None)
    'create_client': _params(
        'srv_type', 'srv_name', kw=[('qos_profile', ANY), ('callback_group', None)]
    ),
    'destroy_publisher': _params('publisher'),
    'destroy_subscription': _params('subscription'),
    'destroy_timer': _params('timer'),
    'destroy_service': _params('service'),
    'destroy_client': _params('client'),
    'destroy_node': _params(),
    'count_publishers': _params('topic_name'),
    'count_subscribers': _params('topic_name'),
}  # fmt: skip

#: rclpy/rclpy/__init__.py @26a7251 (``ok`` is rclpy.utilities.ok).
RCLPY_FUNCTIONS: dict[str, list[Param]] = {
    'init': _params(
        kw=[('args', None), ('context', None), ('domain_id', None),
            ('signal_handler_options', None)]
    ),
    'shutdown': _params(kw=[('context', None), ('uninstall_handlers', None)]),
    'ok': _params(kw=[('context', None)]),
    'try_shutdown': _params(kw=[('context', None)]),  # rclpy.utilities.try_shutdown
    'create_node': _params('node_name', kw=_NODE_OPTIONS),
    'spin_once': _params('node', kw=[('executor', None), ('timeout_sec', None)]),
    'spin': _params('node', 'executor', executor=None),
    'spin_until_future_complete': _params(
        'node', 'future', 'executor', 'timeout_sec', executor=None, timeout_sec=None
    ),
}  # fmt: skip

#: rclpy/rclpy/executors.py: class Executor / SingleThreadedExecutor / MultiThreadedExecutor.
RCLPY_EXECUTOR: dict[str, list[Param]] = {
    '__init__': _params(kw=[('context', None)]),
    'add_node': _params('node'),
    'remove_node': _params('node'),
    'spin': _params(),
    'spin_once': _params('timeout_sec', timeout_sec=None),
    'spin_until_future_complete': _params('future', 'timeout_sec', timeout_sec=None),
    'shutdown': _params('timeout_sec', timeout_sec=None),
}
RCLPY_MULTI_THREADED_INIT = _params('num_threads', kw=[('context', None)], num_threads=None)

#: rclpy/rclpy/publisher.py: ``def publish(self, msg: Union[MsgType, bytes]) -> None``,
#: ``def wait_for_all_acked(self, timeout: Duration = Duration(seconds=-1)) -> bool``.
RCLPY_PUBLISHER = {
    'publish': _params('msg'),
    'get_subscription_count': _params(),
    'wait_for_all_acked': _params('timeout', timeout=ANY),
}
#: rclpy/rclpy/subscription.py: ``def get_publisher_count(self) -> int``.
RCLPY_SUBSCRIPTION = {'get_publisher_count': _params()}

#: rclpy/rclpy/impl/rcutils_logger.py: RcutilsLogger's public methods.
RCLPY_LOGGER_METHODS = frozenset(
    {'debug', 'info', 'warning', 'warn', 'error', 'fatal', 'log', 'get_child', 'set_level',
     'get_effective_level', 'is_enabled_for'}
)  # fmt: skip

#: rclpy/rclpy/impl/rcutils_logger.py: RcutilsLogger's signatures (``self`` omitted).
RCLPY_LOGGER: dict[str, list[Param]] = {
    '__init__': _params('name', name=''),
    'get_child': _params('name'),
    'set_level': _params('level'),
    'get_effective_level': _params(),
    'is_enabled_for': _params('severity'),
    **{method: _params('message', var_kw=True) for method in ('debug', 'info', 'warning',
                                                              'warn', 'error', 'fatal')},
    'log': _params('message', 'severity', var_kw=True),
}  # fmt: skip

#: rclpy parameters the standalone backend may leave out (never used by tf_demo's node code).
UNSUPPORTED_RCLPY_PARAMETERS = frozenset(
    {('init', 'domain_id'), ('init', 'signal_handler_options'), ('shutdown', 'uninstall_handlers')}
)


def signature_of(params: list[Param]) -> inspect.Signature:
    """Return an ``inspect.Signature`` for rclpy parameter data (defaults as placeholders)."""
    kinds = {
        'pos': inspect.Parameter.POSITIONAL_OR_KEYWORD,
        'kw': inspect.Parameter.KEYWORD_ONLY,
        'varkw': inspect.Parameter.VAR_KEYWORD,
    }
    return inspect.Signature(
        [
            inspect.Parameter(
                'kwargs' if kind == 'varkw' else name,
                kinds[kind],
                default=inspect.Parameter.empty if default is REQUIRED else default,
            )
            for name, kind, default in params
        ]
    )


def _ours(function: Callable[..., Any], *, bound: bool) -> list[inspect.Parameter]:
    params = list(inspect.signature(function).parameters.values())
    return params[1:] if bound else params


def incompatibilities(
    label: str, function: Callable[..., Any], rclpy_params: list[Param], *, bound: bool
) -> list[str]:
    """
    Return why a call valid on one side could fail on the other (empty when compatible).

    Rules: same positional parameters in the same order with the same defaults; every keyword-
    only parameter of ours is rclpy's with the same default; no ``*args``/``**kwargs`` rclpy does
    not have; every rclpy parameter exists on our side unless listed as unsupported.
    """
    ours = _ours(function, bound=bound)
    their_var_kw = any(kind == 'varkw' for _, kind, _ in rclpy_params)
    problems = [
        f'{label}: {parameter} accepts what rclpy rejects'
        for parameter in ours
        if parameter.kind is inspect.Parameter.VAR_POSITIONAL
        or (parameter.kind is inspect.Parameter.VAR_KEYWORD and not their_var_kw)
    ]
    if their_var_kw and not any(p.kind is p.VAR_KEYWORD for p in ours):
        problems.append(f'{label}: rclpy takes **kwargs')
    ours = [p for p in ours if p.kind not in (p.VAR_POSITIONAL, p.VAR_KEYWORD)]
    rclpy_params = [param for param in rclpy_params if param[1] != 'varkw']
    theirs = {name: (kind, default) for name, kind, default in rclpy_params}
    our_positional = [p.name for p in ours if p.kind is not p.KEYWORD_ONLY]
    their_positional = [name for name, kind, _ in rclpy_params if kind == 'pos']
    if our_positional != their_positional[: len(our_positional)]:
        problems.append(f'{label}: positional {our_positional} vs rclpy {their_positional}')
    for parameter in ours:
        if parameter.name not in theirs:
            problems.append(f'{label}: {parameter.name!r} is not an rclpy parameter')
            continue
        kind, default = theirs[parameter.name]
        if kind == 'kw' and parameter.kind is not parameter.KEYWORD_ONLY:
            problems.append(f'{label}: {parameter.name!r} is keyword-only in rclpy')
        ours_default = REQUIRED if parameter.default is parameter.empty else parameter.default
        if default is not ANY and ours_default != default:
            problems.append(
                f'{label}: default of {parameter.name!r} is {ours_default!r}, rclpy {default!r}'
            )
    names = {p.name for p in ours}
    short = label.rsplit('.', 1)[-1]
    for name, _kind, _default in rclpy_params:
        if name not in names and (short, name) not in UNSUPPORTED_RCLPY_PARAMETERS:
            problems.append(f'{label}: rclpy parameter {name!r} is missing')
    return problems


def _surface_cases() -> Iterator[Any]:
    if not HAVE_CYCLONEDDS:
        yield pytest.param(
            'DdsNode', None, [], False, id='standalone', marks=pytest.mark.skip(STANDALONE_ONLY)
        )
        return
    from tf_demo.transport import dds_backend as dds

    cases: list[tuple[str, Callable[..., Any], list[Param], bool]] = []
    for name, params in RCLPY_NODE.items():
        cases.append((f'DdsNode.{name}', getattr(dds.DdsNode, name), params, True))
    for name, params in RCLPY_FUNCTIONS.items():
        function = getattr(dds, name)
        if name == 'create_node':  # forwards **kwargs to DdsNode(...), checked through it
            continue
        cases.append((name, function, params, False))
    for name, params in RCLPY_EXECUTOR.items():
        cases.append(
            (f'SingleThreadedExecutor.{name}', getattr(dds.SingleThreadedExecutor, name),
             params, True)
        )  # fmt: skip
    cases.append(
        ('MultiThreadedExecutor.__init__', dds.MultiThreadedExecutor.__init__,
         RCLPY_MULTI_THREADED_INIT, True)
    )  # fmt: skip
    for name, params in RCLPY_PUBLISHER.items():
        cases.append((f'DdsPublisher.{name}', getattr(dds.DdsPublisher, name), params, True))
    for name, params in RCLPY_SUBSCRIPTION.items():
        cases.append((f'DdsSubscription.{name}', getattr(dds.DdsSubscription, name), params, True))
    from tf_demo.transport.logging import Logger

    for name, params in RCLPY_LOGGER.items():
        cases.append((f'Logger.{name}', getattr(Logger, name), params, True))
    for label, function, params, bound in cases:
        yield pytest.param(label, function, params, bound, id=label)


def _real_rclpy_cases() -> Iterator[Any]:
    """The rclpy objects each table above describes (only where rclpy imports)."""
    if WORLD != 'rclpy':
        yield pytest.param(
            'rclpy', None, [], False, id='rclpy', marks=pytest.mark.skip('needs real rclpy')
        )
        return
    import rclpy
    import rclpy.executors
    import rclpy.impl.rcutils_logger
    import rclpy.node
    import rclpy.publisher
    import rclpy.subscription

    tables: list[tuple[str, Any, dict[str, list[Param]], bool]] = [
        ('Node', rclpy.node.Node, RCLPY_NODE, True),
        ('rclpy', rclpy, RCLPY_FUNCTIONS, False),
        ('SingleThreadedExecutor', rclpy.executors.SingleThreadedExecutor, RCLPY_EXECUTOR, True),
        ('Publisher', rclpy.publisher.Publisher, RCLPY_PUBLISHER, True),
        ('Subscription', rclpy.subscription.Subscription, RCLPY_SUBSCRIPTION, True),
        ('RcutilsLogger', rclpy.impl.rcutils_logger.RcutilsLogger, RCLPY_LOGGER, True),
    ]
    for owner, holder, table, bound in tables:
        for name, params in table.items():
            label = f'{owner}.{name}'
            yield pytest.param(label, getattr(holder, name), params, bound, id=label)
    init = rclpy.executors.MultiThreadedExecutor.__init__
    label = 'MultiThreadedExecutor.__init__'
    yield pytest.param(label, init, RCLPY_MULTI_THREADED_INIT, True, id=label)


@pytest.mark.parametrize(('label', 'function', 'rclpy_params', 'bound'), list(_real_rclpy_cases()))
def test_the_rclpy_tables_are_the_real_rclpys_signatures(
    label: str, function: Callable[..., Any], rclpy_params: list[Param], bound: bool
) -> None:
    """Measured, not inferred: every table row above is the signature of the real rclpy."""
    assert incompatibilities(label, function, rclpy_params, bound=bound) == []


@pytest.mark.parametrize(('label', 'function', 'rclpy_params', 'bound'), list(_surface_cases()))
def test_standalone_backend_has_rclpys_signatures(
    label: str, function: Callable[..., Any], rclpy_params: list[Param], bound: bool
) -> None:
    """Each DdsNode/executor/publisher/module function takes exactly rclpy Jazzy's parameters."""
    assert incompatibilities(label, function, rclpy_params, bound=bound) == []


def test_the_signature_checker_catches_each_kind_of_divergence() -> None:
    """The checker reports **kwargs, reordering, wrong defaults, keyword kinds and omissions."""
    reference = _params('a', 'b', kw=[('c', None)], b=1)

    def same(self: object, a: object, b: object = 1, *, c: object = None) -> None: ...
    def swallow(self: object, a: object, b: object = 1, **kwargs: object) -> None: ...
    def reordered(self: object, b: object = 1, a: object = None, *, c: object = None) -> None: ...
    def other_default(self: object, a: object, b: object = 2, *, c: object = None) -> None: ...
    def positional_c(self: object, a: object, b: object = 1, c: object = None) -> None: ...
    def missing_c(self: object, a: object, b: object = 1) -> None: ...

    def _a_kwargs(self: object, a: object, **kwargs: object) -> None: ...

    assert incompatibilities('same', same, reference, bound=True) == []
    for function in (swallow, reordered, other_default, positional_c, missing_c):
        assert incompatibilities(function.__name__, function, reference, bound=True)
    with_kwargs = _params('a', var_kw=True)
    assert "swallow: 'b' is not an rclpy parameter" in incompatibilities(
        'swallow', swallow, with_kwargs, bound=True
    )
    assert incompatibilities('a_kwargs', _a_kwargs, with_kwargs, bound=True) == []
    assert incompatibilities('missing_c', missing_c, with_kwargs, bound=True)
    assert bind_problem_for('f(1, x=2)', with_kwargs) is None


# --------------------------------------------------------------------------------------------
# Every call site in the node code binds to rclpy's signatures.


@dataclass(frozen=True)
class CallSite:
    """One call found in the node code."""

    path: str
    line: int
    receiver: str
    method: str
    node: ast.Call


def _receiver_text(func: ast.Attribute) -> str:
    try:
        return ast.unparse(func.value)
    except Exception:  # pragma: no cover - ast.unparse handles every expression
        return '?'


def node_code_calls() -> list[CallSite]:
    """Return every ``x.method(...)`` call in the node code directories."""
    sites: list[CallSite] = []
    for directory in NODE_CODE_DIRS:
        for path in sorted((REPO_ROOT / directory).glob('*.py')):
            tree = ast.parse(path.read_text(encoding='utf-8'))
            relative = str(path.relative_to(REPO_ROOT))
            sites.extend(
                CallSite(relative, node.lineno, _receiver_text(node.func), node.func.attr, node)
                for node in ast.walk(tree)
                if isinstance(node, ast.Call) and isinstance(node.func, ast.Attribute)
            )
    return sites


def _rclpy_params_for(site: CallSite) -> list[Param] | None:
    """The rclpy signature a call site must bind to, or None when it is not an rclpy call."""
    if site.receiver == 'transport':
        return RCLPY_FUNCTIONS.get(site.method)
    if site.receiver == 'super()' and site.method == '__init__':
        return RCLPY_NODE['__init__']
    if site.method in ('spin_once', 'add_node', 'remove_node', 'spin_until_future_complete'):
        return RCLPY_EXECUTOR[site.method]
    if site.method == 'publish':
        return RCLPY_PUBLISHER['publish']
    if site.method in RCLPY_NODE and site.method != '__init__':
        return RCLPY_NODE[site.method]
    return None


def bind_problem(site: CallSite, params: list[Param]) -> str | None:
    """Return why the call would raise TypeError on rclpy, or None."""
    call = site.node
    if any(isinstance(arg, ast.Starred) for arg in call.args):
        return None  # *args: the count is not known statically
    keywords = [k.arg for k in call.keywords if k.arg is not None]
    has_double_star = any(k.arg is None for k in call.keywords)
    signature = signature_of(params)
    placeholder = object()
    try:
        if has_double_star:
            signature.bind_partial(*([placeholder] * len(call.args)), **dict.fromkeys(keywords))
        else:
            signature.bind(*([placeholder] * len(call.args)), **dict.fromkeys(keywords))
    except TypeError as error:
        return f'{site.path}:{site.line}: {ast.unparse(call)} -> {error}'
    return None


def bind_problem_for(code: str, params: list[Param]) -> str | None:
    """``bind_problem`` for a call written as code (``f(...)``)."""
    call = ast.parse(code).body[0].value  # type: ignore[attr-defined]
    return bind_problem(CallSite('x.py', 1, 'node', 'f', call), params)


def _super_init_in_node_subclasses() -> set[tuple[str, int]]:
    """Lines of ``super().__init__(...)`` inside classes deriving from ``Node``."""
    found = set()
    for directory in NODE_CODE_DIRS:
        for path in sorted((REPO_ROOT / directory).glob('*.py')):
            tree = ast.parse(path.read_text(encoding='utf-8'))
            for cls in ast.walk(tree):
                if not isinstance(cls, ast.ClassDef):
                    continue
                if not any(isinstance(b, ast.Name) and b.id == 'Node' for b in cls.bases):
                    continue
                for node in ast.walk(cls):
                    if (
                        isinstance(node, ast.Call)
                        and isinstance(node.func, ast.Attribute)
                        and node.func.attr == '__init__'
                        and ast.unparse(node.func.value) == 'super()'
                    ):
                        found.add((str(path.relative_to(REPO_ROOT)), node.lineno))
    return found


def test_node_code_calls_bind_to_rclpy_signatures() -> None:
    """Every node/publisher/executor/transport call in ros, nodes and cli is valid for rclpy."""
    node_inits = _super_init_in_node_subclasses()
    checked = 0
    problems = []
    for site in node_code_calls():
        if site.receiver == 'super()' and (site.path, site.line) not in node_inits:
            continue
        params = _rclpy_params_for(site)
        if params is None:
            continue
        checked += 1
        problem = bind_problem(site, params)
        if problem is not None:
            problems.append(problem)
    assert problems == []
    assert checked >= 40  # the scan really sees the node code (about 60 call sites today)


def test_the_call_site_check_rejects_what_rclpy_rejects() -> None:
    """Positional keyword-only arguments and unknown keywords are reported."""

    def site(code: str) -> CallSite:
        call = ast.parse(code).body[0].value  # type: ignore[attr-defined]
        return CallSite('x.py', 1, _receiver_text(call.func), call.func.attr, call)

    bad = [
        'node.create_subscription(T, "/tf", cb, 10, group)',  # callback_group is keyword-only
        'node.create_publisher(T, "/tf", qos=10)',  # rclpy's name is qos_profile
        'node.declare_parameter("a", 1, d, False, 3)',
        'transport.spin_once(node, 0.1)',  # timeout_sec is keyword-only in rclpy.spin_once
        'transport.init(["x"])',  # rclpy.init(*, args=None)
    ]
    for code in bad:
        call_site = site(code)
        params = _rclpy_params_for(call_site)
        assert params is not None, code
        assert bind_problem(call_site, params) is not None, code
    good = site('node.create_subscription(T, "/tf", cb, 10, callback_group=g, raw=True)')
    assert bind_problem(good, RCLPY_NODE['create_subscription']) is None


def test_node_code_logs_only_through_rclpy_logger_methods() -> None:
    """``get_logger().<method>(text)`` uses RcutilsLogger methods with one positional text."""
    problems = []
    for site in node_code_calls():
        if not site.receiver.endswith('get_logger()'):
            continue
        if site.method not in RCLPY_LOGGER_METHODS:
            problems.append(f'{site.path}:{site.line}: RcutilsLogger has no {site.method!r}')
        elif site.method in {'debug', 'info', 'warning', 'warn', 'error', 'fatal'} and (
            len(site.node.args) != 1
        ):
            problems.append(f'{site.path}:{site.line}: {site.method} takes one message')
    assert problems == []


MESSAGE_PACKAGES = ('builtin_interfaces', 'geometry_msgs', 'nav_msgs', 'rosgraph_msgs',
                    'sensor_msgs', 'std_msgs', 'tf2_msgs')  # fmt: skip


def test_node_code_builds_messages_with_keywords_that_are_fields() -> None:
    """``pkg.Msg(...)`` calls use keywords only (rclpy's __init__ is **kwargs) and real fields."""
    import importlib

    problems = []
    checked = 0
    for site in node_code_calls():
        if site.receiver not in MESSAGE_PACKAGES:
            continue
        cls = getattr(importlib.import_module(f'tf_demo.msgs.{site.receiver}'), site.method, None)
        if cls is None:
            problems.append(f'{site.path}:{site.line}: {site.receiver} has no {site.method}')
            continue
        checked += 1
        if site.node.args:
            problems.append(f'{site.path}:{site.line}: positional arguments to {site.method}')
        fields = cls.get_fields_and_field_types()
        problems.extend(
            f'{site.path}:{site.line}: {site.method} has no {keyword.arg!r}'
            for keyword in site.node.keywords
            if keyword.arg is not None and keyword.arg not in fields
        )
    assert problems == []
    assert checked >= 3


# --------------------------------------------------------------------------------------------
# Message field values: rosidl_generator_py's setter checks (ROS_PYTHON_CHECK_FIELDS=1).

FLOAT_LIMIT = {'float': 3.402823466e38, 'double': 1.7976931348623157e308}
INT_RANGE = {
    'int8': (-(2**7), 2**7), 'uint8': (0, 2**8), 'int16': (-(2**15), 2**15),
    'uint16': (0, 2**16), 'int32': (-(2**31), 2**31), 'uint32': (0, 2**32),
    'int64': (-(2**63), 2**63), 'uint64': (0, 2**64),
}  # fmt: skip
ARRAY_TYPECODE = {
    'float': 'f', 'double': 'd', 'int8': 'b', 'uint8': 'B', 'int16': 'h',
    'uint16': 'H', 'int32': 'i', 'uint32': 'I', 'int64': 'q', 'uint64': 'Q',
}  # fmt: skip
NUMPY_DTYPE = {'float': np.float32, 'double': np.float64, 'int8': np.int8, 'uint8': np.uint8,
               'int16': np.int16, 'uint16': np.uint16, 'int32': np.int32, 'uint32': np.uint32,
               'int64': np.int64, 'uint64': np.uint64}  # fmt: skip


def _scalar_problem(rosidl_type: str, value: Any) -> str | None:
    if rosidl_type in FLOAT_LIMIT:
        if not isinstance(value, float):
            return f"must be of type 'float', got {type(value).__name__}"
        limit = FLOAT_LIMIT[rosidl_type]
        if (value < -limit or value > limit) and not math.isinf(value):
            return f'{value!r} is out of range'
        return None
    if rosidl_type in INT_RANGE:
        if not isinstance(value, int):
            return f"must be of type 'int', got {type(value).__name__}"
        low, high = INT_RANGE[rosidl_type]
        return None if low <= value < high else f'{value} is out of [{low}, {high})'
    if rosidl_type == 'boolean':
        return None if isinstance(value, bool) else f"must be of type 'bool', got {value!r}"
    if rosidl_type.startswith('string'):
        return None if isinstance(value, str) else f"must be of type 'str', got {value!r}"
    return None


def _is_sequence_like(value: Any) -> bool:
    """rosidl's test for sequence/array fields given as Python containers."""
    return (
        isinstance(value, (Sequence, Set, UserList))
        and not isinstance(value, str)
        and not isinstance(value, UserString)
    )


def _element_type(rosidl_type: str) -> tuple[str, str, int]:
    """Split a field type into (element type, 'single'|'sequence'|'array', array size)."""
    if rosidl_type.startswith('sequence<'):
        return rosidl_type[len('sequence<') : -1].split(',')[0].strip(), 'sequence', 0
    if rosidl_type.endswith(']'):
        element, _, size = rosidl_type[:-1].partition('[')
        return element, 'array', int(size)
    return rosidl_type, 'single', 0


def rclpy_field_violations(msg: Any, path: str = '') -> list[str]:
    """
    Return what rclpy's generated setters would reject in ``msg`` (recursively).

    Mirrors rosidl_generator_py's ``_idl.py.em`` setter assertions: scalars by ``isinstance``
    and range; nested fields by class; sequences of numbers as ``array.array`` of the right
    type code or a sequence/set (not ``str``) of the right Python type; fixed arrays of numbers
    as a ``numpy.ndarray`` of the right dtype and size or such a sequence of that length.
    """
    from tf_demo.msgs._message import Message
    from tf_demo.msgs._message import message_class

    problems = []
    for name, rosidl_type in type(msg).get_fields_and_field_types().items():
        value = getattr(msg, name)
        where = f'{path}{name}'
        element, kind, size = _element_type(rosidl_type)
        nested = '/' in element
        nested_class = message_class(element.replace('/', '/msg/', 1)) if nested else None
        if kind == 'single':
            if nested:
                if not isinstance(value, nested_class):  # type: ignore[arg-type]
                    problems.append(f'{where}: must be a sub message of type {element}')
                else:
                    problems.extend(rclpy_field_violations(value, f'{where}.'))
                continue
            problem = _scalar_problem(element, value)
            if problem:
                problems.append(f'{where}: {problem}')
            continue
        numeric = element in ARRAY_TYPECODE
        if numeric and kind == 'sequence' and isinstance(value, array.array):
            if value.typecode != ARRAY_TYPECODE[element]:
                problems.append(f'{where}: array.array type code {value.typecode!r}')
            continue
        if numeric and kind == 'array' and isinstance(value, np.ndarray):
            if value.dtype != NUMPY_DTYPE[element] or value.size != size:
                problems.append(f'{where}: ndarray {value.dtype} of size {value.size}')
            continue
        if not _is_sequence_like(value):
            problems.append(f'{where}: must be a set or sequence, got {type(value).__name__}')
            continue
        if kind == 'array' and len(value) != size:
            problems.append(f'{where}: must have length {size}, got {len(value)}')
        for index, item in enumerate(value):
            if nested:
                if not isinstance(item, nested_class):  # type: ignore[arg-type]
                    problems.append(f'{where}[{index}]: must be a {element}')
                elif isinstance(item, Message):
                    problems.extend(rclpy_field_violations(item, f'{where}[{index}].'))
                continue
            problem = _scalar_problem(element, item)
            if problem:
                problems.append(f'{where}[{index}]: {problem}')
    return problems


def test_field_checker_rejects_what_rclpys_generated_setters_reject() -> None:
    """Ints in float fields, numpy float32/ndarrays in sequences, None strings are reported."""
    from tf_demo.msgs import builtin_interfaces
    from tf_demo.msgs import geometry_msgs
    from tf_demo.msgs import sensor_msgs
    from tf_demo.msgs import std_msgs

    # Wrong types on purpose (the type: ignores): the checker's refusal is what is tested.
    rejected = [
        geometry_msgs.Vector3(x=1),
        geometry_msgs.Vector3(y=np.float32(1.0)),
        geometry_msgs.Point32(z=1e39),
        builtin_interfaces.Time(sec=1.0),  # type: ignore[arg-type]
        builtin_interfaces.Time(nanosec=-1),
        builtin_interfaces.Time(sec=np.int64(3)),
        std_msgs.Header(frame_id=None),  # type: ignore[arg-type]
        sensor_msgs.JointState(position=[1, 2]),
        sensor_msgs.JointState(position=np.array([1.0, 2.0])),  # type: ignore[arg-type]
        sensor_msgs.JointState(velocity=array.array('f', [1.0])),
        sensor_msgs.JointState(name='joint'),  # type: ignore[arg-type]
        geometry_msgs.PoseWithCovariance(covariance=[0.0] * 35),
        geometry_msgs.PoseWithCovariance(covariance=np.zeros(36, dtype=np.float32)),
        geometry_msgs.TransformStamped(header=geometry_msgs.Vector3()),  # type: ignore[arg-type]
    ]
    for msg in rejected:
        assert rclpy_field_violations(msg), repr(msg)
    accepted = [
        geometry_msgs.Vector3(x=1.0, y=np.float64(2.0), z=float('inf')),
        builtin_interfaces.Time(sec=-5, nanosec=999_999_999),
        # rclpy takes any sequence of str for a string sequence; the generated class says list.
        sensor_msgs.JointState(name=('a',), position=array.array('d', [1.0]), velocity=[2.0]),  # type: ignore[arg-type]
        geometry_msgs.PoseWithCovariance(covariance=[0.0] * 36),
        geometry_msgs.PoseWithCovariance(covariance=np.zeros(36)),
    ]
    for msg in accepted:
        assert rclpy_field_violations(msg) == [], repr(msg)


@pytest.mark.standalone  # under rclpy, rclpy's own setters check the fields
def test_transform_helpers_give_rclpy_valid_messages_even_from_ints_and_numpy() -> None:
    """make_transform_stamped / fill_transform_stamped convert ints and numpy scalars."""
    from tf_demo.nodes.helpers import make_transform_stamped

    message = make_transform_stamped(
        'odom', 'base_link', 1_500_000_000, (1, np.int64(2), np.float32(3)), (0, 0, 0, 1)
    )
    assert rclpy_field_violations(message) == []
    assert message.header.stamp.sec == 1
    assert message.header.stamp.nanosec == 500_000_000


def test_odometry_and_geometry_outputs_are_rclpy_valid() -> None:
    """transform_from_odometry and every do_transform_* output pass rclpy's field checks."""
    from tf_demo.msgs import cdr
    from tf_demo.msgs import geometry_msgs
    from tf_demo.msgs import nav_msgs
    from tf_demo.nodes.helpers import make_transform_stamped
    from tf_demo.nodes.odom_tf_broadcaster import transform_from_odometry
    from tf_demo.ros import geometry

    odometry = nav_msgs.Odometry()
    odometry.header.stamp.sec = 7
    odometry.pose.pose.position.x = 1.25
    odometry.pose.pose.orientation.z = 1.0
    odometry.pose.pose.orientation.w = 0.0
    received = cdr.deserialize(nav_msgs.Odometry, cdr.serialize(odometry))
    out = transform_from_odometry(received, geometry_msgs.TransformStamped, 'odom', 'base')
    assert rclpy_field_violations(out) == []
    assert (out.header.frame_id, out.child_frame_id) == ('odom', 'base')

    transform = make_transform_stamped('map', 'odom', 3, (1.0, 2.0, 3.0), (0.0, 0.0, 0.6, 0.8))
    inputs = [
        geometry_msgs.PointStamped(),
        geometry_msgs.Vector3Stamped(),
        geometry_msgs.PoseStamped(),
        geometry_msgs.PoseWithCovarianceStamped(),
        geometry_msgs.PolygonStamped(
            polygon=geometry_msgs.Polygon(points=[geometry_msgs.Point32(x=1.0)])
        ),
    ]
    for stamped in inputs:
        function = geometry.TRANSFORM_FUNCTIONS[geometry.ros_type_name(type(stamped))]
        result = function(stamped, transform)
        assert rclpy_field_violations(result) == [], type(stamped).__name__
        assert result.header.frame_id == 'map'


@pytest.mark.standalone  # under rclpy, rclpy's own setters check the fields
def test_buffer_lookup_result_is_rclpy_valid() -> None:
    """Buffer.lookup_transform returns a TransformStamped that rclpy would accept."""
    from tf_demo.nodes.helpers import make_transform_stamped
    from tf_demo.ros import Buffer
    from tf_demo.transport.clock import Time

    buffer = Buffer()
    buffer.set_transform(make_transform_stamped('a', 'b', 10**9, (1, 2, 3), (0, 0, 0, 1)), 'x')
    buffer.set_transform(make_transform_stamped('a', 'b', 3 * 10**9, (3, 2, 1), (0, 0, 0, 1)), 'x')
    result = buffer.lookup_transform('a', 'b', Time(seconds=2))
    assert rclpy_field_violations(result) == []
    assert result.transform.translation.x == pytest.approx(2.0)


ROBOT_URDF = """<robot name="r">
  <link name="base"/><link name="a"/><link name="b"/><link name="c"/>
  <joint name="fixed_j" type="fixed"><parent link="base"/><child link="a"/>
    <origin xyz="1 0 0" rpy="0 0 1"/></joint>
  <joint name="rev" type="revolute"><parent link="a"/><child link="b"/><origin xyz="0 1 0"/>
    <axis xyz="0 0 1"/><limit lower="1" upper="2" effort="1" velocity="1"/></joint>
  <joint name="mim" type="prismatic"><parent link="b"/><child link="c"/><axis xyz="1 0 0"/>
    <limit lower="-1" upper="1" effort="1" velocity="1"/><mimic joint="rev" multiplier="2"/>
  </joint>
</robot>
"""


@pytest.mark.standalone  # under rclpy, rsp builds rclpy's own messages (their setters check)
def test_robot_state_publisher_messages_are_rclpy_valid_and_raw_bytes_are_bytes() -> None:
    """RSP's transforms (integer-looking URDF values) pass rclpy's checks; raw /tf is bytes."""
    from tf_demo.msgs import builtin_interfaces
    from tf_demo.msgs import cdr
    from tf_demo.msgs import tf2_msgs
    from tf_demo.nodes import robot_state_publisher as rsp
    from tf_demo.urdf import RobotModel

    model = RobotModel.from_string(ROBOT_URDF)
    stamp = builtin_interfaces.Time(sec=4, nanosec=5)
    transforms = model.static_transforms() + model.joint_transforms({'rev': 1})
    messages = [rsp._transform_stamped(stamp, t) for t in transforms]
    tf_message = tf2_msgs.TFMessage(transforms=messages)
    assert rclpy_field_violations(tf_message) == []
    encoded = cdr.TfMessageEncoder('').encode(transforms, 4, 5)
    assert type(encoded) is bytes  # rclpy's Publisher.publish takes bytes only (publish_raw)
    assert cdr.deserialize(tf2_msgs.TFMessage, encoded) == tf_message


def test_joint_state_publisher_message_is_rclpy_valid() -> None:
    """The JointState JSP publishes passes rclpy's checks, also after source updates."""
    from tf_demo.msgs import builtin_interfaces
    from tf_demo.msgs import sensor_msgs
    from tf_demo.nodes.joint_state_publisher import joint_state_message
    from tf_demo.nodes.joint_state_publisher import JointStateTable
    from tf_demo.urdf import RobotModel

    table = JointStateTable.from_model(
        RobotModel.from_string(ROBOT_URDF), zeros={'rev': 1}, publish_default_velocities=True
    )
    table.apply_source(['rev'], array.array('d', [1.5]), [2], [])
    table.update(0.1)
    fields = table.message_fields()
    assert fields is not None
    message = joint_state_message(sensor_msgs.JointState, builtin_interfaces.Time(sec=1), fields)
    assert rclpy_field_violations(message) == []
    assert list(message.name) == ['rev', 'mim']


def test_clock_to_msg_gives_valid_stamps() -> None:
    """Time.to_msg()/Duration.to_msg() produce int sec/nanosec in range, as rclpy does."""
    from tf_demo.transport.clock import Duration
    from tf_demo.transport.clock import ROSClock
    from tf_demo.transport.clock import Time

    for msg in (
        ROSClock().now().to_msg(),
        Time(seconds=1.5).to_msg(),
        Time(nanoseconds=2**31 * 10**9 - 1).to_msg(),
        Duration(seconds=-1.5).to_msg(),
    ):
        assert rclpy_field_violations(msg) == [], repr(msg)


# --------------------------------------------------------------------------------------------
# rclpy_backend stays a pure pass-through; each world facade takes one world's names.

#: The one function that does more than pass through: ``init`` calls ``rclpy.init`` and turns
#: rcl's refusal of the ``--ros-args`` into RosArgsError (rcl parses them, once).
RCL_ERROR_TRANSLATORS = frozenset({'init'})
#: The modules that choose the world: standalone names when type checking or outside rclpy.
WORLD_FACADES = ('callback_groups', 'clock', 'executors', 'logging', 'node', 'parameters', 'qos')
RUNTIME_FUNCTIONS = frozenset(
    {'init', 'shutdown', 'try_shutdown', 'ok', 'spin', 'spin_once',
     'spin_until_future_complete', 'create_node', 'SingleThreadedExecutor'}
)  # fmt: skip


def _rclpy_backend_tree() -> ast.Module:
    path = REPO_ROOT / 'tf_demo/transport/rclpy_backend.py'
    return ast.parse(path.read_text(encoding='utf-8'))


def _dotted(node: ast.expr) -> str | None:
    if isinstance(node, ast.Name):
        return node.id
    if isinstance(node, ast.Attribute):
        inner = _dotted(node.value)
        return None if inner is None else f'{inner}.{node.attr}'
    return None


def _rclpy_backend_names() -> set[str]:
    return {
        target.id
        for statement in _rclpy_backend_tree().body
        if isinstance(statement, ast.Assign)
        for target in statement.targets
        if isinstance(target, ast.Name)
    }


def test_rclpy_backend_is_a_pure_pass_through() -> None:
    """Each module-level name is rclpy's object of the same name; no classes, no wrappers."""
    aliases = {}
    for statement in _rclpy_backend_tree().body:
        if isinstance(statement, ast.ClassDef):
            pytest.fail(f'rclpy_backend defines class {statement.name}: wrap nothing')
        if isinstance(statement, ast.FunctionDef):
            assert statement.name in RCL_ERROR_TRANSLATORS, statement.name
            called = {_dotted(n.func) for n in ast.walk(statement) if isinstance(n, ast.Call)}
            assert f'rclpy.{statement.name}' in called, statement.name
        if isinstance(statement, ast.Assign):
            (target,) = statement.targets
            assert isinstance(target, ast.Name)
            if target.id.startswith('_'):
                continue  # a private handle on an rclpy module (the init error types)
            source = _dotted(statement.value)
            assert source is not None, ast.unparse(statement)
            assert source.startswith(('rclpy.', 'rcl_interfaces.msg.')), ast.unparse(statement)
            expected = f'{source.rsplit(".", 1)[0]}.{target.id}'
            assert source == expected, ast.unparse(statement)
            aliases[target.id] = source
    assert aliases['Node'] == 'rclpy.node.Node'


#: Assignments a facade's rclpy branch may make after its star imports (rclpy nests the enum).
RCLPY_BRANCH_ASSIGNMENTS = {'parameters': {'ParameterType = Parameter.Type'}}


def _world_branches(module_name: str) -> tuple[list[str], list[str], set[str]]:
    """A facade's star-imported modules: standalone branch, rclpy branch, and its assignments."""
    path = REPO_ROOT / f'tf_demo/transport/{module_name}.py'
    tree = ast.parse(path.read_text(encoding='utf-8'))
    (selection,) = [statement for statement in tree.body if isinstance(statement, ast.If)]
    assert ast.unparse(selection.test) == 'TYPE_CHECKING or not rclpy_world()'
    standalone: list[str] = []
    for statement in selection.body:
        assert isinstance(statement, ast.ImportFrom), ast.unparse(statement)
        assert [alias.name for alias in statement.names] == ['*'], ast.unparse(statement)
        standalone.append(str(statement.module))
    rclpy_modules: list[str] = []
    assignments: set[str] = set()
    for statement in selection.orelse:
        if isinstance(statement, ast.Assign):
            assignments.add(ast.unparse(statement))
            continue
        assert isinstance(statement, ast.ImportFrom), ast.unparse(statement)
        if str(statement.module).startswith('tf_demo.'):  # tf_demo's own in both worlds
            own = {alias.name for alias in statement.names}
            assert own <= TF_DEMO_ONLY_NAMES[module_name], ast.unparse(statement)
            continue
        assert [alias.name for alias in statement.names] == ['*'], ast.unparse(statement)
        rclpy_modules.append(str(statement.module))
    return standalone, rclpy_modules, assignments


def _facade_names(module_name: str) -> set[str]:
    """What a facade offers: the ``__all__`` of the standalone modules it star-imports."""
    names: set[str] = set()
    for dds_module in _world_branches(module_name)[0]:
        path = REPO_ROOT / (dds_module.replace('.', '/') + '.py')
        tree = ast.parse(path.read_text(encoding='utf-8'))
        (exported,) = [
            statement.value
            for statement in tree.body
            if isinstance(statement, ast.Assign)
            and [ast.unparse(target) for target in statement.targets] == ['__all__']
        ]
        names.update(ast.literal_eval(exported))
    return names


@pytest.mark.parametrize('module_name', WORLD_FACADES)
def test_each_facade_imports_one_world_by_module(module_name: str) -> None:
    """Each branch star-imports whole modules of one world: the standalone ones or rclpy's."""
    standalone, rclpy_modules, assignments = _world_branches(module_name)
    assert standalone, module_name
    assert all(name.startswith('tf_demo.transport.dds.') for name in standalone), standalone
    assert rclpy_modules, module_name
    assert all(name.startswith(('rclpy.', 'rcl_interfaces.')) for name in rclpy_modules)
    assert assignments == RCLPY_BRANCH_ASSIGNMENTS.get(module_name, set())


def _home_module(value: object) -> str:
    """The module that defines ``value`` (for a profile or other instance: its class's)."""
    home = getattr(value, '__module__', None)
    return home if isinstance(home, str) else type(value).__module__


@pytest.mark.parametrize('module_name', WORLD_FACADES)
def test_each_facade_holds_this_worlds_objects(module_name: str) -> None:
    """Imported for real, each world name of a facade is rclpy's object or the standalone one."""
    import importlib

    from tf_demo.transport.backend import rclpy_world

    module = importlib.import_module(f'tf_demo.transport.{module_name}')
    homes = ('rclpy.', 'rcl_interfaces.') if rclpy_world() else ('tf_demo.transport.dds.',)
    names = _facade_names(module_name)
    for name in sorted(names):
        assert hasattr(module, name), f'{module_name}.{name} is missing in this world'
        value = getattr(module, name)
        if name in TF_DEMO_ONLY_NAMES[module_name] or type(value).__module__ == 'builtins':
            continue  # tf_demo's own in both worlds, or a plain constant (S_TO_NS)
        assert _home_module(value).startswith(homes), (name, WORLD)


@pytest.mark.rclpy_world
def test_rclpy_world_facades_name_rclpys_own_classes() -> None:
    """Where rclpy modules reuse a name, the facade holds the one rclpy's node API means."""
    import rclpy.executors
    import rclpy.node
    import rclpy.parameter
    import rclpy.qos
    import rclpy.time
    from tf_demo.transport import clock
    from tf_demo.transport import executors
    from tf_demo.transport import node
    from tf_demo.transport import parameters
    from tf_demo.transport import qos

    assert parameters.Parameter is rclpy.parameter.Parameter  # not rcl_interfaces' message
    assert parameters.ParameterType is rclpy.parameter.Parameter.Type
    assert node.Node is rclpy.node.Node
    assert executors.Executor is rclpy.executors.Executor
    assert clock.Time is rclpy.time.Time
    assert qos.QoSProfile is rclpy.qos.QoSProfile


@pytest.mark.standalone  # imports the DDS backend
def test_both_backends_offer_the_runtime_functions() -> None:
    """What tf_demo.transport forwards to the backend exists in rclpy_backend and dds_backend."""
    from tf_demo.transport import dds_backend

    defined = _rclpy_backend_names() | RCL_ERROR_TRANSLATORS
    assert defined >= RUNTIME_FUNCTIONS, RUNTIME_FUNCTIONS - defined
    assert all(hasattr(dds_backend, name) for name in RUNTIME_FUNCTIONS)


#: Public names of the node-API modules that stay tf_demo's own in the rclpy world.
TF_DEMO_ONLY_NAMES = {
    'qos': {'DynamicBroadcasterQoS', 'DynamicListenerQoS', 'StaticBroadcasterQoS',
            'StaticListenerQoS'},  # tf2_ros's, built on rclpy's classes
    'clock': {'CLOCK_TOPIC', 'USE_SIM_TIME_NAME'},
    'parameters': set(),
    'logging': {'DEFAULT_OUTPUT_FORMAT', 'Logger', 'format_log_line', 'set_default_logger_level'},
    'node': set(),
    'executors': set(),
    'callback_groups': set(),
}  # fmt: skip


@pytest.mark.parametrize('module_name', sorted(TF_DEMO_ONLY_NAMES))
def test_tf_demos_own_facade_names_are_never_rclpys(module_name: str) -> None:
    """tf_demo's own extras (tf2's QoS functions, rcutils' line format...) stay tf_demo's."""
    import importlib

    module = importlib.import_module(f'tf_demo.transport.{module_name}')
    for name in TF_DEMO_ONLY_NAMES[module_name]:
        assert hasattr(module, name), f'{module_name}.{name} is missing in this world'
        assert not _home_module(getattr(module, name)).startswith(('rclpy', 'rcl_interfaces'))


# --------------------------------------------------------------------------------------------
# Standalone behaviour where rclpy's is specified (in-process DDS on the test's domain).


def rclpy_wants_message_info(callback: Callable[..., Any]) -> bool:
    """rclpy's rule (subscription.py, callback setter): one argument binds -> message only."""
    try:
        inspect.signature(callback).bind(object())
    except TypeError:
        pass
    else:
        return False
    try:
        inspect.signature(callback).bind(object(), object())
    except TypeError:
        msg = 'callback should be either be callable with one argument or two'
        raise RuntimeError(msg) from None
    return True


@pytest.fixture
def standalone_world(dds_env: dict[str, str]) -> Iterator[Any]:
    """An initialised standalone world on the test's private domain."""
    from tf_demo.transport import dds_backend

    dds_backend.init()
    yield dds_backend
    if dds_backend.ok():
        dds_backend.shutdown()


def _one_transform_message() -> Any:
    from tf_demo.msgs import tf2_msgs
    from tf_demo.nodes.helpers import make_transform_stamped

    return tf2_msgs.TFMessage(
        transforms=[make_transform_stamped('a', 'b', 1, (1.0, 0.0, 0.0), (0, 0, 0, 1))]
    )


@pytest.mark.dds
def test_subscription_callback_arity_follows_rclpys_rule(standalone_world: Any) -> None:
    """``cb(msg, info=None)`` gets the message only; a 3-argument callback is refused."""
    from tf_demo.msgs import tf2_msgs

    def optional_info(msg: Any, info: Any = None) -> None:
        calls.append(info)

    calls: list[Any] = []
    assert rclpy_wants_message_info(optional_info) is False
    node = standalone_world.DdsNode('arity')
    node.create_subscription(tf2_msgs.TFMessage, '/tf', optional_info, 10)
    publisher = node.create_publisher(tf2_msgs.TFMessage, '/tf', 10)
    executor = standalone_world.SingleThreadedExecutor()
    executor.add_node(node)
    deadline = time.monotonic() + 10.0
    while not calls and time.monotonic() < deadline:
        publisher.publish(_one_transform_message())
        executor.spin_once(timeout_sec=0.05)
    assert calls
    assert calls[0] is None
    with pytest.raises(RuntimeError):
        node.create_subscription(tf2_msgs.TFMessage, '/tf', lambda a, b, c: None, 10)


@pytest.mark.dds
def test_publish_takes_a_message_or_bytes_only(standalone_world: Any) -> None:
    """Like rclpy's Publisher.publish: bytearray and memoryview raise TypeError."""
    from tf_demo.msgs import cdr
    from tf_demo.msgs import tf2_msgs

    node = standalone_world.DdsNode('raw_publisher')
    publisher = node.create_publisher(tf2_msgs.TFMessage, '/tf', 10)
    data = cdr.serialize(_one_transform_message())
    publisher.publish(data)
    for wrong in (bytearray(data), memoryview(data), 'text'):
        with pytest.raises(TypeError):
            publisher.publish(wrong)


@pytest.mark.dds
def test_rsp_qos_override_parameters_are_read_only_like_rclpys(standalone_world: Any) -> None:
    """RSP's qos_overrides.* take an override at start and refuse later sets, as in rclpy."""
    from tf_demo.nodes.robot_state_publisher import RobotStatePublisher
    from tf_demo.transport.parameters import Parameter

    name = 'qos_overrides./tf.publisher.depth'
    node = RobotStatePublisher(
        parameter_overrides=[
            Parameter('robot_description', value=ROBOT_URDF),
            Parameter(name, value=7),
        ]
    )
    try:
        assert node.get_parameter(name).value == 7
        assert node.describe_parameter(name).read_only
        (result,) = node.set_parameters([Parameter(name, value=8)])
        assert not result.successful
        assert node.get_parameter(name).value == 7
        assert node._tf_pub.qos_profile.depth == 7
    finally:
        node.destroy_node()


@pytest.mark.dds
def test_try_shutdown_is_idempotent_like_rclpys(standalone_world: Any) -> None:
    """transport.try_shutdown() shuts down once and is a no-op afterwards (rclpy.try_shutdown)."""
    from tf_demo import transport

    assert transport.ok()
    transport.try_shutdown()
    assert not transport.ok()
    transport.try_shutdown()
    assert not transport.ok()


@pytest.fixture
def published(dds_env: dict[str, str], monkeypatch: pytest.MonkeyPatch) -> Iterator[list[Any]]:
    """
    Everything published in this process, as handed to ``publish`` (then really sent).

    The standalone world is initialised with integer-valued ``-p`` overrides, as a user would
    type them (``-p translation:=[1, 2, 3]`` is an INTEGER_ARRAY for rcl too).
    """
    from tf_demo.transport import dds_backend

    objects: list[Any] = []
    original = dds_backend.DdsPublisher.publish

    def recording_publish(self: Any, msg: Any) -> None:
        objects.append(msg)
        original(self, msg)

    monkeypatch.setattr(dds_backend.DdsPublisher, 'publish', recording_publish)
    overrides = [
        'translation:=[1, 2, 3]', 'rotation:=[0, 0, 1]', 'radius:=2', 'period:=1', 'rate:=5',
    ]  # fmt: skip
    arguments = ['test', '--ros-args']
    for override in overrides:
        arguments += ['-p', override]
    dds_backend.init(args=arguments)
    yield objects
    if dds_backend.ok():
        dds_backend.shutdown()


@pytest.mark.dds
def test_tutorial_nodes_publish_rclpy_valid_messages(published: list[Any], tmp_path: Path) -> None:
    """Each node's published objects pass rclpy's field checks; raw payloads are bytes."""
    from tf_demo.msgs import nav_msgs
    from tf_demo.msgs import sensor_msgs
    from tf_demo.nodes import joint_state_publisher as jsp
    from tf_demo.nodes import robot_state_publisher as rsp
    from tf_demo.nodes.dynamic_tf_pub import DynamicTfPublisher
    from tf_demo.nodes.frame_broadcaster import FrameBroadcaster
    from tf_demo.nodes.odom_tf_broadcaster import OdomTfBroadcaster
    from tf_demo.nodes.static_tf_pub import StaticTfPublisher
    from tf_demo.transport.node import Node
    from tf_demo.transport.parameters import Parameter

    urdf = tmp_path / 'robot.urdf'
    urdf.write_text(ROBOT_URDF, encoding='utf-8')
    nodes: list[Node] = [StaticTfPublisher()]
    dynamic = DynamicTfPublisher()
    frame = FrameBroadcaster()
    odom = OdomTfBroadcaster()
    state = rsp.RobotStatePublisher(
        parameter_overrides=[Parameter('robot_description', value=ROBOT_URDF)]
    )
    joints = jsp.JointStatePublisher(str(urdf))
    nodes += [dynamic, frame, odom, state, joints]
    try:
        dynamic.publish_once()
        frame.publish_once()
        odometry = nav_msgs.Odometry()
        odometry.pose.pose.position.x = 1.5
        odom.on_odometry(odometry)
        joint_state = sensor_msgs.JointState(name=['rev'], position=[1.25])
        joint_state.header.stamp.sec = 10  # newer than the throttle's last (0) + its interval
        state._on_joint_state(joint_state)
        joints._on_timer()
    finally:
        for node in nodes:
            node.destroy_node()
    kinds = [type(obj).__name__ for obj in published]
    assert kinds.count('TFMessage') >= 5, kinds  # static, dynamic, frame, odom, rsp static
    assert 'bytes' in kinds  # robot_state_publisher's pre-encoded /tf
    assert 'JointState' in kinds
    for obj in published:
        if isinstance(obj, (bytes, bytearray, memoryview)):
            assert type(obj) is bytes
        else:
            assert rclpy_field_violations(obj) == [], repr(obj)
    static = published[0]
    assert [t.transform.translation.x for t in static.transforms] == [1.0]


STOPPED_WHILE_STARTING = """
import os, signal, sys
from tf_demo.transport import run_node
from tf_demo.transport.node import Node

class Slow(Node):
    def __init__(self):
        if {before}:  # under rclpy, its handler shuts the context down under the constructor
            os.kill(os.getpid(), signal.{signal_name})
        super().__init__('slow_start')
        if not {before}:
            os.kill(os.getpid(), signal.{signal_name})  # Ctrl-C / SIGTERM while the node starts
        print('constructed', flush=True)

    def destroy_node(self):
        print('destroyed', flush=True)
        super().destroy_node()

sys.exit(run_node(Slow, ['slow']))
"""


@pytest.mark.dds
@pytest.mark.parametrize('before', [False, True], ids=['in-constructor', 'before-node'])
@pytest.mark.parametrize('signal_name', ['SIGINT', 'SIGTERM'])
def test_a_stop_signal_while_the_node_starts_ends_cleanly(
    world_env: dict[str, str], tmp_path: Path, signal_name: str, before: bool
) -> None:
    """run_node's handlers are in place before init and construction: exit 0, no traceback.

    A node that was built is destroyed. Under rclpy a signal before the node exists shuts the
    context down, so building it fails: that is a stop too, not an error.
    """
    script = tmp_path / 'slow.py'
    text = STOPPED_WHILE_STARTING.replace('{signal_name}', signal_name)
    script.write_text(text.replace('{before}', str(before)), 'utf-8')
    python_path = os.pathsep.join([str(PACKAGE_ROOT), world_env.get('PYTHONPATH', '')])
    completed = run_captured(
        [sys.executable, str(script)], {**world_env, 'PYTHONPATH': python_path}
    )
    assert completed.returncode == 0, completed.stderr
    assert 'Traceback' not in completed.stderr
    built = ['constructed', 'destroyed']
    assert completed.stdout.split() in ([built] if WORLD == 'dds' or not before else [built, []])


#: rclpy/rclpy/qos.py (Jazzy): QoSPresetProfiles members in order; BEST_AVAILABLE is left out
#: on purpose (the standalone backend refuses BEST_AVAILABLE policies).
RCLPY_QOS_PRESETS = [
    'UNKNOWN', 'DEFAULT', 'SYSTEM_DEFAULT', 'SENSOR_DATA', 'SERVICES_DEFAULT', 'PARAMETERS',
    'PARAMETER_EVENTS', 'ACTION_STATUS_DEFAULT', 'BEST_AVAILABLE',
]  # fmt: skip


def test_qos_presets_match_rclpys_including_aliases() -> None:
    """Same preset names and order; equal profiles alias each other as in rclpy's Enum."""
    from tf_demo.transport import qos

    assert list(qos.QoSPresetProfiles.__members__) == RCLPY_QOS_PRESETS
    assert qos.QoSPresetProfiles['SERVICES_DEFAULT'].name == 'DEFAULT'  # an alias, as in rclpy
    assert qos.QoSPresetProfiles.get_from_short_key('default') == qos.QoSProfile(depth=10)
    status = qos.QoSPresetProfiles.ACTION_STATUS_DEFAULT.value
    assert (status.depth, status.durability) == (1, qos.DurabilityPolicy.TRANSIENT_LOCAL)


LEVEL_METHODS = frozenset({'debug', 'info', 'warning', 'warn', 'error', 'fatal'})


def _severity_varies(call: ast.Call) -> bool:
    """Whether one call expression can log at more than one severity."""
    func = call.func
    if isinstance(func, ast.IfExp):
        branches = (func.body, func.orelse)
        names = {b.attr for b in branches if isinstance(b, ast.Attribute)}
        return bool(names & LEVEL_METHODS) and len(names) > 1
    if isinstance(func, ast.Attribute) and func.attr == 'log' and len(call.args) >= 2:
        if ast.unparse(func.value).startswith('logging.'):
            return False  # the standard library's logging, not an rclpy logger
        return not isinstance(call.args[1], (ast.Constant, ast.Attribute))
    return False


def test_no_call_site_logs_at_two_severities() -> None:
    """rclpy raises 'Logger severity cannot be changed between calls.' for such a call site."""
    # rclpy/rclpy/impl/rcutils_logger.py: contexts keyed by CallerId(function, file, line,
    # f_lasti); a second call from the same site with another severity raises ValueError.
    problems: list[str] = []
    for directory in NODE_CODE_DIRS:
        for path in sorted((REPO_ROOT / directory).glob('*.py')):
            tree = ast.parse(path.read_text(encoding='utf-8'))
            problems.extend(
                f'{path.relative_to(REPO_ROOT)}:{node.lineno}: {ast.unparse(node)}'
                for node in ast.walk(tree)
                if isinstance(node, ast.Call) and _severity_varies(node)
            )
    assert problems == []


def test_the_severity_check_sees_both_forms() -> None:
    """Conditional logger methods and ``log(text, variable)`` are reported; constants are not."""

    def call(code: str) -> ast.Call:
        node = ast.parse(code).body[0].value  # type: ignore[attr-defined]
        assert isinstance(node, ast.Call)
        return node

    assert _severity_varies(call('(logger.warning if bad else logger.error)(text)'))
    assert _severity_varies(call('logger.log(text, level)'))
    assert not _severity_varies(call('logger.log(text, LoggingSeverity.WARN)'))
    assert not _severity_varies(call('logger.warning(text)'))
    assert not _severity_varies(call("logging.getLogger('x').log(level, text)"))


@pytest.mark.dds
@pytest.mark.parametrize('signal_name', ['SIGTERM', 'SIGINT'])
def test_a_cli_tool_stops_on_a_stop_signal_with_exit_0(spawn: Any, signal_name: str) -> None:
    """tf_echo (run_tool: SIGTERM handler set before init, as rclpy needs) exits 0 quietly."""
    import signal

    echo = spawn.start('tf_echo', 'nowhere', 'nothing')
    assert echo.stderr is not None
    for line in echo.stderr:  # bounded by the process's own output
        if 'Waiting for transform' in line:
            break
    echo.send_signal(getattr(signal, signal_name))
    _, stderr = echo.communicate(timeout=30)
    assert echo.returncode == 0, stderr
    assert 'Traceback' not in stderr
