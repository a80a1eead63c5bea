#!/usr/bin/env python3
"""turtle1's ``rotate_absolute`` action (turtlesim/action/RotateAbsolute) as ROS 2 Jazzy's turtlesim runs it, for
grading a student's action client: started beside the world by a rubric's ``grader_nodes``, it turns the turtle
through ``turtle1/cmd_vel`` on each of turtlesim's 16 ms updates, as turtle.cpp sets the turtle's own velocity.

turtle.cpp (ros/ros_tutorials rolling 1.8.2, Jazzy's) accepts every goal and every cancel; a new goal aborts the one
running ("Rotation goal received before a previous goal finished. Aborting previous goal") and a velocity command
from anyone else aborts it too ("Velocity command received during rotation goal. Aborting goal"). On each update,
with the heading the previous update left: a cancelled goal ends CANCELED ("Rotation goal canceled") and the turtle
stops; else ``remaining`` = normalize(theta - heading) is published as feedback and the result's ``delta`` =
normalize(start heading - heading); within 0.02 rad of theta the goal SUCCEEDS ("Rotation goal completed
successfully") and the turtle stops, otherwise it turns at 1 rad/s towards theta the short way. normalize is
turtle.cpp's ``angle - 2·PI·floor((angle + PI) / (2·PI))`` with its PI 3.14159265.

Here each update's step is taken when that update's pose arrives (the heading it left), and its command reaches the
world for the next update, which is when turtle.cpp would take it; a goal's first step is taken when it is accepted,
from the last pose. A goal's terminal state is therefore set at the pose of the update before the one turtle.cpp sets
it in: 16 ms earlier, the turtle in the same place.

Shipped with the grader and run confined like a student's node; never student code.
"""
import math
import struct
import time

import rclpy
from geometry_msgs.msg import Twist
from rclpy.action import ActionServer, CancelResponse, GoalResponse
from rclpy.callback_groups import ReentrantCallbackGroup
from rclpy.executors import ExternalShutdownException, MultiThreadedExecutor
from rclpy.node import Node
from rclpy.qos import QoSProfile, ReliabilityPolicy
from rclpy.task import Future
from turtlesim.action import RotateAbsolute
from turtlesim.msg import Pose

PI = 3.14159265  # turtle.hpp's
TWO_PI = 2.0 * PI
DONE_RAD = 0.02
WAIT_S = 0.004  # how often a goal's execute callback looks whether the updates have ended it


def normalize(angle):
    """turtle.cpp's normalizeAngle: into [-PI, PI)."""
    return angle - TWO_PI * math.floor((angle + PI) / TWO_PI)


def f32(value):
    """A C++ static_cast<float>."""
    return struct.unpack("<f", struct.pack("<f", value))[0]


class RotateAbsoluteServer(Node):

    def __init__(self):
        super().__init__("turtlesim_rotate_absolute")
        qos = QoSProfile(depth=7, reliability=ReliabilityPolicy.RELIABLE)  # turtlesim's topic_qos()
        group = ReentrantCallbackGroup()  # the updates go on while a goal's execute callback waits for its end
        self.publisher = self.create_publisher(Twist, "turtle1/cmd_vel", qos)
        self.create_subscription(Pose, "turtle1/pose", self.on_pose, qos, callback_group=group)
        self.create_subscription(Twist, "turtle1/cmd_vel", self.on_command, qos, callback_group=group)
        self.heading = None
        self.goal = None  # the running goal's handle
        self.start = 0.0
        self.result = RotateAbsolute.Result()
        self.done = {}  # goal id -> Future of its result
        self.echoes = 0  # own commands not yet heard back on turtle1/cmd_vel
        ActionServer(self, RotateAbsolute, "turtle1/rotate_absolute", self.execute,
                     goal_callback=lambda request: GoalResponse.ACCEPT, cancel_callback=self.on_cancel,
                     handle_accepted_callback=self.accepted, callback_group=group)

    def drive(self, angular):
        cmd = Twist()
        cmd.angular.z = angular
        self.echoes += 1
        self.publisher.publish(cmd)

    def end(self):
        self.done[bytes(self.goal.goal_id.uuid)].set_result(self.result)
        self.goal = None

    def accepted(self, goal_handle):
        if self.goal is not None:
            self.get_logger().warn("Rotation goal received before a previous goal finished. Aborting previous goal")
            self.goal.abort()
            self.end()
        self.done[bytes(goal_handle.goal_id.uuid)] = Future()
        self.goal, self.result = goal_handle, RotateAbsolute.Result()
        self.start = self.heading if self.heading is not None else 0.0
        goal_handle.execute()
        if self.heading is not None:
            self.step()

    def execute(self, goal_handle):
        done = self.done[bytes(goal_handle.goal_id.uuid)]
        while not done.done():
            time.sleep(WAIT_S)
        return done.result()

    def on_cancel(self, goal_handle):
        if goal_handle == self.goal:
            self.drive(0.0)  # turtle.cpp stops the turtle in the update that takes the cancel
        return CancelResponse.ACCEPT

    def on_pose(self, msg):
        self.heading = msg.theta
        if self.goal is not None:
            self.step()

    def on_command(self, msg):
        if self.echoes:
            self.echoes -= 1
            return
        if self.goal is not None:
            self.get_logger().warn("Velocity command received during rotation goal. Aborting goal")
            self.goal.abort()
            self.end()

    def step(self):
        """One update of turtle.cpp's rotate_absolute, from the heading the last update left."""
        if self.goal.is_cancel_requested:
            self.get_logger().info("Rotation goal canceled")
            self.goal.canceled()
            self.end()
            return
        theta = normalize(self.goal.request.theta)
        remaining = normalize(theta - self.heading)
        self.result.delta = normalize(f32(self.start - self.heading))
        feedback = RotateAbsolute.Feedback()
        feedback.remaining = remaining
        self.goal.publish_feedback(feedback)
        if abs(normalize(self.heading - theta)) < DONE_RAD:
            self.get_logger().info("Rotation goal completed successfully")
            self.goal.succeed()
            self.end()
            self.drive(0.0)
        else:
            self.drive(-1.0 if remaining < 0.0 else 1.0)


def main():
    rclpy.init()
    try:
        rclpy.spin(RotateAbsoluteServer(), executor=MultiThreadedExecutor())
    except (KeyboardInterrupt, ExternalShutdownException):
        pass  # Ctrl+C or the end of the run


if __name__ == "__main__":
    main()
