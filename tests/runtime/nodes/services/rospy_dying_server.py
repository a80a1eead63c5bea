"""A rospy Trigger server whose handler ends the whole process before it answers."""
import os

import rospy
from std_srvs.srv import Trigger

rospy.init_node("dying")
rospy.Service("die", Trigger, lambda request: os._exit(3))
rospy.spin()
