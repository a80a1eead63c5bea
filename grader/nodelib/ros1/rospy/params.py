"""The node's parameter server: START's parameters plus ``_private:=value`` arguments, as a namespace tree."""
from __future__ import annotations

import copy
import json
import re
import xmlrpc.client

from rosgrade_node import runtime

from . import names

_root: dict = {}

# YAML 1.1 scalars as PyYAML's safe_load reads them (what rospy uses for ``_param:=value``).
_NULL = re.compile(r"^(?:~|null|Null|NULL|)$")
_BOOL_TRUE = re.compile(r"^(?:yes|Yes|YES|true|True|TRUE|on|On|ON)$")
_BOOL_FALSE = re.compile(r"^(?:no|No|NO|false|False|FALSE|off|Off|OFF)$")
_INT = re.compile(r"^[-+]?(?:0|[1-9][0-9_]*)$")
_INT_BASES = ((re.compile(r"^[-+]?0b[01_]+$"), 2), (re.compile(r"^[-+]?0x[0-9a-fA-F_]+$"), 16),
              (re.compile(r"^[-+]?0[0-7_]+$"), 8))
_FLOAT = re.compile(r"^[-+]?(?:[0-9][0-9_]*\.[0-9_]*(?:[eE][-+][0-9]+)?|\.[0-9_]+(?:[eE][-+][0-9]+)?)$")
_INF = re.compile(r"^([-+]?)\.(?:inf|Inf|INF)$")
_NAN = re.compile(r"^\.(?:nan|NaN|NAN)$")


def parse_scalar(text: str):
    """A command-line parameter value: YAML-style null/bool/int/float, quoted or flow (JSON) values, else text."""
    s = text.strip()
    if _NULL.match(s):
        return None
    if _BOOL_TRUE.match(s):
        return True
    if _BOOL_FALSE.match(s):
        return False
    if _INT.match(s):
        return int(s.replace("_", ""))
    for pattern, base in _INT_BASES:
        if pattern.match(s):
            sign = -1 if s[0] == "-" else 1
            digits = s.lstrip("+-").replace("_", "")
            return sign * int(digits[2:] if base != 8 else digits[1:], base)
    if _FLOAT.match(s):
        return float(s.replace("_", ""))
    if m := _INF.match(s):
        return float(m.group(1) + "inf")
    if _NAN.match(s):
        return float("nan")
    if len(s) >= 2 and s[0] == s[-1] and s[0] in "'\"":
        return s[1:-1]
    if s[:1] in "[{":
        try:
            return json.loads(s)
        except ValueError:
            pass
    return s


def _parts(resolved: str) -> list[str]:
    return [p for p in resolved.split(names.SEP) if p]


def load(params: dict) -> None:
    """START's parameters: absolute names (or nested dicts under '/') to JSON values."""
    for key, value in params.items():
        set_param(names.make_global_ns(key)[:-1] if key.strip("/") else "/", value)


def _as_master_stores(value):
    """The value as it comes back from rosmaster: sent over XML-RPC, so a tuple reads back as a list and None or
    an object XML-RPC cannot carry raises its TypeError."""
    return xmlrpc.client.loads(xmlrpc.client.dumps((value,)))[0][0]


def set_param(param_name: str, param_value) -> None:
    """Set a parameter; a dict value sets a whole namespace."""
    param_value = _as_master_stores(param_value)
    parts = _parts(names.resolve_name(param_name))
    if not parts:
        if not isinstance(param_value, dict):
            raise TypeError("cannot set root of parameter tree to non-dictionary")
        _root.clear()
        _root.update(param_value)
        return
    node = _root
    for part in parts[:-1]:
        child = node.get(part)
        if not isinstance(child, dict):
            child = node[part] = {}
        node = child
    node[parts[-1]] = param_value


def _lookup(param_name: str):
    node = _root
    for part in _parts(names.resolve_name(param_name)):
        if not isinstance(node, dict) or part not in node:
            raise KeyError(param_name)
        node = node[part]
    return node


_unspecified = object()


def get_param(param_name: str, default=_unspecified):
    """A parameter's value (a dict for a namespace); KeyError(param_name) if missing and no default."""
    try:
        return copy.deepcopy(_lookup(param_name))
    except KeyError:
        if default is _unspecified:
            raise
        return default


def has_param(param_name: str) -> bool:
    try:
        _lookup(param_name)
    except KeyError:
        return False
    return True


def delete_param(param_name: str) -> None:
    parts = _parts(names.resolve_name(param_name))
    if not parts:
        raise KeyError(param_name)
    parent = _lookup(names.SEP + names.SEP.join(parts[:-1])) if len(parts) > 1 else _root
    if not isinstance(parent, dict) or parts[-1] not in parent:
        raise KeyError(param_name)
    del parent[parts[-1]]


def search_param(param_name: str) -> str | None:
    """The closest parameter named ``param_name`` in the node's namespace or its parents (its full name)."""
    if not param_name or names.is_global(param_name) or names.is_private(param_name):
        raise ValueError("param_name must be a relative name without '~': %s" % param_name)
    first = param_name.split(names.SEP)[0]
    ns = names.get_namespace()
    while True:
        candidate = ns + first
        if has_param(candidate):
            return ns + param_name
        if ns == names.SEP:
            return None
        ns = names.namespace(ns)


def get_param_names() -> list[str]:
    """Full names of every leaf parameter."""
    found: list[str] = []

    def walk(prefix: str, node: dict) -> None:
        for key, value in node.items():
            if isinstance(value, dict) and value:
                walk(prefix + key + names.SEP, value)
            else:
                found.append(prefix + key)

    walk(names.SEP, _root)
    return found


def load_start_parameters() -> None:
    """The parameter server as the grader started it (readable before init_node, as rosmaster's is)."""
    load(runtime.params)
    if not has_param("/use_sim_time"):
        set_param("/use_sim_time", True)


load_start_parameters()
