from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    ld = LaunchDescription()
    ld.add_action(Node(package='course_pkg', executable='square', parameters=[{'side': 1.0, 'laps': 2}]))
    ld.add_action(Node(package='course_pkg', executable='listener', name='odom_logger',
                       arguments=['--log', 'odom'], remappings=[('odom', '/robot/odom')]))
    return ld
