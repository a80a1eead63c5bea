"""An rclpy node calling turtlesim's services as the ROS 2 CLI tutorials do: spawn (a free name, then a taken one),
clear, set_pen, teleport_absolute, kill; it prints the replies."""
import rclpy
from std_srvs.srv import Empty
from turtlesim.srv import Kill, SetPen, Spawn, TeleportAbsolute


def call(node, srv_type, name, request):
    client = node.create_client(srv_type, name)
    client.wait_for_service()
    future = client.call_async(request)
    rclpy.spin_until_future_complete(node, future)
    return future.result()


def main():
    rclpy.init()
    node = rclpy.create_node('turtle_services')
    print(f"spawn free: {call(node, Spawn, '/spawn', Spawn.Request(x=2.0, y=3.0, theta=0.0)).name!r}")
    print(f"spawn taken: {call(node, Spawn, '/spawn', Spawn.Request(x=1.0, y=1.0, name='turtle2')).name!r}")
    call(node, Empty, '/clear', Empty.Request())
    call(node, SetPen, '/turtle2/set_pen', SetPen.Request(r=255, g=0, b=0, width=5, off=0))
    call(node, TeleportAbsolute, '/turtle2/teleport_absolute', TeleportAbsolute.Request(x=6.0, y=3.0, theta=0.0))
    print(f"kill nobody: {call(node, Kill, '/kill', Kill.Request(name='nobody'))!r}")
    print('done')


if __name__ == '__main__':
    main()
