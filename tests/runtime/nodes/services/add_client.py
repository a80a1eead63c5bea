"""An rclpy client: waits for the service, calls it twice with call_async, prints the sums and their sim times."""
import sys

import rclpy
from example_interfaces.srv import AddTwoInts
from rclpy.node import Node

rclpy.init()
node = Node("add_two_ints_client")
client = node.create_client(AddTwoInts, "add_two_ints")
print(f"ready before: {client.service_is_ready()}", flush=True)
while not client.wait_for_service(timeout_sec=1.0):
    print("service not available, waiting again...", flush=True)
print(f"ready at {node.get_clock().now().nanoseconds}", flush=True)
for a, b in ((2, 3), (40, 2)):
    future = client.call_async(AddTwoInts.Request(a=a, b=b))
    sent = node.get_clock().now().nanoseconds
    rclpy.spin_until_future_complete(node, future)
    print(f"sum {future.result().sum} sent {sent} got {node.get_clock().now().nanoseconds}", flush=True)
sys.exit(0)
