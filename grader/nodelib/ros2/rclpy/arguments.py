"""The ``--ros-args`` command line as rcl reads it: parameters, remaps, log levels; and the YAML scalars of ``-p``."""
from __future__ import annotations

import json
import re
from dataclasses import dataclass, field

_FLAGS_WITH_VALUE = {"-p", "--param", "-r", "--remap", "--params-file", "--log-level", "-e", "--enclave",
                     "--log-config-file", "--log-file-name"}
_LOG_LEVELS = {"unset": 0, "debug": 10, "info": 20, "warn": 30, "warning": 30, "error": 40, "fatal": 50}

_NULL = re.compile(r"^(?:~|null|Null|NULL|)$")
_TRUE = re.compile(r"^(?:y|Y|yes|Yes|YES|true|True|TRUE|on|On|ON)$")
_FALSE = re.compile(r"^(?:n|N|no|No|NO|false|False|FALSE|off|Off|OFF)$")
_INT = re.compile(r"^[-+]?(?:0|[1-9][0-9_]*)$")
_HEX = re.compile(r"^[-+]?0x[0-9a-fA-F_]+$")
_FLOAT = re.compile(r"^[-+]?(?:[0-9][0-9_]*)?\.?[0-9_]*(?:[eE][-+]?[0-9]+)?$")
_INF = re.compile(r"^([-+]?)\.(?:inf|Inf|INF)$")
_NAN = re.compile(r"^\.(?:nan|NaN|NAN)$")


class ArgumentError(ValueError):
    """A ROS argument is malformed (rcl refuses it at rclpy.init)."""


@dataclass
class RosArgs:
    """What the ``--ros-args`` sections of a command line say. Keys of ``params`` and ``remaps`` are
    (node name or '' for every node, name)."""

    params: dict[tuple[str, str], object] = field(default_factory=dict)
    remaps: list[tuple[str, str, str]] = field(default_factory=list)  # (node or '', from, to)
    log_levels: dict[str, int] = field(default_factory=dict)  # logger name ('' = default) -> severity
    non_ros: list[str] = field(default_factory=list)


def parse_scalar(text: str):
    """A parameter value as rcl's YAML reading of ``-p name:=value`` gives it."""
    s = text.strip()
    if _TRUE.match(s):
        return True
    if _FALSE.match(s):
        return False
    if _INT.match(s):
        return int(s.replace("_", ""))
    if _HEX.match(s):
        return int(s.replace("_", ""), 16)
    if any(c.isdigit() for c in s) and _FLOAT.match(s):
        return float(s.replace("_", ""))
    if m := _INF.match(s):
        return float(m.group(1) + "inf")
    if _NAN.match(s):
        return float("nan")
    if len(s) >= 2 and s[0] == s[-1] and s[0] in "'\"":
        return s[1:-1]
    if s.startswith("[") and s.endswith("]"):
        inner = s[1:-1].strip()
        return [parse_scalar(part) for part in _split_flow(inner)] if inner else []
    if _NULL.match(s):
        return None
    return s


def _split_flow(inner: str) -> list[str]:
    try:
        return [json.dumps(v) if isinstance(v, str) else str(v).lower() if isinstance(v, bool) else str(v)
                for v in json.loads("[" + inner + "]")]
    except ValueError:
        return [p.strip() for p in inner.split(",")]


def _node_scoped(rule: str) -> tuple[str, str, str]:
    """'node:from:=to' or 'from:=to' -> (node or '', from, to)."""
    lhs, sep, rhs = rule.partition(":=")
    if not sep or not lhs:
        raise ArgumentError(f"Couldn't parse rule '{rule}'")
    node, colon, name = lhs.rpartition(":")
    return (node if colon else "", name, rhs)


def parse(argv: list[str]) -> RosArgs:
    """Split ``argv`` into ROS arguments (after ``--ros-args``, up to ``--``) and the rest."""
    out = RosArgs()
    in_ros = False
    i = 0
    while i < len(argv):
        arg = argv[i]
        i += 1
        if arg == "--ros-args":
            in_ros = True
            continue
        if not in_ros:
            out.non_ros.append(arg)
            continue
        if arg == "--":
            in_ros = False
            continue
        if arg not in _FLAGS_WITH_VALUE:
            continue  # --enable-rosout-logs and the like change nothing here
        if i >= len(argv):
            raise ArgumentError(f"Couldn't parse trailing {arg} flag. No value given.")
        value = argv[i]
        i += 1
        if arg in ("-p", "--param"):
            node, name, text = _node_scoped(value)
            out.params[(node, name)] = parse_scalar(text)
        elif arg in ("-r", "--remap"):
            out.remaps.append(_node_scoped(value))
        elif arg == "--log-level":
            name, sep, level = value.rpartition(":=")
            level_value = _LOG_LEVELS.get(level.lower())
            if level_value is None:
                raise ArgumentError(f"Argument {value} is not a valid log level rule")
            out.log_levels[name if sep else ""] = level_value
    return out
