"""The Fibonacci action client of the ROS 2 action tutorial: waits for /fibonacci, sends order 10, logs each
feedback's sequence and the result's, then shuts down."""
import rclpy
from example_interfaces.action import Fibonacci
from rclpy.action import ActionClient
from rclpy.node import Node


class FibonacciActionClient(Node):

    def __init__(self):
        super().__init__('fibonacci_action_client')
        self._client = ActionClient(self, Fibonacci, 'fibonacci')

    def send_goal(self, order):
        self._client.wait_for_server()
        goal = Fibonacci.Goal(order=order)
        future = self._client.send_goal_async(goal, feedback_callback=self.on_feedback)
        future.add_done_callback(self.on_goal_response)

    def on_goal_response(self, future):
        goal_handle = future.result()
        if not goal_handle.accepted:
            self.get_logger().info('Goal rejected')
            return
        self.get_logger().info('Goal accepted')
        goal_handle.get_result_async().add_done_callback(self.on_result)

    def on_feedback(self, feedback_msg):
        self.get_logger().info(f'Received feedback: {list(feedback_msg.feedback.sequence)}')

    def on_result(self, future):
        self.get_logger().info(f'Result: {list(future.result().result.sequence)}')
        rclpy.shutdown()


def main():
    rclpy.init()
    node = FibonacciActionClient()
    node.send_goal(10)
    rclpy.spin(node)


if __name__ == '__main__':
    main()
