"""rospkg/roslib on a submission's catkin packages, and tf2_geometry_msgs (absent from Debian: no PyKDL), by value."""
from __future__ import annotations

import math
import sys

import pytest

import roslib
import rospkg
import rospy
import tf2_geometry_msgs
import tf2_ros
from geometry_msgs.msg import PointStamped, PoseStamped, TransformStamped, Vector3Stamped


@pytest.fixture
def workspace(tmp_path, monkeypatch):
    """A catkin src/ with two packages; the running script is inside the first one."""
    for name in ("part2_navigation", "helpers"):
        (tmp_path / "src" / name / "scripts").mkdir(parents=True)
        (tmp_path / "src" / name / "package.xml").write_text(
            f'<?xml version="1.0"?>\n<package format="2">\n  <name>{name}</name>\n</package>\n')
    monkeypatch.delenv("ROS_PACKAGE_PATH", raising=False)
    monkeypatch.setattr(sys, "argv", [str(tmp_path / "src" / "part2_navigation" / "scripts" / "move.py")])
    return tmp_path / "src"


def test_rospack_finds_the_submissions_packages(workspace):
    pack = rospkg.RosPack()
    assert pack.get_path("part2_navigation") == str(workspace / "part2_navigation")
    assert pack.get_path("helpers") == str(workspace / "helpers")
    assert pack.list() == ["helpers", "part2_navigation"]


def test_rospack_uses_ros_package_path_when_set(workspace, monkeypatch):
    monkeypatch.setenv("ROS_PACKAGE_PATH", str(workspace / "helpers"))
    assert rospkg.RosPack().list() == ["helpers"]


def test_unknown_package_is_resource_not_found_with_the_paths(workspace):
    with pytest.raises(rospkg.ResourceNotFound) as caught:
        rospkg.RosPack().get_path("nope")
    assert str(caught.value).splitlines()[0] == "nope"
    assert "ROS path [0]=" in str(caught.value)


def test_load_manifest_of_the_own_package_is_quiet(workspace):
    assert roslib.load_manifest("part2_navigation") is None


def _quarter_turn_and_shift() -> TransformStamped:
    t = TransformStamped()
    t.header.frame_id, t.header.stamp, t.child_frame_id = "odom", rospy.Time(3, 5), "base"
    t.transform.translation.x, t.transform.translation.y = 1.0, 2.0
    t.transform.rotation.z, t.transform.rotation.w = math.sin(math.pi / 4), math.cos(math.pi / 4)
    return t


def test_do_transform_point_rotates_then_translates():
    p = PointStamped()
    p.header.frame_id, p.point.x = "base", 1.0
    out = tf2_geometry_msgs.do_transform_point(p, _quarter_turn_and_shift())
    assert (out.header.frame_id, out.header.stamp) == ("odom", rospy.Time(3, 5))
    assert (out.point.x, out.point.y, out.point.z) == pytest.approx((1.0, 3.0, 0.0))


def test_do_transform_vector3_does_not_translate():
    v = Vector3Stamped()
    v.vector.x = 2.0
    out = tf2_geometry_msgs.do_transform_vector3(v, _quarter_turn_and_shift())
    assert (out.vector.x, out.vector.y) == pytest.approx((0.0, 2.0))


def test_do_transform_pose_composes_the_orientation():
    pose = PoseStamped()
    pose.pose.orientation.z, pose.pose.orientation.w = math.sin(math.pi / 4), math.cos(math.pi / 4)
    out = tf2_geometry_msgs.do_transform_pose(pose, _quarter_turn_and_shift())
    assert (out.pose.position.x, out.pose.position.y) == pytest.approx((1.0, 2.0))
    assert (out.pose.orientation.z, out.pose.orientation.w) == pytest.approx((1.0, 0.0))


def test_buffer_transform_uses_the_registered_conversion():
    buf = tf2_ros.Buffer()
    buf.set_transform(_quarter_turn_and_shift(), "test")
    p = PointStamped()
    p.header.frame_id, p.header.stamp, p.point.x = "base", rospy.Time(3, 5), 1.0
    assert (buf.transform(p, "odom").point.x, buf.transform(p, "odom").point.y) == pytest.approx((1.0, 3.0))
    with pytest.raises(tf2_ros.TypeException):
        buf.transform(_quarter_turn_and_shift(), "odom")
