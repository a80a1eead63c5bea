from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, LogInfo
from launch.conditions import IfCondition, LaunchConfigurationEquals, UnlessCondition
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('use_follower', default_value='true'),
        DeclareLaunchArgument('mode', default_value='square'),
        Node(package='course_pkg', executable='follower', condition=IfCondition(LaunchConfiguration('use_follower'))),
        Node(package='course_pkg', executable='mover', condition=UnlessCondition(LaunchConfiguration('use_follower'))),
        Node(package='course_pkg', executable='square', condition=LaunchConfigurationEquals('mode', 'square')),
        LogInfo(msg=['mode is ', LaunchConfiguration('mode')]),
    ])
