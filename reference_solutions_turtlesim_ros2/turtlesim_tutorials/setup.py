from setuptools import find_packages, setup

package_name = 'turtlesim_tutorials'

setup(
    name=package_name,
    version='0.0.0',
    packages=find_packages(exclude=['test']),
    data_files=[
        ('share/ament_index/resource_index/packages', ['resource/' + package_name]),
        ('share/' + package_name, ['package.xml']),
    ],
    install_requires=['setuptools'],
    zip_safe=True,
    maintainer='rosgrade',
    maintainer_email='rosgrade@example.org',
    description='ROS 2 reference solutions for the turtlesim exercises',
    license='MIT',
    entry_points={
        'console_scripts': [
            'move = turtlesim_tutorials.move:main',
            'rotate = turtlesim_tutorials.rotate:main',
            'turtle_circle = turtlesim_tutorials.turtle_circle:main',
            'triangle = turtlesim_tutorials.triangle:main',
            'go_to_goal = turtlesim_tutorials.go_to_goal:main',
            'clean = turtlesim_tutorials.clean:main',
            'spawn_draw = turtlesim_tutorials.spawn_draw:main',
            'rotate_absolute = turtlesim_tutorials.rotate_absolute:main',
        ],
    },
)
