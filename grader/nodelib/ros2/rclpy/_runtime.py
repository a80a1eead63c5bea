"""rclpy's view of rosgrade's node runtime: the scheduler, the clocks it patches, call charges (no-ops without a grader)."""
from __future__ import annotations

import rosgrade_channel as ch
from rosgrade_node import runtime

# time.monotonic() under rosgrade is world time plus this offset (rosgrade_node.timepatch).
from rosgrade_node.timepatch import _MONOTONIC_OFFSET_NS as STEADY_OFFSET_NS

CLOCK_PERIOD_NS = ch.CLOCK_PERIOD_NS


class RuntimeMissingError(RuntimeError):
    """rclpy was asked to talk to the grader in a process the grader did not start."""


def scheduler():
    """The lockstep scheduler; an error when this process was not started by the grader."""
    if runtime.scheduler is None:
        raise RuntimeMissingError("rosgrade's rclpy runs only in a node started by the grader (ROSGRADE_CHANNEL unset)")
    return runtime.scheduler


def link():
    scheduler()
    return runtime.link


def charge() -> None:
    """Account one non-blocking library call (see rosgrade_node.scheduler)."""
    if runtime.scheduler is not None:
        runtime.scheduler.charge()


def world_ns() -> int:
    return runtime.scheduler.world_ns if runtime.scheduler is not None else 0


def system_ns() -> int:
    """The system (wall) clock as the node sees it: patched time.time_ns() without a charge."""
    return runtime.wall_epoch_ns + world_ns()


def steady_ns() -> int:
    """The steady clock: patched time.monotonic_ns() without a charge."""
    return STEADY_OFFSET_NS + world_ns()


def clock_msg_ns() -> int:
    """The last /clock value the grader has given this node (0 before the first)."""
    return runtime.scheduler.clock_ns if runtime.scheduler is not None else 0


def clock_wake_ns(target_ns: int) -> int:
    """World time of the first /clock tick that carries ROS time >= ``target_ns`` (never now: the clock must move)."""
    target = max(target_ns, world_ns() + 1)
    return -(-target // CLOCK_PERIOD_NS) * CLOCK_PERIOD_NS
