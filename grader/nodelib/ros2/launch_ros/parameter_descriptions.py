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
        if isinstance(value, (str, Substitution)) or (isinstance(value, (list, tuple)) and value
                                                       and all(isinstance(v, (str, Substitution)) for v in value)):
            text = perform_substitutions(context, normalize_to_list_of_substitutions(value))
            if self.value_type is str:
                return text
            loaded = yaml.safe_load(text) if text else ""
            if self.value_type in (int, float, bool) and not isinstance(loaded, self.value_type):
                return self.value_type(loaded)
            return loaded
        return value


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
