from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='course_pkg', executable='follower', name='follower'),
        Node(package='rviz2', executable='rviz2', name='rviz2', arguments=['-d', 'view.rviz']),
    ])
