#!/usr/bin/env python3
"""turtlesim's ``turtle_teleop_key`` for launch files graded by rosgrade: the keys come from the node's stdin.

Behaves as ROS 1 noetic ``turtlesim/tutorials/teleop_turtle_key.cpp``: it reads one byte at a time; the last byte of
an arrow key's escape sequence (``ESC [ A`` .. ``ESC [ D``, so a bare ``A``..``D`` too) sets linear.x to
``scale_linear`` (up), ``-scale_linear`` (down) or angular.z to ``scale_angular`` (left), ``-scale_angular`` (right),
and publishes that Twist on ``turtle1/cmd_vel`` (relative to the node's namespace, remappable); any other byte
publishes nothing; ``q`` ends the node. ``scale_linear`` and ``scale_angular`` (default 2.0) are read as the C++
node reads them, from its namespace, not its private ``~`` names.

Two differences, both because stdin here is a keyboard typed at once: the node waits until its publisher is
connected (at most ``CONNECT_WAIT_S``) before reading, as a person types once the turtle is on screen; and at the end
of stdin it waits for Ctrl+C like an idle keyboard, where the C++ node, reading a closed pipe, would repeat its last
key forever.

Shipped with the grader and run confined like a student's node; never student code.
"""
import os

import rospy
from geometry_msgs.msg import Twist

UP, DOWN, RIGHT, LEFT, QUIT = b"A", b"B", b"C", b"D", b"q"
CONNECT_WAIT_S = 1.0


def twist_for(key, scale_linear, scale_angular):
    """The Twist one key publishes, or None for a key that publishes nothing (QUIT is handled by the caller)."""
    if key not in (UP, DOWN, LEFT, RIGHT):
        return None
    twist = Twist()
    twist.linear.x = scale_linear * {UP: 1.0, DOWN: -1.0}.get(key, 0.0)
    twist.angular.z = scale_angular * {LEFT: 1.0, RIGHT: -1.0}.get(key, 0.0)
    return twist


def wait_for_turtle(publisher):
    """Wait until something subscribes to the publisher, for at most CONNECT_WAIT_S."""
    deadline = rospy.Time.now() + rospy.Duration(CONNECT_WAIT_S)
    while publisher.get_num_connections() == 0 and rospy.Time.now() < deadline and not rospy.is_shutdown():
        rospy.sleep(0.01)


def key_loop(publisher, scale_linear, scale_angular):
    """Publish one Twist per arrow key read from stdin; return at 'q' (True) or at the end of stdin (False)."""
    while not rospy.is_shutdown():
        key = os.read(0, 1)
        if not key:
            return False
        if key == QUIT:
            return True
        twist = twist_for(key, scale_linear, scale_angular)
        if twist is not None:
            publisher.publish(twist)
    return True


def main():
    rospy.init_node("teleop_turtle")
    scale_angular = float(rospy.get_param("scale_angular", 2.0))
    scale_linear = float(rospy.get_param("scale_linear", 2.0))
    publisher = rospy.Publisher("turtle1/cmd_vel", Twist, queue_size=1)
    print("Reading from keyboard")
    print("---------------------------")
    print("Use arrow keys to move the turtle. 'q' to quit.", flush=True)
    wait_for_turtle(publisher)
    if not key_loop(publisher, scale_linear, scale_angular):
        rospy.spin()


if __name__ == "__main__":
    main()
