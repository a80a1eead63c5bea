"""Calls every public tf.transformations function on many inputs and prints one canonical JSON line per call.

Run as a script with either Debian's tf or rosgrade's first on the path; test_transformations_vs_tf.py compares the
lines. Floats are written as float.hex so that a one-bit difference shows; inputs come from a seeded generator and
are given both as lists and as numpy arrays (numpy 2 treats the two differently where tf asks for copy=False).
"""
from __future__ import annotations

import json
import math
import sys

import numpy

import tf.transformations as tft

AXES = sorted(tft._AXES2TUPLE)
_rng = numpy.random.RandomState(20090418)


def render(value):
    """A JSON-able canonical form of a result: type names plus exact float bits."""
    if isinstance(value, numpy.ndarray):
        return ["ndarray", str(value.dtype), list(value.shape), [render(x) for x in value.ravel().tolist()]]
    if isinstance(value, (bool, numpy.bool_)):
        return [type(value).__name__, bool(value)]
    if isinstance(value, (float, numpy.floating)):
        return [type(value).__name__, float(value).hex()]
    if isinstance(value, complex):
        return ["complex", value.real.hex(), value.imag.hex()]
    if isinstance(value, (int, numpy.integer)):
        return [type(value).__name__, int(value)]
    if isinstance(value, (tuple, list)):
        return [type(value).__name__, [render(x) for x in value]]
    if value is None or isinstance(value, str):
        return value
    return ["object", type(value).__name__]


def call(label: str, fn, *args, **kwargs) -> None:
    try:
        out = render(fn(*args, **kwargs))
    except Exception as exc:  # noqa: BLE001 - the exception is part of the behaviour compared
        out = ["raised", type(exc).__name__, str(exc)]
    print(json.dumps({"call": label, "out": out}))


def vec(n: int, scale: float = 1.0):
    return (_rng.uniform(-1.0, 1.0, n) * scale).tolist()


def both(values):
    """The same input as a list and as a float64 array."""
    return [("list", list(values)), ("array", numpy.array(values, dtype=numpy.float64))]


def unit_perpendicular(normal):
    d = numpy.cross(normal, vec(3))
    return (d / math.sqrt(numpy.dot(d, d))).tolist()


def run() -> None:
    numpy.random.seed(7)
    call("identity_matrix", tft.identity_matrix)
    for n in range(6):
        v = vec(3, 5)
        for kind, x in both(v):
            call("translation_matrix/%s/%d" % (kind, n), tft.translation_matrix, x)
            call("translation_from_matrix/%s/%d" % (kind, n), tft.translation_from_matrix,
                 tft.translation_matrix(v).tolist() if kind == "list" else tft.translation_matrix(v))
    for n in range(8):
        point, normal = vec(3, 3), vec(3)
        for kind, p in both(point):
            R = tft.reflection_matrix(p, normal)
            call("reflection_matrix/%s/%d" % (kind, n), tft.reflection_matrix, p, normal)
            call("reflection_from_matrix/%s/%d" % (kind, n), tft.reflection_from_matrix,
                 R.tolist() if kind == "list" else R)
    call("reflection_from_matrix/identity", tft.reflection_from_matrix, numpy.identity(4))
    for n in range(10):
        angle, direction, point = float(_rng.uniform(-7, 7)), vec(3), vec(3, 2)
        for kind, p in both(point):
            R = tft.rotation_matrix(angle, direction, p)
            call("rotation_matrix/%s/%d" % (kind, n), tft.rotation_matrix, angle, direction, p)
            call("rotation_from_matrix/%s/%d" % (kind, n), tft.rotation_from_matrix, R.tolist() if kind == "list" else R)
        call("rotation_matrix/origin/%d" % n, tft.rotation_matrix, angle, direction)
    for axis in ([1, 0, 0], [0, 1, 0], [0, 0, 1], [0, 0, -1]):
        call("rotation_from_matrix/axis%r" % (axis,), tft.rotation_from_matrix, tft.rotation_matrix(0.7, axis))
    call("rotation_from_matrix/scale", tft.rotation_from_matrix, tft.scale_matrix(2.0))
    for n in range(8):
        factor, origin, direction = float(_rng.uniform(-3, 3)), vec(3, 4), vec(3)
        for kind, o in both(origin):
            for d in (None, direction):
                S = tft.scale_matrix(factor, o, d)
                label = "%s/%s/%d" % (kind, "uniform" if d is None else "direction", n)
                call("scale_matrix/" + label, tft.scale_matrix, factor, o, d)
                call("scale_from_matrix/" + label, tft.scale_from_matrix, S.tolist() if kind == "list" else S)
    call("scale_matrix/factor-only", tft.scale_matrix, 0.5)
    for n in range(8):
        point, normal, direction, persp = vec(3, 2), vec(3), vec(3), vec(3, 4)
        for kind, p in both(point):
            for mode, kwargs in (("orthogonal", {}), ("parallel", {"direction": direction}),
                                 ("perspective", {"perspective": persp}),
                                 ("pseudo", {"perspective": persp, "pseudo": True})):
                label = "%s/%s/%d" % (mode, kind, n)
                P = tft.projection_matrix(p, normal, **kwargs)
                call("projection_matrix/" + label, tft.projection_matrix, p, normal, **kwargs)
                call("projection_from_matrix/" + label, tft.projection_from_matrix,
                     P.tolist() if kind == "list" else P, pseudo=mode == "pseudo")
    call("projection_from_matrix/identity", tft.projection_from_matrix, numpy.identity(4))
    for n in range(6):
        l, b, near = (float(x) for x in _rng.uniform(-5, 5, 3))
        r, t, far = l + float(_rng.uniform(0.1, 5)), b + float(_rng.uniform(0.1, 5)), abs(near) + float(_rng.uniform(0.1, 5))
        call("clip_matrix/box/%d" % n, tft.clip_matrix, l, r, b, t, near, far)
        call("clip_matrix/frustum/%d" % n, tft.clip_matrix, l, r, b, t, abs(near) + 0.01, far + 1, True)
    call("clip_matrix/invalid", tft.clip_matrix, 1, 0, 0, 1, 0, 1)
    call("clip_matrix/near0", tft.clip_matrix, 0, 1, 0, 1, 0, 1, True)
    for n in range(8):
        angle, normal, point = float(_rng.uniform(-1.4, 1.4)), vec(3), vec(3, 3)
        direction = unit_perpendicular(normal)
        for kind, p in both(point):
            S = tft.shear_matrix(angle, direction, p, normal)
            call("shear_matrix/%s/%d" % (kind, n), tft.shear_matrix, angle, direction, p, normal)
            call("shear_from_matrix/%s/%d" % (kind, n), tft.shear_from_matrix, S.tolist() if kind == "list" else S)
    call("shear_matrix/not-orthogonal", tft.shear_matrix, 0.3, [1, 0, 0], [0, 0, 0], [1, 1, 0])
    call("shear_from_matrix/rotation", tft.shear_from_matrix, tft.rotation_matrix(0.5, [0, 0, 1]))
    for n in range(10):
        scale = (_rng.uniform(0.2, 3, 3) * _rng.choice([-1, 1])).tolist()
        shear, angles, translate = vec(3, 0.5), vec(3, 3), vec(3, 10)
        perspective = vec(3, 0.2) + [1.0] if n % 2 else None
        for kind, s in both(scale):
            M = tft.compose_matrix(s, shear, angles, translate, perspective)
            call("compose_matrix/%s/%d" % (kind, n), tft.compose_matrix, s, shear, angles, translate, perspective)
            call("decompose_matrix/%s/%d" % (kind, n), tft.decompose_matrix, M.tolist() if kind == "list" else M)
    call("compose_matrix/none", tft.compose_matrix)
    call("compose_matrix/angles", tft.compose_matrix, angles=[0.1, 0.2, 0.3])
    call("decompose_matrix/gimbal", tft.decompose_matrix, tft.euler_matrix(0.3, math.pi / 2, 0.2))
    call("decompose_matrix/zero-w", tft.decompose_matrix, numpy.zeros((4, 4)))
    call("decompose_matrix/singular", tft.decompose_matrix, numpy.diag([1.0, 0.0, 1.0, 1.0]))
    for n in range(6):
        lengths, angles = _rng.uniform(1, 20, 3).tolist(), _rng.uniform(60, 120, 3).tolist()
        for kind, a in both(angles):
            call("orthogonalization_matrix/%s/%d" % (kind, n), tft.orthogonalization_matrix, lengths, a)
    for n in range(8):
        v0 = _rng.uniform(-10, 10, (3, 5 + n))
        M = tft.concatenate_matrices(tft.translation_matrix(vec(3, 5)), tft.random_rotation_matrix(_rng.rand(3)),
                                     tft.scale_matrix(float(_rng.uniform(0.5, 2))))
        v1 = numpy.dot(M, numpy.vstack((v0, numpy.ones(v0.shape[1]))))[:3] + _rng.normal(0, 0.01, v0.shape)
        for kind, a in (("list", v0.tolist()), ("array", v0)):
            for scaling in (False, True):
                for usesvd in (True, False):
                    call("superimposition_matrix/%s/%s/%s/%d" % (kind, scaling, usesvd, n),
                         tft.superimposition_matrix, a, v1, scaling, usesvd)
    call("superimposition_matrix/shape", tft.superimposition_matrix, [[1, 2], [3, 4], [5, 6]], [[1, 2], [3, 4], [5, 6]])
    for axes in AXES + [(0, 1, 0, 1)]:
        for n in range(4):
            angles = vec(3, 4) if n else [0.0, math.pi / 2, 0.0]
            M = tft.euler_matrix(*angles, axes=axes)
            call("euler_matrix/%s/%d" % (axes, n), tft.euler_matrix, *angles, axes=axes)
            call("euler_from_matrix/%s/%d" % (axes, n), tft.euler_from_matrix, M.tolist(), axes)
            q = tft.quaternion_from_euler(*angles, axes=axes)
            call("quaternion_from_euler/%s/%d" % (axes, n), tft.quaternion_from_euler, *angles, axes=axes)
            call("euler_from_quaternion/%s/%d" % (axes, n), tft.euler_from_quaternion, q.tolist(), axes)
    call("euler_matrix/bad-axes", tft.euler_matrix, 0, 0, 0, "xyz")
    for n in range(10):
        angle, axis = float(_rng.uniform(-7, 7)), vec(3)
        call("quaternion_about_axis/%d" % n, tft.quaternion_about_axis, angle, axis)
        q0, q1 = vec(4), vec(4)
        for kind, q in both(q0):
            call("quaternion_matrix/%s/%d" % (kind, n), tft.quaternion_matrix, q)
            call("quaternion_conjugate/%s/%d" % (kind, n), tft.quaternion_conjugate, q)
            call("quaternion_inverse/%s/%d" % (kind, n), tft.quaternion_inverse, q)
            call("quaternion_multiply/%s/%d" % (kind, n), tft.quaternion_multiply, q, q1)
        M = tft.quaternion_matrix(q0)
        call("quaternion_from_matrix/%d" % n, tft.quaternion_from_matrix, M.tolist())
        for fraction in (0.0, 1.0, 0.25, float(_rng.uniform(-1, 2))):
            for spin, shortest in ((0, True), (1, True), (0, False), (-1, False)):
                call("quaternion_slerp/%d/%r/%d/%s" % (n, fraction, spin, shortest), tft.quaternion_slerp,
                     q0, q1, fraction, spin, shortest)
    call("quaternion_about_axis/zero-axis", tft.quaternion_about_axis, 1.0, [0, 0, 0])
    call("quaternion_slerp/same", tft.quaternion_slerp, [0, 0, 0, 1], [0, 0, 0, 1], 0.5)
    for n in range(6):
        rand = _rng.rand(3).tolist()
        call("random_quaternion/%d" % n, tft.random_quaternion, rand)
        call("random_rotation_matrix/%d" % n, tft.random_rotation_matrix, rand)
    numpy.random.seed(11)
    call("random_quaternion/seeded", tft.random_quaternion)
    call("random_rotation_matrix/seeded", tft.random_rotation_matrix)
    call("random_vector/seeded", tft.random_vector, 5)
    call("random_quaternion/bad", tft.random_quaternion, [0.1, 0.2])
    for n in range(6):
        data = _rng.uniform(-5, 5, (4, 3))
        call("vector_norm/1d/%d" % n, tft.vector_norm, data[0].tolist())
        call("vector_norm/axis0/%d" % n, tft.vector_norm, data, axis=0)
        call("vector_norm/axis1/%d" % n, tft.vector_norm, data.tolist(), axis=1)
        call("vector_norm/all/%d" % n, tft.vector_norm, data)
        out = numpy.empty(3)
        tft.vector_norm(data, axis=0, out=out)
        call("vector_norm/out/%d" % n, lambda: out)
        call("unit_vector/1d/%d" % n, tft.unit_vector, data[0].tolist())
        call("unit_vector/axis0/%d" % n, tft.unit_vector, data, axis=0)
        call("unit_vector/axis1/%d" % n, tft.unit_vector, data.tolist(), axis=1)
        out = numpy.empty((4, 3))
        tft.unit_vector(data.tolist(), axis=1, out=out)
        call("unit_vector/out/%d" % n, lambda: out)
        inplace = data.copy()
        tft.unit_vector(inplace, axis=0, out=inplace)
        call("unit_vector/inplace/%d" % n, lambda: inplace)
        M = tft.compose_matrix(vec(3, 2), vec(3, 0.3), vec(3, 2), vec(3, 5))
        call("inverse_matrix/%d" % n, tft.inverse_matrix, M)
        call("concatenate_matrices/%d" % n, tft.concatenate_matrices, M, tft.euler_matrix(*vec(3)), M.tolist())
        call("is_same_transform/%d" % n, tft.is_same_transform, M, M * 2.0)
        call("is_same_transform/other/%d" % n, tft.is_same_transform, M, tft.identity_matrix())
    call("concatenate_matrices/none", tft.concatenate_matrices)
    call("vector_norm/empty", tft.vector_norm, [])
    call("unit_vector/empty", tft.unit_vector, [[]], 1)
    for n in range(8):
        center, radius = _rng.uniform(100, 500, 2).tolist(), float(_rng.uniform(50, 400))
        point = _rng.uniform(0, 600, 2).tolist()
        call("arcball_map_to_sphere/%d" % n, tft.arcball_map_to_sphere, point, center, radius)
        axis = tft.unit_vector(vec(3))
        call("arcball_constrain_to_axis/%d" % n, tft.arcball_constrain_to_axis, vec(3), axis)
        axes = [tft.unit_vector(vec(3)) for _ in range(3)]
        call("arcball_nearest_axis/%d" % n, tft.arcball_nearest_axis, vec(3), axes)
    call("arcball_constrain_to_axis/z", tft.arcball_constrain_to_axis, [0, 0, 1], [0, 0, 1])
    call("arcball_constrain_to_axis/parallel", tft.arcball_constrain_to_axis, [1, 0, 0], [1, 0, 0])
    arcball_sessions()


def arcball_sessions() -> None:
    """Drag sessions on an Arcball: each step's rotation matrix is compared."""
    for n, initial in enumerate((None, numpy.identity(4), [0, 0, 0, 1], vec(4), tft.random_rotation_matrix(_rng.rand(3)))):
        def session(initial=initial, constrain=bool(n % 2)):
            ball = tft.Arcball(initial=initial)
            ball.place(_rng.uniform(200, 400, 2).tolist(), float(_rng.uniform(100, 300)))
            ball.setaxes([1, 1, 0], [-1, 1, 0], [0, 0, 1])
            ball.setconstrain(constrain)
            steps = [ball.getconstrain()]
            for _ in range(3):
                ball.down(_rng.uniform(0, 640, 2).tolist())
                for _ in range(3):
                    ball.drag(_rng.uniform(0, 640, 2).tolist())
                    steps.append(ball.matrix())
                ball.next()
                steps.append(ball.matrix())
                ball.next(0.5)
                steps.append(ball.matrix())
            return steps
        call("Arcball/%d" % n, session)
    call("Arcball/bad-initial", tft.Arcball, [1, 2, 3])
    euler_from_quaternion_inputs()


def euler_from_quaternion_inputs() -> None:
    """The inputs rosgrade computes without numpy (lists and tuples of floats and ints) and those it hands to numpy."""
    for n in range(60):
        q = vec(4, [1e-9, 1e-3, 1.0, 1e3][n % 4])
        for axes in ("sxyz", "rzyx", AXES[n % len(AXES)]):
            call("euler_from_quaternion/list/%s/%d" % (axes, n), tft.euler_from_quaternion, q, axes)
        call("euler_from_quaternion/tuple/%d" % n, tft.euler_from_quaternion, tuple(q))
        call("euler_from_quaternion/ints/%d" % n, tft.euler_from_quaternion, [round(v * 3) for v in q])
        call("euler_from_quaternion/array/%d" % n, tft.euler_from_quaternion, numpy.array(q))
        call("euler_from_quaternion/long/%d" % n, tft.euler_from_quaternion, q + [5.0])
    for label, q in (("zero", [0.0, 0.0, 0.0, 0.0]), ("zero-ints", [0, 0, 0, 0]), ("tiny", [1e-9, 0.0, 0.0, 0.0]),
                     ("nan", [math.nan, 0.0, 0.0, 1.0]), ("inf", [0.0, math.inf, 0.0, 1.0]),
                     ("bools", [False, False, True, True]), ("strings", ["0", "0", "1", "0"]),
                     ("short", [0.0, 0.0, 1.0]), ("mixed", [0.0, numpy.float64(0.5), 0.5, 1]), ("empty", [])):
        call("euler_from_quaternion/%s" % label, tft.euler_from_quaternion, q)
    call("euler_from_quaternion/bad-axes", tft.euler_from_quaternion, [0.0, 0.0, 0.0, 1.0], "xyz")


if __name__ == "__main__":
    numpy.seterr(all="ignore")
    run()
    sys.stdout.flush()
