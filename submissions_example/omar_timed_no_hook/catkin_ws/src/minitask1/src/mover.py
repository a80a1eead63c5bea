#!/usr/bin/env python3
# License removed for brevity
import rospy
from geometry_msgs.msg import Twist


def mover():
    pub = rospy.Publisher('cmd_vel', Twist, queue_size=10)
    rospy.init_node('mover', anonymous=True)
    rate = rospy.Rate(10) # 10hz
    start = rospy.Time.now().to_sec()
    while not rospy.is_shutdown():
        t = (rospy.Time.now().to_sec() - start) % 8.0
        move = Twist()
        if t < 5.0:
            move.linear.x = 0.2       # 5 s forwards: 1 m
        else:
            move.angular.z = 0.5236   # 3 s at 30 deg/s: 90 degrees
        pub.publish(move)
        rate.sleep()


if __name__ == '__main__':
    try:
        mover()
    except rospy.ROSInterruptException:
        pass
