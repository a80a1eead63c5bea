from setuptools import find_packages, setup

package_name = 'part3_lidar'

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
    description='ROS 2 reference solutions for the LiDAR tasks',
    license='MIT',
    entry_points={
        'console_scripts': [
            'obstacle_stop = part3_lidar.obstacle_stop:main',
            'lidar_distance = part3_lidar.lidar_distance:main',
            'obstacle_avoidance = part3_lidar.obstacle_avoidance:main',
            'wall_follower = part3_lidar.wall_follower:main',
        ],
    },
)
