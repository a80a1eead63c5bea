#!/usr/bin/env python3
import rospy
import math
import numpy as np
import tf
from std_msgs.msg import String
from geometry_msgs.msg import Twist, PoseWithCovariance, Pose
from nav_msgs.msg import Odometry
from tf2_msgs.msg import TFMessage

x = 0
y = 0
yaw = 0


def tf_callback(msg):
    global x, y, theta
    frame_id = "odom"
    child_frame_id = "base_link"
    for transform in msg.transforms:
        if transform.header.frame_id == frame_id and transform.child_frame_id == child_frame_id:
            # Extract the position and orientation
            x = transform.transform.translation.x
            y = transform.transform.translation.y
            quat = (
                transform.transform.rotation.x,
                transform.transform.rotation.y,
                transform.transform.rotation.z,
                transform.transform.rotation.w,
            )
            euler = tf.transformations.euler_from_quaternion(quat)
            theta = euler[2]
            break
    # uncomment to see position info logged
    # rospy.loginfo(f"x: {x}, y: {y}, yaw: {yaw}")


def main():
    rospy.init_node("ctrl_husky")
    sub = rospy.Subscriber("/tf", TFMessage, tf_callback, queue_size=10)
    pub = rospy.Publisher("/husky_velocity_controller/cmd_vel", Twist, queue_size=10)
    initial_position = np.array([0., 0.])
    # for an extra challenge, see if you can make this initialize to any starting position
    while not rospy.is_shutdown():
        if np.linalg.norm(initial_position - np.array([x, y])) > 10:
            rospy.loginfo("Finished Planning")
            break
        else:
            control_message = Twist()
            control_message.linear.x = 1.0
            control_message.angular.z = 0.3
            pub.publish(control_message)


if __name__ == "__main__":
    try:
        main()
    except rospy.ROSInterruptException:
        pass
