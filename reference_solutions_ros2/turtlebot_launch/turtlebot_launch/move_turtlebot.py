"""Reference for move_distance_launch in ROS 2: drive along x at `speed` until odometry x >= `distance`, then stop.

The parameters' defaults are the seed's command line (0.2 m/s, 3 m), so `ros2 run` alone drives it as
`move_turtlebot.py 0.2 0 3` did; the launch file sets `distance` from its argument.
"""

import rclpy
from geometry_msgs.msg import TwistStamped
from nav_msgs.msg import Odometry
from rclpy.node import Node
from rclpy.signals import SignalHandlerOptions


class DistanceMover(Node):

    def __init__(self):
        super().__init__('move_turtlebot')
        self.speed = self.declare_parameter('speed', 0.2).value
        self.distance = self.declare_parameter('distance', 3.0).value
        self.arrived = False
        self.cmd_pub = self.create_publisher(TwistStamped, 'cmd_vel', 10)
        self.create_subscription(Odometry, 'odom', self.on_odom, 10)
        self.get_logger().info(f'Driving at {self.speed} m/s until x = {self.distance} m')

    def command(self, speed):
        msg = TwistStamped()
        msg.header.stamp = self.get_clock().now().to_msg()
        msg.twist.linear.x = speed
        self.cmd_pub.publish(msg)

    def on_odom(self, msg):
        x = msg.pose.pose.position.x
        if not self.arrived and x >= self.distance:
            self.arrived = True
            self.get_logger().info(f'Reached x = {x:.3f} m, stopping')
        self.command(0.0 if self.arrived else self.speed)


def main(args=None):
    rclpy.init(args=args, signal_handler_options=SignalHandlerOptions.NO)
    node = DistanceMover()
    try:
        rclpy.spin(node)
    except KeyboardInterrupt:
        pass
    finally:
        node.command(0.0)
        node.destroy_node()
        rclpy.try_shutdown()


if __name__ == '__main__':
    main()
