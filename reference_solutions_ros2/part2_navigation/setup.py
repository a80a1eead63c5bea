from setuptools import find_packages, setup

package_name = 'part2_navigation'

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
    description='ROS 2 reference solutions for Part 2 (odometry and navigation)',
    license='MIT',
    entry_points={
        'console_scripts': [
            'move_circle = part2_navigation.move_circle:main',
            'move_square = part2_navigation.move_square:main',
            'odom_subscriber = part2_navigation.odom_subscriber:main',
        ],
    },
)
