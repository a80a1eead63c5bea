#!/usr/bin/env python3
"""The number game client, which logs the future at once instead of waiting for the response."""

import rclpy
from rclpy.node import Node

from part4_services.srv import MyNumberGame


class NumberGameClient(Node):

    def __init__(self):
        super().__init__("number_game_client")
        self.client = self.create_client(srv_type=MyNumberGame, srv_name="guess_the_number")
        self.declare_parameters(namespace="", parameters=[("guess", 0), ("cheat", False)])
        while not self.client.wait_for_service(timeout_sec=1.0):
            self.get_logger().info("Waiting for the /guess_the_number service...")

    def send_request(self):
        guess = self.get_parameter("guess").get_parameter_value().integer_value
        cheat = self.get_parameter("cheat").get_parameter_value().bool_value
        self.get_logger().info(f"Sending the request:\n - guess: {guess}\n - cheat: {cheat}\n   Awaiting response...")
        request = MyNumberGame.Request()
        request.guess = guess
        request.cheat = cheat
        return self.client.call_async(request)


def main(args=None):
    rclpy.init(args=args)
    client = NumberGameClient()
    future = client.send_request()
    client.get_logger().info(f"The server responded with: {future}")
    client.destroy_node()
    rclpy.shutdown()


if __name__ == "__main__":
    main()
