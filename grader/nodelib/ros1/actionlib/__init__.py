"""rosgrade's actionlib (ROS 1): SimpleActionServer, SimpleActionClient, ActionServer and ActionClient over rospy's
topics, with the goal states and callbacks of Debian's python3-actionlib 1.14."""
from __future__ import annotations

from actionlib_msgs.msg import GoalID, GoalStatus, GoalStatusArray  # noqa: F401 - actionlib's star imports give them

from .action_client import (ActionClient, ClientGoalHandle, CommState, CommStateMachine, GoalManager,
                            TerminalState, get_name_of_constant)
from .action_server import ActionServer, nop_cb
from .exceptions import ActionException
from .server_goal_handle import GoalIDGenerator, ServerGoalHandle, StatusTracker
from .simple_action_client import SimpleActionClient, SimpleGoalState
from .simple_action_server import SimpleActionServer

__all__ = ["ActionClient", "ActionException", "ActionServer", "ClientGoalHandle", "CommState", "CommStateMachine",
           "GoalID", "GoalIDGenerator", "GoalManager", "GoalStatus", "GoalStatusArray", "ServerGoalHandle",
           "SimpleActionClient", "SimpleActionServer", "SimpleGoalState", "StatusTracker", "TerminalState",
           "get_name_of_constant", "nop_cb"]
