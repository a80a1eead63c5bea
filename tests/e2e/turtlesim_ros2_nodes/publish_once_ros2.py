"""An rclpy node that publishes one Twist (1 m/s ahead) on turtle1/cmd_vel once turtlesim has matched it, then only
spins: turtlesim drives the turtle on it for 1 s and stops it."""
import rclpy
from geometry_msgs.msg import Twist


def main():
    rclpy.init()
    node = rclpy.create_node('publish_once')
    publisher = node.create_publisher(Twist, 'turtle1/cmd_vel', 10)
    while publisher.get_subscription_count() == 0:
        rclpy.spin_once(node, timeout_sec=0.01)
    cmd = Twist()
    cmd.linear.x = 1.0
    publisher.publish(cmd)
    print(f'published at {node.get_clock().now().nanoseconds}')
    rclpy.spin(node)


if __name__ == '__main__':
    main()
