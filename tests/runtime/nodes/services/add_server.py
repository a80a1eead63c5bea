"""An rclpy AddTwoInts server (the ROS 2 service tutorial's), logging each request with its sim time."""
import rclpy
from example_interfaces.srv import AddTwoInts
from rclpy.node import Node


class Server(Node):
    def __init__(self):
        super().__init__("add_two_ints_server")
        self.create_service(AddTwoInts, "add_two_ints", self.add)

    def add(self, request, response):
        response.sum = request.a + request.b
        print(f"serve {request.a}+{request.b} at {self.get_clock().now().nanoseconds}", flush=True)
        return response


rclpy.init()
rclpy.spin(Server())
