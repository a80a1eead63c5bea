from launch import LaunchDescription
from launch.actions import LogInfo, RegisterEventHandler, Shutdown
from launch.event_handlers import OnProcessExit, OnShutdown
from launch_ros.actions import Node


def generate_launch_description():
    mover = Node(package='course_pkg', executable='mover', name='mover')
    return LaunchDescription([
        mover,
        RegisterEventHandler(OnProcessExit(target_action=mover, on_exit=[Shutdown(reason='mover finished')])),
        RegisterEventHandler(OnShutdown(on_shutdown=[LogInfo(msg='launch is shutting down')])),
    ])
