"""The node's own process id as it would be in a sandbox, in every isolation mode.

bubblewrap and unshare give the node a PID namespace of its own, where it is pid 2 (under the sandbox's init), so
``os.getpid()`` and the names built from it (``rospy.init_node(..., anonymous=True)``) are the same in every run.
Where no namespace could be had (rlimits only, or a per-node uid), the real pid would reach the node's name and so
the recording. There the node's process sees the same ``SANDBOX_PID`` instead, and the calls that take a pid map it
back to the real one, so ``os.kill(os.getpid(), ...)`` still signals the node itself. A child the node forks sees
its own real pid, as it would see its own namespace pid in a sandbox.
"""
from __future__ import annotations

import os
from collections.abc import Callable

SANDBOX_PID = 2  # the node's pid inside bwrap's or unshare's PID namespace (its init is pid 1)

_real_getpid = os.getpid


def install() -> None:
    """Give the node ``SANDBOX_PID`` when it is not already in a PID namespace of its own."""
    real = _real_getpid()
    if real == SANDBOX_PID:
        return

    def own(pid: int) -> int:
        """A pid as the node names it, as the kernel knows it."""
        return real if pid == SANDBOX_PID and _real_getpid() == real else pid

    def getpid() -> int:
        return SANDBOX_PID if _real_getpid() == real else _real_getpid()

    os.getpid = getpid
    for name in ("kill", "killpg"):
        os.__dict__[name] = _mapping_first(getattr(os, name), own)
    for name in ("getpgid", "getsid", "sched_getaffinity", "sched_setaffinity", "waitpid"):
        if hasattr(os, name):
            os.__dict__[name] = _mapping_first(getattr(os, name), own)


def _mapping_first(call: Callable[..., object], own: Callable[[int], int]) -> Callable[..., object]:
    """``call`` with its first argument, a pid, translated by ``own``."""

    def mapped(pid: int, *args: object) -> object:
        return call(own(pid), *args)

    mapped.__name__ = call.__name__
    mapped.__doc__ = call.__doc__
    return mapped
