from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, GroupAction, SetLaunchConfiguration, TimerAction
from launch.conditions import LaunchConfigurationNotEquals, UnlessCondition
from launch.substitutions import (AndSubstitution, EqualsSubstitution, LaunchConfiguration, NotSubstitution,
                                  PythonExpression)
from launch_ros.actions import Node, PushRosNamespace, SetParameter, SetRemap


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('robots', default_value='2'),
        DeclareLaunchArgument('world', default_value='arena'),
        SetLaunchConfiguration('speed', '0.1'),
        GroupAction(scoped=False, actions=[SetLaunchConfiguration('speed', '0.15'), SetRemap('odom', '/odom_shared')]),
        GroupAction([
            PushRosNamespace('fleet'),
            GroupAction([
                PushRosNamespace('tb3_0'),
                SetParameter('max_speed', LaunchConfiguration('speed')),
                Node(package='course_pkg', executable='follower', exec_name='leader', name='follower',
                     parameters=[{'angle': PythonExpression(['round(pi / ', LaunchConfiguration('robots'), ', 3)'])}]),
            ]),
            Node(package='course_pkg', executable='mover', namespace='tb3_1', name='mover',
                 remappings=[('cmd_vel', ['/fleet/tb3_1/', LaunchConfiguration('world'), '/cmd_vel'])]),
        ]),
        GroupAction(forwarding=False, launch_configurations={'world': 'corridor'}, actions=[
            Node(package='course_pkg', executable='talker', name='talker',
                 arguments=['--world', LaunchConfiguration('world', default='none')]),
        ]),
        Node(package='course_pkg', executable='listener', name='listener',
             condition=LaunchConfigurationNotEquals('world', 'corridor')),
        Node(package='course_pkg', executable='square', name='square',
             condition=UnlessCondition(AndSubstitution(EqualsSubstitution(LaunchConfiguration('world'), 'arena'),
                                                       NotSubstitution('false')))),
        TimerAction(period=PythonExpression(['0.1 * ', LaunchConfiguration('robots')]),
                    actions=[Node(package='course_pkg', executable='waypoints', name='late')]),
    ])
