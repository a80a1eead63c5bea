"""Conditions of ROS 2 launch: IfCondition, UnlessCondition, LaunchConfigurationEquals/NotEquals."""
from __future__ import annotations

from typing import Any

from launch.core import (
    Condition, LaunchContext, Substitution, normalize_to_list_of_substitutions, perform_substitutions,
)

__all__ = ["IfCondition", "InvalidConditionExpressionError", "LaunchConfigurationEquals",
           "LaunchConfigurationNotEquals", "UnlessCondition", "evaluate_condition_expression"]

_TRUE, _FALSE = ["true", "1"], ["false", "0"]


class InvalidConditionExpressionError(ValueError):
    """A condition's text is none of true, 1, false, 0."""

    def __init__(self, expression: str, unexpanded: list[Substitution]) -> None:
        super().__init__(f"invalid condition expression, expected one of [{', '.join(_TRUE + _FALSE)}] but got "
                         f"'{expression}', expanded from '{' + '.join(str(s) for s in unexpanded)}'")


def evaluate_condition_expression(context: LaunchContext, expression: list[Substitution]) -> bool:
    value = perform_substitutions(context, expression).strip().lower()
    if value in _TRUE:
        return True
    if value in _FALSE:
        return False
    raise InvalidConditionExpressionError(value, expression)


class IfCondition(Condition):
    """True when the expression is true or 1."""

    def __init__(self, predicate_expression: Any) -> None:
        self.expression = normalize_to_list_of_substitutions(predicate_expression)
        super().__init__(predicate=lambda context: evaluate_condition_expression(context, self.expression))


class UnlessCondition(Condition):
    """True when the expression is false or 0."""

    def __init__(self, predicate_expression: Any) -> None:
        self.expression = normalize_to_list_of_substitutions(predicate_expression)
        super().__init__(predicate=lambda context: not evaluate_condition_expression(context, self.expression))


class LaunchConfigurationEquals(Condition):
    """True when a launch configuration has the expected value (None: is not set)."""

    def __init__(self, launch_configuration_name: str, expected_value: Any) -> None:
        self.name = launch_configuration_name
        self.expected = None if expected_value is None else normalize_to_list_of_substitutions(expected_value)
        super().__init__(predicate=self._equal)

    def _equal(self, context: LaunchContext) -> bool:
        expected = None if self.expected is None else perform_substitutions(context, self.expected)
        if self.name not in context.launch_configurations:
            return expected is None
        return context.launch_configurations[self.name] == expected


class LaunchConfigurationNotEquals(LaunchConfigurationEquals):
    """True when a launch configuration does not have the value."""

    def _equal(self, context: LaunchContext) -> bool:
        return not super()._equal(context)
