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
The message base class; each subclass gets its slots and methods from the schema table.

A package module declares ``class Vector3(Message): ...``; the metaclass looks up
``geometry_msgs/msg/Vector3`` in :data:`tf_demo.msgs._schema.SPECS` and generates ``__slots__``,
a keyword-only constructor with rclpy's defaults, ``__eq__``, an rclpy-like ``__repr__`` and the
class attributes ``__msgtype__``, ``__dds_typename__`` and ``__typehash__``.
"""

from __future__ import annotations

from array import array
from collections.abc import Callable
import importlib
import sys
from typing import Any
from typing import cast
from typing import ClassVar
from typing import TYPE_CHECKING
from typing import TypeVar

import numpy
from tf_demo.msgs._schema import FieldSpec
from tf_demo.msgs._schema import MessageSpec
from tf_demo.msgs._schema import PRIMITIVES
from tf_demo.msgs._schema import rclpy_field_type
from tf_demo.msgs._schema import spec_for
from tf_demo.msgs.typehash import type_hash

MessageT = TypeVar('MessageT', bound='Message')

#: Every generated message class, by ``pkg/msg/Name``.
REGISTRY: dict[str, type[Message]] = {}


def message_class(msgtype: str) -> type[Message]:
    """
    Return the class of ``msgtype`` (``pkg/msg/Name``), importing its package module.

    :raises KeyError: the type is not one of :mod:`tf_demo.msgs`.
    """
    cls = REGISTRY.get(msgtype)
    if cls is None:
        spec = spec_for(msgtype)
        importlib.import_module(f'tf_demo.msgs.{spec.package}')
        cls = REGISTRY[spec.msgtype]
    return cls


def _sequence_equal(left: Any, right: Any) -> bool:
    """Compare two sequences element-wise, whatever container (list, array, ndarray) holds them."""
    try:
        return len(left) == len(right) and all(a == b for a, b in zip(left, right, strict=True))
    except TypeError:
        return False


def _reject_arguments(cls: type, positional: tuple[Any, ...], unknown: dict[str, Any]) -> None:
    """Raise the error for positional arguments or keyword arguments that are not fields."""
    if positional:
        count = len(positional)
        msg = (
            f'{cls.__name__}() takes keyword arguments only (as in rclpy), got {count} positional'
        )
        raise TypeError(msg)
    names = ', '.join(sorted(unknown))
    fields = ', '.join(cls.__slots__)  # type: ignore[attr-defined]
    msg = f'{cls.__name__}() got unknown field(s) {names}; its fields are: {fields}'
    raise TypeError(msg)


def _default_source(field: FieldSpec, namespace: dict[str, Any]) -> tuple[str, bool]:
    """Return (Python expression of the default value, whether it must be built per call)."""
    if field.kind == 'single':
        if field.is_nested:
            alias = '_C_' + field.base.replace('/', '_')
            namespace[alias] = message_class(field.base)
            return f'{alias}()', True
        if field.base == 'string':
            return repr(field.default if field.default is not None else ''), False
        value = field.default if field.default is not None else PRIMITIVES[field.base].default
        return repr(value), False
    if field.kind == 'sequence':
        if field.base in PRIMITIVES and PRIMITIVES[field.base].array_code:
            return f'_array({PRIMITIVES[field.base].array_code!r})', True
        return '[]', True
    # fixed-size array
    if field.base in PRIMITIVES and PRIMITIVES[field.base].numpy_dtype:
        return f'_numpy.zeros({field.size}, dtype={PRIMITIVES[field.base].numpy_dtype!r})', True
    if field.is_nested:
        alias = '_C_' + field.base.replace('/', '_')
        namespace[alias] = message_class(field.base)
        return f'[{alias}() for _ in range({field.size})]', True
    if field.base == 'string':
        return f'[""] * {field.size}', True
    return f'[{PRIMITIVES[field.base].default!r}] * {field.size}', True


def blank_instance_maker(cls: type[MessageT]) -> Callable[[], MessageT]:
    """
    Return a function that makes an instance of the message class ``cls`` with no field set.

    It calls ``type.__call__`` on the class, which runs no Python code (the classes have no
    ``__init__``; their keyword constructor is their metaclass's ``__call__``): the fastest way
    to make objects there is, for decoders that then set every field.
    """
    make: Callable[[], MessageT] = type.__call__.__get__(cls)
    return make


def _generate_methods(spec: MessageSpec) -> dict[str, Any]:
    """Generate the keyword constructor (a metaclass ``__call__``) and ``__eq__`` for ``spec``."""
    namespace: dict[str, Any] = {
        '_array': array,
        '_numpy': numpy,
        '_reject_arguments': _reject_arguments,
        '_sequence_equal': _sequence_equal,
    }
    params = []
    body = []
    for field in spec.fields:
        default, per_call = _default_source(field, namespace)
        if per_call:
            params.append(f'{field.name}=None')
            body.append(
                f'    self.{field.name} = {default} if {field.name} is None else {field.name}'
            )
        else:
            params.append(f'{field.name}={default}')
            body.append(f'    self.{field.name} = {field.name}')
    lines = [
        f'def __call__(cls_, /, *positional_, {"".join(p + ", " for p in params)}**unknown_):',
        '    if unknown_ or positional_:',
        '        _reject_arguments(cls_, positional_, unknown_)',
        '    self = _make()',
        *body,
        '    return self',
        '',
        'def __eq__(self, other):',
        '    if type(other) is not type(self):',
        '        return NotImplemented if not isinstance(other, _Message) else False',
    ]
    for field in spec.fields:
        if field.kind == 'single':
            lines.append(f'    if self.{field.name} != other.{field.name}:')
        else:
            lines.append(f'    if not _sequence_equal(self.{field.name}, other.{field.name}):')
        lines.append('        return False')
    lines += ['    return True', '']
    namespace['_Message'] = Message
    exec(compile('\n'.join(lines), f'<tf_demo.msgs {spec.msgtype}>', 'exec'), namespace)
    # The caller binds ``_make`` (the class's blank_instance_maker) once the class exists.
    return {
        '__call__': namespace['__call__'],
        '__eq__': namespace['__eq__'],
        '_globals': namespace,
    }


def _field_repr(field: FieldSpec, value: Any) -> str:
    """Format one field value as rclpy's ``__repr__`` does (arrays shown as lists)."""
    text = repr(value)
    if field.kind == 'sequence' and isinstance(value, array):
        text = '[]' if not value else repr(value.tolist())
    return text


class _MessageMeta(type):
    """
    Build a message class from its entry in the schema table.

    Each class gets its own metaclass (``Metaclass_<Name>``, as rclpy's generated classes do)
    whose ``__call__`` is the class's generated keyword constructor, so that the class itself
    has no ``__init__`` and :func:`blank_instance_maker` makes instances without Python code.
    """

    def __new__(
        mcs,
        name: str,
        bases: tuple[type, ...],
        namespace: dict[str, Any],
    ) -> _MessageMeta:
        module = str(namespace.get('__module__', ''))
        if not bases or module == __name__:
            return super().__new__(mcs, name, bases, namespace)
        package = module.rsplit('.', 1)[-1]
        declared = namespace.get('__msgtype__')  # a service's request/response/event
        spec = spec_for(declared if isinstance(declared, str) else f'{package}/msg/{name}')
        namespace['__slots__'] = tuple(field.name for field in spec.fields)
        namespace['__msgtype__'] = spec.msgtype
        namespace['__dds_typename__'] = spec.dds_typename
        namespace['__typehash__'] = type_hash(spec.msgtype)
        namespace['_spec'] = spec
        namespace['_fields_and_field_types'] = {
            field.name: rclpy_field_type(field) for field in spec.fields
        }
        methods = _generate_methods(spec)
        namespace['__eq__'] = methods['__eq__']
        metaclass = type(
            f'Metaclass_{name}',
            (mcs,),
            {'__call__': methods['__call__'], '__module__': module},
        )
        cls: Any = super().__new__(metaclass, name, bases, namespace)
        methods['_globals']['_make'] = blank_instance_maker(cls)
        REGISTRY[spec.msgtype] = cls
        return cast('_MessageMeta', cls)


class Message(metaclass=_MessageMeta):
    """Base of the standalone world's ROS message classes (rclpy-compatible surface)."""

    __slots__ = ()
    __msgtype__: ClassVar[str]
    __dds_typename__: ClassVar[str]
    __typehash__: ClassVar[str]
    _spec: ClassVar[MessageSpec]
    _fields_and_field_types: ClassVar[dict[str, str]]

    if TYPE_CHECKING:

        def __init__(self, **fields: Any) -> None: ...

        def __getattr__(self, name: str) -> Any: ...

        def __setattr__(self, name: str, value: Any) -> None: ...

    __hash__ = None  # type: ignore[assignment]

    @classmethod
    def get_fields_and_field_types(cls) -> dict[str, str]:
        """Return field names mapped to their rosidl type strings, as rclpy does."""
        return dict(cls._fields_and_field_types)

    def __repr__(self) -> str:
        """Format as rclpy does: ``pkg.msg.Name(field=value, ...)`` (``pkg.srv.`` for services)."""
        spec = self._spec
        args = ', '.join(
            f'{field.name}={_field_repr(field, getattr(self, field.name))}'
            for field in spec.fields
        )
        return f'{spec.package}.{spec.interface}.{spec.name}({args})'


#: Every generated service type, by ``pkg/srv/Name``.
SERVICE_REGISTRY: dict[str, type[Service]] = {}


class Service:
    """
    Base of the standalone world's ROS service types (rclpy's ``srv`` class surface).

    A package module declares ``class GetParameters(Service): ...``; the subclass gets the
    message classes ``Request``, ``Response`` and ``Event`` (also module attributes
    ``GetParameters_Request`` etc.) from the schema table, and ``__srvtype__``,
    ``__typehash__`` (the service's RIHS01 hash, as rosidl computes it).
    """

    Request: ClassVar[type[Message]]
    Response: ClassVar[type[Message]]
    Event: ClassVar[type[Message]]
    __srvtype__: ClassVar[str]
    __typehash__: ClassVar[str]

    def __init_subclass__(cls, **kwargs: Any) -> None:
        super().__init_subclass__(**kwargs)
        module = sys.modules[cls.__module__]
        package = cls.__module__.rsplit('.', 1)[-1]
        srvtype = f'{package}/srv/{cls.__name__}'
        for part in ('Request', 'Response', 'Event'):
            name = f'{cls.__name__}_{part}'
            namespace = {
                '__module__': cls.__module__,
                '__qualname__': name,
                '__doc__': f'{srvtype}_{part}.',
                '__msgtype__': f'{srvtype}_{part}',
            }
            message_cls = _MessageMeta(name, (Message,), namespace)
            setattr(module, name, message_cls)
            setattr(cls, part, message_cls)
        cls.__srvtype__ = srvtype
        cls.__typehash__ = type_hash(srvtype)
        SERVICE_REGISTRY[srvtype] = cls
