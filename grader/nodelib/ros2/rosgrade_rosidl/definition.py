"""The field type descriptors a message class lists in ``SLOT_TYPES``, shaped like ``rosidl_parser.definition``'s."""
from __future__ import annotations


class AbstractType:
    """Base of all descriptors; equal when of the same class and contents, as rosidl_parser compares them."""

    __slots__ = ()

    def __eq__(self, other: object) -> bool:
        return type(self) is type(other) and all(
            getattr(self, name) == getattr(other, name) for cls in type(self).__mro__
            for name in getattr(cls, "__slots__", ()))

    __hash__ = None  # type: ignore[assignment]  # rosidl_parser's descriptors are unhashable too


class AbstractNestableType(AbstractType):
    __slots__ = ()


class BasicType(AbstractNestableType):
    """A numeric, boolean or octet type named by its IDL ``typename`` ('double', 'uint8', 'boolean', ...)."""

    __slots__ = ("typename",)

    def __init__(self, typename: str) -> None:
        self.typename = typename


class NamespacedType(AbstractNestableType):
    """Another message, e.g. ``NamespacedType(['geometry_msgs', 'msg'], 'Vector3')``."""

    __slots__ = ("namespaces", "name")

    def __init__(self, namespaces: list[str], name: str) -> None:
        self.namespaces = namespaces
        self.name = name

    def namespaced_name(self) -> tuple[str, ...]:
        return (*self.namespaces, self.name)


class AbstractGenericString(AbstractNestableType):
    __slots__ = ()


class AbstractString(AbstractGenericString):
    __slots__ = ()


class UnboundedString(AbstractString):
    __slots__ = ()

    def has_maximum_size(self) -> bool:
        return False


class BoundedString(AbstractString):
    __slots__ = ("maximum_size",)

    def __init__(self, maximum_size: int) -> None:
        self.maximum_size = maximum_size

    def has_maximum_size(self) -> bool:
        return True


class AbstractNestedType(AbstractType):
    __slots__ = ("value_type",)

    def __init__(self, value_type: AbstractNestableType) -> None:
        self.value_type = value_type


class Array(AbstractNestedType):
    """A fixed-size array (``double[36]``)."""

    __slots__ = ("size",)

    def __init__(self, value_type: AbstractNestableType, size: int) -> None:
        super().__init__(value_type)
        self.size = size

    def has_maximum_size(self) -> bool:
        return True


class AbstractSequence(AbstractNestedType):
    __slots__ = ()


class UnboundedSequence(AbstractSequence):
    __slots__ = ()

    def has_maximum_size(self) -> bool:
        return False


class BoundedSequence(AbstractSequence):
    __slots__ = ("maximum_size",)

    def __init__(self, value_type: AbstractNestableType, maximum_size: int) -> None:
        super().__init__(value_type)
        self.maximum_size = maximum_size

    def has_maximum_size(self) -> bool:
        return True
