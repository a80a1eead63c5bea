"""A Node's parameter dictionaries as launch_ros reads them: nested keys joined with '.', text read as YAML, lists
of one type, and the YAML file launch_ros writes for each dictionary."""
from __future__ import annotations

from collections.abc import Mapping, Sequence
from typing import Any

import yaml

from launch.core import LaunchContext, Substitution, normalize_to_list_of_substitutions, perform_substitutions
from launch_ros.parameter_descriptions import Parameter, ParameterFile, ParameterValue

_SCALARS = (bool, int, float, str)


def _array(value: Sequence[Any]) -> tuple[Any, ...]:
    kinds = {Substitution if isinstance(v, Substitution) else str if isinstance(v, str) else bool
             if isinstance(v, bool) else int if isinstance(v, int) else float if isinstance(v, float) else tuple
             for v in value}
    if kinds == {int}:
        return tuple(int(v) for v in value)
    if kinds in ({float}, {int, float}):
        return tuple(float(v) for v in value)
    if Substitution in kinds and kinds <= {str, Substitution}:
        return ("subs", tuple(normalize_to_list_of_substitutions(list(value))))
    if kinds == {bool}:
        return tuple(bool(v) for v in value)
    return ("items", tuple(normalize_to_list_of_substitutions(yaml.dump(v) if isinstance(v, _SCALARS) else v)
                           for v in value))


def normalize_dict(parameters: Mapping[Any, Any], prefix: list[Substitution] | None = None) -> dict[tuple, Any]:
    """Keys as substitutions (nested dictionaries flattened), values kept for evaluation."""
    if not isinstance(parameters, Mapping):
        raise TypeError("expected dict")
    out: dict[tuple, Any] = {}
    for key, value in parameters.items():
        name = normalize_to_list_of_substitutions(key)
        if prefix:
            name = [*prefix, *normalize_to_list_of_substitutions("."), *name]
        if isinstance(value, Mapping):
            out.update(normalize_dict(value, name))
        elif isinstance(value, ParameterValue):
            out[tuple(name)] = value
        elif isinstance(value, str):
            out[tuple(name)] = ("subs", tuple(normalize_to_list_of_substitutions(yaml.dump(value))))
        elif isinstance(value, Substitution):
            out[tuple(name)] = ("subs", (value,))
        elif isinstance(value, (float, bool, int, bytes)):
            out[tuple(name)] = value
        elif isinstance(value, Sequence):
            out[tuple(name)] = _array(value)
        else:
            raise TypeError(f"Unexpected type for parameter value {value!r}")
    return out


def normalize(parameters: Any) -> list[Any]:
    if isinstance(parameters, str) or not isinstance(parameters, Sequence):
        raise TypeError(f"Expecting list of parameters, got {parameters}")
    return [normalize_dict(p) if isinstance(p, Mapping) else p if isinstance(p, (Parameter, ParameterFile))
            else ParameterFile(p) for p in parameters]


def _uniform(values: list[Any]) -> bool:
    return bool(values) and type(values[0]) in _SCALARS and all(isinstance(v, type(values[0])) for v in values)


def _from_text(name: str, text: str) -> Any:
    try:
        value = yaml.safe_load(text if text else "''")
    except yaml.YAMLError:
        raise TypeError(f"Unable to parse the value of parameter {name} as yaml. If the parameter is meant to be a "
                        "string, try wrapping it in launch_ros.parameter_descriptions.ParameterValue(value, "
                        "value_type=str)") from None
    if type(value) in (*_SCALARS, bytes):
        return value
    if isinstance(value, list):
        if not _uniform(value):
            raise TypeError("Expected a non-empty sequence, with items of uniform type. Allowed sequence item types "
                            f'are bool, int, float, str. Got inconsistent input for "{name}"')
        return tuple(value)
    raise TypeError(f"Allowed value types are bytes, bool, int, float, str, Sequence[bool], Sequence[int], "
                    f'Sequence[float], Sequence[str]. Got {type(value)} for "{name}". If the parameter is meant to '
                    "be a string, try wrapping it in launch_ros.parameter_descriptions.ParameterValue(value, "
                    "value_type=str)")


def evaluate_dict(context: LaunchContext, parameters: dict[tuple, Any]) -> dict[str, Any]:
    out: dict[str, Any] = {}
    for key, value in parameters.items():
        name = perform_substitutions(context, list(key))
        if isinstance(value, tuple) and value and value[0] == "subs":
            out[name] = _from_text(name, perform_substitutions(context, list(value[1])))
        elif isinstance(value, tuple) and value and value[0] == "items":
            items = [yaml.safe_load(perform_substitutions(context, list(v))) for v in value[1]]
            if not _uniform(items):
                raise TypeError("Expected a non-empty sequence, with items of uniform type. Allowed sequence item "
                                f'types are bool, int, float, str. Got inconsistent input for "{name}"')
            out[name] = tuple(items)
        elif isinstance(value, ParameterValue):
            out[name] = value.evaluate(context)
        else:
            out[name] = value
    return out


def params_file_content(node_name: str | None, parameters: dict[str, Any]) -> str:
    """The YAML launch_ros writes for one dictionary: under the node's full name, else under /**."""
    return yaml.dump({node_name or "/**": {"ros__parameters": parameters}}, default_flow_style=False)


def rule(name: str, value: Any) -> str:
    """A -p rule as launch_ros writes it."""
    return f"{name}:={yaml.dump(value)}"
