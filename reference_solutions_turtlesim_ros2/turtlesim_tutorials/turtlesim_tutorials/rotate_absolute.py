#!/usr/bin/env python3
"""turtlesim (ROS 2): turn turtle1 to the heading typed in (radians) through its rotate_absolute action, as
`ros2 action send_goal /turtle1/rotate_absolute turtlesim/action/RotateAbsolute "{theta: 1.57}"` does in the CLI
tutorials, logging the feedback's remaining angle and the result's delta."""
import rclpy
from rclpy.action import ActionClient
from rclpy.node import Node
from turtlesim.action import RotateAbsolute


class RotateAbsoluteClient(Node):

    def __init__(self):
        super().__init__('rotate_absolute_client')
        self.client = ActionClient(self, RotateAbsolute, 'turtle1/rotate_absolute')
        self.done = False

    def send_goal(self, theta):
        goal = RotateAbsolute.Goal()
        goal.theta = theta
        self.client.wait_for_server()
        future = self.client.send_goal_async(goal, feedback_callback=self.on_feedback)
        future.add_done_callback(self.on_goal_response)

    def on_feedback(self, feedback_msg):
        self.get_logger().info(f'remaining: {feedback_msg.feedback.remaining:.3f}', throttle_duration_sec=0.5)

    def on_goal_response(self, future):
        goal_handle = future.result()
        if not goal_handle.accepted:
            self.get_logger().info('goal rejected')
            self.done = True
            return
        goal_handle.get_result_async().add_done_callback(self.on_result)

    def on_result(self, future):
        self.get_logger().info(f'delta: {future.result().result.delta}')
        self.done = True


def main(args=None):
    rclpy.init(args=args)
    theta = float(input('theta (rad): '))
    node = RotateAbsoluteClient()
    node.send_goal(theta)
    while rclpy.ok() and not node.done:
        rclpy.spin_once(node)
    node.destroy_node()
    rclpy.shutdown()


if __name__ == '__main__':
    main()
