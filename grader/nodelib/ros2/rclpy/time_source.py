"""rclpy.time_source.TimeSource: use_sim_time for a node's ROS clocks.

Real rclpy subscribes to /clock and updates the clocks in that subscription's callback, so the time only moves while
an executor spins the node, and before the first /clock it reads 0. Here the grader hands the last /clock value in
every BATCH (``scheduler.clock_ns``); an executor applies it to the node's clocks when it processes the node, which
is the same thing: ``now()`` in ``__init__`` is 0, a callback that blocks starves the clock too.
"""
from __future__ import annotations

from . import _runtime
from .clock import ROSClock
from .time import Time

USE_SIM_TIME_NAME = "use_sim_time"


class TimeSource:
    def __init__(self, node=None) -> None:
        self._clocks: list[ROSClock] = []
        self._ros_time_is_active = False
        self._applied_ns = 0
        self._node = None
        if node is not None:
            self.attach_node(node)

    @property
    def ros_time_is_active(self) -> bool:
        return self._ros_time_is_active

    @ros_time_is_active.setter
    def ros_time_is_active(self, enabled: bool) -> None:
        if self._ros_time_is_active == enabled:
            return
        self._ros_time_is_active = enabled
        for clock in self._clocks:
            clock.set_ros_time_override(Time(nanoseconds=self._applied_ns, clock_type=clock.clock_type))
            clock._set_ros_time_is_active(enabled)

    def attach_node(self, node) -> None:
        from .parameter import Parameter
        self._node = node
        if not node.has_parameter(USE_SIM_TIME_NAME):
            node.declare_parameter(USE_SIM_TIME_NAME, False)
        param = node.get_parameter(USE_SIM_TIME_NAME)
        if param.type_ != Parameter.Type.NOT_SET:
            if param.type_ != Parameter.Type.BOOL:
                raise ValueError(f"{USE_SIM_TIME_NAME} parameter set to something besides a bool")
            self.ros_time_is_active = param.value
        node.add_on_set_parameters_callback(self._on_parameter_event)

    def _on_parameter_event(self, parameter_list):
        from .parameter import Parameter, SetParametersResult
        for param in parameter_list:
            if param.name != USE_SIM_TIME_NAME:
                continue
            if param.type_ == Parameter.Type.BOOL:
                self.ros_time_is_active = param.value
            else:
                return SetParametersResult(successful=False,
                                           reason=f"{USE_SIM_TIME_NAME} parameter set to something besides a bool")
        return SetParametersResult(successful=True)

    def detach_node(self) -> None:
        self._node = None

    def attach_clock(self, clock: ROSClock) -> None:
        if not isinstance(clock, ROSClock):
            raise ValueError("Only clocks with type ROS_TIME can be attached.")
        clock.set_ros_time_override(Time(nanoseconds=self._applied_ns, clock_type=clock.clock_type))
        clock._set_ros_time_is_active(self._ros_time_is_active)
        self._clocks.append(clock)

    def clock_pending(self) -> bool:
        """A /clock value newer than the one applied is waiting (the /clock subscription is ready)."""
        return self._ros_time_is_active and _runtime.clock_msg_ns() != self._applied_ns

    def first_sleep_target(self) -> int | None:
        """The earliest ROS time a thread sleeps until on one of the node's clocks (None: nobody sleeps on sim time)."""
        if not self._ros_time_is_active:
            return None
        return min((t for clock in self._clocks for t in clock._sleep_targets), default=None)

    def apply_clock(self) -> None:
        """The /clock subscription's callback: the node's ROS clocks take the grader's latest /clock."""
        ns = _runtime.clock_msg_ns()
        if not self._ros_time_is_active or ns == self._applied_ns:
            return  # no /clock subscription without use_sim_time
        self._applied_ns = ns
        for clock in self._clocks:
            clock._ros_time_ns = ns

    def destroy(self) -> None:
        self._clocks = []
        self._node = None
