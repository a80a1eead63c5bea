"""The grader's action goals as a recording holds them, where ROS 2 carries them: the goal, result and cancel calls
(``/rosgrade/service/<action>/_action/...``) and the server's ``<action>/_action/feedback`` and ``status`` topics,
gathered per goal id."""
from __future__ import annotations

from dataclasses import dataclass
from typing import Any

GRADER = "/rosgrade"  # the grader's callerid; a student node may not take a name under /rosgrade
_SERVICE_PREFIX = "/rosgrade/service"
_PARTS = ("send_goal", "get_result", "cancel_goal")


@dataclass(frozen=True)
class ActionGoal:
    """One goal the grader sent; times in seconds of sim time."""

    t: float
    action: str
    goal: dict[str, Any]
    accepted: bool | None = None  # None: the server never answered the goal request
    feedback_t: tuple[float, ...] = ()
    statuses: tuple[int, ...] = ()  # each status the server published for the goal, repeats dropped
    result_status: int | None = None  # the GetResult response's status (None: no result came)
    result: dict[str, Any] | None = None
    cancel_t: float | None = None  # when the grader's Ctrl+C asked to cancel it
    cancel_return_code: int | None = None

    @property
    def final_status(self) -> int | None:
        """The last status the server gave the goal (on its status topic, else in its result)."""
        return self.statuses[-1] if self.statuses else self.result_status


def plain(value: Any) -> Any:
    """A decoded field as plain values: messages as dicts, arrays as lists."""
    if hasattr(value, "__dataclass_fields__"):
        return {name: plain(getattr(value, name)) for name in value.__dataclass_fields__
                if not name.startswith("__")}
    if hasattr(value, "tolist"):
        return value.tolist()
    if isinstance(value, (list, tuple)):
        return [plain(v) for v in value]
    return value


def _uuid(message: Any) -> bytes:
    return bytes(bytearray(message.uuid))


def action_goals(recording: Any) -> tuple[ActionGoal, ...]:
    """Every goal the grader sent, in the order sent. Answers pair with requests in the order the server received
    them, a result with the earliest open request of a goal that has ended by then (a server answers results as
    goals end, not as they were asked for)."""
    infos = list(getattr(recording, "topics", list)())
    actions = sorted({i.topic[len(_SERVICE_PREFIX):-len("/_action/send_goal/request")] for i in infos
                      if i.topic.startswith(_SERVICE_PREFIX) and i.topic.endswith("/_action/send_goal/request")
                      and i.callerid == GRADER})
    goals: list[dict] = []
    for action in actions:
        goals += _goals_of(recording, action, {i.topic for i in infos})
    goals.sort(key=lambda g: g["t"])
    return tuple(ActionGoal(**{k: (tuple(v) if isinstance(v, list) else v) for k, v in g.items() if k != "id"})
                 for g in goals)


def _goals_of(recording: Any, action: str, topics: set[str]) -> list[dict]:
    grader_ids = {_uuid(m.goal_id) for _, m in recording.messages(
        f"{_SERVICE_PREFIX}{action}/_action/send_goal/request", GRADER)}
    wanted = {f"{_SERVICE_PREFIX}{action}/_action/{part}/{kind}" for part in _PARTS for kind in ("request", "response")}
    wanted |= {f"{action}/_action/feedback", f"{action}/_action/status"}
    by_id: dict[bytes, dict] = {}
    open_goals: list[bytes] = []
    open_results: list[bytes] = []
    open_cancels: list[bytes] = []
    last_status: dict[bytes, int] = {}
    for topic, t_ns, message in recording.messages_on(wanted & topics):
        t = t_ns / 1e9
        part = topic.rsplit("/", 2)[-2:] if topic.startswith(_SERVICE_PREFIX) else None
        if part == ["send_goal", "request"]:
            goal_id = _uuid(message.goal_id)
            open_goals.append(goal_id)
            if goal_id in grader_ids and goal_id not in by_id:
                by_id[goal_id] = {"id": goal_id, "t": t, "action": action, "goal": plain(message.goal),
                                  "feedback_t": [], "statuses": []}
        elif part == ["send_goal", "response"] and open_goals:
            goal = by_id.get(open_goals.pop(0))
            if goal is not None:
                goal["accepted"] = bool(message.accepted)
        elif part == ["get_result", "request"]:
            open_results.append(_uuid(message.goal_id))
        elif part == ["get_result", "response"] and open_results:
            ended = [g for g in open_results if last_status.get(g, 0) >= 4]
            goal_id = (ended or open_results)[0]
            open_results.remove(goal_id)
            if goal_id in by_id:
                by_id[goal_id].update(result_status=int(message.status), result=plain(message.result))
        elif part == ["cancel_goal", "request"]:
            goal_id = _uuid(message.goal_info.goal_id)
            open_cancels.append(goal_id)
            if goal_id in by_id:
                by_id[goal_id]["cancel_t"] = t
        elif part == ["cancel_goal", "response"] and open_cancels:
            goal_id = open_cancels.pop(0)
            if goal_id in by_id:
                by_id[goal_id]["cancel_return_code"] = int(message.return_code)
        elif topic.endswith("/_action/feedback"):
            goal_id = _uuid(message.goal_id)
            if goal_id in by_id:
                by_id[goal_id]["feedback_t"].append(t)
        elif topic.endswith("/_action/status"):
            for status in message.status_list:
                goal_id = _uuid(status.goal_info.goal_id)
                last_status[goal_id] = int(status.status)
                if goal_id in by_id and by_id[goal_id]["statuses"][-1:] != [int(status.status)]:
                    by_id[goal_id]["statuses"].append(int(status.status))
    return list(by_id.values())
