#!/usr/bin/env python3
"""spawn_draw in rclpy with a copy-pasted pen call: turtle2's green goes to /turtle1/set_pen, so turtle1 draws green
and turtle2 keeps turtlesim's default pen; the squares are right."""
import math

import rclpy
from geometry_msgs.msg import Twist
from turtlesim.srv import SetPen, Spawn


def call(node, srv_type, name, request):
    client = node.create_client(srv_type, name)
    client.wait_for_service()
    future = client.call_async(request)
    rclpy.spin_until_future_complete(node, future)
    return future.result()


def main():
    rclpy.init()
    node = rclpy.create_node('spawn_draw')
    call(node, Spawn, '/spawn', Spawn.Request(x=2.0, y=2.0, theta=0.0, name='turtle2'))
    call(node, SetPen, '/turtle1/set_pen', SetPen.Request(r=255, g=0, b=0, width=3, off=0))
    call(node, SetPen, '/turtle1/set_pen', SetPen.Request(r=0, g=255, b=0, width=3, off=0))
    publishers = [node.create_publisher(Twist, f'{name}/cmd_vel', 10) for name in ('turtle1', 'turtle2')]
    while any(p.get_subscription_count() == 0 for p in publishers):
        rclpy.spin_once(node, timeout_sec=0.01)
    for linear, angular in [(1.0, 0.0), (0.0, math.pi / 4)] * 4:
        start = node.get_clock().now()
        while (node.get_clock().now() - start).nanoseconds < 2_000_000_000:
            cmd = Twist()
            cmd.linear.x, cmd.angular.z = linear, angular
            for publisher in publishers:
                publisher.publish(cmd)
            rclpy.spin_once(node, timeout_sec=0.01)
        for publisher in publishers:
            publisher.publish(Twist())
    rclpy.shutdown()


if __name__ == '__main__':
    main()
