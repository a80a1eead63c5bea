#!/usr/bin/env python3
"""move in rclpy with spin_once in a busy loop: the Twist is published as fast as the loop goes, the distance timed
on the node's clock, then a zero Twist."""
import rclpy
from geometry_msgs.msg import Twist


def main():
    rclpy.init()
    node = rclpy.create_node('move')
    publisher = node.create_publisher(Twist, 'turtle1/cmd_vel', 10)
    speed = float(input('Input your speed: '))
    distance = float(input('Type your distance: '))
    forward = input('Forward? (1/0): ').strip() == '1'
    cmd = Twist()
    cmd.linear.x = abs(speed) if forward else -abs(speed)
    start = node.get_clock().now()
    travelled = 0.0
    while rclpy.ok() and travelled < distance:
        publisher.publish(cmd)
        rclpy.spin_once(node, timeout_sec=0.0)
        travelled = abs(speed) * (node.get_clock().now() - start).nanoseconds * 1e-9
    publisher.publish(Twist())
    rclpy.shutdown()


if __name__ == '__main__':
    main()
