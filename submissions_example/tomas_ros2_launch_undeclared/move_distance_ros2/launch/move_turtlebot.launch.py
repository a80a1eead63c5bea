from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node
from launch_ros.parameter_descriptions import ParameterValue


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('distance', default_value='3.0'),
        Node(package='move_distance_ros2', executable='move_turtlebot', output='screen',
             parameters=[{'distance': ParameterValue(LaunchConfiguration('distance'), value_type=float),
                          'speed': ParameterValue(LaunchConfiguration('speed'), value_type=float)}]),
    ])
