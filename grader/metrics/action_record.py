"""The grader's action goals as a recording holds them, where ROS 2 carries them: the goal, result and cancel calls
(``/rosgrade/service/<action>/_action/...``) and the server's ``<action>/_action/feedback`` and ``status`` topics,
gathered per goal id; or where ROS 1's actionlib carries them: the grader's ``<action>/goal`` and ``cancel`` and the
server's ``status``, ``feedback`` and ``result`` topics, with actionlib's statuses in action_msgs' numbers."""
from __future__ import annotations

from dataclasses import dataclass
from typing import Any

GRADER = "/rosgrade"  # the grader's callerid; a student node may not take a name under /rosgrade
_SERVICE_PREFIX = "/rosgrade/service"
_PARTS = ("send_goal", "get_result", "cancel_goal")
# actionlib_msgs/GoalStatus -> action_msgs/msg/GoalStatus: PENDING->ACCEPTED, ACTIVE->EXECUTING, PREEMPTED->CANCELED,
# SUCCEEDED, ABORTED, PREEMPTING and RECALLING->CANCELING, RECALLED->CANCELED, LOST->UNKNOWN; REJECTED (5) has no
# ROS 2 status: a rejected goal is one not accepted.
ROS1_STATUS = {0: 1, 1: 2, 2: 5, 3: 4, 4: 6, 6: 3, 7: 3, 8: 5, 9: 0}
ROS1_REJECTED = 5


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
    """Every goal the grader sent (ROS 2 or actionlib), in the order sent. Answers pair with requests in the order the server received
    them, a result with the earliest open request of a goal that has ended by then (a server answers results as
    goals end, not as they were asked for)."""
    infos = list(getattr(recording, "topics", list)())
    actions = sorted({i.topic[len(_SERVICE_PREFIX):-len("/_action/send_goal/request")] for i in infos
                      if i.topic.startswith(_SERVICE_PREFIX) and i.topic.endswith("/_action/send_goal/request")
                      and i.callerid == GRADER})
    actionlib = sorted({i.topic[:-len("/goal")] for i in infos if i.topic.endswith("/goal")
                        and i.type.endswith("ActionGoal") and i.callerid == GRADER})
    goals: list[dict] = []
    for action in actions:
        goals += _goals_of(recording, action, {i.topic for i in infos})
    for action in actionlib:
        goals += _actionlib_goals_of(recording, action)
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


def _actionlib_goals_of(recording: Any, action: str) -> list[dict]:
    """The grader's goals to an actionlib server, by goal id: accepted once the server gives it a status other than
    REJECTED, its feedback times, its statuses (action_msgs' numbers) and its result."""
    by_id: dict[str, dict] = {}
    for t_ns, message in recording.messages(f"{action}/goal", GRADER):
        by_id.setdefault(message.goal_id.id, {"id": message.goal_id.id, "t": t_ns / 1e9, "action": action,
                                              "goal": plain(message.goal), "feedback_t": [], "statuses": []})
    for t_ns, message in recording.messages(f"{action}/cancel", GRADER):
        if message.id in by_id:
            by_id[message.id].setdefault("cancel_t", t_ns / 1e9)
    topics = {f"{action}/{part}" for part in ("status", "feedback", "result")}
    for topic, t_ns, message in recording.messages_on(topics):
        part = topic.rsplit("/", 1)[-1]
        statuses = message.status_list if part == "status" else [message.status]
        for status in statuses:
            goal = by_id.get(status.goal_id.id)
            if goal is None:
                continue
            goal["accepted"] = status.status != ROS1_REJECTED and goal.get("accepted", True)
            mapped = ROS1_STATUS.get(int(status.status))
            if part == "feedback":
                goal["feedback_t"].append(t_ns / 1e9)
            if part == "result":
                goal.update(result_status=mapped, result=plain(message.result))
            if mapped is not None and goal["statuses"][-1:] != [mapped]:
                goal["statuses"].append(mapped)
    return list(by_id.values())
