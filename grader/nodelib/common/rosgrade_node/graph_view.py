"""The run's other nodes as this process sees them now (one GRAPH exchange, charged as a library call)."""
from __future__ import annotations

from rosgrade_node import runtime


def other_nodes() -> list[dict]:
    """[{"name", "kind", "pub", "sub", "srv"}, ...] of the run's nodes this one has discovered, its process's own left out (the
    client library knows those); kind "node" (a node of the run), "world" or "grader" (/rosgrade). Outside a run, or from a thread rosgrade does not schedule, none."""
    sched = runtime.scheduler
    if runtime.link is None or sched is None or not sched.holds_token():
        return []
    sched.charge()
    return list(runtime.link.graph().get("nodes") or [])
