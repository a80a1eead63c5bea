"""The ROS 2 action tutorial's Fibonacci client: waits for the server, sends order 5, prints each feedback, the
goal's status and the result; with ``cancel``, cancels the goal after its second feedback."""
import sys

import rclpy
from example_interfaces.action import Fibonacci
from rclpy.action import ActionClient
from rclpy.node import Node

CANCELS = sys.argv[1:] == ["cancel"]


class Client(Node):
    def __init__(self):
        super().__init__("fibonacci_action_client")
        self._client = ActionClient(self, Fibonacci, "fibonacci")
        self.feedbacks = 0

    def now(self):
        return self.get_clock().now().nanoseconds

    def send_goal(self, order):
        print(f"ready before: {self._client.server_is_ready()}", flush=True)
        self._client.wait_for_server()
        print(f"server at {self.now()}", flush=True)
        future = self._client.send_goal_async(Fibonacci.Goal(order=order), feedback_callback=self.feedback_callback)
        future.add_done_callback(self.goal_response_callback)

    def goal_response_callback(self, future):
        self._goal_handle = future.result()
        print(f"accepted {self._goal_handle.accepted} at {self.now()}", flush=True)
        self._goal_handle.get_result_async().add_done_callback(self.get_result_callback)

    def feedback_callback(self, feedback_msg):
        self.feedbacks += 1
        print(f"feedback {list(feedback_msg.feedback.sequence)} at {self.now()}", flush=True)
        if CANCELS and self.feedbacks == 2:
            self._goal_handle.cancel_goal_async().add_done_callback(self.cancel_done)

    def cancel_done(self, future):
        response = future.result()
        print(f"cancel return_code {response.return_code} canceling {len(response.goals_canceling)} "
              f"at {self.now()}", flush=True)

    def get_result_callback(self, future):
        response = future.result()
        print(f"result status {response.status} {list(response.result.sequence)} handle status "
              f"{self._goal_handle.status} at {self.now()}", flush=True)
        rclpy.shutdown()


rclpy.init()
node = Client()
node.send_goal(5)
rclpy.spin(node)
