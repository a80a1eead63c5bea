"""The AddTwoInts client of the ROS 2 service tutorial: `ros2 run py_srvcli add_two_ints_client 2 3` waits for
/add_two_ints, sends a and b from its arguments and logs the sum that comes back."""
import sys

import rclpy
from example_interfaces.srv import AddTwoInts
from rclpy.node import Node


class AddTwoIntsClient(Node):

    def __init__(self):
        super().__init__('add_two_ints_client')
        self.client = self.create_client(AddTwoInts, 'add_two_ints')
        while not self.client.wait_for_service(timeout_sec=1.0):
            self.get_logger().info('service not available, waiting again...')

    def send_request(self, a, b):
        return self.client.call_async(AddTwoInts.Request(a=a, b=b))


def main():
    rclpy.init()
    node = AddTwoIntsClient()
    a, b = int(sys.argv[1]), int(sys.argv[2])
    future = node.send_request(a, b)
    rclpy.spin_until_future_complete(node, future)
    node.get_logger().info(f'Result of add_two_ints: for {a} + {b} = {future.result().sum}')
    node.destroy_node()
    rclpy.shutdown()


if __name__ == '__main__':
    main()
