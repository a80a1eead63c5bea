from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('robot_name'),
        DeclareLaunchArgument('rate', default_value='10'),
        Node(package='course_pkg', executable='talker', name=LaunchConfiguration('robot_name'),
             parameters=[{'rate': LaunchConfiguration('rate')}]),
    ])
