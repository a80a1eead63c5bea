#!/usr/bin/env python3
"""rotate_absolute in rclpy that sends the goal, then publishes a zero Twist on turtle1/cmd_vel "to hold the turtle
still" while it turns: turtlesim aborts a rotation goal on any velocity command."""
import rclpy
from geometry_msgs.msg import Twist
from rclpy.action import ActionClient
from turtlesim.action import RotateAbsolute


def main():
    rclpy.init()
    theta = float(input('theta (rad): '))
    node = rclpy.create_node('rotate_absolute_client')
    client = ActionClient(node, RotateAbsolute, 'turtle1/rotate_absolute')
    publisher = node.create_publisher(Twist, 'turtle1/cmd_vel', 10)
    client.wait_for_server()
    goal_future = client.send_goal_async(RotateAbsolute.Goal(theta=theta))
    rclpy.spin_until_future_complete(node, goal_future)
    publisher.publish(Twist())
    result_future = goal_future.result().get_result_async()
    rclpy.spin_until_future_complete(node, result_future)
    node.get_logger().info(f'delta: {result_future.result().result.delta}')
    rclpy.shutdown()


if __name__ == '__main__':
    main()
