"""The CPUs the node sees: always ``NODE_CPUS``, whatever the machine has and whichever CPU its run is pinned to.

What a node reads of the machine can reach its recording: rclpy's ``MultiThreadedExecutor()`` sizes its thread pool
by the CPUs it may use. The grader pins each run to one CPU when it can (``grader/runtime/cpu_claim.py``) and cannot
always, and machines differ; a fixed view keeps the run's result the same on all of them.
"""
from __future__ import annotations

import os

NODE_CPUS = 4  # a typical student laptop


def install() -> None:
    """Make ``os.cpu_count`` and the node's own ``os.sched_getaffinity`` report ``NODE_CPUS`` CPUs."""
    real_affinity = getattr(os, "sched_getaffinity", None)

    def cpu_count() -> int:
        return NODE_CPUS

    os.cpu_count = cpu_count
    if real_affinity is not None:
        def sched_getaffinity(pid: int) -> set[int]:
            if pid in (0, os.getpid()):
                return set(range(NODE_CPUS))
            return real_affinity(pid)

        sched_getaffinity.__doc__ = real_affinity.__doc__
        os.sched_getaffinity = sched_getaffinity
