#!/usr/bin/env python3
"""Probe 23: turtle1's rotate_absolute action: a goal that succeeds, one replaced by a new goal, one cancelled, one
aborted by a cmd_vel message: each goal's status, its result's delta (0.1 rad) and feedback, and what is logged.
"""
import rclpy
from action_msgs.msg import GoalStatus
from geometry_msgs.msg import Twist
from rcl_interfaces.msg import Log
from rclpy.action import ActionClient
from rclpy.node import Node
from std_srvs.srv import Empty
from turtlesim.action import RotateAbsolute
from turtlesim.msg import Pose

STATUS = {v: k.removeprefix("STATUS_") for k, v in vars(GoalStatus).items() if k.startswith("STATUS_")}


class Probe(Node):
    def __init__(self):
        super().__init__("p23_turtle_action")
        self.pose = None
        self.logs = []
        self.feedback = []
        self.client = ActionClient(self, RotateAbsolute, "/turtle1/rotate_absolute")
        self.pub = self.create_publisher(Twist, "/turtle1/cmd_vel", 10)
        self.create_subscription(Pose, "/turtle1/pose", self.on_pose, 10)
        self.create_subscription(Log, "/rosout", self.on_log, 100)

    def on_pose(self, msg):
        self.pose = msg

    def on_log(self, msg):
        if "goal" in msg.msg:
            self.logs.append(f"{msg.level} {msg.msg}")

    def wait(self, seconds):
        end = self.get_clock().now().nanoseconds + seconds * 1e9
        while self.get_clock().now().nanoseconds < end:
            rclpy.spin_once(self, timeout_sec=0.05)

    def until(self, future):
        rclpy.spin_until_future_complete(self, future, timeout_sec=5.0)
        return future.result()

    def send(self, theta):
        self.feedback = []
        handle = self.until(self.client.send_goal_async(
            RotateAbsolute.Goal(theta=theta), feedback_callback=lambda f: self.feedback.append(f.feedback.remaining)))
        return handle, handle.get_result_async()

    def report(self, label, result_future):
        result = self.until(result_future)
        print(label, STATUS[result.status], "delta %.1f" % result.result.delta, "heading %.1f" % self.pose.theta)
        return result

    def report_turn(self, label, result_future, started_at=None):
        """A goal whose turn depends on when another goal, a cancel or a cmd_vel message came, a matter of wall time on
        the real side (0.3-0.5 rad measured): the status, a turn within bounds and, where the turtle is at rest after
        it (``started_at`` given), that the result's delta is the turn made from where the goal started."""
        result = self.until(result_future)
        delta = result.result.delta
        turn = () if started_at is None else ("delta is the turn", abs(delta - (started_at - self.pose.theta)) < 0.05)
        print(label, STATUS[result.status], "delta 0.1-0.9 rad", 0.1 <= abs(delta) <= 0.9, *turn)
        return self.pose.theta


rclpy.init()
node = Probe()
node.client.wait_for_server(timeout_sec=5.0)
while node.pose is None or node.get_clock().now().nanoseconds == 0:
    rclpy.spin_once(node, timeout_sec=0.1)
reset = node.create_client(Empty, "/reset")  # the world as it starts, whatever ran before
reset.wait_for_service(timeout_sec=5.0)
rclpy.spin_until_future_complete(node, reset.call_async(Empty.Request()), timeout_sec=2.0)
print("#REF %.6f" % (node.get_clock().now().nanoseconds / 1e9))
handle, result = node.send(1.0)
print("accepted", handle.accepted)
node.report("to 1.0:", result)
print("feedback first %.1f" % node.feedback[0], "last below 0.02", abs(node.feedback[-1]) < 0.02,
      "more than 30", len(node.feedback) > 30, "decreasing", node.feedback == sorted(node.feedback, reverse=True))
_, first = node.send(-1.0)
node.wait(0.3)
_, second = node.send(0.0)
node.report_turn("to -1.0, replaced:", first)
node.report_turn("then to 0.0:", second)
print("at 0.0 %.1f" % node.pose.theta)
handle, result = node.send(2.0)
node.wait(0.3)
cancel = node.until(handle.cancel_goal_async())
print("cancel return_code", cancel.return_code, "goals canceling", len(cancel.goals_canceling))
stopped_at = node.report_turn("to 2.0, cancelled:", result, 0.0)
_, result = node.send(-2.0)
node.wait(0.3)
node.pub.publish(Twist())
node.report_turn("to -2.0, cmd_vel sent:", result, stopped_at)
node.wait(0.3)
for line in node.logs:
    print("logged", line)
print("end")
