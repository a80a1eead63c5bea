#!/usr/bin/env python3
"""Probe (issue 9 item 6): the 16 tf.transformations functions beyond the common ones, in a node, to 9 decimals
(real tf runs on Debian's numpy 1, ours on numpy 2; the bit-for-bit comparison is tests/nodelib_msgs)."""
import math

import numpy
import tf.transformations as tft


def show(label, value):
    if isinstance(value, (tuple, list)):
        print(label, [show_value(v) for v in value])
    else:
        print(label, show_value(value))


def show_value(value):
    if value is None or isinstance(value, bool):
        return value
    return [round(float(x), 9) + 0.0 for x in numpy.ravel(value)]


M = tft.compose_matrix([1.0, 2.0, 3.0], [0.1, 0.2, 0.3], [0.4, -0.5, 0.6], [1.5, -2.5, 3.5], [0.0, 0.0, 0.0, 1.0])
show("compose_matrix", M)
show("decompose_matrix", tft.decompose_matrix(M))
show("decompose_matrix gimbal", tft.decompose_matrix(tft.euler_matrix(0.3, math.pi / 2, 0.2)))
show("clip_matrix box", tft.clip_matrix(-1.0, 2.0, -3.0, 4.0, 0.5, 10.0))
show("clip_matrix frustum", tft.clip_matrix(-1.0, 2.0, -3.0, 4.0, 0.5, 10.0, perspective=True))
show("orthogonalization_matrix", tft.orthogonalization_matrix([10.0, 12.0, 14.0], [80.0, 95.0, 100.0]))
show("projection_matrix orthogonal", tft.projection_matrix([0.1, 0.2, 0.3], [0.0, 0.6, 0.8]))
show("projection_matrix perspective", tft.projection_matrix([0.1, 0.2, 0.3], [0.0, 0.6, 0.8], perspective=[1.0, 2.0, 5.0]))
show("shear_matrix", tft.shear_matrix(0.4, [1.0, 0.0, 0.0], [0.5, 0.5, 0.5], [0.0, 0.6, 0.8]))
v0 = [[0.0, 1.0, 0.0, 2.0], [0.0, 0.0, 1.0, 1.0], [0.0, 0.0, 0.0, 3.0]]
v1 = numpy.dot(tft.euler_matrix(0.1, 0.2, 0.3), numpy.vstack((v0, numpy.ones(4))))[:3] + 1.0
show("superimposition_matrix svd", tft.superimposition_matrix(v0, v1))
show("superimposition_matrix quaternion", tft.superimposition_matrix(v0, v1, usesvd=False))
for name, make, args in (("reflection", tft.reflection_matrix, ([0.3, -0.2, 1.0], [0.2, 0.5, -0.8])),
                         ("rotation", tft.rotation_matrix, (2.1, [0.3, -0.4, 0.5], [1.0, 2.0, -1.0])),
                         ("scale", tft.scale_matrix, (1.7, [0.5, 0.1, 0.2], [0.1, 0.9, -0.3])),
                         ("projection", tft.projection_matrix, ([0.1, 0.2, 0.3], [0.0, 0.6, 0.8], [0.3, 0.1, 0.9]))):
    matrix = make(*args)
    recovered = getattr(tft, name + "_from_matrix")(matrix)
    print(name + "_from_matrix rebuilds", tft.is_same_transform(matrix, make(*recovered[:len(args)])))
angle, direction, point, normal = tft.shear_from_matrix(tft.shear_matrix(0.4, [1.0, 0.0, 0.0], [0.5, 0.5, 0.5],
                                                                         [0.0, 0.6, 0.8]))
print("shear_from_matrix angle", round(abs(angle), 9))
show("arcball_map_to_sphere", tft.arcball_map_to_sphere([400, 250], [320, 320], 320))
show("arcball_constrain_to_axis", tft.arcball_constrain_to_axis([0.3, 0.4, 0.5], [0.0, 0.0, 1.0]))
show("arcball_nearest_axis", tft.arcball_nearest_axis([0.3, 0.4, 0.5], [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0]]))
ball = tft.Arcball()
ball.place([320, 320], 320)
ball.down([500, 250])
ball.drag([475, 275])
show("Arcball drag", ball.matrix())
ball = tft.Arcball(initial=[0, 0, 0, 1])
ball.place([320, 320], 320)
ball.setaxes([1, 1, 0], [-1, 1, 0])
ball.setconstrain(True)
ball.down([400, 200])
ball.drag([200, 400])
show("Arcball constrained", ball.matrix())
ball.next()
show("Arcball next", ball.matrix())
try:
    tft.decompose_matrix(numpy.diag([1.0, 0.0, 1.0, 1.0]))
except ValueError as e:
    print("decompose_matrix singular !!", e)
