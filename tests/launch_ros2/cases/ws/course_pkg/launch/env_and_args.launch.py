from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import EnvironmentVariable, LaunchConfiguration
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('model', default_value=EnvironmentVariable('ROSGRADE_MODEL', default_value='waffle')),
        Node(package='course_pkg', executable='talker', name='talker',
             arguments=['--model', LaunchConfiguration('model')],
             ros_arguments=['--log-level', 'info']),
    ])
