"""A node's clean-up must never reach another student's node running beside it in a batch.

Found by the 100-submission hostile batch (tests/bench_hostile_batch.py): an honest node in the scenario graded right
after a node killed at its CPU limit was SIGKILLed ("was killed with SIGKILL, not by the grader"). The kernel reuses PID
namespace ids (`unshare --pid` three times in a row gives pid:[…177], pid:[…179], pid:[…177]), and the node's
clean-up matched processes by a namespace id remembered from when its sandbox was alive.
"""
from __future__ import annotations

import os
import types

from grader.runtime import confine
from grader.runtime.process import NodeProcess

# Pids above this machine's pid_max (no real process has them: os.getsid/getpgid on them fail).
BWRAP, INIT, NODE, OTHER_STUDENT = 4_000_000, 4_000_001, 4_000_002, 4_000_010
OWN_NS, SANDBOX_NS = "pid:[4026531836]", "pid:[4026532177]"


def _fake_node() -> NodeProcess:
    node = object.__new__(NodeProcess)  # only what leftovers() reads
    node.plan = confine.Plan(argv=[], cwd="/", home="/tmp", uid=None, sandboxed=True)
    node.popen = types.SimpleNamespace(pid=BWRAP, returncode=None)
    node.marker = "test-marker"
    node._init = None
    return node


def _world(monkeypatch, pids: list[int], namespaces: dict[int, str], parents: dict[int, int]) -> None:
    monkeypatch.setattr(confine, "processes", lambda: list(pids))
    monkeypatch.setattr(confine, "pid_namespace", lambda pid: OWN_NS if pid == os.getpid() else namespaces.get(pid))
    monkeypatch.setattr(confine, "children_of", lambda pid: [p for p in pids if parents.get(p) == pid])
    monkeypatch.setattr(confine, "descendants", lambda root: {root} | {p for p in pids if parents.get(p) == root})
    monkeypatch.setattr(confine, "has_marker", lambda pid, marker: False)
    monkeypatch.setattr(confine, "uid_of", lambda pid: None)


def test_a_finished_sandbox_does_not_claim_the_next_namespace_given_its_id(monkeypatch):
    node = _fake_node()
    # While the sandbox runs: bwrap, its init (pid 1 inside) and the node (pid 2 inside) share SANDBOX_NS.
    _world(monkeypatch, [BWRAP, INIT, NODE], {INIT: SANDBOX_NS, NODE: SANDBOX_NS}, {INIT: BWRAP, NODE: INIT})
    assert node.leftovers() == [BWRAP, INIT, NODE]
    # The sandbox is gone and reaped; another student's node now runs in a new namespace that got the same id.
    node.popen.returncode = -9
    _world(monkeypatch, [OTHER_STUDENT], {OTHER_STUDENT: SANDBOX_NS}, {})
    assert node.leftovers() == []


def test_the_sandbox_init_is_looked_up_once_and_then_only_checked(monkeypatch):
    node = _fake_node()
    scans = []
    parents, started = {INIT: BWRAP, NODE: INIT}, {INIT: 100}
    monkeypatch.setattr(confine, "children_of", lambda pid: scans.append(pid) or [p for p in (INIT, NODE)
                                                                                  if parents.get(p) == pid])
    monkeypatch.setattr(confine, "parent_of", lambda pid: parents.get(pid))
    monkeypatch.setattr(confine, "started_at", lambda pid: started.get(pid))
    assert [node._sandbox_init() for _ in range(3)] == [INIT] * 3 and scans == [BWRAP]
    # The init's pid now belongs to a process started later (the sandbox ended, the pid was given again): not ours.
    started[INIT] = 200
    del parents[INIT]
    assert node._sandbox_init() is None and scans == [BWRAP, BWRAP]
    parents[INIT] = BWRAP
    assert node._sandbox_init() == INIT and node._init == (INIT, 200)
    node.popen.returncode = 0  # bwrap reaped: its children are nobody's to claim
    assert node._sandbox_init() is None
