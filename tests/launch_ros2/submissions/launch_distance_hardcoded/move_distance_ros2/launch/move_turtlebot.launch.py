from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    # Flawed: the seed's 3 m is written into the node's arguments; no distance argument is declared, so
    # `ros2 launch ... distance:=2` changes nothing.
    return LaunchDescription([
        Node(package='move_distance_ros2', executable='move_turtlebot', output='screen',
             arguments=['0.2', '0', '3']),
    ])
