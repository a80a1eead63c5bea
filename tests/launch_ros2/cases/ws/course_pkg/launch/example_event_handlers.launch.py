from launch import LaunchDescription
from launch.actions import ExecuteProcess, LogInfo, RegisterEventHandler
from launch.event_handlers import OnProcessExit, OnProcessStart
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def generate_launch_description():
    sim = Node(package='turtlesim', namespace='turtlesim1', executable='turtlesim_node', name='sim')
    spawn = ExecuteProcess(cmd=['ros2', 'service', 'call', '/turtlesim1/spawn', 'turtlesim/srv/Spawn',
                                '{x: 2, y: 2, theta: 0.2}'])
    change = ExecuteProcess(cmd=['ros2', 'param', 'set', '/turtlesim1/sim', 'background_r', '120'])
    return LaunchDescription([
        sim,
        RegisterEventHandler(OnProcessStart(target_action=sim, on_start=[
            LogInfo(msg='Turtlesim started, spawning turtle'), spawn])),
        RegisterEventHandler(OnProcessExit(target_action=spawn, on_exit=[
            LogInfo(msg='Spawn finished'), change])),
    ])
