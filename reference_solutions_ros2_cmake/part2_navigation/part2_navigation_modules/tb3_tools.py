"""Helpers the package's nodes share: a robot's yaw from its odometry quaternion, and heading differences."""

import math


def quaternion_to_yaw(x, y, z, w):
    """The yaw (rotation about z) of a unit quaternion, in radians."""
    return math.atan2(2.0 * (w * z + x * y), 1.0 - 2.0 * (y * y + z * z))


def angle_diff(a, b):
    """a - b wrapped to [-pi, pi], so headings either side of +-180 degrees compare correctly."""
    return math.atan2(math.sin(a - b), math.cos(a - b))
