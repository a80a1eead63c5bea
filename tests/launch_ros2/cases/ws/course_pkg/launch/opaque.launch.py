from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, OpaqueFunction
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def spawn_robots(context):
    count = int(LaunchConfiguration('count').perform(context))
    return [Node(package='course_pkg', executable='follower', name=f'follower_{i}', namespace=f'robot{i}',
                 parameters=[{'index': i, 'leader': 'robot0'}]) for i in range(count)]


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('count', default_value='2'),
        OpaqueFunction(function=spawn_robots),
    ])
