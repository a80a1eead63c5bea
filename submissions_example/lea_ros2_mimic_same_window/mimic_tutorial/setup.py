import os
from glob import glob

from setuptools import setup

package_name = 'mimic_tutorial'

setup(
    name=package_name,
    version='0.0.1',
    packages=[package_name],
    data_files=[
        ('share/ament_index/resource_index/packages', ['resource/' + package_name]),
        ('share/' + package_name, ['package.xml']),
        (os.path.join('share', package_name, 'launch'), glob('launch/*launch.[pxy][yma]*')),
    ],
    install_requires=['setuptools'],
    zip_safe=True,
    maintainer='Lea',
    maintainer_email='lea@example.com',
    description='The ROS 2 launch tutorial: two turtlesims and mimic',
    license='Apache-2.0',
)
