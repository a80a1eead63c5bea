"""rclpy.context.Context: init/ok/shutdown of one ROS 2 context, and the signal-handler shutdown of all of them."""
from __future__ import annotations

import sys
import weakref
from inspect import ismethod

from . import _runtime, arguments
from ._rclpy_pybind11 import ALREADY_SHUT_DOWN, RCLError

# Python's start, the imports and rcl_init: the first rclpy.init returns this long after the process started (real
# rclpy: about 0.35 s; DEVELOPERS.md, start-up). The DDS discovery that follows is the grader's (wire.DISCOVERY_NS).
STARTUP_NS = 350_000_000

# Initialized contexts not yet shut down, in init order (rclpy's signal handler shuts all of them down).
_live: list[Context] = []


class Context:
    """Encapsulates the lifecycle of init and shutdown."""

    def __init__(self) -> None:
        self._initialized = False
        self._ok = False
        self._callbacks: list = []
        self._nodes: list[weakref.ref] = []
        self.ros_args = arguments.RosArgs()
        self._domain_id = 0

    @property
    def handle(self):
        """Non-None once init() has run (real rclpy: the C context)."""
        return self if self._initialized else None

    def init(self, args: list[str] | None = None, *, initialize_logging: bool = True,
             domain_id: int | None = None) -> None:
        if domain_id is not None and domain_id < 0:
            raise RuntimeError(f"Domain id ({domain_id}) should not be lower than zero.")
        if self._initialized:
            raise RuntimeError("Context.init() must only be called once")
        self.ros_args = arguments.parse(list(args if args is not None else sys.argv))
        self._domain_id = domain_id or 0
        starting_ns = _runtime.runtime.start_ns + STARTUP_NS - _runtime.world_ns()
        if _runtime.runtime.scheduler is not None and starting_ns > 0:
            _runtime.runtime.scheduler.sleep_ns(starting_ns)
        self._initialized = self._ok = True
        _live.append(self)

    def ok(self) -> bool:
        return self._ok

    def track_node(self, node) -> None:
        self._nodes.append(weakref.ref(node))

    def untrack_node(self, node) -> None:
        self._nodes = [ref for ref in self._nodes if ref() is not None and ref() is not node]

    def _call_on_shutdown_callbacks(self) -> None:
        for entry in self._callbacks:
            callback = entry() if isinstance(entry, weakref.WeakMethod) else entry
            if callback is not None:
                callback()
        self._callbacks = []

    def _invalidate(self) -> None:
        """rcl_shutdown: publishers of this context fail from now on."""
        self._ok = False
        if self in _live:
            _live.remove(self)

    def shutdown(self) -> None:
        """Destroy the context's nodes, invalidate it and run its on_shutdown callbacks."""
        if not self._initialized:
            raise RuntimeError("Context must be initialized before it can be shutdown")
        if not self._ok:  # Jazzy's rcl refuses a second shutdown (after Ctrl+C's, say); Kilted's returns
            raise RCLError(ALREADY_SHUT_DOWN)
        self._cleanup()

    def try_shutdown(self) -> None:
        if self._initialized and self._ok:
            self._cleanup()

    def _cleanup(self) -> None:
        for ref in list(self._nodes):
            node = ref()
            if node is not None:
                node.destroy_node()
        self._invalidate()
        self._call_on_shutdown_callbacks()

    def on_shutdown(self, callback) -> None:
        if not callable(callback):
            raise TypeError("callback should be a callable, got {}", type(callback))
        if self._initialized and not self._ok:
            callback()
            return
        self._callbacks.append(weakref.WeakMethod(callback) if ismethod(callback) else callback)

    def get_domain_id(self) -> int:
        if not self._initialized:
            raise RuntimeError("Context must be initialized before it can have a domain id")
        return self._domain_id

    def __enter__(self) -> Context:
        if not self._initialized:
            self.init()
        return self

    def __exit__(self, *exc) -> None:
        self.try_shutdown()


def signal_shutdown_all() -> None:
    """What rclpy's SIGINT/SIGTERM handler does: every live context becomes invalid at once. Nodes are not
    destroyed and on_shutdown callbacks do not run (in Jazzy a later rclpy.shutdown() raises, so they never do)."""
    for context in list(_live):
        context._invalidate()
