#!/usr/bin/env python3
import rospy
import math
import numpy as np
import tf
from geometry_msgs.msg import Twist
from tf2_msgs.msg import TFMessage

x = 0
y = 0
theta = 0
have_tf = False


def tf_callback(msg):
    global x, y, theta, have_tf
    for transform in msg.transforms:
        if transform.header.frame_id == "odom" and transform.child_frame_id == "base_link":
            x = transform.transform.translation.x
            y = transform.transform.translation.y
            quat = (transform.transform.rotation.x, transform.transform.rotation.y,
                    transform.transform.rotation.z, transform.transform.rotation.w)
            theta = tf.transformations.euler_from_quaternion(quat)[2]
            have_tf = True
            break


def main():
    rospy.init_node("ctrl_husky")
    sub = rospy.Subscriber("/tf", TFMessage, tf_callback, queue_size=10)
    pub = rospy.Publisher("/husky_velocity_controller/cmd_vel", Twist, queue_size=10)
    rate = rospy.Rate(20)
    while not have_tf and not rospy.is_shutdown():
        rate.sleep()
    # extra challenge: start from wherever the robot is
    initial_position = np.array([x, y])
    while not rospy.is_shutdown():
        if np.linalg.norm(initial_position - np.array([x, y])) > 10:
            rospy.loginfo("Finished Planning")
            break
        control_message = Twist()
        control_message.linear.x = 0.5
        pub.publish(control_message)
        rate.sleep()
    pub.publish(Twist())


if __name__ == "__main__":
    try:
        main()
    except rospy.ROSInterruptException:
        pass
