#!/usr/bin/env python3
"""turtlesim's ``mimic`` for ROS 1 runs graded by rosgrade (the roslaunch tutorial's turtlemimic.launch starts it): for
each pose it hears, it publishes a Twist of that pose's velocities (linear.x = linear_velocity, angular.z =
angular_velocity), as Noetic's turtlesim 0.10.2 ``tutorials/mimic.cpp`` does. Its default name is ``turtle_mimic``;
both queues hold one message.

The C++ node subscribes through ``ros::NodeHandle("input")`` and publishes through ``ros::NodeHandle("output")``. roscpp
resolves and remaps a NodeHandle's namespace itself, then the full topic name again, so the tutorial's
``<remap from="input" to="turtlesim1/turtle1"/>`` moves ``input/pose`` to ``turtlesim1/turtle1/pose`` (and a remap of
``input/pose`` works too). rospy remaps whole names only, so this node resolves the two namespaces first, the same way.

Shipped with the grader and run confined like a student's node; never student code.
"""
import rospy
from geometry_msgs.msg import Twist
from turtlesim.msg import Pose

QUEUE_SIZE = 1  # mimic.cpp: advertise(..., 1) and subscribe(..., 1)


def topic_in(namespace, name):
    """``name`` under ``namespace`` resolved and remapped as roscpp's ``NodeHandle(namespace)`` resolves it."""
    return rospy.resolve_name(namespace).rstrip("/") + "/" + name


def main():
    rospy.init_node("turtle_mimic")
    publisher = rospy.Publisher(topic_in("output", "cmd_vel"), Twist, queue_size=QUEUE_SIZE)

    def on_pose(pose):
        twist = Twist()
        twist.angular.z = pose.angular_velocity
        twist.linear.x = pose.linear_velocity
        publisher.publish(twist)

    rospy.Subscriber(topic_in("input", "pose"), Pose, on_pose, queue_size=QUEUE_SIZE)
    rospy.spin()


if __name__ == "__main__":
    main()
