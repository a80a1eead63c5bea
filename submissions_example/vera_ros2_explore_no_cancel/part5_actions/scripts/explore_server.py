#!/usr/bin/env python3
"""An ExploreForward server without a cancel callback (rclpy's default refuses every cancel) and without a check of
is_cancel_requested: a cancelled goal drives on."""
import math

import rclpy
from geometry_msgs.msg import TwistStamped
from nav_msgs.msg import Odometry
from rclpy.action import ActionServer, GoalResponse
from rclpy.callback_groups import ReentrantCallbackGroup
from rclpy.executors import MultiThreadedExecutor
from rclpy.node import Node
from rclpy.qos import qos_profile_sensor_data
from rclpy.signals import SignalHandlerOptions
from sensor_msgs.msg import LaserScan

from part5_actions.action import ExploreForward

MAX_SPEED = 0.26      # m/s, the TurtleBot3's limit
LIDAR_MIN = 0.12      # m, the nearest the LiDAR measures
HALF_WIDTH = math.radians(15)  # the beams either side of straight ahead that count as "ahead"


class ExploreServer(Node):

    def __init__(self):
        super().__init__("explore_forward_server_node")
        group = ReentrantCallbackGroup()
        self.posx = self.posy = None
        self.ahead = None
        self.vel_pub = self.create_publisher(TwistStamped, "cmd_vel", 10)
        self.create_subscription(Odometry, "odom", self.odom_callback, 10, callback_group=group)
        self.create_subscription(LaserScan, "scan", self.scan_callback, qos_profile_sensor_data,
                                 callback_group=group)
        self.loop_rate = self.create_rate(frequency=10, clock=self.get_clock())
        ActionServer(self, ExploreForward, "explore_forward", self.execute_callback,
                     goal_callback=self.goal_callback, callback_group=group)

    def odom_callback(self, odom):
        self.posx = odom.pose.pose.position.x
        self.posy = odom.pose.pose.position.y

    def scan_callback(self, scan):
        valid = [r for i, r in enumerate(scan.ranges)
                 if abs(math.remainder(scan.angle_min + i * scan.angle_increment, 2 * math.pi)) <= HALF_WIDTH
                 and scan.range_min <= r <= scan.range_max]
        self.ahead = min(valid) if valid else math.inf

    def goal_callback(self, goal):
        if not 0.0 < goal.fwd_velocity <= MAX_SPEED or goal.stopping_distance <= LIDAR_MIN:
            self.get_logger().warn(f"Rejecting goal: speed {goal.fwd_velocity:.2f} m/s, stopping distance "
                                   f"{goal.stopping_distance:.2f} m")
            return GoalResponse.REJECT
        return GoalResponse.ACCEPT

    def drive(self, speed):
        cmd = TwistStamped()
        cmd.header.stamp = self.get_clock().now().to_msg()
        cmd.twist.linear.x = speed
        self.vel_pub.publish(cmd)

    def execute_callback(self, goal_handle):
        goal = goal_handle.request
        while self.posx is None or self.ahead is None:
            self.loop_rate.sleep()
        x0, y0 = self.posx, self.posy
        result = ExploreForward.Result()
        feedback = ExploreForward.Feedback()
        self.get_logger().info(f"Exploring forwards at {goal.fwd_velocity:.2f} m/s")
        while rclpy.ok():
            travelled = math.hypot(self.posx - x0, self.posy - y0)
            result.total_distance_travelled = travelled
            result.closest_obstacle = self.ahead
            remaining = self.ahead - goal.stopping_distance
            if remaining <= 0.0:
                break
            # slow down over the last stretch: /scan comes at 5 Hz
            self.drive(min(goal.fwd_velocity, max(0.03, 0.5 * remaining)))
            feedback.current_distance_travelled = travelled
            goal_handle.publish_feedback(feedback)
            self.loop_rate.sleep()
        self.drive(0.0)
        goal_handle.succeed()
        self.get_logger().info(f"Stopped {self.ahead:.2f} m from an obstacle after "
                               f"{result.total_distance_travelled:.2f} m")
        return result


def main(args=None):
    # Without the default signal handlers the context stays valid after Ctrl+C, so the zero still goes out.
    rclpy.init(args=args, signal_handler_options=SignalHandlerOptions.NO)
    node = ExploreServer()
    executor = MultiThreadedExecutor()
    executor.add_node(node)
    try:
        executor.spin()
    except KeyboardInterrupt:
        pass
    finally:
        node.drive(0.0)
        node.destroy_node()
        rclpy.shutdown()


if __name__ == "__main__":
    main()
