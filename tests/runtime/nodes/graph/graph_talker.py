"""Graph test node: publishes /chatter, serves /graph_switch and the action /team/count, subscribes to /odom, then
spins."""
import rclpy
from example_interfaces.action import Fibonacci
from rclpy.action import ActionServer
from rclpy.node import Node
from nav_msgs.msg import Odometry
from std_msgs.msg import String
from std_srvs.srv import SetBool

rclpy.init()
node = Node("graph_talker", namespace="/team")
publisher = node.create_publisher(String, "/chatter", 10)
node.create_service(SetBool, "/graph_switch", lambda request, response: response)
node.create_subscription(Odometry, "/odom", lambda msg: None, 10)
ActionServer(node, Fibonacci, "count", lambda goal_handle: Fibonacci.Result())
node.create_timer(0.5, lambda: publisher.publish(String(data="hi")))
try:
    rclpy.spin(node)
except KeyboardInterrupt:
    pass
