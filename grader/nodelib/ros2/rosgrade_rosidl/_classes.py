"""Builds message and service classes that behave like rosidl_generator_py's (Jazzy 0.22.2 / Kilted) generated ones.

Same slots, ``_fields_and_field_types``, ``SLOT_TYPES``, constants, defaults, constructor, ``__repr__``, ``__eq__``
(including its numpy quirk), and field checks that, as in Jazzy, run only when ``ROS_PYTHON_CHECK_FIELDS=1`` or the
constructor gets ``check_fields=True``. Classes are built on first use so that importing a package costs little.
"""
from __future__ import annotations

import array
import math
import os
import re
from collections import UserList, UserString
from collections.abc import Sequence, Set
from copy import copy
from typing import Any, Callable

from . import definition
from ._model import ARRAY, NUMERIC_CONTAINERS, SCALAR, SEQUENCE, Field, TypeSpec, UnknownType, snake_case, spec
from ._defs import SERVICES
from ._extra import ACTIONS

# rosidl reads it once per generated module at import; here once per process.
CHECK_FIELDS = os.environ.get("ROS_PYTHON_CHECK_FIELDS", "") == "1"

_PY_TYPES = {"boolean": bool, "octet": bytes, "float": float, "double": float, "string": str, "wstring": str,
             **{name: int for name in ("int8", "uint8", "int16", "uint16", "int32", "uint32", "int64", "uint64")}}
_FLOAT_BOUNDS = {"float": ("float", 3.402823466e+38), "double": ("double", 1.7976931348623157e+308)}

_classes: dict[str, type] = {}
_numpy_module: list = []


def _numpy() -> Any:
    if not _numpy_module:
        import numpy  # noqa: PLC0415 - ~60 ms, paid only by types with fixed numeric arrays
        _numpy_module.append(numpy)
    return _numpy_module[0]


class TypeSupport:
    """What ``_TYPE_SUPPORT`` holds once imported: a marker naming the interface (there is no C type support)."""

    __slots__ = ("type_name",)

    def __init__(self, type_name: str) -> None:
        self.type_name = type_name

    def __repr__(self) -> str:
        return f"<rosgrade type support {self.type_name}>"


def _module_name(type_name: str) -> str:
    """rosidl's module of an interface: geometry_msgs/msg/TwistStamped -> geometry_msgs.msg._twist_stamped."""
    package, namespace, name = type_name.split("/")
    if namespace in ("srv", "action"):  # a service's or action's parts live in its own module
        name = name.split("_", 1)[0]
    return f"{package}.{namespace}._{snake_case(name)}"


def _short(type_name: str) -> str:
    return type_name.rsplit("/", 1)[1]


def _is_numeric(field: Field) -> bool:
    return not field.nested and field.idl in NUMERIC_CONTAINERS


# --- descriptions -------------------------------------------------------------------------------------------------
def _field_type_text(field: Field) -> str:
    """The ``_fields_and_field_types`` text: 'double', 'sequence<int32>', 'double[36]', 'std_msgs/Header', ..."""
    if field.nested:
        package, _, name = field.base.split("/")
        text = f"{package}/{name}"
    elif field.base in ("string", "wstring"):
        text = ("w" if field.base == "wstring" else "") + "string" + (
            f"<{field.string_bound}>" if field.string_bound else "")
    else:
        text = field.idl
    if field.kind == SEQUENCE:
        return f"sequence<{text}, {field.size}>" if field.size else f"sequence<{text}>"
    if field.kind == ARRAY:
        return f"{text}[{field.size}]"
    return text


def _slot_type(field: Field) -> definition.AbstractType:
    if field.nested:
        package, namespace, name = field.base.split("/")
        element: definition.AbstractNestableType = definition.NamespacedType([package, namespace], name)
    elif field.base in ("string", "wstring"):
        element = definition.BoundedString(field.string_bound) if field.string_bound else definition.UnboundedString()
    else:
        element = definition.BasicType(field.idl)
    if field.kind == ARRAY:
        return definition.Array(element, field.size)
    if field.kind == SEQUENCE:
        return definition.BoundedSequence(element, field.size) if field.size else definition.UnboundedSequence(element)
    return element


# --- field checks (the asserts rosidl runs when fields are checked) -----------------------------------------------
def _range_check(field: Field) -> tuple[Callable[[Any], bool], str, str]:
    """(predicate on one value, scalar message, sequence message suffix) for a numeric field."""
    idl = field.idl
    if idl in _FLOAT_BOUNDS:
        word, bound = _FLOAT_BOUNDS[idl]
        return ((lambda v: not (v < -bound or v > bound) or math.isinf(v)),
                f"must be a {word} in [{-bound!r}, {bound!r}]", "and each %s in [%f, %f]" % (word, -bound, bound))
    bits = int(re.sub(r"\D", "", idl))
    if idl.startswith("u"):
        top = 1 << bits
        return ((lambda v: v >= 0 and v < top), f"must be an unsigned integer in [0, {top - 1}]",
                "and each unsigned integer in [0, %d]" % (top - 1))
    half = 1 << (bits - 1)
    return ((lambda v: v >= -half and v < half), f"must be an integer in [{-half}, {half - 1}]",
            "and each integer in [%d, %d]" % (-half, half - 1))


def _element_type(field: Field) -> tuple[type | Callable[[], type], str]:
    """(type or lazy class getter, its name as the assert messages spell it)."""
    if field.nested:
        return (lambda: message_class(field.base)), _short(field.base)
    python_type = _PY_TYPES[field.idl]
    return python_type, python_type.__name__


def _scalar_check(field: Field) -> Callable[[Any], None]:
    name = field.name
    if field.nested:
        base, short = field.base, _short(field.base)

        def check(value: Any) -> None:
            assert isinstance(value, message_class(base)), f"The '{name}' field must be a sub message of type '{short}'"
        return check
    idl = field.idl
    if idl == "octet":
        def check(value: Any) -> None:
            assert isinstance(value, (bytes, bytearray)) and len(value) == 1, \
                f"The '{name}' field must be of type 'bytes' or 'ByteString' with length 1"
        return check
    if field.base in ("string", "wstring"):
        bound = field.string_bound
        if bound:
            def check(value: Any) -> None:
                assert isinstance(value, (str, UserString)) and len(value) <= bound, \
                    f"The '{name}' field must be string value not longer than {bound}"
            return check

        def check(value: Any) -> None:
            assert isinstance(value, str), f"The '{name}' field must be of type 'str'"
        return check
    python_type = _PY_TYPES[idl]
    type_message = f"The '{name}' field must be of type '{python_type.__name__}'"
    if idl == "boolean":
        def check(value: Any) -> None:
            assert isinstance(value, bool), type_message
        return check
    in_range, range_message, _ = _range_check(field)
    range_message = f"The '{name}' field {range_message}"

    def check(value: Any) -> None:
        assert isinstance(value, python_type), type_message
        assert in_range(value), range_message
    return check


def _nested_check(field: Field) -> Callable[[Any], bool]:
    """Check of an array or sequence field; returns True when the value is stored as given (numpy/array fast path)."""
    name = field.name
    numeric = _is_numeric(field)
    dtype, typecode = NUMERIC_CONTAINERS[field.idl] if numeric else ("", "")
    element, element_name = _element_type(field)
    suffixes = ["a set or sequence"]
    string_bound = field.string_bound if field.base in ("string", "wstring") else 0
    if string_bound:
        suffixes.append("and each string value not longer than %d" % string_bound)
    if field.kind == SEQUENCE and field.size:
        suffixes.insert(1, "with length <= %d" % field.size)
    elif field.kind == ARRAY:
        suffixes.insert(1, "with length %d" % field.size)
    suffixes.append("and each value of type '%s'" % element_name)
    in_range: Callable[[Any], bool] | None = None
    if not field.nested and field.idl not in ("boolean", "octet", "string", "wstring"):
        in_range, _, range_suffix = _range_check(field)
        suffixes.append(range_suffix)
    message = f"The '{name}' field must be {' '.join(suffixes)}"

    def check(value: Any) -> bool:
        if numeric and field.kind == ARRAY and isinstance(value, _numpy().ndarray):
            assert value.dtype == dtype, f"The '{name}' numpy.ndarray() must have the dtype of 'numpy.{dtype}'"
            assert value.size == field.size, f"The '{name}' numpy.ndarray() must have a size of {field.size}"
            return True
        if numeric and field.kind == SEQUENCE and isinstance(value, array.array):
            assert value.typecode == typecode, \
                f"The '{name}' array.array() must have the type code of '{typecode}'"
            if field.size:
                assert len(value) <= field.size, f"The '{name}' array.array() must have a size <= {field.size}"
            return True
        element_type = element() if field.nested else element
        assert ((isinstance(value, (Sequence, Set, UserList)))
                and not isinstance(value, (str, UserString))
                and (not string_bound or all(len(v) <= string_bound for v in value))
                and (field.kind != ARRAY or len(value) == field.size)
                and (field.kind != SEQUENCE or not field.size or len(value) <= field.size)
                and all(isinstance(v, element_type) for v in value)
                and (in_range is None or all(in_range(v) for v in value))), message
        return False
    return check


def _property(field: Field) -> property:
    slot = "_" + field.name
    numeric = _is_numeric(field)
    if field.kind == SCALAR:
        scalar_check = _scalar_check(field)

        def fset(self: Any, value: Any) -> None:
            if self._check_fields:
                scalar_check(value)
            setattr(self, slot, value)
    else:
        nested_check = _nested_check(field)
        if numeric and field.kind == ARRAY:
            dtype = NUMERIC_CONTAINERS[field.idl][0]

            def convert(value: Any) -> Any:
                return _numpy().array(value, dtype=dtype)
        elif numeric:
            typecode = NUMERIC_CONTAINERS[field.idl][1]

            def convert(value: Any) -> Any:
                return array.array(typecode, value)
        else:
            def convert(value: Any) -> Any:
                return value

        def fset(self: Any, value: Any) -> None:
            if self._check_fields and nested_check(value):
                setattr(self, slot, value)
                return
            setattr(self, slot, convert(value))

    def fget(self: Any) -> Any:
        return getattr(self, slot)
    fget.__name__ = fset.__name__ = field.name
    return property(fget, fset, doc=f"Message field '{field.name}'.")


# --- constructor, repr, eq ----------------------------------------------------------------------------------------
def _initialiser(field: Field) -> Callable[[type, dict], Any]:
    """``(cls, kwargs) -> value`` the constructor assigns to one field, as rosidl's ``__init__`` computes it."""
    name = field.name
    if field.default is not None:
        default_attr = name.upper() + "__DEFAULT"
        return lambda cls, kwargs: kwargs.get(name, getattr(cls, default_attr))
    numeric = _is_numeric(field)
    if field.kind == ARRAY and numeric:
        dtype, size = NUMERIC_CONTAINERS[field.idl][0], field.size

        def numpy_array(cls: type, kwargs: dict) -> Any:
            return kwargs[name] if name in kwargs else _numpy().zeros(size, dtype=dtype)
        return numpy_array
    if field.kind == SEQUENCE and numeric:
        typecode = NUMERIC_CONTAINERS[field.idl][1]
        return lambda cls, kwargs: array.array(typecode, kwargs.get(name, []))
    if field.kind == SEQUENCE:
        return lambda cls, kwargs: kwargs[name] if name in kwargs else []
    if field.nested:
        def make() -> Any:
            return message_class(field.base)()
    elif field.idl == "octet":
        def make() -> Any:
            return bytes([0])
    else:
        make = _PY_TYPES[field.idl]
    if field.kind == ARRAY:
        size = field.size
        return lambda cls, kwargs: kwargs[name] if name in kwargs else [make() for _ in range(size)]
    return lambda cls, kwargs: kwargs[name] if name in kwargs else make()


def _init(type_spec: TypeSpec, slots: list[str]) -> Callable[..., None]:
    steps = [(field.name, _initialiser(field)) for field in type_spec.fields]
    slot_set = frozenset(slots)

    def __init__(self: Any, **kwargs: Any) -> None:
        check = kwargs["check_fields"] if "check_fields" in kwargs else CHECK_FIELDS
        self._check_fields = check
        if check:
            assert all("_" + key in slot_set for key in kwargs), \
                "Invalid arguments passed to constructor: %s" % ", ".join(
                    sorted(k for k in kwargs if "_" + k not in slot_set))
        cls = type(self)
        for name, initialise in steps:
            setattr(self, name, initialise(cls, kwargs))
    return __init__


def _repr(type_spec: TypeSpec) -> Callable[[Any], str]:
    names = [field.name for field in type_spec.fields]
    as_list = [field.kind == SEQUENCE and _is_numeric(field) for field in type_spec.fields]

    def __repr__(self: Any) -> str:
        typename = type(self).__module__.split(".")
        typename.pop()
        typename.append(type(self).__name__)
        args = []
        for name, strip in zip(names, as_list):
            value = getattr(self, name)
            text = repr(value)
            if strip:
                if len(value) == 0:
                    text = "[]"
                else:
                    if self._check_fields:
                        assert text.startswith("array(")
                    text = text[len("array('X', "):-1]
            args.append(name + "=" + text)
        return "%s(%s)" % (".".join(typename), ", ".join(args))
    return __repr__


def _eq(type_spec: TypeSpec) -> Callable[[Any, Any], bool]:
    # numpy array fields compare with any(a != b) (Jazzy 0.22.1 fixed the all() that 0.22.0 had).
    fields = [(field.name, field.kind == ARRAY and _is_numeric(field)) for field in type_spec.fields]

    def __eq__(self: Any, other: Any) -> bool:
        if not isinstance(other, self.__class__):
            return False
        for name, elementwise in fields:
            if elementwise:
                if any(getattr(self, name) != getattr(other, name)):
                    return False
            elif getattr(self, name) != getattr(other, name):
                return False
        return True
    return __eq__


# --- metaclasses and classes --------------------------------------------------------------------------------------
def _constant_property(name: str, value: Any, doc: str) -> property:
    def fget(cls: Any) -> Any:
        return value
    fget.__name__ = name
    return property(fget, doc=doc)


def _import_type_support(type_name: str) -> classmethod:
    def __import_type_support__(cls: Any) -> None:
        cls._TYPE_SUPPORT = TypeSupport(type_name)
    return classmethod(__import_type_support__)


def _build_message(type_spec: TypeSpec) -> type:
    name = _short(type_spec.name)
    constants = {cname: value for cname, _, value in type_spec.constants}
    defaults = {f"{f.name.upper()}__DEFAULT": f.default for f in type_spec.fields if f.default is not None}
    meta_ns: dict[str, Any] = {
        "__doc__": f"Metaclass of message '{name}'.",
        "_CREATE_ROS_MESSAGE": None, "_CONVERT_FROM_PY": None, "_CONVERT_TO_PY": None,
        "_DESTROY_ROS_MESSAGE": None, "_TYPE_SUPPORT": None,
        f"_Metaclass_{name}__constants": dict(constants),
        "__import_type_support__": _import_type_support(type_spec.name),
        "_rosgrade_type": type_spec.name,
    }
    for cname, value in constants.items():
        meta_ns[cname] = _constant_property(cname, value, f"Message constant '{cname}'.")
    for dname, value in defaults.items():
        meta_ns[dname] = _constant_property(dname, value, f"Return default value for message field '{dname[:-9].lower()}'.")
    meta = type(f"Metaclass_{name}", (type,), meta_ns)
    meta.__module__ = _module_name(type_spec.name)

    slots = [f"_{field.name}" for field in type_spec.fields] + ["_check_fields"]
    doc = f"Message class '{name}'."
    if constants:
        doc = f"\n    Message class '{name}'.\n\n    Constants:\n" + "".join(f"      {c}\n" for c in constants) + "    "
    ns: dict[str, Any] = {
        "__doc__": doc,
        "__module__": _module_name(type_spec.name),
        "__qualname__": name,
        "__slots__": slots,
        "_fields_and_field_types": {field.name: _field_type_text(field) for field in type_spec.fields},
        "SLOT_TYPES": tuple(_slot_type(field) for field in type_spec.fields),
        "__init__": _init(type_spec, slots),
        "__repr__": _repr(type_spec),
        "__eq__": _eq(type_spec),
        "get_fields_and_field_types": classmethod(lambda cls: copy(cls._fields_and_field_types)),
        **constants,
        **defaults,
    }
    for field in type_spec.fields:
        ns[field.name] = _property(field)
    for method in ("__init__", "__repr__", "__eq__"):  # tracebacks name them as rosidl's: "Twist.__init__()"
        ns[method].__qualname__ = f"{name}.{method}"
    return meta(name, (), ns)


def _build_service(type_name: str) -> type:
    name = _short(type_name)
    meta = type(f"Metaclass_{name}", (type,), {
        "__doc__": f"Metaclass of service '{name}'.",
        "_TYPE_SUPPORT": None,
        "__import_type_support__": _import_type_support(type_name),
        "_rosgrade_type": type_name,
    })
    meta.__module__ = _module_name(type_name + "_Request")

    def __init__(self: Any) -> None:
        raise NotImplementedError("Service classes can not be instantiated")
    return meta(name, (), {
        "__module__": _module_name(type_name + "_Request"),
        "__qualname__": name,
        "Request": message_class(type_name + "_Request"),
        "Response": message_class(type_name + "_Response"),
        "Event": message_class(type_name + "_Event"),
        "__init__": __init__,
    })


def message_class(type_name: str) -> type:
    """The class of ``pkg/msg/Name`` (or a service's ``pkg/srv/Name_Request``), built once."""
    cls = _classes.get(type_name)
    if cls is None:
        cls = _classes[type_name] = _build_message(spec(type_name))
    return cls


def service_class(type_name: str) -> type:
    """The class of ``pkg/srv/Name`` with its Request, Response and Event classes."""
    cls = _classes.get(type_name)
    if cls is None:
        if type_name not in SERVICES:
            raise UnknownType(f"unknown service type {type_name!r}")
        cls = _classes[type_name] = _build_service(type_name)
    return cls


def _build_action(type_name: str) -> type:
    name = _short(type_name)
    module = _module_name(type_name + "_Goal")
    meta = type(f"Metaclass_{name}", (type,), {
        "__doc__": f"Metaclass of action '{name}'.",
        "_TYPE_SUPPORT": None,
        "__import_type_support__": _import_type_support(type_name),
        "_rosgrade_type": type_name,
    })
    meta.__module__ = module
    impl = type("Impl", (), {
        "__module__": module, "__qualname__": f"{name}.Impl",
        "SendGoalService": service_class(type_name + "_SendGoal"),
        "GetResultService": service_class(type_name + "_GetResult"),
        "FeedbackMessage": message_class(type_name + "_FeedbackMessage"),
        # every action's generic cancel service and status message, as rosidl_generator_py names them
        "CancelGoalService": service_class("action_msgs/srv/CancelGoal"),
        "GoalStatusMessage": message_class("action_msgs/msg/GoalStatusArray"),
    })

    def __init__(self: Any) -> None:
        raise NotImplementedError("Action classes can not be instantiated")
    return meta(name, (), {
        "__module__": module,
        "__qualname__": name,
        "Goal": message_class(type_name + "_Goal"),
        "Result": message_class(type_name + "_Result"),
        "Feedback": message_class(type_name + "_Feedback"),
        "Impl": impl,
        "__init__": __init__,
    })


def action_class(type_name: str) -> type:
    """The class of ``pkg/action/Name`` with its Goal, Result and Feedback classes and, in ``Impl``, the services
    and feedback message rcl_action carries them in."""
    cls = _classes.get(type_name)
    if cls is None:
        if type_name not in ACTIONS:
            raise UnknownType(f"unknown action type {type_name!r}")
        cls = _classes[type_name] = _build_action(type_name)
    return cls
