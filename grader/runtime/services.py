"""Services routed like topics: each service has one server (a node, the world, or none yet), calls go to it and
answers come back in sim time, and the router records both.

A node's or the grader's call reaches the server at the caller's time; the world answers at once, a node when its
server callback has run (a RESPOND in one of its later steps), and the answer reaches the caller in its next BATCH
(or the grader's callback). Requests, responses and failures are recorded under ``/rosgrade/service/<service>/``.
"""
from __future__ import annotations

import itertools
from collections.abc import Callable
from dataclasses import dataclass, field

from grader.nodelib.common import rosgrade_channel as ch
from grader.runtime.node_link import Endpoint, ProtocolViolation, ServiceAnswer, ServiceCall, ServiceReply
from grader.runtime.plain_values import nested, plain
from grader.runtime.wire import Wire
from sim import WorldService

# A call is recorded under this prefix and the service's name: ``<service>/request`` (what the caller sent, when the
# server took it), then ``<service>/response`` (what the server answered) or ``<service>/error`` (why it failed).
SERVICE_PREFIX = "/rosgrade/service"


class ServiceRouteError(Exception):
    """A call the grader itself would make cannot be built (a scenario's request that does not fit its srv type)."""


@dataclass(frozen=True)
class Caller:
    """Who made a call: a node (its index, the client handle and call number its answer goes to), or the grader
    (``done`` gets the status, the server's error text, the response bytes and the answer's time)."""

    callerid: str
    origin: str
    node: int | None = None
    ident: int = 0
    seq: int = 0
    done: Callable[[str, str, bytes, int], None] | None = None


class _NodeServer:
    """A service a node offers: a request goes to the node in its next BATCH; its RESPOND answers it."""

    def __init__(self, node: int, endpoint: Endpoint, callerid: Callable[[], str], alive: Callable[[], bool]) -> None:
        self.node, self.endpoint = node, endpoint
        self.type, self.md5sum, self.origin = endpoint.type, endpoint.md5sum, "node"
        self._callerid, self._alive = callerid, alive
        self.pending: dict[int, Caller] = {}
        self._seq = itertools.count(1)

    @property
    def callerid(self) -> str:
        return self._callerid()

    def live(self) -> bool:
        return self._alive() and not self.endpoint.closed

    def take(self, router: ServiceRouter, caller: Caller, request: bytes, t: int) -> ServiceReply | None:
        seq = next(self._seq)
        self.pending[seq] = caller
        router.deliver(self.node, (self.endpoint.ident, request, (seq, ch.SERVICE_REQUEST, "")))
        return None


class _WorldServer:
    """A service the world declares: it answers at once, at the caller's time."""

    origin = "world"

    def __init__(self, served: WorldService, router: ServiceRouter) -> None:
        # The world names a srv type once for both flavours (``turtlesim/Spawn``); a ROS 2 client's call spells it
        # ``turtlesim/srv/Spawn``.
        self.name, self.type = served.name, router.wire.catalog.service_type(served.type)
        self.md5sum = router.wire.catalog.service_md5sum(served.type)
        self.callerid = router.world.node_name

    @staticmethod
    def live() -> bool:
        return True

    def take(self, router: ServiceRouter, caller: Caller, request: bytes, t: int) -> ServiceReply:
        values = {name: plain(value) for name, value in router.wire.request_values(self.type, request).items()}
        result = router.world.call(self.name, values)
        for sample in result.samples:
            router.world_sample(sample)
        router.world_changed()  # a spawned or killed turtle's topics and services
        if not result.ok and router.wire.name == "ros1":
            return ServiceReply(ch.SERVICE_FAILED, result.error)
        # A ROS 2 server has no failure reply: what turtlesim's callbacks return is ignored and the response goes out
        # as the callback left it (/spawn of a taken name answers an empty name).
        response = nested(router.wire.catalog, router.wire.service_part(self.type, "Response"), result.response)
        return ServiceReply(ch.SERVICE_OK, response=router.wire.response_bytes(self.type, response))


@dataclass
class ServiceRouter:
    """The run's services: who serves each, the calls in flight, and what the recording says of them."""

    wire: Wire
    world: object  # the run's world: ``services``, ``call``, ``node_name``
    record: Callable[..., None]  # the recorder's write(topic, type, data, t, callerid=, origin=)
    deliver: Callable[[int, tuple], None]  # queue an item for a node's next BATCH
    world_sample: Callable[[object], None]  # what the world logged while serving
    world_changed: Callable[[], None]
    offers: list[_NodeServer] = field(default_factory=list)  # in the order nodes offered them
    on_offer: list[Callable[[int], None]] = field(default_factory=list)  # told when a node offers a service

    def server(self, name: str) -> _NodeServer | _WorldServer | None:
        """Who serves ``name`` now: the world's server, else the first live node that offered it."""
        served = next((s for s in self.world.services if s.name == name), None)
        if served is not None:
            return _WorldServer(served, self)
        return next((s for s in self.offers if s.endpoint.topic == name and s.live()), None)

    def offer(self, node: int, endpoint: Endpoint, callerid: Callable[[], str], alive: Callable[[], bool],
              t: int) -> None:
        """A node's SERVE."""
        self.offers.append(_NodeServer(node, endpoint, callerid, alive))
        for told in self.on_offer:
            told(t)

    def call(self, caller: Caller, call: ServiceCall, t: int) -> ServiceReply | None:
        """Route a call at t. A probe is answered at once (served or not); a call's answer reaches the caller later."""
        server = self.server(call.service)
        if call.probe:  # a probe names no srv type (md5sum "*"), which roscpp lets through
            return ServiceReply(ch.SERVICE_OK if server is not None else ch.SERVICE_UNAVAILABLE)
        if server is None:
            self._answer(caller, call.service, None, ServiceReply(ch.SERVICE_UNAVAILABLE), t)
        elif call.type != server.type or call.md5sum != server.md5sum:
            # roscpp's words when a client's srv type is not the server's
            self._answer(caller, call.service, server, ServiceReply(
                ch.SERVICE_REFUSED, f"client wants service {call.service} to have md5sum {call.md5sum}, but it has "
                                    f"{server.md5sum}. Dropping connection."), t)
        else:
            if self.wire.catalog.known_service(server.type):
                self.record(f"{SERVICE_PREFIX}{call.service}/request", self.wire.service_part(server.type, "Request"),
                            call.request, t, callerid=caller.callerid, origin=caller.origin)
            reply = server.take(self, caller, call.request, t)
            if reply is not None:
                self._answer(caller, call.service, server, reply, t)
        return None

    def answer(self, node: int, answer: ServiceAnswer, t: int) -> None:
        """A node's RESPOND to a request it was given."""
        server = next((s for s in self.offers if s.node == node and s.endpoint is answer.endpoint), None)
        caller = None if server is None else server.pending.pop(answer.seq, None)
        if caller is None:
            raise ProtocolViolation(f"RESPOND to request {answer.seq} of {answer.endpoint.topic}, which it was not "
                                    "given or has answered")
        self._answer(caller, answer.endpoint.topic, server,
                     ServiceReply(answer.status, answer.error, answer.response), t)

    def node_ended(self, node: int, t: int) -> None:
        """A node ended: the calls its servers had not answered are lost (rospy's connection closes; an rclpy
        client's Future never completes)."""
        for server in self.offers:
            if server.node == node:
                pending, server.pending = server.pending, {}
                for caller in pending.values():
                    self._answer(caller, server.endpoint.topic, server, ServiceReply(ch.SERVICE_LOST), t)

    def _answer(self, caller: Caller, service: str, server, reply: ServiceReply, t: int) -> None:
        """Record an answer at t and send it to the caller."""
        callerid = server.callerid if server is not None else self.world.node_name
        origin = server.origin if server is not None else "world"
        if reply.status == ch.SERVICE_OK:
            if self.wire.catalog.known_service(server.type):
                self.record(f"{SERVICE_PREFIX}{service}/response", self.wire.service_part(server.type, "Response"),
                            reply.response, t, callerid=callerid, origin=origin)
        else:
            text = f"{reply.status}: {reply.error}" if reply.error else reply.status
            self.record(f"{SERVICE_PREFIX}{service}/error", self.wire.string_type, self.wire.string(text), t,
                        callerid=callerid, origin=origin)
        if caller.done is not None:
            caller.done(reply.status, reply.error, reply.response, t)
        elif caller.node is not None:
            self.deliver(caller.node, (caller.ident, reply.response, (caller.seq, reply.status, reply.error)))
