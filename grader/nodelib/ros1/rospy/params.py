"""rospy's parameter calls on the run's one parameter server: read locally, changes sent to the grader."""
from __future__ import annotations

import copy
import json
import re

import rosgrade_channel as ch
import rosgrade_params
from rosgrade_node import runtime

from . import names

# The run's parameter server as this node sees it: bootstrap built it from START, every batch brings the changes
# other nodes made (rosgrade_node.scheduler), this node's own changes are made here and sent on.
_root: dict = runtime.param_tree

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


def _as_master_stores(value):
    """The value as it comes back from rosmaster: sent over XML-RPC, so a tuple reads back as a list and None or
    an object XML-RPC cannot carry raises its TypeError."""
    import xmlrpc.client  # here, not at import: it pulls in http and email, ~40 ms of every node's start-up
    return xmlrpc.client.loads(xmlrpc.client.dumps((value,)))[0][0]


def _tell_grader(op: str, name: str, value=None) -> None:
    """Send the change to the run's parameter server (the grader), which passes it on to the other nodes.

    XML-RPC values JSON cannot carry (Binary, DateTime) or a value past the frame's size stay in this node only."""
    if runtime.link is None:
        return
    frame = {"op": op, "name": name} if op == ch.PARAM_DELETE else {"op": op, "name": name, "value": value}
    try:
        encoded = ch.encode_json(ch.PARAM, frame)
    except (TypeError, ValueError):
        return
    if len(encoded) - 5 <= ch.MAX_JSON_BYTES and len(name) <= ch.MAX_NAME_CHARS:
        runtime.link.send(encoded)


def set_param(param_name: str, param_value) -> None:
    """Set a parameter on the run's parameter server; a dict value sets a whole namespace."""
    param_value = _as_master_stores(param_value)
    resolved = names.resolve_name(param_name)
    rosgrade_params.set_value(_root, resolved, param_value)
    _tell_grader(ch.PARAM_SET, resolved, param_value)


def _lookup(param_name: str):
    try:
        return rosgrade_params.lookup(_root, names.resolve_name(param_name))
    except KeyError:
        raise KeyError(param_name) from None


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
    """Delete a parameter or a whole namespace; KeyError(param_name) when there is none."""
    resolved = names.resolve_name(param_name)
    try:
        rosgrade_params.delete(_root, resolved)
    except KeyError:
        raise KeyError(param_name) from None
    _tell_grader(ch.PARAM_DELETE, resolved)


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
    """Make the shared tree this module's root (readable before init_node, as rosmaster's is)."""
    if not has_param("/use_sim_time"):
        rosgrade_params.set_value(_root, "/use_sim_time", True)  # this node's default, not the server's


load_start_parameters()
