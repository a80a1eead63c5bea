"""A Fibonacci action client that sends its goal without a feedback callback: it logs the result only."""
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
        self._client.send_goal_async(Fibonacci.Goal(order=order)).add_done_callback(self.on_goal_response)

    def on_goal_response(self, future):
        goal_handle = future.result()
        self.get_logger().info('Goal accepted' if goal_handle.accepted else 'Goal rejected')
        if goal_handle.accepted:
            goal_handle.get_result_async().add_done_callback(self.on_result)

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
