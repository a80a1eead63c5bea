"""An rclpy client putting turtlesim's rotate_absolute through its cases: a goal replaced by a newer one, the newer
one to its end, and a goal cancelled on the way; it prints each goal's status, delta and the feedback it got."""
import rclpy
from rclpy.action import ActionClient
from turtlesim.action import RotateAbsolute


def wait(node, seconds):
    end = node.get_clock().now().nanoseconds + int(seconds * 1e9)
    while node.get_clock().now().nanoseconds < end:
        rclpy.spin_once(node, timeout_sec=0.01)


def main():
    rclpy.init()
    node = rclpy.create_node('rotate_goals')
    client = ActionClient(node, RotateAbsolute, 'turtle1/rotate_absolute')
    client.wait_for_server()
    remaining = {}

    def send(name, theta):
        remaining[name] = []
        future = client.send_goal_async(
            RotateAbsolute.Goal(theta=theta), feedback_callback=lambda m: remaining[name].append(m.feedback.remaining))
        rclpy.spin_until_future_complete(node, future)
        return future.result()

    def report(name, handle):
        future = handle.get_result_async()
        rclpy.spin_until_future_complete(node, future)
        values = remaining[name]
        print(f'{name}: status {future.result().status} delta {future.result().result.delta:.3f} '
              f'feedback {len(values)} first {values[0]:.3f} last {values[-1]:.3f}')

    first = send('replaced', 1.0)
    wait(node, 0.3)
    second = send('newer', -1.0)
    report('replaced', first)
    report('newer', second)
    third = send('cancelled', 2.0)
    wait(node, 0.2)
    rclpy.spin_until_future_complete(node, third.cancel_goal_async())
    report('cancelled', third)
    rclpy.shutdown()


if __name__ == '__main__':
    main()
