"""Jazzy turtlesim's own parameters: what its node declares, and what its set_parameters and get_parameters services
answer (rclcpp's ParameterService and NodeParameters, ros2/rclcpp branch jazzy), in plain values.

turtle_frame.cpp (ros/ros_tutorials rolling 1.8.2, what Jazzy ships) declares ``background_r/g/b`` as integers with
the range 0..255 step 1 and ``holonomic`` as a bool; rclcpp adds ``use_sim_time`` and the read-only
``start_type_description_service``. None is dynamically typed, so a value of another type is refused, as is a name the
node never declared. The values live on the run's parameter tree under ``/turtlesim/<name>``.
"""
from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from typing import Protocol

NOT_SET, BOOL, INTEGER, DOUBLE, STRING = 0, 1, 2, 3, 4
# rcl_interfaces/msg/ParameterType by number, as rclcpp's to_string names them, and the ParameterValue field of each.
TYPE_NAMES = ("not set", "bool", "integer", "double", "string", "byte_array", "bool_array", "integer_array",
              "double_array", "string_array")
VALUE_FIELDS = ("", "bool_value", "integer_value", "double_value", "string_value", "byte_array_value",
                "bool_array_value", "integer_array_value", "double_array_value", "string_array_value")


class Tree(Protocol):
    """The run's parameter tree as the world reads and changes it (absolute names)."""

    def get(self, name: str, default: object = None) -> object: ...

    def set(self, name: str, value: object) -> None: ...


@dataclass(frozen=True)
class Declared:
    """One parameter as the node declares it: type, default, an integer range (from, to, step), read-only."""

    name: str
    type: int
    default: object
    integer_range: tuple[int, int, int] | None = None
    read_only: bool = False
    description: str = ""


DECLARED = {d.name: d for d in (
    Declared("background_b", INTEGER, 255, (0, 255, 1), description="Blue channel of the background color"),
    Declared("background_g", INTEGER, 86, (0, 255, 1), description="Green channel of the background color"),
    Declared("background_r", INTEGER, 69, (0, 255, 1), description="Red channel of the background color"),
    Declared("holonomic", BOOL, False, description="If true, then turtles will be holonomic"),
    Declared("start_type_description_service", BOOL, True, read_only=True), Declared("use_sim_time", BOOL, False))}


def _in_range(value: int, declared: Declared) -> bool:
    """rclcpp's integer range check: the ends always, else inside and on a step from ``from``."""
    if declared.integer_range is None:
        return True
    low, high, step = declared.integer_range
    if value in (low, high):
        return True
    return low <= value <= high and (step == 0 or (value - low) % step == 0)


def refusal(name: str, kind: int, value: object) -> str:
    """Why rclcpp refuses setting ``name`` to a value of ParameterType ``kind`` ('' when it is accepted)."""
    declared = DECLARED.get(name)
    if declared is None:
        return f"parameter '{name}' cannot be set because it was not declared"
    if declared.read_only:
        return f"parameter '{name}' cannot be set because it is read-only"
    if kind != declared.type:
        return (f"Wrong parameter type, parameter {{{name}}} is of type {{{TYPE_NAMES[declared.type]}}}, setting it "
                f"to {{{_type_name(kind)}}} is not allowed.")
    if kind == INTEGER and not _in_range(int(value), declared):  # type: ignore[call-overload]
        return f"Parameter {{{name}}} doesn't comply with integer range."
    return ""


def _type_name(kind: int) -> str:
    return TYPE_NAMES[kind] if 0 <= kind < len(TYPE_NAMES) else "unknown type"


def value_of(message: Mapping[str, object]) -> tuple[int, object]:
    """(type, value) of a ParameterValue given as plain values."""
    kind = int(message["type"])  # type: ignore[call-overload]
    field = VALUE_FIELDS[kind] if 0 < kind < len(VALUE_FIELDS) else ""
    return kind, message.get(field) if field else None


def value_message(kind: int, value: object) -> dict[str, object]:
    """A ParameterValue as plain values: the type and its one field (the others keep their defaults)."""
    return {"type": kind, VALUE_FIELDS[kind]: value} if kind else {"type": NOT_SET}


def set_parameters(node: str, tree: Tree, parameters: Sequence[Mapping[str, object]]) -> tuple[list[dict], list[str]]:
    """The SetParameters results for each parameter in turn (rclcpp sets them one by one), and the names set."""
    results, changed = [], []
    for parameter in parameters:
        name = str(parameter["name"])
        kind, value = value_of(parameter["value"])  # type: ignore[arg-type]
        reason = refusal(name, kind, value)
        if not reason:
            tree.set(f"{node}/{name}", value)
            changed.append(name)
        results.append({"successful": not reason, "reason": reason})
    return results, changed


def get_parameters(node: str, tree: Tree, names: Sequence[str]) -> list[dict]:
    """The GetParameters values in order; none at all when one name is not declared (rclcpp's service catches the
    exception and answers an empty list)."""
    if any(name not in DECLARED for name in names):
        return []
    return [value_message(DECLARED[name].type, tree.get(f"{node}/{name}", DECLARED[name].default)) for name in names]


def describe_parameters(names: Sequence[str]) -> list[dict]:
    """The DescribeParameters descriptors in order (`ros2 param describe`); none at all when one name is not
    declared, as get_parameters. turtle_frame.cpp's descriptions; rclcpp's own two are given without one."""
    if any(name not in DECLARED for name in names):
        return []
    return [{"name": name, "type": DECLARED[name].type, "description": DECLARED[name].description,
             "read_only": DECLARED[name].read_only,
             "integer_range": [] if DECLARED[name].integer_range is None else [dict(zip(
                 ("from_value", "to_value", "step"), DECLARED[name].integer_range))]}
            for name in names]
