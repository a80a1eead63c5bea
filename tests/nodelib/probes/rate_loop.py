"""Probe: a 10 Hz Rate created before the first /clock publishes twice at the start, then every 100 ms."""
import rospy
from std_msgs.msg import String

rospy.init_node("rateprobe")
pub = rospy.Publisher("chatter", String, queue_size=10)
rate = rospy.Rate(10)
print("remaining0", rate.remaining().to_nsec())
i = 0
while not rospy.is_shutdown() and i < 5:
    i += 1
    pub.publish(String(data="m%d" % (i - 1)))
    rate.sleep()
