"""An rclpy node that spawns turtle2 at (2, 2) and drives turtle1 at 1 m/s, 0.5 rad/s from a timer: the leader a
mimic node copies."""
import rclpy
from geometry_msgs.msg import Twist
from turtlesim.srv import Spawn


def main():
    rclpy.init()
    node = rclpy.create_node('leader')
    client = node.create_client(Spawn, '/spawn')
    client.wait_for_service()
    future = client.call_async(Spawn.Request(x=2.0, y=2.0, theta=0.0, name='turtle2'))
    rclpy.spin_until_future_complete(node, future)
    publisher = node.create_publisher(Twist, 'turtle1/cmd_vel', 10)
    cmd = Twist()
    cmd.linear.x, cmd.angular.z = 1.0, 0.5
    node.create_timer(0.1, lambda: publisher.publish(cmd))
    rclpy.spin(node)


if __name__ == '__main__':
    main()
