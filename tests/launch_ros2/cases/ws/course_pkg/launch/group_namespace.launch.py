from launch import LaunchDescription
from launch.actions import GroupAction
from launch_ros.actions import Node, PushRosNamespace, SetParameter, SetRemap


def generate_launch_description():
    return LaunchDescription([
        SetParameter(name='use_sim_time', value=True),
        GroupAction([
            PushRosNamespace('robot1'),
            SetRemap(src='cmd_vel', dst='cmd_vel_safe'),
            Node(package='course_pkg', executable='mover', name='mover'),
            Node(package='course_pkg', executable='follower', namespace='inner', name='follower'),
        ]),
        Node(package='course_pkg', executable='mover', name='mover_outside'),
    ])
