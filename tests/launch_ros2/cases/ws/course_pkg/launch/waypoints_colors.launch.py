from launch import LaunchDescription
from launch.substitutions import PathJoinSubstitution
from launch_ros.actions import Node
from launch_ros.substitutions import FindPackageShare


def generate_launch_description():
    colors = PathJoinSubstitution([FindPackageShare('course_pkg'), 'config', 'colors.yaml'])
    return LaunchDescription([
        Node(package='turtlesim', executable='turtlesim_node', name='roving_turtle', parameters=[colors]),
        Node(package='course_pkg', executable='waypoints', name='waypoints',
             parameters=[{'tolerance': 0.05, 'waypoints': [1.4, 1.6, 2.2, 9.4]}, colors]),
    ])
