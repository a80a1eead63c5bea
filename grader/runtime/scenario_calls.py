"""The grader as a caller: a scenario's service calls, made at their sim times through the run's service routing,
one after the other, as a script of ``ros2 service call`` commands would make them."""
from __future__ import annotations

from dataclasses import dataclass

from grader.recording import RecordingError
from grader.runtime.node_link import ServiceCall
from grader.runtime.services import Caller, ServiceRouteError, ServiceRouter
from grader.runtime.wire import Wire
from sim.scenario import ServiceCallSpec

# The grader's name on the graph (``ros2 service call`` is a node of its own too); names under /rosgrade are refused
# to student nodes, so scoring can trust what this name called.
CALLER_ID = "/rosgrade"


@dataclass(frozen=True)
class PlannedCall:
    """A scenario's call with its request's bytes and its srv type's md5sum (RIHS01), built before the run starts."""

    t_ns: int  # relative to the start
    call: ServiceCall


def planned_calls(calls: list[ServiceCallSpec], wire: Wire) -> list[PlannedCall]:
    """The scenario's calls encoded for the run's wire; ServiceRouteError names a call that cannot be made."""
    planned = []
    for index, spec in enumerate(calls):
        try:
            request = wire.part_bytes(spec.type, "Request", spec.request)
            md5sum = wire.catalog.service_md5sum(spec.type)
        except (RecordingError, TypeError, ValueError) as exc:
            raise ServiceRouteError(f"scenario service_calls[{index}] to {spec.service}: {spec.request} is not a "
                                    f"request of {spec.type}: {exc}") from None
        planned.append(PlannedCall(spec.t_ns, ServiceCall(spec.service, spec.type, md5sum, False, request)))
    return planned


class ScenarioCaller:
    """Makes each call once its time has come and the one before it has been answered; a call whose service is not
    offered yet waits for it (``ros2 service call`` prints "waiting for service to become available..." meanwhile)
    and goes out when a node offers it."""

    def __init__(self, calls: list[PlannedCall], start_ns: int, router: ServiceRouter) -> None:
        self._calls = [(start_ns + planned.t_ns, planned.call) for planned in calls]
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
        if due > t or self._router.server(call.service) is None:
            return
        self._busy = True
        self._router.call(Caller(CALLER_ID, "grader", done=self._answered), call, t)

    def _answered(self, status: str, error: str, response: bytes) -> None:
        self._busy = False
        self._next += 1
