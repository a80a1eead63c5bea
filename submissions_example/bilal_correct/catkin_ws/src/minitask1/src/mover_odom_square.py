#!/usr/bin/env python3
# Task 5b: drive a square with 1 m edges using odometry
import math
import rospy
import tf
from geometry_msgs.msg import Twist, Pose2D
from nav_msgs.msg import Odometry


class Mover:
    def __init__(self):
        rospy.init_node('mover', anonymous=True)
        self.pub = rospy.Publisher('cmd_vel', Twist, queue_size=10)
        rospy.Subscriber("odom", Odometry, self.odom_callback)
        self.pose = Pose2D()
        self.got_odom = False
        rospy.on_shutdown(self.shutdown)

    def odom_callback(self, msg):
        quaternion = [msg.pose.pose.orientation.x, msg.pose.pose.orientation.y,
                      msg.pose.pose.orientation.z, msg.pose.pose.orientation.w]
        (roll, pitch, yaw) = tf.transformations.euler_from_quaternion(quaternion)
        self.pose.theta = yaw
        self.pose.x = msg.pose.pose.position.x
        self.pose.y = msg.pose.pose.position.y
        self.got_odom = True

    def shutdown(self):
        self.pub.publish(Twist())

    def run(self):
        rate = rospy.Rate(20)
        while not self.got_odom and not rospy.is_shutdown():
            rate.sleep()
        for edge in range(4):
            start_x, start_y = self.pose.x, self.pose.y
            while not rospy.is_shutdown():
                dist = math.sqrt((self.pose.x - start_x) ** 2 + (self.pose.y - start_y) ** 2)
                if dist > 1.0:
                    break
                t = Twist()
                t.linear.x = 0.15 if dist < 0.9 else 0.04
                self.pub.publish(t)
                rate.sleep()
            self.pub.publish(Twist())
            rospy.sleep(0.5)
            theta_target = self.pose.theta + math.pi / 2
            while not rospy.is_shutdown():
                error = math.atan2(math.sin(theta_target - self.pose.theta), math.cos(theta_target - self.pose.theta))
                if error < 0.005:
                    break
                t = Twist()
                t.angular.z = 0.4 if error > 0.2 else 0.06
                self.pub.publish(t)
                rate.sleep()
            self.pub.publish(Twist())
            rospy.sleep(0.5)
        rospy.loginfo("Finished the square")


if __name__ == '__main__':
    try:
        Mover().run()
    except rospy.ROSInterruptException:
        pass
