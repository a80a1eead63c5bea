#!/usr/bin/env python3
"""Probe 6: tf.transformations values, including yaw at +-pi, non-unit and zero quaternions, and error texts."""
import math

import tf
import tf.transformations as tft
from geometry_msgs.msg import Quaternion


def err(e):
    return "%s: %s" % (type(e).__name__, e)


def show(label, fn):
    try:
        v = fn()
        if hasattr(v, "dtype"):
            print(label, "->", type(v).__name__, v.dtype, v.shape, [float(x) for x in v.ravel()])
        else:
            print(label, "->", type(v).__name__, [(type(x).__name__, x) for x in v] if isinstance(v, (tuple, list)) else v)
    except Exception as e:
        print(label, "!!", err(e))


print("tf.transformations is tft", tf.transformations is tft)
print("has TransformListener", hasattr(tf, "TransformListener"), "has TransformBroadcaster", hasattr(tf, "TransformBroadcaster"))
s = math.sin(math.pi / 4)
c = math.cos(math.pi / 4)
for q in ([0, 0, 0, 1], [0, 0, s, c], [0, 0, 1, 0], [0, 0, -1, 0], [0, 0, 0, -1], [0, 0, 0.7071, 0.7071],
          [0, 0, 2 * s, 2 * c], [0, 0, 0, 0], (0.0342708, 0.10602051, 0.14357218, 0.98334744), [0, 0, -s, c]):
    show("euler_from_quaternion(%r)" % (q,), lambda: tft.euler_from_quaternion(q))
show("euler_from_quaternion(Quaternion(0,0,0,1))", lambda: tft.euler_from_quaternion(Quaternion(0, 0, 0, 1)))
show("euler_from_quaternion([0,0,1])", lambda: tft.euler_from_quaternion([0, 0, 1]))
for e in ((0, 0, 0), (0, 0, math.pi / 2), (0, 0, math.pi), (0, 0, -math.pi), (0, 0, 3 * math.pi / 2),
          (0.1, 0.2, 0.3), (0, 0, 4.0)):
    show("quaternion_from_euler%r" % (e,), lambda: tft.quaternion_from_euler(*e))
for yaw in (math.pi, -math.pi, 4.0, -3.5, 0.5, 2.0, -2.0, 1e-9):
    show("round_trip yaw=%r" % yaw, lambda: tft.euler_from_quaternion(tft.quaternion_from_euler(0, 0, yaw))[2:])
show("rzyx yaw pi/2", lambda: tft.euler_from_quaternion(tft.quaternion_from_euler(0, 0, math.pi / 2), axes="rzyx"))
show("quaternion_from_euler(pi/2,0,0,'rzyx')", lambda: tft.quaternion_from_euler(math.pi / 2, 0, 0, "rzyx"))
show("quaternion_multiply", lambda: tft.quaternion_multiply([0, 0, s, c], [0, 0, s, c]))
show("quaternion_inverse", lambda: tft.quaternion_inverse([0, 0, s, c]))
show("euler_from_matrix", lambda: tft.euler_from_matrix(tft.quaternion_matrix([0, 0, s, c])))
show("translation_from_matrix", lambda: tft.translation_from_matrix(tft.translation_matrix([1, 2, 3])))
show("quaternion_from_euler(0,0,'x')", lambda: tft.quaternion_from_euler(0, 0, "x"))
show("quaternion_from_euler bad axes", lambda: tft.quaternion_from_euler(0, 0, 0, "abc"))
