from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def generate_launch_description():
    distance = LaunchConfiguration('distance')
    return LaunchDescription([
        DeclareLaunchArgument('distance', default_value='1.0', description='How far to drive (m)'),
        DeclareLaunchArgument('speed', default_value='0.15'),
        Node(package='course_pkg', executable='mover', name='mover', output='screen',
             parameters=[{'distance': distance, 'speed': LaunchConfiguration('speed'), 'frame': 'odom'}]),
    ])
