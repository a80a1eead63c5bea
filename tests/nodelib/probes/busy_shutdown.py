"""Probe: a busy publish loop with no sleep advances sim time per call and stops at the SHUTDOWN; the hook's
publish is the last message."""
import rospy
from std_msgs.msg import String


class Mover:
    def __init__(self):
        rospy.init_node("busy")
        self.pub = rospy.Publisher("/chatter", String, queue_size=10)
        rospy.on_shutdown(self.shutdownhook)

    def shutdownhook(self):
        print("hook is_shutdown", rospy.is_shutdown())
        self.pub.publish(String(data="stop"))

    def main(self):
        n = 0
        while not rospy.is_shutdown():
            self.pub.publish(String(data="go"))
            n += 1
        print("loops", n, rospy.Time.now().to_nsec())
        self.pub.publish(String(data="after"))


Mover().main()
