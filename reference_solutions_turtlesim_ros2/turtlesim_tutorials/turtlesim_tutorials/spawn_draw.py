#!/usr/bin/env python3
"""turtlesim (ROS 2): spawn turtle2 at (2, 2), give turtle1 a red pen and turtle2 a green one (3 px), then drive both
round a 2 m square at once: forward 2 s at 1 m/s, turn 90 degrees in 2 s, four times, timed by a timer on the node's
clock."""
import math

import rclpy
from geometry_msgs.msg import Twist
from rclpy.node import Node
from turtlesim.srv import SetPen, Spawn

PENS = {'turtle1': (255, 0, 0), 'turtle2': (0, 255, 0)}
STEPS = [(1.0, 0.0, 2.0), (0.0, math.pi / 4, 2.0)] * 4  # (linear, angular, seconds)


class SpawnDraw(Node):

    def __init__(self):
        super().__init__('spawn_draw')
        self.publishers_ = {name: self.create_publisher(Twist, f'{name}/cmd_vel', 10) for name in PENS}
        self.step = 0
        self.step_start = None
        self.done = False
        self.timer = None

    def call(self, srv_type, name, request):
        client = self.create_client(srv_type, name)
        client.wait_for_service()
        future = client.call_async(request)
        rclpy.spin_until_future_complete(self, future)
        return future.result()

    def set_up(self):
        spawned = self.call(Spawn, '/spawn', Spawn.Request(x=2.0, y=2.0, theta=0.0, name='turtle2'))
        self.get_logger().info(f'spawned {spawned.name}')
        for name, (r, g, b) in PENS.items():
            self.call(SetPen, f'/{name}/set_pen', SetPen.Request(r=r, g=g, b=b, width=3, off=0))
        self.timer = self.create_timer(0.01, self.on_timer)

    def on_timer(self):
        if self.step_start is None:
            if any(p.get_subscription_count() == 0 for p in self.publishers_.values()):
                return  # a turtle has not matched yet
            self.step_start = self.get_clock().now()
        linear, angular, duration = STEPS[self.step]
        elapsed = (self.get_clock().now() - self.step_start).nanoseconds * 1e-9
        cmd = Twist()
        if elapsed < duration:
            cmd.linear.x = linear
            cmd.angular.z = angular
        for publisher in self.publishers_.values():
            publisher.publish(cmd)
        if elapsed >= duration:
            self.step += 1
            self.step_start = self.get_clock().now()
            if self.step == len(STEPS):
                self.timer.cancel()
                self.done = True


def main(args=None):
    rclpy.init(args=args)
    node = SpawnDraw()
    node.set_up()
    while rclpy.ok() and not node.done:
        rclpy.spin_once(node)
    node.destroy_node()
    rclpy.shutdown()


if __name__ == '__main__':
    main()
