#!/usr/bin/env python3
"""Changes turtlesim's background as the course does (set background_r/g/b, then /clear), draws on it, then sets
values turtlesim reads its own way (a string, a deleted one, 300) and calls /reset."""
import rospy
from geometry_msgs.msg import Twist
from std_srvs.srv import Empty


def drive(publisher, seconds):
    command = Twist()
    command.linear.x, command.angular.z = 1.0, 0.5
    for _ in range(int(round(seconds * 10))):
        publisher.publish(command)
        rospy.sleep(0.1)


rospy.init_node("background")
rospy.wait_for_service("/clear")
print("start %r" % [rospy.get_param("/turtlesim/background_%s" % c) for c in "rgb"])
cmd = rospy.Publisher("/turtle1/cmd_vel", Twist, queue_size=1)
rospy.set_param("/turtlesim/background_r", 255)
rospy.set_param("/turtlesim/background_g", 128.5)
rospy.set_param("/turtlesim/background_b", 0)
rospy.sleep(0.2)  # nothing changes on the canvas until /clear
print("clear at %.3f" % rospy.get_time())
rospy.ServiceProxy("/clear", Empty)()
drive(cmd, 0.5)
rospy.sleep(1.2)
rospy.set_param("/turtlesim/background_b", "blue")
rospy.delete_param("/turtlesim/background_r")
rospy.set_param("/turtlesim/background_g", 300)
print("reset at %.3f" % rospy.get_time())
rospy.ServiceProxy("/reset", Empty)()
drive(cmd, 0.5)
print("done at %.3f" % rospy.get_time())
