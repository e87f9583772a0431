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
The base classes of the message and service classes, and the registry of both.

The message classes are generated from the schema table
(:data:`tf_demo.msgs._schema.DEFINITIONS`) into the type store ``_types.py`` by
:mod:`tf_demo.msgs._typegen`, and re-exported by their package modules (``geometry_msgs.py``
etc.), which are their ``__module__``. Each message class declares its ``__msgtype__``, its
``__slots__`` and typed fields, its constants, a keyword-only constructor with rclpy's defaults
(written as ``__new__``) and ``__eq__``.

:class:`MessageMeta` adds what follows from the table (``__dds_typename__``, ``__typehash__``,
rclpy's field type strings) and installs the constructor as the class's own call, in a metaclass
``Metaclass_<Name>`` as rclpy's generated classes have. The class itself keeps ``object``'s
``__new__`` and ``__init__``, so that ``type.__call__`` makes a bare instance of it without
running any Python code (:func:`blank_instance_maker`): the fastest way to make objects there is,
for the decoders, which then set every field.
"""

from __future__ import annotations

from array import array
from collections.abc import Callable
from collections.abc import Collection
from collections.abc import Mapping
import importlib
from typing import ClassVar
from typing import NoReturn
from typing import TYPE_CHECKING
from typing import TypeVar

from tf_demo.msgs._schema import FieldSpec
from tf_demo.msgs._schema import MessageSpec
from tf_demo.msgs._schema import rclpy_field_type
from tf_demo.msgs._schema import SchemaError
from tf_demo.msgs._schema import spec_for
from tf_demo.msgs.typehash import type_hash

MessageT = TypeVar('MessageT', bound='Message')

#: Every message class, by ``pkg/msg/Name``.
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


def sequences_equal(left: Collection[object], right: Collection[object]) -> bool:
    """Compare two sequences element-wise, whatever container (list, array, ndarray) holds them."""
    try:
        return len(left) == len(right) and all(a == b for a, b in zip(left, right, strict=True))
    except TypeError:  # a field that holds no sequence
        return False


def blank_instance_maker(cls: type[MessageT]) -> Callable[[], MessageT]:
    """
    Return a function that makes an instance of the message class ``cls`` with no field set.

    It is ``type.__call__`` bound to the class, which runs no Python code (see the module
    docstring): the fastest way to make objects there is, for decoders that set every field.
    """
    make: Callable[[], MessageT] = type.__call__.__get__(cls)
    return make


def _field_repr(field: FieldSpec, value: object) -> str:
    """Format one field value as rclpy's ``__repr__`` does (arrays shown as lists)."""
    text = repr(value)
    if field.kind == 'sequence' and isinstance(value, array):
        text = '[]' if not value else repr(value.tolist())
    return text


class MessageMeta(type):
    """
    Complete a generated message class from its entry in the schema table (module docstring).

    The class's ``__new__`` (its keyword constructor) becomes the ``__call__`` of the class's
    own metaclass ``Metaclass_<Name>``, a subclass of this one.
    """

    def __new__(
        mcs,
        name: str,
        bases: tuple[type, ...],
        namespace: dict[str, object],
    ) -> MessageMeta:
        constructor = namespace.pop('__new__', None)
        if constructor is None:  # Message itself
            return super().__new__(mcs, name, bases, namespace)
        spec = spec_for(str(namespace['__msgtype__']))
        if namespace.get('__slots__') != tuple(field.name for field in spec.fields):
            msg = (
                f'the class of {spec.msgtype} in {namespace["__module__"]} does not have the '
                'fields of the schema table: run python -m tf_demo.msgs._typegen --write'
            )
            raise SchemaError(msg)
        # The class lives in the type store; its home for users is its package's module.
        namespace['__module__'] = f'tf_demo.msgs.{spec.package}'
        namespace['__dds_typename__'] = spec.dds_typename
        namespace['__typehash__'] = type_hash(spec.msgtype)
        namespace['_spec'] = spec
        namespace['_fields_and_field_types'] = {
            field.name: rclpy_field_type(field) for field in spec.fields
        }
        metaclass = type(
            f'Metaclass_{name}',
            (mcs,),
            {'__call__': constructor, '__module__': namespace['__module__']},
        )
        cls: MessageMeta = super().__new__(metaclass, name, bases, namespace)
        return cls


class Message(metaclass=MessageMeta):
    """Base of the standalone world's ROS message classes (rclpy-compatible surface)."""

    __slots__ = ()
    __msgtype__: ClassVar[str]
    __dds_typename__: ClassVar[str]
    __typehash__: ClassVar[str]
    _spec: ClassVar[MessageSpec]
    _fields_and_field_types: ClassVar[dict[str, str]]
    __hash__ = None  # type: ignore[assignment]

    if TYPE_CHECKING:  # what generic code may call; each class's own __new__ names its fields

        def __new__(cls: type[MessageT], **fields: object) -> MessageT: ...

    def __init_subclass__(cls, **kwargs: object) -> None:
        super().__init_subclass__(**kwargs)
        REGISTRY[cls.__msgtype__] = cls

    @classmethod
    def _reject_arguments(
        cls, positional: tuple[object, ...], unknown: Mapping[str, object]
    ) -> NoReturn:
        """Raise the error for positional arguments or keyword arguments that are not fields."""
        if positional:
            count = len(positional)
            msg = (
                f'{cls.__name__}() takes keyword arguments only (as in rclpy), '
                f'got {count} positional'
            )
            raise TypeError(msg)
        names = ', '.join(sorted(unknown))
        fields = ', '.join(cls.__slots__)
        msg = f'{cls.__name__}() got unknown field(s) {names}; its fields are: {fields}'
        raise TypeError(msg)

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


#: Every service type, by ``pkg/srv/Name``.
SERVICE_REGISTRY: dict[str, type[Service]] = {}


class Service:
    """
    Base of the standalone world's ROS service types (rclpy's ``srv`` class surface).

    The type store declares ``class GetParameters(Service)`` with its
    ``__srvtype__`` and the message classes ``Request``, ``Response`` and ``Event`` (module
    attributes ``GetParameters_Request`` etc.); the subclass gets ``__typehash__``, the
    service's RIHS01 hash as rosidl computes it.
    """

    Request: ClassVar[type[Message]]
    Response: ClassVar[type[Message]]
    Event: ClassVar[type[Message]]
    __srvtype__: ClassVar[str]
    __typehash__: ClassVar[str]

    def __init_subclass__(cls, **kwargs: object) -> None:
        super().__init_subclass__(**kwargs)
        cls.__typehash__ = type_hash(cls.__srvtype__)
        cls.__module__ = f'tf_demo.msgs.{cls.__srvtype__.split("/", 1)[0]}'
        SERVICE_REGISTRY[cls.__srvtype__] = cls
