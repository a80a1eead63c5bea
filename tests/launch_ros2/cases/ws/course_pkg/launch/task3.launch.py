from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('target_beacon', description='The colour of the beacon to find',
                              choices=['yellow', 'red', 'green', 'blue']),
        Node(package='course_pkg', executable='beacon_search', name='beacon_search',
             parameters=[{'target_colour': LaunchConfiguration('target_beacon')}]),
    ])
