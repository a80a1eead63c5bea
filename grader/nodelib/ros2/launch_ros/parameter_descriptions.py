"""How a Node's parameters are described: ParameterValue (a value of a type), ParameterFile, Parameter."""
from __future__ import annotations

from typing import Any

import yaml

from launch.core import LaunchContext, Substitution, normalize_to_list_of_substitutions, perform_substitutions

__all__ = ["Parameter", "ParameterFile", "ParameterValue"]


class ParameterValue:
    """A parameter's value, kept as its type (value_type=str keeps text that looks like a number a string)."""

    def __init__(self, value: Any, *, value_type: Any = None) -> None:
        self.value = value
        self.value_type = value_type

    def evaluate(self, context: LaunchContext) -> Any:
        value = self.value
        if isinstance(value, (list, tuple)) and any(isinstance(v, Substitution) for v in value) \
                and all(isinstance(v, (str, Substitution)) for v in value):
            return self._coerced(perform_substitutions(context, normalize_to_list_of_substitutions(value)))
        if isinstance(value, (str, Substitution)):
            return self._coerced(perform_substitutions(context, normalize_to_list_of_substitutions(value)))
        if isinstance(value, (list, tuple)):
            # A list of values, each typed on its own (the items of an XML value with value-sep, for instance).
            return [self._coerced(perform_substitutions(context, item)) if isinstance(item, list) else item
                    for item in value]
        return value

    def _coerced(self, text: str) -> Any:
        """The text as launch types it: YAML rules, or the value_type asked for."""
        if self.value_type is str:
            return text
        loaded = yaml.safe_load(text) if text else ""
        if self.value_type in (int, float, bool) and not isinstance(loaded, self.value_type):
            return self.value_type(loaded)
        return loaded


class ParameterFile:
    """A YAML parameter file handed to the node with --params-file."""

    def __init__(self, param_file: Any, *, allow_substs: Any = False) -> None:
        self.param_file = normalize_to_list_of_substitutions(
            str(param_file) if not isinstance(param_file, (str, Substitution, list, tuple)) else param_file)
        self.allow_substs = allow_substs

    def evaluate(self, context: LaunchContext) -> str:
        return perform_substitutions(context, self.param_file)


class Parameter:
    """One parameter given with -p name:=value."""

    def __init__(self, name: Any, value: Any, *, value_type: Any = None) -> None:
        self.name = normalize_to_list_of_substitutions(name)
        self.value = value if isinstance(value, ParameterValue) else ParameterValue(value, value_type=value_type)

    def evaluate(self, context: LaunchContext) -> tuple[str, Any]:
        return perform_substitutions(context, self.name), self.value.evaluate(context)
