#!/usr/bin/env python3
"""Grid cleaning. Flaw: the rows are 2 m apart, so the pen leaves most of the canvas untouched."""
import math

import rospy
from geometry_msgs.msg import Twist
from turtlesim.msg import Pose

LOW, HIGH = 0.5, 10.5  # m: the sweep keeps this far from the walls
ROW = 2.0  # m between rows: fewer rows, done sooner
TOLERANCE = 0.05  # m

pose = None


def on_pose(msg):
    global pose
    pose = msg


def go_to(pub, rate, x, y):
    """Turn towards (x, y) and drive there, slowing down as it gets close."""
    cmd = Twist()
    while not rospy.is_shutdown():
        distance = math.hypot(x - pose.x, y - pose.y)
        if distance < TOLERANCE:
            break
        heading = math.atan2(y - pose.y, x - pose.x)
        error = math.atan2(math.sin(heading - pose.theta), math.cos(heading - pose.theta))
        cmd.angular.z = 6.0 * error
        cmd.linear.x = min(2.0 * distance, 4.0) if abs(error) < 0.2 else 0.0
        pub.publish(cmd)
        rate.sleep()


def waypoints():
    """Lower-left corner, then a back-and-forth sweep upwards."""
    points, y, rightwards = [], LOW, True
    while y <= HIGH + 1e-9:
        points += [(LOW, y), (HIGH, y)] if rightwards else [(HIGH, y), (LOW, y)]
        y += ROW
        rightwards = not rightwards
    return points


def main():
    rospy.init_node("grid_cleaner")
    pub = rospy.Publisher("turtle1/cmd_vel", Twist, queue_size=10)
    rospy.Subscriber("turtle1/pose", Pose, on_pose)
    rate = rospy.Rate(50)
    while (pose is None or pub.get_num_connections() == 0) and not rospy.is_shutdown():
        rate.sleep()
    for x, y in waypoints():
        go_to(pub, rate, x, y)
    pub.publish(Twist())
    rospy.loginfo("cleaning done")


if __name__ == "__main__":
    try:
        main()
    except rospy.ROSInterruptException:
        pass
