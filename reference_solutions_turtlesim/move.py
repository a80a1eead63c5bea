#!/usr/bin/env python3
"""turtlesim: move turtle1 a distance at a speed, forwards or backwards, as typed in (wiki "Moving in a Straight Line").

The distance is timed with the ROS clock (rospy.Time), which is the simulation's clock when /use_sim_time is set.
"""
import rospy
from geometry_msgs.msg import Twist


def move():
    rospy.init_node("robot_cleaner", anonymous=True)
    velocity_publisher = rospy.Publisher("/turtle1/cmd_vel", Twist, queue_size=10)
    vel_msg = Twist()

    print("Let's move your robot")
    speed = float(input("Input your speed: "))
    distance = float(input("Type your distance: "))
    is_forward = input("Forward? (1/0): ").strip() in ("1", "y", "yes", "True", "true")

    vel_msg.linear.x = abs(speed) if is_forward else -abs(speed)
    rate = rospy.Rate(100)
    while velocity_publisher.get_num_connections() == 0 and not rospy.is_shutdown():
        rate.sleep()  # turtlesim has not connected yet: a message published now would be lost
    t0 = rospy.Time.now().to_sec()
    current_distance = 0.0
    while current_distance < distance and not rospy.is_shutdown():
        velocity_publisher.publish(vel_msg)
        rate.sleep()
        t1 = rospy.Time.now().to_sec()
        current_distance = abs(speed) * (t1 - t0)
    vel_msg.linear.x = 0.0
    velocity_publisher.publish(vel_msg)


if __name__ == "__main__":
    try:
        move()
    except rospy.ROSInterruptException:
        pass
