#!/usr/bin/env python3
"""turtlesim's ``mimic`` for ROS 2 runs graded by rosgrade (the launch tutorial's turtlesim_mimic_launch.py starts it):
the node ``turtle_mimic`` subscribes to ``input/pose`` (turtlesim/msg/Pose) and, for each pose, publishes on
``output/cmd_vel`` a Twist of that pose's velocities (linear.x = linear_velocity, angular.z = angular_velocity), with
turtlesim's topic QoS (reliable, depth 7), as ros/ros_tutorials rolling 1.8.2 ``turtlesim/tutorials/mimic.cpp`` does.
Remapped from the launch file (``input/pose`` to one turtle's pose, ``output/cmd_vel`` to another's cmd_vel), the second
turtle drives as the first does. A ROS 1 run gets Noetic's mimic instead (``turtle_mimic.py``).

Shipped with the grader and run confined like a student's node; never student code.
"""
import rclpy
from geometry_msgs.msg import Twist
from rclpy.executors import ExternalShutdownException
from rclpy.node import Node
from rclpy.qos import QoSProfile, ReliabilityPolicy
from turtlesim.msg import Pose


class Mimic(Node):

    def __init__(self):
        super().__init__("turtle_mimic")
        qos = QoSProfile(depth=7, reliability=ReliabilityPolicy.RELIABLE)  # turtlesim's topic_qos()
        self.publisher = self.create_publisher(Twist, "output/cmd_vel", qos)
        self.create_subscription(Pose, "input/pose", self.on_pose, qos)

    def on_pose(self, pose):
        twist = Twist()
        twist.angular.z = pose.angular_velocity
        twist.linear.x = pose.linear_velocity
        self.publisher.publish(twist)


def main():
    rclpy.init()
    try:
        rclpy.spin(Mimic())
    except (KeyboardInterrupt, ExternalShutdownException):
        pass


if __name__ == "__main__":
    main()
