"""Without a PID namespace the node still sees itself as pid 2 (as in a sandbox), so anonymous names and recordings
do not depend on the host's pids, and the calls that take a pid still reach the node itself."""
from __future__ import annotations

import os
import subprocess
import sys
import textwrap
from pathlib import Path

from grader.nodelib import pythonpath

NODELIB_PATH = pythonpath("ros1")


def _run(code: str) -> str:
    env = {**os.environ, "PYTHONPATH": NODELIB_PATH}
    env.pop("ROSGRADE_CHANNEL", None)  # no grader: sitecustomize leaves the process alone
    done = subprocess.run([sys.executable, "-c", textwrap.dedent(code)], env=env, capture_output=True, text=True,
                          timeout=60, check=True)
    return done.stdout


def test_the_node_is_pid_2_and_can_still_signal_itself():
    out = _run("""
        import os, signal
        from rosgrade_node import pids
        real = os.getpid()
        pids.install()
        got = []
        signal.signal(signal.SIGUSR1, lambda *a: got.append(1))
        os.kill(os.getpid(), signal.SIGUSR1)
        print(os.getpid(), got, os.getsid(os.getpid()) == os.getsid(0), real != 2)
    """)
    assert out.split() == ["2", "[1]", "True", "True"]


def test_a_forked_child_sees_its_own_pid():
    out = _run("""
        import os
        from rosgrade_node import pids
        pids.install()
        r, w = os.pipe()
        child = os.fork()
        if child == 0:
            os.write(w, str(os.getpid()).encode()); os._exit(0)
        os.waitpid(child, 0)
        print(os.read(r, 32).decode() == str(child), os.getpid())
    """)
    assert out.split() == ["True", "2"]
