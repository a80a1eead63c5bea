"""An rclpy node that drives turtle1 east at 3 m/s from a timer until Ctrl+C: it reaches the wall in about 2 s."""
import rclpy
from geometry_msgs.msg import Twist


def main():
    rclpy.init()
    node = rclpy.create_node('into_the_wall')
    publisher = node.create_publisher(Twist, 'turtle1/cmd_vel', 10)
    cmd = Twist()
    cmd.linear.x = 3.0
    node.create_timer(0.1, lambda: publisher.publish(cmd))
    try:
        rclpy.spin(node)
    except KeyboardInterrupt:
        pass


if __name__ == '__main__':
    main()
