from launch import LaunchDescription
from launch.actions import ExecuteProcess, RegisterEventHandler, TimerAction
from launch.event_handlers import OnProcessStart
from launch_ros.actions import Node


def generate_launch_description():
    # As the ROS 2 launch tutorials do: turtlesim, a node, and the ros2 command line against turtlesim.
    sim = Node(package='turtlesim', executable='turtlesim_node', name='sim')
    spawn = ExecuteProcess(cmd=[['ros2 service call /spawn turtlesim/srv/Spawn ',
                                 '"{x: 2.0, y: 2.0, theta: 0.0, name: \'turtle2\'}"']], shell=True)
    return LaunchDescription([
        sim,
        Node(package='turtle_tutorial', executable='turtle_circle', output='screen'),
        RegisterEventHandler(OnProcessStart(target_action=sim, on_start=[spawn])),
        TimerAction(period=1.0, actions=[
            ExecuteProcess(cmd=['ros2', 'service', 'call', '/turtle2/teleport_absolute',
                                'turtlesim/srv/TeleportAbsolute', '{x: 5.0, y: 5.0, theta: 0.0}'])]),
    ])
