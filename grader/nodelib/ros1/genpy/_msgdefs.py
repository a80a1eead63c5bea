"""The ROS 1 message and service definitions rosgrade's nodes can import, as comment-free .msg/.srv text.

This is data only: genpy._builder turns each entry into a class. Names without a package resolve against the
entry's own package (and ``Header`` to std_msgs/Header), as in real .msg files. Comments are left out, so each
class's ``_full_text`` is the comment-free concatenated definition (the same text the recordings carry); the md5
sums do not depend on comments and equal real ROS's.
"""
from __future__ import annotations

_STD_SCALARS = {"Bool": "bool", "Byte": "byte", "Char": "char", "Duration": "duration", "Float32": "float32",
                "Float64": "float64", "Int8": "int8", "Int16": "int16", "Int32": "int32", "Int64": "int64",
                "String": "string", "Time": "time", "UInt8": "uint8", "UInt16": "uint16", "UInt32": "uint32",
                "UInt64": "uint64"}
_MULTI_ARRAYS = {"Byte": "byte", "Float32": "float32", "Float64": "float64", "Int8": "int8", "Int16": "int16",
                 "Int32": "int32", "Int64": "int64", "UInt8": "uint8", "UInt16": "uint16", "UInt32": "uint32",
                 "UInt64": "uint64"}
_XYZ = "float64 x\nfloat64 y\nfloat64 z"
TEST_REQUEST_GOAL = ("int32 TERMINATE_SUCCESS=0\nint32 TERMINATE_ABORTED=1\nint32 TERMINATE_REJECTED=2\n"
                     "int32 TERMINATE_LOSE=3\nint32 TERMINATE_DROP=4\nint32 TERMINATE_EXCEPTION=5\n"
                     "int32 terminate_status\nbool ignore_cancel\nstring result_text\nint32 the_result\n"
                     "bool is_simple_client\nduration delay_accept\nduration delay_terminate\n"
                     "duration pause_status")


def action_messages(package: str, name: str, goal: str, result: str, feedback: str) -> dict[str, str]:
    """The seven messages genmsg generates from one .action: its three parts and the wrappers actionlib sends."""
    return {
        f"{package}/{name}Goal": goal,
        f"{package}/{name}Result": result,
        f"{package}/{name}Feedback": feedback,
        f"{package}/{name}ActionGoal": f"Header header\nactionlib_msgs/GoalID goal_id\n{name}Goal goal",
        f"{package}/{name}ActionResult": f"Header header\nactionlib_msgs/GoalStatus status\n{name}Result result",
        f"{package}/{name}ActionFeedback": f"Header header\nactionlib_msgs/GoalStatus status\n"
                                           f"{name}Feedback feedback",
        f"{package}/{name}Action": f"{name}ActionGoal action_goal\n{name}ActionResult action_result\n"
                                   f"{name}ActionFeedback action_feedback",
    }

MESSAGES: dict[str, str] = {
    **{"std_msgs/" + name: "%s data" % type_ for name, type_ in _STD_SCALARS.items()},
    **{"std_msgs/%sMultiArray" % name: "MultiArrayLayout layout\n%s[] data" % type_
       for name, type_ in _MULTI_ARRAYS.items()},
    "std_msgs/ColorRGBA": "float32 r\nfloat32 g\nfloat32 b\nfloat32 a",
    "std_msgs/Empty": "",
    "std_msgs/Header": "uint32 seq\ntime stamp\nstring frame_id",
    "std_msgs/MultiArrayDimension": "string label\nuint32 size\nuint32 stride",
    "std_msgs/MultiArrayLayout": "MultiArrayDimension[] dim\nuint32 data_offset",

    "geometry_msgs/Accel": "Vector3 linear\nVector3 angular",
    "geometry_msgs/AccelStamped": "Header header\nAccel accel",
    "geometry_msgs/AccelWithCovariance": "Accel accel\nfloat64[36] covariance",
    "geometry_msgs/AccelWithCovarianceStamped": "Header header\nAccelWithCovariance accel",
    "geometry_msgs/Inertia": "float64 m\nVector3 com\nfloat64 ixx\nfloat64 ixy\nfloat64 ixz\nfloat64 iyy\n"
                             "float64 iyz\nfloat64 izz",
    "geometry_msgs/InertiaStamped": "Header header\nInertia inertia",
    "geometry_msgs/Point": _XYZ,
    "geometry_msgs/Point32": "float32 x\nfloat32 y\nfloat32 z",
    "geometry_msgs/PointStamped": "Header header\nPoint point",
    "geometry_msgs/Polygon": "Point32[] points",
    "geometry_msgs/PolygonStamped": "Header header\nPolygon polygon",
    "geometry_msgs/Pose": "Point position\nQuaternion orientation",
    "geometry_msgs/Pose2D": "float64 x\nfloat64 y\nfloat64 theta",
    "geometry_msgs/PoseArray": "Header header\nPose[] poses",
    "geometry_msgs/PoseStamped": "Header header\nPose pose",
    "geometry_msgs/PoseWithCovariance": "Pose pose\nfloat64[36] covariance",
    "geometry_msgs/PoseWithCovarianceStamped": "Header header\nPoseWithCovariance pose",
    "geometry_msgs/Quaternion": _XYZ + "\nfloat64 w",
    "geometry_msgs/QuaternionStamped": "Header header\nQuaternion quaternion",
    "geometry_msgs/Transform": "Vector3 translation\nQuaternion rotation",
    "geometry_msgs/TransformStamped": "Header header\nstring child_frame_id\nTransform transform",
    "geometry_msgs/Twist": "Vector3 linear\nVector3 angular",
    "geometry_msgs/TwistStamped": "Header header\nTwist twist",
    "geometry_msgs/TwistWithCovariance": "Twist twist\nfloat64[36] covariance",
    "geometry_msgs/TwistWithCovarianceStamped": "Header header\nTwistWithCovariance twist",
    "geometry_msgs/Vector3": _XYZ,
    "geometry_msgs/Vector3Stamped": "Header header\nVector3 vector",
    "geometry_msgs/Wrench": "Vector3 force\nVector3 torque",
    "geometry_msgs/WrenchStamped": "Header header\nWrench wrench",

    "nav_msgs/GridCells": "Header header\nfloat32 cell_width\nfloat32 cell_height\ngeometry_msgs/Point[] cells",
    "nav_msgs/MapMetaData": "time map_load_time\nfloat32 resolution\nuint32 width\nuint32 height\n"
                            "geometry_msgs/Pose origin",
    "nav_msgs/OccupancyGrid": "Header header\nMapMetaData info\nint8[] data",
    "nav_msgs/Odometry": "Header header\nstring child_frame_id\ngeometry_msgs/PoseWithCovariance pose\n"
                         "geometry_msgs/TwistWithCovariance twist",
    "nav_msgs/Path": "Header header\ngeometry_msgs/PoseStamped[] poses",

    "sensor_msgs/BatteryState": (
        "uint8 POWER_SUPPLY_STATUS_UNKNOWN=0\nuint8 POWER_SUPPLY_STATUS_CHARGING=1\n"
        "uint8 POWER_SUPPLY_STATUS_DISCHARGING=2\nuint8 POWER_SUPPLY_STATUS_NOT_CHARGING=3\n"
        "uint8 POWER_SUPPLY_STATUS_FULL=4\nuint8 POWER_SUPPLY_HEALTH_UNKNOWN=0\nuint8 POWER_SUPPLY_HEALTH_GOOD=1\n"
        "uint8 POWER_SUPPLY_HEALTH_OVERHEAT=2\nuint8 POWER_SUPPLY_HEALTH_DEAD=3\n"
        "uint8 POWER_SUPPLY_HEALTH_OVERVOLTAGE=4\nuint8 POWER_SUPPLY_HEALTH_UNSPEC_FAILURE=5\n"
        "uint8 POWER_SUPPLY_HEALTH_COLD=6\nuint8 POWER_SUPPLY_HEALTH_WATCHDOG_TIMER_EXPIRE=7\n"
        "uint8 POWER_SUPPLY_HEALTH_SAFETY_TIMER_EXPIRE=8\nuint8 POWER_SUPPLY_TECHNOLOGY_UNKNOWN=0\n"
        "uint8 POWER_SUPPLY_TECHNOLOGY_NIMH=1\nuint8 POWER_SUPPLY_TECHNOLOGY_LION=2\n"
        "uint8 POWER_SUPPLY_TECHNOLOGY_LIPO=3\nuint8 POWER_SUPPLY_TECHNOLOGY_LIFE=4\n"
        "uint8 POWER_SUPPLY_TECHNOLOGY_NICD=5\nuint8 POWER_SUPPLY_TECHNOLOGY_LIMN=6\n"
        "Header header\nfloat32 voltage\nfloat32 temperature\nfloat32 current\nfloat32 charge\nfloat32 capacity\n"
        "float32 design_capacity\nfloat32 percentage\nuint8 power_supply_status\nuint8 power_supply_health\n"
        "uint8 power_supply_technology\nbool present\nfloat32[] cell_voltage\nfloat32[] cell_temperature\n"
        "string location\nstring serial_number"),
    "sensor_msgs/Imu": "Header header\ngeometry_msgs/Quaternion orientation\nfloat64[9] orientation_covariance\n"
                       "geometry_msgs/Vector3 angular_velocity\nfloat64[9] angular_velocity_covariance\n"
                       "geometry_msgs/Vector3 linear_acceleration\nfloat64[9] linear_acceleration_covariance",
    "sensor_msgs/JointState": "Header header\nstring[] name\nfloat64[] position\nfloat64[] velocity\n"
                              "float64[] effort",
    "sensor_msgs/LaserScan": "Header header\nfloat32 angle_min\nfloat32 angle_max\nfloat32 angle_increment\n"
                             "float32 time_increment\nfloat32 scan_time\nfloat32 range_min\nfloat32 range_max\n"
                             "float32[] ranges\nfloat32[] intensities",
    "sensor_msgs/Range": "uint8 ULTRASOUND=0\nuint8 INFRARED=1\nHeader header\nuint8 radiation_type\n"
                         "float32 field_of_view\nfloat32 min_range\nfloat32 max_range\nfloat32 range",

    "tf2_msgs/TFMessage": "geometry_msgs/TransformStamped[] transforms",

    "rosgraph_msgs/Clock": "time clock",
    "rosgraph_msgs/Log": "byte DEBUG=1\nbyte INFO=2\nbyte WARN=4\nbyte ERROR=8\nbyte FATAL=16\nHeader header\n"
                         "byte level\nstring name\nstring msg\nstring file\nstring function\nuint32 line\n"
                         "string[] topics",

    "actionlib_msgs/GoalID": "time stamp\nstring id",
    "actionlib_msgs/GoalStatus": "GoalID goal_id\nuint8 status\nuint8 PENDING=0\nuint8 ACTIVE=1\nuint8 PREEMPTED=2\n"
                                 "uint8 SUCCEEDED=3\nuint8 ABORTED=4\nuint8 REJECTED=5\nuint8 PREEMPTING=6\n"
                                 "uint8 RECALLING=7\nuint8 RECALLED=8\nuint8 LOST=9\nstring text",
    "actionlib_msgs/GoalStatusArray": "Header header\nGoalStatus[] status_list",
    # actionlib's own test actions (Debian's python3-actionlib ships their classes as actionlib.msg)
    **action_messages("actionlib", "TwoInts", "int64 a\nint64 b", "int64 sum", ""),
    **action_messages("actionlib", "Test", "int32 goal", "int32 result", "int32 feedback"),
    **action_messages("actionlib", "TestRequest", TEST_REQUEST_GOAL, "int32 the_result\nbool is_simple_server",
                      ""),

    "turtlesim/Color": "uint8 r\nuint8 g\nuint8 b",
    "turtlesim/Pose": "float32 x\nfloat32 y\nfloat32 theta\nfloat32 linear_velocity\nfloat32 angular_velocity",
}

# request and response of each service, split at the "---" line as in a .srv file
SERVICES: dict[str, str] = {
    "nav_msgs/GetMap": "---\nnav_msgs/OccupancyGrid map",
    "nav_msgs/GetPlan": "geometry_msgs/PoseStamped start\ngeometry_msgs/PoseStamped goal\nfloat32 tolerance\n---\n"
                        "nav_msgs/Path plan",
    "nav_msgs/LoadMap": "string map_url\n---\nuint8 RESULT_SUCCESS=0\nuint8 RESULT_MAP_DOES_NOT_EXIST=1\n"
                        "uint8 RESULT_INVALID_MAP_DATA=2\nuint8 RESULT_INVALID_MAP_METADATA=3\n"
                        "uint8 RESULT_UNDEFINED_FAILURE=255\nnav_msgs/OccupancyGrid map\nuint8 result",
    "nav_msgs/SetMap": "nav_msgs/OccupancyGrid map\ngeometry_msgs/PoseWithCovarianceStamped initial_pose\n---\n"
                       "bool success",
    "std_srvs/Empty": "---",
    "std_srvs/SetBool": "bool data\n---\nbool success\nstring message",
    "std_srvs/Trigger": "---\nbool success\nstring message",
    "turtlesim/Kill": "string name\n---",
    "turtlesim/SetPen": "uint8 r\nuint8 g\nuint8 b\nuint8 width\nuint8 off\n---",
    "turtlesim/Spawn": "float32 x\nfloat32 y\nfloat32 theta\nstring name\n---\nstring name",
    "turtlesim/TeleportAbsolute": "float32 x\nfloat32 y\nfloat32 theta\n---",
    "turtlesim/TeleportRelative": "float32 linear\nfloat32 angular\n---",
}
