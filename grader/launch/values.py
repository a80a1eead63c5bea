"""Typed values from launch-file text: ``<param>`` conversion and YAML as rosparam reads it."""
from __future__ import annotations

import math

import yaml

TRUE, FALSE = ("true", "1"), ("false", "0")
MAX_ITEMS = 100_000  # YAML aliases can make a short text a huge tree: larger values are refused


class ValueTooLarge(ValueError):
    """A YAML value with more items than a parameter of a course launch file could need."""


class YamlLoader(yaml.SafeLoader):
    """YAML as rosparam reads it: safe, plus the ``!degrees`` and ``!radians`` tags."""


YamlLoader.add_constructor("!degrees", lambda loader, node: math.radians(float(loader.construct_scalar(node))))
YamlLoader.add_constructor("!radians", lambda loader, node: float(loader.construct_scalar(node)))


def convert(value: str, kind: str) -> object:
    """A ``<param>`` value as roslaunch types it: auto (int, float, bool, else str), str, int, double, bool, yaml."""
    kind = kind.lower()
    if kind == "auto":
        try:
            if "." in value:
                return float(value)
            if "_" not in value:  # Python would read 1_000 as a number; roslaunch keeps it a string
                return int(value)
        except ValueError:
            pass
        return convert(value, "bool") if value.lower() in ("true", "false") else value
    if kind in ("str", "string"):
        return value
    if kind == "int":
        return int(value)
    if kind == "double":
        return float(value)
    if kind in ("bool", "boolean"):
        lowered = value.lower().strip()
        if lowered in TRUE or lowered in FALSE:
            return lowered in TRUE
        raise ValueError(f"{value} is not a 'bool' (expected true or false)")
    if kind == "yaml":
        try:
            return load_yaml(value)
        except yaml.YAMLError as exc:
            raise ValueError(f"not valid YAML: {exc}") from None
    raise ValueError(f"unknown type '{kind}'; expected one of str, int, double, bool, yaml")


def load_yaml(text: str) -> object:
    """YAML as rosparam loads it, refusing a value of more than MAX_ITEMS items (aliases counted each time used)."""
    data = yaml.load(text, Loader=YamlLoader)
    pending, seen = [data], 0
    while pending:
        item = pending.pop()
        seen += 1
        if seen > MAX_ITEMS:
            raise ValueTooLarge(f"the YAML value has more than {MAX_ITEMS} items")
        if isinstance(item, dict):
            pending.extend(item.values())
        elif isinstance(item, list):
            pending.extend(item)
    return data
