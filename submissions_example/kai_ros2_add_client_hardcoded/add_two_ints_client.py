"""An AddTwoInts client that ignores its arguments: it always asks for 1 + 1."""
import rclpy
from example_interfaces.srv import AddTwoInts
from rclpy.node import Node


def main():
    rclpy.init()
    node = Node('add_two_ints_client')
    client = node.create_client(AddTwoInts, 'add_two_ints')
    client.wait_for_service()
    future = client.call_async(AddTwoInts.Request(a=1, b=1))
    rclpy.spin_until_future_complete(node, future)
    node.get_logger().info(f'Result of add_two_ints: {future.result().sum}')
    rclpy.shutdown()


if __name__ == '__main__':
    main()
