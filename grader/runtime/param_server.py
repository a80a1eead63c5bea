"""The run's one ROS 1 parameter server: what every node and the world read and change, recorded and passed on.

Each node keeps a copy of the tree (START gives it the whole tree); a change one node makes is applied here at once
and reaches every other node in its next BATCH, before any of its threads runs again. The nodes run one after the
other, so a node never misses a change made before it runs, and every copy is the server's tree when its node runs.
"""
from __future__ import annotations

import json
from collections.abc import Callable

from grader.nodelib.common import rosgrade_params as tree_ops

# The grader channel that records the tree and every change to it (std_msgs/String, JSON).
PARAM_TOPIC = "/rosgrade/param"
# Who made a change, for the recording: a node's index, or one of these.
WORLD = "world"
GRADER = "grader"

Author = int | str
# Records one change: (JSON text of {"op", "name"[, "value"]}, author).
Recorder = Callable[[str, Author], None]


def change_text(name: str, value: object) -> str:
    """A change as recorded: ``{"op": "set", "name", "value"}`` or ``{"op": "delete", "name"}``."""
    if value is None:
        return json.dumps({"op": "delete", "name": name}, separators=(",", ":"))
    return json.dumps({"op": "set", "name": name, "value": value}, separators=(",", ":"))


def initial_tree(use_sim_time: bool, params: list[dict[str, object]]) -> dict:
    """The tree a run starts with: /use_sim_time as the world runs, then each node's parameters (absolute names,
    or namespaces as dicts), later ones over earlier ones, as roslaunch sets them before starting anything."""
    tree: dict = {}
    tree_ops.set_value(tree, "/use_sim_time", use_sim_time)
    for given in params:
        for name, value in given.items():
            tree_ops.set_value(tree, "/" + name.lstrip("/"), value)
    return tree


class ParamServer:
    """The tree, and per node the changes others made since it last ran (only the last change per name: a change
    replaces the ones before it on that name and under it)."""

    def __init__(self, tree: dict, record: Recorder) -> None:
        self.tree = tree
        self._record = record
        self._pending: dict[int, list[tuple[str, object]]] = {}
        self._started = False

    def start(self) -> None:
        """Record the tree the run starts with: what the task set and the world made of it as it started (those
        changes are part of it, not recorded apart). The first record of a recording is therefore the start."""
        self._started = True
        self._record(change_text("/", self.tree), GRADER)

    # -- reads (the world's view) --------------------------------------------------------------------------------
    def has(self, name: str) -> bool:
        try:
            tree_ops.lookup(self.tree, name)
        except KeyError:
            return False
        return True

    def get(self, name: str, default: object = None) -> object:
        try:
            return tree_ops.lookup(self.tree, name)
        except KeyError:
            return default

    # -- changes -------------------------------------------------------------------------------------------------
    def set(self, name: str, value: object, author: Author = WORLD) -> None:
        """Set ``name`` (a dict sets a namespace; the root takes only a dict: TypeError)."""
        tree_ops.set_value(self.tree, name, value)
        self._changed(name, value, author)

    def delete(self, name: str, author: Author = WORLD) -> bool:
        """Delete ``name`` and everything under it; False (and nothing changes) when it is not there."""
        try:
            tree_ops.delete(self.tree, name)
        except KeyError:
            return False
        self._changed(name, None, author)
        return True

    def _changed(self, name: str, value: object, author: Author) -> None:
        if self._started:
            self._record(change_text(name, value), author)
        for index, pending in self._pending.items():
            if index != author:
                pending[:] = [(n, v) for n, v in pending if not tree_ops.is_under(n, name)]
                pending.append((name, value))

    # -- nodes ---------------------------------------------------------------------------------------------------
    def joined(self, index: int) -> None:
        """The node has the whole tree (its START): from now on it is sent what changes."""
        self._pending[index] = []

    def take(self, index: int) -> list[tuple[str, object]]:
        """What changed since the node last ran, in order, for its next BATCH."""
        if index not in self._pending:
            return []
        taken, self._pending[index] = self._pending[index], []
        return taken
