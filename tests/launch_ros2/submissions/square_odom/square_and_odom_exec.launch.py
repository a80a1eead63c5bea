from launch import LaunchDescription
from launch.actions import ExecuteProcess
from launch_ros.actions import Node


def generate_launch_description():
    # The square mover as a Node, the odometry printer as a student often starts it: `ros2 run` through a shell.
    return LaunchDescription([
        Node(package='part2_navigation', executable='move_square', name='move_square', output='screen'),
        ExecuteProcess(cmd=['ros2 run part2_navigation odom_subscriber'], shell=True, output='screen'),
    ])
