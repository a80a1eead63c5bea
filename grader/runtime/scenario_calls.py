"""The grader as a caller: a scenario's service calls, made at their sim times through the run's service routing,
one after the other, as a script of ``ros2 service call`` commands would make them."""
from __future__ import annotations

from sim.scenario import ServiceCallSpec

from grader.runtime.node_link import ServiceCall
from grader.runtime.services import Caller, ServiceRouter

# The grader's name on the graph (``ros2 service call`` is a node of its own too); names under /rosgrade are refused
# to student nodes, so scoring can trust what this name called.
CALLER_ID = "/rosgrade"


class ScenarioCaller:
    """Makes each call once its time has come and the one before it has been answered; a call whose service is not
    offered yet waits for it (``ros2 service call`` prints "waiting for service to become available..." meanwhile)
    and goes out when a node offers it."""

    def __init__(self, calls: list[ServiceCallSpec], start_ns: int, router: ServiceRouter) -> None:
        self._calls = [(start_ns + call.t_ns, call) for call in calls]
        self._next = 0
        self._busy = False  # a call is out and not answered yet
        self._router = router
        router.on_offer.append(self.tick)

    def next_ns(self) -> int | None:
        """When the loop must stop for the next call (None: none, or it waits for an answer or a server)."""
        if self._busy or self._next >= len(self._calls):
            return None
        due, call = self._calls[self._next]
        return due if self._router.server(call.service) is not None else None

    def tick(self, t: int) -> None:
        """Make the next call if it is due at t and its service is offered."""
        if self._busy or self._next >= len(self._calls):
            return
        due, call = self._calls[self._next]
        server = self._router.server(call.service)
        if due > t or server is None:
            return
        self._busy = True
        request = self._router.request_bytes(call.type, call.request)
        md5sum = self._router.wire.catalog.service_md5sum(call.type)
        self._router.call(Caller(CALLER_ID, "grader", done=self._answered),
                          ServiceCall(call.service, call.type, md5sum, False, request), t)

    def _answered(self, status: str, error: str, response: bytes) -> None:
        self._busy = False
        self._next += 1
