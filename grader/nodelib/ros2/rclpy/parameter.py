"""rclpy.parameter.Parameter and its types; ParameterDescriptor/SetParametersResult from rcl_interfaces when that
message package is present, else small stand-ins with the same fields."""
from __future__ import annotations

import array
from enum import IntEnum

try:
    from rcl_interfaces.msg import ParameterDescriptor, SetParametersResult  # type: ignore
except ImportError:  # the message packages of this tree may not carry rcl_interfaces
    class ParameterDescriptor:  # type: ignore[no-redef]
        def __init__(self, name: str = "", type: int = 0, description: str = "", additional_constraints: str = "",
                     read_only: bool = False, dynamic_typing: bool = False, floating_point_range=None,
                     integer_range=None) -> None:
            self.name = name
            self.type = type
            self.description = description
            self.additional_constraints = additional_constraints
            self.read_only = read_only
            self.dynamic_typing = dynamic_typing
            self.floating_point_range = list(floating_point_range or [])
            self.integer_range = list(integer_range or [])

    class SetParametersResult:  # type: ignore[no-redef]
        def __init__(self, successful: bool = False, reason: str = "") -> None:
            self.successful = successful
            self.reason = reason

        def __repr__(self) -> str:
            return f"rcl_interfaces.msg.SetParametersResult(successful={self.successful}, reason='{self.reason}')"


# rcl_interfaces/msg/ParameterValue's field for each Parameter.Type
_VALUE_FIELDS = {1: "bool_value", 2: "integer_value", 3: "double_value", 4: "string_value", 5: "byte_array_value",
                 6: "bool_array_value", 7: "integer_array_value", 8: "double_array_value", 9: "string_array_value"}


class Parameter:
    class Type(IntEnum):
        NOT_SET = 0
        BOOL = 1
        INTEGER = 2
        DOUBLE = 3
        STRING = 4
        BYTE_ARRAY = 5
        BOOL_ARRAY = 6
        INTEGER_ARRAY = 7
        DOUBLE_ARRAY = 8
        STRING_ARRAY = 9

        # Jazzy's Parameter.Type is an Enum: it prints as Type.DOUBLE (on-set refusals name it so), where Kilted's
        # IntEnum prints 3.
        def __str__(self) -> str:
            return f"Type.{self.name}"

        def __format__(self, spec: str) -> str:
            return format(str(self), spec)

        @classmethod
        def from_parameter_value(cls, parameter_value) -> Parameter.Type:
            if parameter_value is None:
                return Parameter.Type.NOT_SET
            if isinstance(parameter_value, bool):
                return Parameter.Type.BOOL
            if isinstance(parameter_value, int):
                return Parameter.Type.INTEGER
            if isinstance(parameter_value, float):
                return Parameter.Type.DOUBLE
            if isinstance(parameter_value, str):
                return Parameter.Type.STRING
            if isinstance(parameter_value, (list, tuple, array.array)):
                for kind, cls_ in ((Parameter.Type.BYTE_ARRAY, bytes), (Parameter.Type.BOOL_ARRAY, bool),
                                   (Parameter.Type.INTEGER_ARRAY, int), (Parameter.Type.DOUBLE_ARRAY, float),
                                   (Parameter.Type.STRING_ARRAY, str)):
                    if all(isinstance(v, cls_) for v in parameter_value):
                        return kind
                raise TypeError(f"The given value is not a list of one of the allowed types '{parameter_value}'.")
            raise TypeError(f"The given value is not one of the allowed types '{parameter_value}'.")

        def check(self, parameter_value) -> bool:
            try:
                kind = Parameter.Type.from_parameter_value(parameter_value)
            except TypeError:
                return False
            return kind == self or (isinstance(parameter_value, (list, tuple, array.array)) and not parameter_value
                                    and self >= Parameter.Type.BYTE_ARRAY)

    @classmethod
    def from_parameter_msg(cls, param_msg) -> Parameter:
        """The Parameter an rcl_interfaces/msg/Parameter carries (a set_parameters request's)."""
        type_ = Parameter.Type(param_msg.value.type)
        field = _VALUE_FIELDS.get(int(type_))
        return cls(param_msg.name, type_, None if field is None else getattr(param_msg.value, field))

    def __init__(self, name: str, type_: Type | None = None, value=None) -> None:
        if type_ is None:
            type_ = Parameter.Type.from_parameter_value(value)
        if not isinstance(type_, Parameter.Type):
            raise TypeError("type must be an instance of '{}'".format(repr(Parameter.Type)))
        if not type_.check(value):
            raise ValueError(f"Type '{type_}' and value '{value}' do not agree")
        self._type_ = type_
        self._name = name
        self._value = value

    @property
    def name(self) -> str:
        return self._name

    @property
    def type_(self) -> Type:
        return self._type_

    @property
    def value(self):
        return self._value

    def get_parameter_value(self):
        from rcl_interfaces.msg import ParameterValue
        value = ParameterValue(type=self.type_.value)
        field = _VALUE_FIELDS.get(int(self.type_))
        if field is not None:
            setattr(value, field, self.value)
        return value

    def to_parameter_msg(self):
        from rcl_interfaces.msg import Parameter as ParameterMsg
        return ParameterMsg(name=self.name, value=self.get_parameter_value())

    def __repr__(self) -> str:
        return "<rclpy.parameter.Parameter object at 0x7f0000000000>"


def parameter_value_to_python(parameter_value):
    field = _VALUE_FIELDS.get(parameter_value.type)
    if parameter_value.type == 0:
        return None
    if field is None:
        raise RuntimeError(f"unexpected parameter type {parameter_value.type}")
    value = getattr(parameter_value, field)
    return list(value) if parameter_value.type >= 5 else value
