#!/usr/bin/env python3
"""Names itself /gazebo and publishes fake world topics (and zero-width look-alikes) with a robot far away."""
import sys

import rospy
from nav_msgs.msg import Odometry
from rosgraph_msgs.msg import Clock
from tf2_msgs.msg import TFMessage
from geometry_msgs.msg import TransformStamped

rospy.init_node(sys.argv[1] if len(sys.argv) > 1 else "gazebo")
fake = Odometry()
fake.header.frame_id, fake.child_frame_id = "odom", "base_footprint"
fake.pose.pose.position.x, fake.pose.pose.orientation.w = 9.0, 1.0
transform = TransformStamped()
transform.header.frame_id, transform.child_frame_id = "odom", "base_footprint"
transform.transform.translation.x, transform.transform.rotation.w = 9.0, 1.0
publishers = [(rospy.Publisher(topic, Odometry, queue_size=10), fake)
              for topic in ("/odom", "/ground_truth/odom", "/odom\u200b", "/ground_truth/odom\u200b")]
publishers += [(rospy.Publisher(topic, TFMessage, queue_size=10), TFMessage(transforms=[transform]))
               for topic in ("/tf", "/tf_static")]
publishers.append((rospy.Publisher("/clock", Clock, queue_size=10), Clock()))
rate = rospy.Rate(20)
while not rospy.is_shutdown():
    stamp = rospy.Time.now()
    fake.header.stamp = transform.header.stamp = stamp
    for pub, msg in publishers:
        pub.publish(msg)
    rate.sleep()
