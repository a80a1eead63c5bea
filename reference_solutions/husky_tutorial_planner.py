#!/usr/bin/env python3
"""Reference for husky_distance (seed 004): read the pose from /tf, drive 10 m from wherever it starts, stop."""

import numpy as np
import rospy
import tf
from geometry_msgs.msg import Twist
from tf2_msgs.msg import TFMessage

x = None
y = None
theta = None


def tf_callback(msg):
    global x, y, theta
    frame_id = "odom"
    child_frame_id = "base_link"
    for transform in msg.transforms:
        if transform.header.frame_id == frame_id and transform.child_frame_id == child_frame_id:
            x = transform.transform.translation.x
            y = transform.transform.translation.y
            quat = (
                transform.transform.rotation.x,
                transform.transform.rotation.y,
                transform.transform.rotation.z,
                transform.transform.rotation.w,
            )
            theta = tf.transformations.euler_from_quaternion(quat)[2]
            break


def main():
    rospy.init_node("ctrl_husky")
    rospy.Subscriber("/tf", TFMessage, tf_callback, queue_size=10)
    pub = rospy.Publisher("/husky_velocity_controller/cmd_vel", Twist, queue_size=10)
    rospy.on_shutdown(lambda: pub.publish(Twist()))
    rate = rospy.Rate(50)

    while x is None and not rospy.is_shutdown():  # wait for the first transform
        rate.sleep()
    initial_position = np.array([x, y])  # start from wherever the robot is

    while not rospy.is_shutdown():
        remaining = 10.0 - np.linalg.norm(np.array([x, y]) - initial_position)
        if remaining <= 0.0:
            rospy.loginfo("Finished Planning")
            break
        control_message = Twist()
        control_message.linear.x = float(min(1.0, max(0.2, remaining)))  # slow down for the last metre
        pub.publish(control_message)
        rate.sleep()
    pub.publish(Twist())


if __name__ == "__main__":
    try:
        main()
    except rospy.ROSInterruptException:
        pass
