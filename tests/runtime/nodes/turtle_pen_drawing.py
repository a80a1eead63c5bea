#!/usr/bin/env python3
"""Draws with everything that changes turtlesim's picture: the default pen, /reset, a red 5 px pen, /clear, the pen
lifted for a teleport, a green 2 px pen drawing a relative teleport, a second turtle with a 1 px (width 0) blue pen
crossing turtle1's lines, a failed set_pen, and /kill of the second turtle (its lines stay)."""
import rospy
from geometry_msgs.msg import Twist
from std_srvs.srv import Empty
from turtlesim.srv import Kill, SetPen, Spawn, TeleportAbsolute, TeleportRelative


def drive(publisher, linear, angular, seconds):
    """Publish one command every 0.1 s for ``seconds``."""
    command = Twist()
    command.linear.x, command.angular.z = linear, angular
    for _ in range(int(round(seconds * 10))):
        publisher.publish(command)
        rospy.sleep(0.1)


def service(name, srv):
    rospy.wait_for_service(name, timeout=2.0)
    return rospy.ServiceProxy(name, srv)


rospy.init_node("turtle_pen_drawing")
turtle1 = rospy.Publisher("/turtle1/cmd_vel", Twist, queue_size=1)
while turtle1.get_num_connections() == 0:
    rospy.sleep(0.05)
drive(turtle1, 1.0, 0.7, 1.0)  # default pen, then wiped by the reset
service("/reset", Empty)()
drive(turtle1, 1.3, 0.0, 0.5)
service("/turtle1/set_pen", SetPen)(255, 0, 0, 5, 0)
drive(turtle1, 1.0, -1.1, 1.5)
service("/clear", Empty)()
drive(turtle1, 0.8, 0.4, 1.0)
pen = service("/turtle1/set_pen", SetPen)
pen(0, 0, 0, 0, 1)  # lifted: the teleport draws nothing
service("/turtle1/teleport_absolute", TeleportAbsolute)(2.0, 2.5, 0.3)
rospy.sleep(0.1)
pen(30, 200, 60, 2, 0)
service("/turtle1/teleport_relative", TeleportRelative)(1.7, 0.9)  # drawn in green
rospy.sleep(0.1)
name = service("/spawn", Spawn)(8.0, 3.0, 2.0, "").name
service("/%s/set_pen" % name, SetPen)(20, 20, 240, 0, 0)  # width 0: a 1 px pen
turtle2 = rospy.Publisher("/%s/cmd_vel" % name, Twist, queue_size=1)
while turtle2.get_num_connections() == 0:
    rospy.sleep(0.05)
command1, command2 = Twist(), Twist()
command1.linear.x, command1.angular.z = 1.2, 0.25
command2.linear.x, command2.angular.z = 1.5, 0.6
for _ in range(25):
    turtle1.publish(command1)
    turtle2.publish(command2)
    rospy.sleep(0.1)
service("/kill", Kill)(name)
try:
    rospy.ServiceProxy("/%s/set_pen" % name, SetPen)(255, 255, 0, 9, 0)
except rospy.ServiceException as exc:
    print("gone: %s" % exc)
drive(turtle1, 0.0, 0.0, 0.2)
print("done at %.3f" % rospy.get_time())
