from launch import LaunchDescription
from launch.substitutions import Command, PathJoinSubstitution
from launch_ros.actions import Node
from launch_ros.parameter_descriptions import ParameterValue
from launch_ros.substitutions import FindPackageShare


def generate_launch_description():
    urdf = PathJoinSubstitution([FindPackageShare('course_pkg'), 'config', 'robot.urdf'])
    description = ParameterValue(Command(['cat ', urdf]), value_type=str)
    return LaunchDescription([
        Node(package='course_pkg', executable='talker', name='description_publisher',
             parameters=[{'robot_description': description}]),
    ])
