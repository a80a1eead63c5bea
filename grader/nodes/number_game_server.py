#!/usr/bin/env python3
"""The number game's server for grading a student's client (COM2009 Part 4, Exercise 5): ``/guess_the_number`` with
the student's own MyNumberGame type, answering as the course's server does (Higher/Lower, Winner, the secret in a
cheat's hint, every call counted), from a secret and a count of earlier guesses fixed by the rubric, so that what it
answers is known in advance and the student's node must report it.

Usage: ``number_game_server.py <package>/srv/<Name> <secret> <earlier guesses>``. Silent: what the run's log and
/rosout hold is the student's node's.

Shipped with the grader and run confined like a student's node; never student code.
"""
import importlib
import sys

import rclpy
from rclpy.executors import ExternalShutdownException
from rclpy.node import Node


class NumberGameServer(Node):

    def __init__(self, srv_type, secret, played):
        super().__init__("number_game_service")
        self.secret = secret
        self.num_guesses = played
        self.create_service(srv_type, "guess_the_number", self.answer)

    def answer(self, request, response):
        self.num_guesses += 1
        response.num_guesses = self.num_guesses
        response.correct = request.guess == self.secret and not request.cheat
        if request.cheat:
            response.hint = f"The answer is {self.secret}!"
        elif request.guess < 0 or request.guess > 100:
            response.hint = "Error"
        elif request.guess == self.secret:
            response.hint = "Winner"
        else:
            response.hint = "Higher" if request.guess < self.secret else "Lower"
        return response


def main():
    type_name, secret, played = sys.argv[1:4]
    package, _, name = type_name.split("/")
    srv_type = getattr(importlib.import_module(f"{package}.srv"), name)
    rclpy.init()
    try:
        rclpy.spin(NumberGameServer(srv_type, int(secret), int(played)))
    except (KeyboardInterrupt, ExternalShutdownException):
        pass  # Ctrl+C or the end of the run: quietly, as the run's text is the student's


if __name__ == "__main__":
    main()
