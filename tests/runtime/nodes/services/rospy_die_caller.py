"""Calls /die, whose server's process ends before it answers, and prints what rospy raised."""
import rospy
from std_srvs.srv import Trigger

rospy.init_node("caller")
rospy.wait_for_service("/die")
try:
    rospy.ServiceProxy("/die", Trigger)()
except rospy.ServiceException as exc:
    print(f"failed: {exc}", flush=True)
