"""An rclpy node that only listens to turtle1/pose and logs the last heading once a second: the student's side of a
run in which the grader's teleop drives the turtle."""
import rclpy
from rclpy.executors import ExternalShutdownException
from turtlesim.msg import Pose


class PoseListener:

    def __init__(self):
        self.node = rclpy.create_node('pose_listener')
        self.theta = None
        self.node.create_subscription(Pose, 'turtle1/pose', self.on_pose, 10)
        self.node.create_timer(1.0, self.on_timer)

    def on_pose(self, pose):
        self.theta = pose.theta

    def on_timer(self):
        if self.theta is not None:
            self.node.get_logger().info(f'theta {self.theta:.3f}')


def main():
    rclpy.init()
    listener = PoseListener()
    try:
        rclpy.spin(listener.node)
    except (KeyboardInterrupt, ExternalShutdownException):
        pass


if __name__ == '__main__':
    main()
