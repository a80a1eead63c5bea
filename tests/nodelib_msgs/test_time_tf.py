"""genpy Time/Duration (reference table a) and tf.transformations (section f, behaviour 13), checked by name."""
from __future__ import annotations

import math
import os
import re
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

import tf
import rosgrade_transformations
import tf.transformations as tft
from genpy import Duration, Time
from geometry_msgs.msg import Quaternion

from grader.nodelib import pythonpath


def test_time_construction_and_text():
    assert repr(Time(5, 2500)) == "genpy.Time[5000002500]"
    assert (Time(1.5).secs, Time(1.5).nsecs) == (1, 500000000)
    assert Time(0, 1500000000) == Time(1, 500000000)
    with pytest.raises(TypeError, match="^time values must be positive$"):
        Time(-1)
    assert (Time.from_sec(12.345678901).secs, Time.from_sec(12.345678901).nsecs) == (12, 345678900)
    assert Time.from_sec(1700000000.123456789).nsecs == 123456716
    assert str(Time(1, 500000000)) == "1500000000" and "%s" % Time(1, 500000000) == "1500000000"
    assert (Time(1, 500000000).to_sec(), Time(1, 500000000).to_nsec()) == (1.5, 1500000000)


def test_time_arithmetic():
    assert Time(10) + Duration(1.5) == Duration(1.5) + Time(10) == Time(11, 500000000)
    assert repr(Time(10) - Time(8, 5)) == "genpy.Duration[1999999995]"
    assert Time(10) - Duration(1) == Time(9)
    with pytest.raises(TypeError, match=r"unsupported operand type\(s\) for \+: 'Time' and 'Time'"):
        Time(1) + Time(1)
    with pytest.raises(TypeError, match="'>' not supported between instances of 'Duration' and 'float'"):
        Duration(1) > 0.5
    assert Duration(1) * 3 == 3 * Duration(1) == Duration(3) and Duration(1) * 1.5 == Duration(1.5)
    assert Duration(3) / 2 == Duration(1.5) and Duration(3) // 2 == Duration(1)
    assert Duration(3) / Duration(2) == 1.5 and -Duration(3) == Duration(-3) and abs(Duration(-3)) == Duration(3)
    assert (Duration(-0.5).secs, Duration(-0.5).nsecs) == (-1, 500000000)
    assert (Duration.from_sec(-1.25).secs, Duration.from_sec(-1.25).nsecs) == (-2, 750000000)
    assert not Time(0) and not Duration(0) and Time(0).is_zero()
    with pytest.raises(TypeError, match="float\\(\\) argument must be a string or a real number, not 'Time'"):
        float(Time(1, 5))
    assert Time(1) != Duration(1) and hash(Time(3)) == hash(Time(3))


def test_euler_from_quaternion_values():
    assert tft.euler_from_quaternion([0, 0, 0, 1]) == (0.0, -0.0, 0.0)
    assert math.copysign(1, tft.euler_from_quaternion([0, 0, 0, 1])[1]) == -1
    assert tft.euler_from_quaternion([0, 0, math.sin(math.pi / 4), math.cos(math.pi / 4)])[2] == 1.5707963267948966
    assert tft.euler_from_quaternion([0, 0, 1, 0])[2] == math.pi
    assert tft.euler_from_quaternion([0, 0, -1, 0]) == (0.0, 0.0, math.pi)
    assert tft.euler_from_quaternion([0, 0, 0.7071, 0.7071])[2] == math.pi / 2
    assert tft.euler_from_quaternion([0, 0, 0, 0]) == (0.0, -0.0, 0.0)
    assert all(type(v) is float for v in tft.euler_from_quaternion(np.array([0.1, 0.2, 0.3, 0.9])))


class _DotInOrder:
    """numpy, but with dot of two vectors summing their products from the first to the last (no BLAS)."""

    def __getattr__(self, name):
        return getattr(np, name)

    @staticmethod
    def dot(a, b):
        total = 0.0
        for x, y in zip(np.asarray(a).tolist(), np.asarray(b).tolist()):
            total += x * y
        return np.float64(total)


def _quaternions():
    rng = np.random.default_rng(5)
    for scale in (1e-8, 1e-3, 1.0, 1e4):
        yield from rng.normal(size=(2000, 4)) * scale


@pytest.mark.parametrize("axes", ["sxyz", "rzyx", "sxzx", "rxyx"])
def test_euler_from_quaternion_of_floats_is_tfs_arithmetic_with_the_squares_summed_in_order(axes, monkeypatch):
    # numpy.dot hands |q|^2 to BLAS, whose kernel (FMA or not, the order of the sum) depends on the CPU: the one step of
    # tf's code whose bits are not the same everywhere. With it summed in order, the float path is tf's to the bit.
    monkeypatch.setattr(rosgrade_transformations, "numpy", _DotInOrder())
    for q in _quaternions():
        expected = tft.euler_from_matrix(tft.quaternion_matrix(q), axes)
        got = tft.euler_from_quaternion(q.tolist(), axes)
        assert [v.hex() for v in got] == [float(v).hex() for v in expected], q.tolist()


@pytest.mark.parametrize("axes", ["sxyz", "rzyx", "sxzx", "rxyx"])
def test_euler_from_quaternion_of_floats_is_within_1e13_of_numpys_path_on_this_cpu(axes):
    worst = max(abs(a - float(b)) for q in _quaternions()
                for a, b in zip(tft.euler_from_quaternion(q.tolist(), axes),
                                tft.euler_from_matrix(tft.quaternion_matrix(q), axes)))
    assert worst <= 1e-13


@pytest.mark.parametrize("limits", [{"NPY_DISABLE_CPU_FEATURES": "X86_V3 X86_V4 AVX512_ICL AVX512_SPR"},
                                    {"OPENBLAS_CORETYPE": "Prescott"}], ids=["numpy-baseline", "blas-generic"])
def test_euler_float_path_holds_with_numpy_and_blas_limited_to_their_baseline(limits):
    # NPY_DISABLE_CPU_FEATURES only names features this numpy dispatches; numpy warns about and ignores the others.
    env = {**os.environ, **limits, "PYTHONWARNINGS": "ignore"}
    done = subprocess.run([sys.executable, "-m", "pytest", "-q", "-p", "no:cacheprovider", __file__,
                           "-k", "squares_summed_in_order or within_1e13"], capture_output=True, text=True,
                          timeout=300, env=env, cwd=Path(__file__).parents[2])
    assert done.returncode == 0, done.stdout[-3000:] + done.stderr[-2000:]
    assert re.search(r"\b8 passed", done.stdout), done.stdout[-2000:]


def test_tf_transformations_imports_numpy_only_when_a_call_needs_it():
    script = ("import sys, tf.transformations as t\n"
              "print(t.euler_from_quaternion([0.0, 0.0, 0.5, 0.5]), 'numpy' in sys.modules)\n"
              "print(t.quaternion_from_euler(0, 0, 1.0)[3], 'numpy' in sys.modules)\n")
    done = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, timeout=60,
                          env={"PYTHONPATH": pythonpath("ros1"), "PATH": "/usr/bin:/bin"})
    assert done.returncode == 0, done.stderr
    assert done.stdout.splitlines() == [f"(0.0, -0.0, {math.pi / 2!r}) False", f"{math.cos(0.5)!r} True"]


def test_tf_errors():
    with pytest.raises(TypeError, match="'Quaternion' object is not subscriptable"):
        tft.euler_from_quaternion(Quaternion(0, 0, 0, 1))
    with pytest.raises(IndexError, match="^index 3 is out of bounds for axis 1 with size 3$"):
        tft.euler_from_quaternion([0, 0, 1])


def test_quaternion_from_euler_and_round_trips():
    q = tft.quaternion_from_euler(0, 0, 0)
    assert isinstance(q, np.ndarray) and q.dtype == np.float64 and q.tolist() == [0, 0, 0, 1]
    assert tft.quaternion_from_euler(0, 0, math.pi)[2:].tolist() == [1.0, 6.123233995736766e-17]
    q = tft.quaternion_from_euler(0, 0, 3 * math.pi / 2)
    assert math.copysign(1, q[0]) == -1 and q[3] < 0
    assert np.allclose(tft.quaternion_from_euler(0.1, 0.2, 0.3), [0.0342708, 0.10602051, 0.14357218, 0.98334744])
    yaw = lambda y: tft.euler_from_quaternion(tft.quaternion_from_euler(0, 0, y))[2]  # noqa: E731
    assert (yaw(math.pi), yaw(-math.pi), yaw(4.0), yaw(-3.5), yaw(0.5)) == (
        math.pi, -math.pi, -2.2831853071795867, 2.7831853071795867, 0.5000000000000001)
    assert tft.euler_from_quaternion(tft.quaternion_from_euler(0, 0, math.pi / 2), axes="rzyx") == (
        1.5707963267948966, -0.0, 0.0)


@pytest.mark.parametrize("axes", sorted(tft._AXES2TUPLE))
def test_all_axes_round_trip(axes):
    angles = (0.1, -0.7, 2.5)
    matrix = tft.euler_matrix(*angles, axes=axes)
    # Euler angles are not unique, so compare the rotations they describe
    back = tft.euler_from_quaternion(tft.quaternion_from_euler(*angles, axes=axes), axes)
    assert np.allclose(tft.euler_matrix(*back, axes=axes), matrix)
    assert np.allclose(tft.euler_matrix(*tft.euler_from_matrix(matrix, axes), axes=axes), matrix)
    assert np.allclose(tft.quaternion_matrix(tft.quaternion_from_euler(*angles, axes=axes)), matrix)


def test_tf_module_layout():
    assert tf.transformations is tft
    assert issubclass(tf.LookupException, tf.Exception) and issubclass(tf.ExtrapolationException, tf.Exception)


def test_transformer_lookup_and_errors():
    from geometry_msgs.msg import TransformStamped
    tr = tf.Transformer(True)
    for stamp, x in ((10, 1.0), (11, 2.0)):
        m = TransformStamped()
        m.header.frame_id, m.child_frame_id, m.header.stamp = "odom", "base", Time(stamp)
        m.transform.translation.x, m.transform.rotation.w = x, 1.0
        tr.setTransform(m)
    assert tr.lookupTransform("odom", "base", Time(0)) == ([2.0, 0.0, 0.0], [0.0, 0.0, 0.0, 1.0])
    assert tr.lookupTransform("/odom", "base", Time(10, 500000000))[0] == [1.5, 0.0, 0.0]
    with pytest.raises(tf.LookupException, match='^"nope" passed to lookupTransform argument source_frame does not '
                                                 'exist. $'):
        tr.lookupTransform("odom", "nope", Time(0))
    with pytest.raises(tf.ExtrapolationException, match="extrapolation 1.000000000s into the future"):
        tr.lookupTransform("base", "odom", Time(12))
