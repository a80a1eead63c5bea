"""Where an rclpy script puts a Python int into a velocity command's float64 field (``msg.linear.x = 2``).

Real rclpy (Jazzy, built without field checks) serializes whatever a float64 field holds as if it were a float
object: an int's internal size word becomes the double's bits, about 5e-324 for a small int (measured with
ros-jazzy-rclpy 7.1.6 on CPython 3.11: 2 is sent as 5e-324, 2**40 as 1e-323, -3 as NaN), so the robot or turtle
barely moves and nothing says why. rospy converts the int (genpy packs it as a double), so only rclpy scripts are
checked. Found from the source: an int literal, or a name or ``self`` attribute bound once in the file to one. The
value named is the one rosgrade's rclpy sends on this interpreter (``as_double``, its model of rosidl's conversion).
"""
from __future__ import annotations

import ast
from dataclasses import dataclass
from pathlib import Path

from grader.nodelib.ros2.rosgrade_rosidl._convert import as_double
from grader.runtime.scripts import read_script
from grader.workspace.python_source import parse

VELOCITY_PARTS = frozenset({"linear", "angular"})
AXES = frozenset({"x", "y", "z"})


@dataclass(frozen=True)
class IntAssignment:
    """One assignment of an int to a Twist's linear/angular component: where, what it wrote, and the int."""

    line: int
    target: str
    value: int


def _int_literal(node: ast.expr) -> int | None:
    """The int an expression is when it is a literal (bools are not: rclpy's bool would be 1e-323 too, but nobody
    writes that)."""
    if isinstance(node, ast.Constant) and type(node.value) is int:
        return node.value
    if isinstance(node, ast.UnaryOp) and isinstance(node.op, (ast.USub, ast.UAdd)):
        inner = _int_literal(node.operand)
        return None if inner is None else (-inner if isinstance(node.op, ast.USub) else inner)
    return None


def _key(node: ast.expr) -> str | None:
    """A name or ``self.<attr>`` as text, the things a constant is kept in."""
    if isinstance(node, ast.Name):
        return node.id
    if isinstance(node, ast.Attribute) and isinstance(node.value, ast.Name) and node.value.id == "self":
        return f"self.{node.attr}"
    return None


def _constants(tree: ast.AST) -> dict[str, int]:
    """Names and self attributes assigned exactly once in the file, to an int literal."""
    seen: dict[str, list[int | None]] = {}
    for node in ast.walk(tree):
        if isinstance(node, ast.Assign):
            for target in node.targets:
                key = _key(target)
                if key is not None:
                    seen.setdefault(key, []).append(_int_literal(node.value))
        elif isinstance(node, (ast.AugAssign, ast.AnnAssign)):
            key = _key(node.target)
            if key is not None:
                seen.setdefault(key, []).append(None)
    return {key: values[0] for key, values in seen.items() if len(values) == 1 and values[0] is not None}


def _is_velocity(target: ast.expr) -> bool:
    """``<anything>.linear.x`` ... ``<anything>.angular.z``."""
    return (isinstance(target, ast.Attribute) and target.attr in AXES and isinstance(target.value, ast.Attribute)
            and target.value.attr in VELOCITY_PARTS)


def int_assignments(source: str) -> list[IntAssignment]:
    """Every assignment of a non-zero int to a velocity component, in line order (none for code that does not parse:
    Python's own error is reported elsewhere)."""
    try:
        tree = parse(source)
    except (SyntaxError, ValueError, RecursionError, MemoryError):
        return []
    constants = _constants(tree)
    found = []
    for node in ast.walk(tree):
        if not isinstance(node, ast.Assign):
            continue
        value = _int_literal(node.value)
        if value is None:
            key = _key(node.value)
            value = constants.get(key) if key is not None else None
        if not value:  # 0 is sent as 0.0 (an empty size word): no harm done
            continue
        found += [IntAssignment(node.lineno, ast.unparse(t), value) for t in node.targets if _is_velocity(t)]
    return sorted(found, key=lambda a: a.line)


def int_field_findings(script: Path) -> list[str]:
    """One finding per int assignment in an rclpy script: the line, what rclpy sends, and the fix."""
    raw = read_script(script)
    if isinstance(raw, str):
        return []
    found = int_assignments(raw.decode("utf-8", "replace"))
    return [f"{script.name} line {a.line}: {a.target} = {a.value} puts a Python int in a float64 field, which rclpy "
            f"sends as the int's internal size word read as a double: {as_double(a.value)!r}, not {a.value}.0, so "
            f"the command does not do what it says. Write {a.value}.0 (or float(...))."
            for a in found]
