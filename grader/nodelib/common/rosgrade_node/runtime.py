"""The node runtime's singletons, set once by ``bootstrap.start`` (None when no grader channel exists)."""
from __future__ import annotations

from .link import Link
from .scheduler import Scheduler

link: Link | None = None
scheduler: Scheduler | None = None
# From START: parameters (absolute names -> JSON values), namespace and the wall-clock epoch of world time 0.
params: dict = {}
# The run's parameter server as a tree (rosgrade_params), START's parameters kept up to date by every batch: the
# scheduler's ``param_tree``. ROS 1 client libraries read and write it; ``params`` stays START's, as it came.
param_tree: dict = {}
ros_namespace: str = ""
wall_epoch_ns: int = 0
start_ns: int = 0  # world time when the process started (START's t_ns)
world_topics: list = []  # [topic, type] pairs the world publishes (for rospy.get_published_topics)
world_qos: dict = {}  # ROS 2: topic -> (reliability, durability) the world offers it with (rosgrade_qos names)


def wall_time() -> float:
    """The node's wall clock (what patched ``time.time()`` returns), without charging a call."""
    return (wall_epoch_ns + (scheduler.world_ns if scheduler else 0)) / 1e9
