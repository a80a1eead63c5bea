#!/usr/bin/env python3
# Moving in a straight line (turtlesim), ported to Python 3. Flaw: isForward is the text typed in, so "0" is true.
import rospy
from geometry_msgs.msg import Twist


def move():
    rospy.init_node('robot_cleaner', anonymous=True)
    velocity_publisher = rospy.Publisher('/turtle1/cmd_vel', Twist, queue_size=10)
    vel_msg = Twist()

    print("Let's move your robot")
    speed = float(input("Input your speed:"))
    distance = float(input("Type your distance:"))
    isForward = input("Foward?: ")  # True or False

    if isForward:
        vel_msg.linear.x = abs(speed)
    else:
        vel_msg.linear.x = -abs(speed)

    rate = rospy.Rate(100)
    while velocity_publisher.get_num_connections() == 0:
        rate.sleep()

    t0 = rospy.Time.now().to_sec()
    current_distance = 0
    while current_distance < distance:
        velocity_publisher.publish(vel_msg)
        rate.sleep()
        t1 = rospy.Time.now().to_sec()
        current_distance = speed * (t1 - t0)
    vel_msg.linear.x = 0
    velocity_publisher.publish(vel_msg)


if __name__ == '__main__':
    try:
        move()
    except rospy.ROSInterruptException:
        pass
