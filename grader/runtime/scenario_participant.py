"""The scenario as a participant: /rosgrade on the run's graph, which makes the scenario's service calls, parameter
sets and action goals (scenario_calls.py, scenario_goals.py; actionlib's in scenario_actionlib.py) and its
publications (scenario_topics.py) at their sim times, through the run's routing, recorded with origin "grader" as any node's traffic is recorded."""
from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

from grader.runtime.param_server import ParamServer
from grader.runtime.scenario_actionlib import planned_actionlib_goals
from grader.runtime.scenario_calls import PlannedCall, ScenarioCaller, planned_calls
from grader.runtime.scenario_goals import PlannedGoal, planned_goals
from grader.runtime.scenario_topics import Graph, PlannedPublication, PublicationError, TopicPublisher, \
    planned_publications
from grader.runtime.services import ServiceRouteError, ServiceRouter
from grader.runtime.wire import Wire
from sim.scenario import Scenario


class ParticipantError(Exception):
    """Something the scenario asks the grader to do cannot be done on this run's wire (what, and what to change)."""


@dataclass(frozen=True)
class ParticipantPlan:
    """Everything the scenario will do, encoded for the run's wire before the run starts."""

    calls: list[PlannedCall]
    goals: list[PlannedGoal]
    publications: list[PlannedPublication]


def plan(scenario: Scenario, wire: Wire) -> ParticipantPlan:
    """The scenario's acts encoded for ``wire``; ParticipantError names the first that cannot be made."""
    actionlib = wire.name == "ros1"  # rospy's actions are actionlib's topics; rclpy's are services and topics
    try:
        return ParticipantPlan(planned_calls(scenario.service_calls, wire, scenario.param_sets),
                               [] if actionlib else planned_goals(scenario.action_goals, wire),
                               planned_publications(scenario.publications, wire)
                               + (planned_actionlib_goals(scenario.action_goals, wire) if actionlib else []))
    except (ServiceRouteError, PublicationError) as exc:
        raise ParticipantError(str(exc)) from None


class ScenarioParticipant:
    """Drives the scenario's acts from the lockstep loop: ``next_ns`` says when it must stop next, ``tick(t)`` acts."""

    def __init__(self, planned: ParticipantPlan, start_ns: int, router: ServiceRouter, params: ParamServer | None,
                 graph: Graph, write: Callable[..., None], lost_prefix: str) -> None:
        self._caller = ScenarioCaller(planned.calls, start_ns, router, params, planned.goals)
        self._publishers = [TopicPublisher(publication, start_ns, graph, write, lost_prefix)
                            for publication in planned.publications]

    def next_ns(self) -> int | None:
        """When the loop must stop for the next act (None: none, or they wait for answers, servers or subscribers)."""
        times = [due for actor in (self._caller, *self._publishers) if (due := actor.next_ns()) is not None]
        return min(times, default=None)

    def tick(self, t: int) -> None:
        """Every act due at t: calls, sets and goals first, then publications."""
        self._caller.tick(t)
        for publisher in self._publishers:
            publisher.tick(t)
