"""The message classes an action spec (genmsg's ``<Name>Action``) wraps, as actionlib reads them from an instance."""
from __future__ import annotations

from .exceptions import ActionException


class ActionTypes:
    """``ActionGoal``, ``ActionResult``, ``ActionFeedback`` and the bare ``Result`` class of one action spec."""

    def __init__(self, action_spec: type) -> None:
        try:
            sample = action_spec()
            self.ActionSpec = action_spec
            self.ActionGoal = type(sample.action_goal)
            self.ActionResult = type(sample.action_result)
            self.ActionResultType = type(sample.action_result.result)
            self.ActionFeedback = type(sample.action_feedback)
        except AttributeError:
            raise ActionException("Type is not an action spec: %s" % str(action_spec)) from None


def name_of_constant(holder: type, value: int) -> str:
    """The name of the int class attribute of ``holder`` equal to ``value`` (actionlib's ``get_name_of_constant``)."""
    for key, item in holder.__dict__.items():
        if isinstance(item, int) and item == value:
            return key
    return "NO_SUCH_STATE_%d" % value
