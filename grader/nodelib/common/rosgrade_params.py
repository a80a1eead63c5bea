"""The parameter tree as rosmaster keeps it, by absolute name (stdlib only: the grader and every node share it).

A tree is a dict of dicts; a name's parts are its namespaces. Setting a dict sets a whole namespace, setting below a
leaf turns the leaf into a namespace, and deleting a namespace deletes everything under it, as rosmaster does.
"""
from __future__ import annotations

import copy

SEP = "/"


def parts(name: str) -> list[str]:
    """The namespaces and leaf of an absolute name ("/" is the root: no parts)."""
    return [p for p in name.split(SEP) if p]


def is_under(name: str, namespace: str) -> bool:
    """Whether ``name`` is ``namespace`` itself or lies inside it."""
    inner, outer = parts(name), parts(namespace)
    return inner[:len(outer)] == outer


def set_value(tree: dict, name: str, value) -> None:
    """Set ``name`` to ``value`` (a copy); the root takes only a dict, which replaces the whole tree in place."""
    path = parts(name)
    value = copy.deepcopy(value)
    if not path:
        if not isinstance(value, dict):
            raise TypeError("cannot set root of parameter tree to non-dictionary")
        tree.clear()
        tree.update(value)
        return
    _namespace(tree, path[:-1])[path[-1]] = value


def lookup(tree: dict, name: str):
    """The value stored at ``name`` (the tree itself for the root); KeyError(name) when there is none."""
    node = tree
    for part in parts(name):
        if not isinstance(node, dict) or part not in node:
            raise KeyError(name)
        node = node[part]
    return node


def delete(tree: dict, name: str) -> None:
    """Remove ``name`` and everything under it; KeyError(name) when it is not there (or is the root)."""
    path = parts(name)
    if not path:
        raise KeyError(name)
    parent = lookup(tree, SEP + SEP.join(path[:-1]))
    if not isinstance(parent, dict) or path[-1] not in parent:
        raise KeyError(name)
    del parent[path[-1]]


def apply(tree: dict, changes: list) -> None:
    """Replay ``[name, value]`` changes in order (``None``: deleted; XML-RPC cannot carry None, so no value is None).

    The grader keeps only the last change per name and drops the changes under a name changed later, so a deletion
    may arrive without the change that made its namespace: a deletion makes its namespace as rosmaster had it."""
    for name, value in changes:
        path = parts(name)
        if value is not None:
            set_value(tree, name, value)
        elif path:
            _namespace(tree, path[:-1]).pop(path[-1], None)


def _namespace(tree: dict, path: list[str]) -> dict:
    """The namespace at ``path``, made (over any leaf in the way) when missing."""
    node = tree
    for part in path:
        child = node.get(part)
        if not isinstance(child, dict):
            child = node[part] = {}
        node = child
    return node
