from setuptools import find_packages, setup

package_name = 'com2009_sam'

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
    maintainer='sam',
    maintainer_email='sam@example.org',
    description='Part 2 exercises',
    license='TODO: License declaration',
    entry_points={
        'console_scripts': [
            'move_circle = com2009_sam.move_circle:main',
        ],
    },
)
