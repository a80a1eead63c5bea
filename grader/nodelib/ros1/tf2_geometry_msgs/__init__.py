"""rosgrade's tf2_geometry_msgs: apply a TransformStamped to stamped points, vectors and poses (do_transform_*).

Importing it registers these with tf2_ros.Buffer.transform, as the real package does. The result's header is the
transform's (target frame, transform time).
"""
from __future__ import annotations

import copy

import tf2_ros
from geometry_msgs.msg import PointStamped, PoseStamped, PoseWithCovarianceStamped, Vector3Stamped

__all__ = ["do_transform_point", "do_transform_pose", "do_transform_pose_with_covariance_stamped",
           "do_transform_vector3"]


def _rotation(transform):
    r = transform.transform.rotation
    return r.x, r.y, r.z, r.w


def _rotate(q, v):
    """v rotated by the unit quaternion q = (x, y, z, w)."""
    x, y, z, w = q
    tx, ty, tz = 2 * (y * v[2] - z * v[1]), 2 * (z * v[0] - x * v[2]), 2 * (x * v[1] - y * v[0])
    return (v[0] + w * tx + y * tz - z * ty, v[1] + w * ty + z * tx - x * tz, v[2] + w * tz + x * ty - y * tx)


def _qmul(a, b):
    ax, ay, az, aw = a
    bx, by, bz, bw = b
    return (aw * bx + ax * bw + ay * bz - az * by, aw * by - ax * bz + ay * bw + az * bx,
            aw * bz + ax * by - ay * bx + az * bw, aw * bw - ax * bx - ay * by - az * bz)


def _moved(point, transform):
    t = transform.transform.translation
    x, y, z = _rotate(_rotation(transform), (point.x, point.y, point.z))
    return x + t.x, y + t.y, z + t.z


def do_transform_point(point, transform):
    """geometry_msgs/PointStamped ``point`` expressed in the transform's target frame."""
    res = PointStamped()
    res.point.x, res.point.y, res.point.z = _moved(point.point, transform)
    res.header = transform.header
    return res


def do_transform_vector3(vector3, transform):
    """geometry_msgs/Vector3Stamped rotated (not translated) into the transform's target frame."""
    res = Vector3Stamped()
    v = vector3.vector
    res.vector.x, res.vector.y, res.vector.z = _rotate(_rotation(transform), (v.x, v.y, v.z))
    res.header = transform.header
    return res


def _pose(pose, transform, out):
    out.position.x, out.position.y, out.position.z = _moved(pose.position, transform)
    o = pose.orientation
    out.orientation.x, out.orientation.y, out.orientation.z, out.orientation.w = _qmul(
        _rotation(transform), (o.x, o.y, o.z, o.w))


def do_transform_pose(pose, transform):
    """geometry_msgs/PoseStamped expressed in the transform's target frame."""
    res = PoseStamped()
    _pose(pose.pose, transform, res.pose)
    res.header = transform.header
    return res


def do_transform_pose_with_covariance_stamped(pose, transform):
    """geometry_msgs/PoseWithCovarianceStamped moved into the target frame (the covariance is kept as it is)."""
    res = PoseWithCovarianceStamped()
    _pose(pose.pose.pose, transform, res.pose.pose)
    res.pose.covariance = copy.copy(pose.pose.covariance)
    res.header = transform.header
    return res


_registry = tf2_ros.TransformRegistration()
_registry.add(PointStamped, do_transform_point)
_registry.add(Vector3Stamped, do_transform_vector3)
_registry.add(PoseStamped, do_transform_pose)
_registry.add(PoseWithCovarianceStamped, do_transform_pose_with_covariance_stamped)
