"""ROS graph names as rospy handles them: namespaces, ``from:=to`` remapping, resolution and ``myargv``."""
from __future__ import annotations

import os
import re
import sys

SEP = "/"
PRIV_NAME = "~"
REMAP = ":="
ANYTYPE = "*"

_BASE_NAME = re.compile(r"^[A-Za-z]\w*$", re.ASCII)


def canonicalize_name(name: str) -> str:
    """Drop empty path elements ('//', trailing '/'), keeping a leading '/'."""
    if not name or name == SEP:
        return name
    parts = "/".join(p for p in name.split(SEP) if p)
    return SEP + parts if name[0] == SEP else parts


def is_global(name: str) -> bool:
    return bool(name) and name[0] == SEP


def is_private(name: str) -> bool:
    return bool(name) and name[0] == PRIV_NAME


def is_legal_base_name(name: str) -> bool:
    return bool(_BASE_NAME.match(name))


def namespace(name: str) -> str:
    """The namespace of a resolved name, with its trailing slash ('/a/b' -> '/a/')."""
    if not name:
        return SEP
    if name[-1] == SEP:
        name = name[:-1]
    return name[:name.rfind(SEP) + 1] or SEP


def make_global_ns(ns: str) -> str:
    """'robot1' -> '/robot1/'."""
    if is_private(ns):
        raise ValueError("cannot turn [%s] into a global name" % ns)
    if not is_global(ns):
        ns = SEP + ns
    return ns if ns[-1] == SEP else ns + SEP


def load_mappings(argv: list[str]) -> dict[str, str]:
    """``from:=to`` arguments, without ``_param:=value`` assignments (special ``__name`` etc. are kept)."""
    mappings: dict[str, str] = {}
    for arg in argv:
        if REMAP not in arg:
            continue
        try:
            src, dst = (x.strip() for x in arg.split(REMAP))
        except ValueError:
            sys.stderr.write("ERROR: Invalid remapping argument '%s'\n" % arg)
            continue
        if src and dst and not (len(src) > 1 and src[0] == "_" and src[1] != "_"):
            mappings[src] = dst
    return mappings


def resolve_in(name: str, caller_id: str, remappings: dict[str, str] | None = None) -> str:
    """Resolve ``name`` relative to node ``caller_id`` ('~' = the node's own namespace), then apply remappings."""
    if not name:
        return namespace(caller_id)
    name = canonicalize_name(name)
    if name[0] == SEP:
        resolved = name
    elif is_private(name):
        # '~' alone resolves to the node's name with a trailing '/', as rospy's ns_join gives it.
        resolved = canonicalize_name(caller_id + SEP + name[1:]) if name[1:] else caller_id + SEP
    else:
        resolved = namespace(caller_id) + name
    if remappings and resolved in remappings:
        return remappings[resolved]
    return resolved


def myargv(argv: list[str] | None = None) -> list[str]:
    """``argv`` (default sys.argv) without ROS remapping arguments."""
    return [a for a in (sys.argv if argv is None else argv) if REMAP not in a]


# -- this node's names (rospy keeps them process-global) -------------------------------------------------------------
_mappings: dict[str, str] = load_mappings(sys.argv)
_resolved_mappings: dict[str, str] = {}


def _ros_namespace() -> str:
    return make_global_ns(_mappings.get("__ns") or os.environ.get("ROS_NAMESPACE") or SEP)


_namespace = _ros_namespace()
_caller_id = _namespace + "unnamed"


def get_mappings() -> dict[str, str]:
    return _mappings


def get_resolved_mappings() -> dict[str, str]:
    return _resolved_mappings


def reload_mappings(argv: list[str]) -> None:
    """init_node(argv=...) replaces the argument mappings."""
    global _mappings
    _mappings = load_mappings(argv)


def initialize_mappings(node_name: str) -> None:
    """Resolve both sides of every mapping against the node (done by init_node, so earlier names are not remapped)."""
    global _resolved_mappings
    _resolved_mappings = {}
    for src, dst in _mappings.items():
        if src.startswith("__"):
            _resolved_mappings[src] = dst
        else:
            _resolved_mappings[resolve_in(src, node_name)] = resolve_in(dst, node_name)


def set_node_name(resolved: str) -> None:
    global _caller_id, _namespace
    _caller_id = resolved
    _namespace = namespace(resolved)


def get_name() -> str:
    """The node's fully resolved name ('/unnamed' before init_node)."""
    return _caller_id


get_caller_id = get_name


def get_namespace() -> str:
    """The node's namespace, with a trailing slash."""
    return _namespace


def resolve_name(name: str, caller_id: str | None = None) -> str:
    """Resolve a graph name for this node, applying command-line remappings."""
    return resolve_in(name, caller_id or get_name(), _resolved_mappings)
