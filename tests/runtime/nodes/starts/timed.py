"""Says that it started, then runs for the sim seconds given (from its first /clock), or until Ctrl+C."""
import sys

import rospy

rospy.init_node(sys.argv[1])
rospy.loginfo("%s started", sys.argv[1])
while rospy.get_time() == 0.0 and not rospy.is_shutdown():  # no /clock yet
    rospy.sleep(0.01)
end = rospy.get_time() + float(sys.argv[2])
while not rospy.is_shutdown() and rospy.get_time() < end:
    rospy.sleep(0.1)
