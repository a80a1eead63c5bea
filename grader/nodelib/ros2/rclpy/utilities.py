"""rclpy.utilities: the default context, ok/shutdown, remove_ros_args and timeout conversion."""
from __future__ import annotations

import sys

from . import arguments
from .constants import S_TO_NS
from .context import Context

g_default_context: Context | None = None


def get_default_context(*, shutting_down: bool = False) -> Context:
    """Return the global default context singleton."""
    global g_default_context
    if g_default_context is None:
        g_default_context = Context()
    if shutting_down:
        old, g_default_context = g_default_context, None
        return old
    return g_default_context


def remove_ros_args(args=None) -> list[str]:
    """The command line without its ROS arguments."""
    return arguments.parse(list(args if args is not None else sys.argv), at_init=False).non_ros


def ok(*, context: Context | None = None) -> bool:
    if context is None:
        context = get_default_context()
    return context.ok()


def shutdown(*, context: Context | None = None) -> None:
    if context is None:
        context = get_default_context(shutting_down=True)
    context.shutdown()


def try_shutdown(*, context: Context | None = None) -> None:
    global g_default_context
    if context is None:
        if g_default_context is None:
            g_default_context = Context()
        g_default_context.try_shutdown()
        if not g_default_context.ok():
            g_default_context = None
    else:
        context.try_shutdown()


def get_rmw_implementation_identifier() -> str:
    return "rmw_fastrtps_cpp"


def timeout_sec_to_nsec(timeout_sec: float | None) -> int:
    """Seconds to rcl_wait's nanoseconds: -1 (forever) for None or negative."""
    if timeout_sec is None or timeout_sec < 0:
        return -1
    return int(float(timeout_sec) * S_TO_NS)
