#!/usr/bin/env python3
"""The number game client, where only the guess comes from a parameter: cheat is never declared nor read."""

import rclpy
from rclpy.node import Node

from part4_services.srv import MyNumberGame


class NumberGameClient(Node):

    def __init__(self):
        super().__init__("number_game_client")
        self.client = self.create_client(srv_type=MyNumberGame, srv_name="guess_the_number")
        self.declare_parameter("guess", 0)
        while not self.client.wait_for_service(timeout_sec=1.0):
            self.get_logger().info("Waiting for the /guess_the_number service...")

    def send_request(self):
        guess = self.get_parameter("guess").get_parameter_value().integer_value
        self.get_logger().info(f"Sending the request:\n - guess: {guess}\n   Awaiting response...")
        request = MyNumberGame.Request()
        request.guess = guess
        return self.client.call_async(request)


def main(args=None):
    rclpy.init(args=args)
    client = NumberGameClient()
    future = client.send_request()
    rclpy.spin_until_future_complete(client, future)
    response = future.result()
    verdict = "Correct guess!" if response.correct else "Incorrect guess :("
    client.get_logger().info(
        f"The server responded with:\n - {verdict}\n - Number of attempts so far: {response.num_guesses}\n"
        f" - A hint: '{response.hint}'.")
    client.destroy_node()
    rclpy.shutdown()


if __name__ == "__main__":
    main()
