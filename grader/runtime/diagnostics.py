"""Plain-language findings about a run that a student can act on: topics, types, init_node, exceptions."""
from __future__ import annotations

from typing import TYPE_CHECKING

from grader.runtime import qos_match

if TYPE_CHECKING:
    from grader.runtime.session import Session, _Node

_CONNECT_MS = 50
# Per node, at most this many lines about single publishers or subscribers; the rest are summarised in one line.
MAX_ENDPOINT_LINES = 20


def _count(n: int, what: str) -> str:
    return f"{n} {what}{'' if n == 1 else 's'}"


def _location(exc: dict) -> str:
    """' at file line N (`code`)' for the student's innermost frame, or ''."""
    if not exc.get("frames"):
        return ""
    last = exc["frames"][-1]
    where = f" at {last.get('file', '?')} line {last.get('line', '?')}"
    return where + (f" (`{last['text']}`)" if last.get("text") else "")


def _capped(lines: list[str], what: str) -> list[str]:
    """The first MAX_ENDPOINT_LINES lines, then one line saying how many more there were."""
    if len(lines) <= MAX_ENDPOINT_LINES:
        return lines
    return lines[:MAX_ENDPOINT_LINES] + [f"... and {len(lines) - MAX_ENDPOINT_LINES} more {what} (not listed)."]


def diagnose(session: Session) -> list[str]:
    """Findings for every node of a finished session, most useful first."""
    world = session.world
    command_topics = tuple(world.command_topics)
    world_topics = {p.topic: p.type for p in session.publications.values() if p.to_nodes}
    init_call = "rclpy.init() and create a Node" if session.wire.client_library == "rclpy" else "rospy.init_node()"
    robot_received = sum(session.received.values())
    notes: list[str] = []
    for node in session.nodes:
        state = node.link.state
        label = node.outcome.script
        if node.outcome.status == "not_started":
            notes.append(f"{label} {node.outcome.message}.")
            continue
        if node.spec.provided:  # the grader's own node: only its failure is worth a line (a request it choked on)
            if state.exception:
                notes.append(f"the grader's {label} stopped with an uncaught {state.exception.get('type')}: "
                             f"{state.exception.get('message')}")
            elif node.outcome.status not in ("exited", "stopped_at_end"):
                notes.append(f"the grader's {label}: {node.outcome.message}.")
            continue
        if state.name is None:
            notes.append(f"{label} never called {init_call}: a ROS node must do so before it can publish, "
                         "subscribe or read the time.")
        notes += _capped(_endpoint_notes(session, node, command_topics, world_topics, robot_received),
                         f"findings about {label}'s publishers and subscribers")
        if state.exception:
            exc = state.exception
            notes.append(f"{label} stopped with an uncaught {exc.get('type')}{_location(exc)}: {exc.get('message')}")
        for exc in state.caught:
            notes.append(f"{label} raised {exc.get('type')} in a {exc['where']}{_location(exc)}: {exc.get('message')} "
                         f"({session.wire.client_library} printed the traceback and carried on)")
        if state.output_truncated:
            notes.append(f"{label} printed more than the output limit; the rest was discarded.")
        if node.outcome.status != "exited" or state.name is None:
            notes.append(f"{label}: {node.outcome.message}.")
        notes.extend(node.outcome.findings)
    return notes


# What a client library publishes on its own in every node (rclpy's parameter events, whose declarations go out
# before discovery): nothing the student did, so no finding or summary line names it.
LIBRARY_TOPICS = frozenset({"/parameter_events"})


def _endpoint_notes(session: Session, node: _Node, command_topics: tuple[str, ...], world_topics: dict[str, str],
                    robot_received: int) -> list[str]:
    """Findings about one node's publishers and subscribers: wrong types or topics, messages lost at the start."""
    state, label = node.link.state, node.outcome.script
    notes: list[str] = []
    # The world as users know it when it names itself ("turtlesim"), else the robot.
    known_as = getattr(session.world, "known_as", None)
    here, world = known_as or "this robot", known_as or "the robot"
    for pub in state.publishers.values():
        if pub.topic in command_topics and pub.type not in session.command_types:
            notes.append(f"{pub.topic} carries {' or '.join(sorted(session.command_types))} on {here}, but "
                         f"{label} published {pub.type} there: {world} ignores it.")
        elif (pub.type in session.command_types and pub.topic not in command_topics and pub.count
              and robot_received == 0):
            notes.append(f"Your node published {_count(pub.count, 'message')} on {pub.topic}; {here} "
                         f"listens on {' or '.join(command_topics)}.")
        # Only worth saying when it cost the student something: a loop that publishes on loses nothing that matters.
        if (pub.dropped_before_connect and pub.count - pub.dropped_before_connect < 3
                and pub.topic not in LIBRARY_TOPICS):
            notes.append(
                f"{_count(pub.dropped_before_connect, 'message')} on {pub.topic} went out in the first "
                f"{_CONNECT_MS} ms after the publisher was created, before the robot had connected, and were "
                "lost (as on a real ROS system). Wait briefly after creating a publisher, or publish in a loop.")
    notes += qos_match.findings(session, node, world)
    for sub in state.subscribers.values():
        expected = world_topics.get(sub.topic)
        if expected is not None and expected != sub.type:
            notes.append(f"{label} subscribed to {sub.topic} as {sub.type}, but it carries {expected}: "
                         "no messages can arrive.")
        elif expected is None and sub.count == 0 and not any(sub.topic == p.topic for n in session.nodes
                                           for p in n.link.state.publishers.values()):
            available = ", ".join(sorted(world_topics))
            notes.append(f"{label} subscribed to {sub.topic}, which nothing publishes here (the robot publishes "
                         f"{available}).")
    return notes


def topic_summary(session: Session) -> list[str]:
    """What each node published and received, with counts (the same kind of line for every run)."""
    lines = []
    for node in session.nodes:
        if node.spec.provided:  # the grader's own node: its traffic is not the student's to read about
            continue
        label = node.outcome.script
        state = node.link.state
        lines += _capped([f"{label} published {_count(p.count, 'message')} on {p.topic} ({p.type})."
                          for p in state.publishers.values() if p.topic not in LIBRARY_TOPICS]
                         + [f"{label} received {_count(qos_match.heard(session, s), 'message')} on {s.topic} "
                            f"({s.type})."
                            for s in state.subscribers.values()], f"publishers and subscribers of {label}")
    return lines
