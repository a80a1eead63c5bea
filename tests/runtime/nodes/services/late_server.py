"""An rclpy AddTwoInts server that offers its service only after a second of work (a service not up yet)."""
import time

import rclpy
from example_interfaces.srv import AddTwoInts
from rclpy.node import Node

rclpy.init()
node = Node("late_server")
time.sleep(1.0)
node.create_service(AddTwoInts, "add_two_ints", lambda request, response: AddTwoInts.Response(sum=request.a + request.b))
print(f"serving at {time.monotonic():.3f}", flush=True)
rclpy.spin(node)
