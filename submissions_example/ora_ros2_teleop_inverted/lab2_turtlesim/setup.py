import os
from glob import glob

from setuptools import find_packages, setup

package_name = 'lab2_turtlesim'

setup(
    name=package_name,
    version='0.0.0',
    packages=find_packages(exclude=['test']),
    data_files=[
        ('share/ament_index/resource_index/packages', ['resource/' + package_name]),
        ('share/' + package_name, ['package.xml']),
        (os.path.join('share', package_name, 'launch'), glob(os.path.join('launch', '*launch.[pxy][yma]*'))),
    ],
    install_requires=['setuptools'],
    zip_safe=True,
    maintainer='rosgrade',
    maintainer_email='rosgrade@example.org',
    description='ROS 2 reference for the turtlesim launch exercise: turtlesim with keyboard teleop or pubvel',
    license='MIT',
    entry_points={
        'console_scripts': [
            'pubvel = lab2_turtlesim.pubvel:main',
        ],
    },
)
