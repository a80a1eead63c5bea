#!/usr/bin/env python3
"""The number game server, where a cheat is answered before the guess is counted."""

from random import random

import rclpy
from rclpy.node import Node

from part4_services.srv import MyNumberGame


class NumberGameServer(Node):

    def __init__(self):
        super().__init__("number_game_service")
        self.srv = self.create_service(
            srv_type=MyNumberGame,
            srv_name="guess_the_number",
            callback=self.srv_callback,
        )
        self.get_logger().info("The '/guess_the_number' service is active.")
        self.new_game()

    def new_game(self):
        self.secret = int(random() * 100)  # 0 to 99
        self.num_guesses = 0
        self.get_logger().info("A secret number has been set... Game on!")

    def srv_callback(self, request, response):
        response.correct = False
        if request.cheat:
            response.hint = f"The answer is {self.secret}!"
            response.num_guesses = self.num_guesses
            return response
        self.num_guesses += 1
        response.num_guesses = self.num_guesses
        if request.guess < 0 or request.guess > 100:
            response.hint = "Error"
            self.get_logger().warning(f"Invalid guess {request.guess}: guess between 0 and 100.")
        elif request.guess < self.secret:
            response.hint = "Higher"
        elif request.guess > self.secret:
            response.hint = "Lower"
        else:
            response.hint = "Winner"
            response.correct = True
            self.new_game()
        return response


def main(args=None):
    rclpy.init(args=args)
    node = NumberGameServer()
    try:
        rclpy.spin(node)
    except KeyboardInterrupt:
        pass
    node.destroy_node()
    rclpy.try_shutdown()


if __name__ == "__main__":
    main()
