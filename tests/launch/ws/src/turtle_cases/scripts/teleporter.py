#!/usr/bin/env python3
"""Teleports turtle1 to (2, 3) through turtle1/teleport_absolute, resolved in this node's namespace."""
import rospy
from turtlesim.srv import TeleportAbsolute

rospy.init_node("teleporter")
rospy.wait_for_service("turtle1/teleport_absolute")
rospy.ServiceProxy("turtle1/teleport_absolute", TeleportAbsolute)(2.0, 3.0, 0.0)
rospy.spin()
