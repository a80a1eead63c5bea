from setuptools import find_packages, setup

package_name = 'part3_kai'

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
    maintainer='kai',
    maintainer_email='kai@example.org',
    description='Part 3 LiDAR exercises',
    license='MIT',
    entry_points={
        'console_scripts': [
            'lidar_distance = part3_kai.lidar_distance:main',
        ],
    },
)
