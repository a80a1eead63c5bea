from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node
from launch_ros.parameter_descriptions import ParameterValue


def generate_launch_description():
    # distance:=2 would reach the node as the integer 2, and a parameter declared as a float refuses an integer:
    # value_type=float keeps it a float whatever the user types.
    distance = ParameterValue(LaunchConfiguration('distance'), value_type=float)
    return LaunchDescription([
        DeclareLaunchArgument('distance', default_value='3.0', description='Where to stop along x (m)'),
        Node(package='move_distance_param', executable='move_turtlebot', name='mover', output='screen',
             parameters=[{'distance': distance, 'speed': 0.2}]),
    ])
