"""rcl_action's goal state machine: which event moves a goal from which state, and the error for any other."""
from __future__ import annotations

from enum import IntEnum

from .._rclpy_pybind11 import RCLError


class GoalEvent(IntEnum):
    EXECUTE = 0
    CANCEL_GOAL = 1
    SUCCEED = 2
    ABORT = 3
    CANCELED = 4


# action_msgs/GoalStatus values: UNKNOWN 0, ACCEPTED 1, EXECUTING 2, CANCELING 3, SUCCEEDED 4, CANCELED 5, ABORTED 6
_NAMES = ("UNKNOWN", "ACCEPTED", "EXECUTING", "CANCELING", "SUCCEEDED", "CANCELED", "ABORTED")
_TRANSITIONS = {
    (1, GoalEvent.EXECUTE): 2, (1, GoalEvent.CANCEL_GOAL): 3,
    (2, GoalEvent.CANCEL_GOAL): 3, (2, GoalEvent.SUCCEED): 4, (2, GoalEvent.ABORT): 6,
    (3, GoalEvent.SUCCEED): 4, (3, GoalEvent.ABORT): 6, (3, GoalEvent.CANCELED): 5,
}


def transition(state: int, event: GoalEvent) -> int:
    """The state after ``event``; RCLError, worded as the Jazzy wheels' rcl_action (measured, conformance p15), when
    the machine has no such transition."""
    new_state = _TRANSITIONS.get((state, event))
    if new_state is None:
        raise RCLError(f"Failed to update goal state: goal_handle attempted invalid transition from state "
                       f"{_NAMES[state]} with event {event.name}, at /project/src/rcl_action/goal_handle.c:100")
    return new_state
