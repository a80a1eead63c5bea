#!/usr/bin/env python3
# Task 5a: drive in a square by timing each move
import rospy
from geometry_msgs.msg import Twist


def stop():
    pub.publish(Twist())


def mover():
    global pub
    pub = rospy.Publisher('cmd_vel', Twist, queue_size=10)
    rospy.init_node('mover', anonymous=True)
    rospy.on_shutdown(stop)
    rate = rospy.Rate(10) # 10hz
    drive_time = 4.0      # 0.25 m/s for 4 s = 1 m
    turn_time = 3.1416    # 0.5 rad/s for pi/2 / 0.5 s = 90 degrees
    state = "forward"
    # with use_sim_time the clock is 0 until the first /clock message arrives
    while rospy.Time.now().to_sec() == 0 and not rospy.is_shutdown():
        rate.sleep()
    start = rospy.Time.now().to_sec()
    while not rospy.is_shutdown():
        now = rospy.Time.now().to_sec()
        twist = Twist()
        if state == "forward":
            if now - start < drive_time:
                twist.linear.x = 0.25
            else:
                state = "turn"
                start = now
        if state == "turn":
            if now - start < turn_time:
                twist.angular.z = 0.5
            else:
                state = "forward"
                start = now
                twist.linear.x = 0.25
        pub.publish(twist)
        rate.sleep()


if __name__ == '__main__':
    try:
        mover()
    except rospy.ROSInterruptException:
        pass
