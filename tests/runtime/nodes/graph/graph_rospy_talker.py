"""Graph test node (rospy): publishes /chatter every 0.5 s."""
import rospy
from std_msgs.msg import String

rospy.init_node("graph_talker")
publisher = rospy.Publisher("/chatter", String, queue_size=10)
rate = rospy.Rate(2)
while not rospy.is_shutdown():
    publisher.publish(String(data="hi"))
    rate.sleep()
