from setuptools import find_packages, setup

package_name = 'py_srvcli'

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
    description='ROS 2 reference solution for the service tutorial (AddTwoInts server and client)',
    license='MIT',
    entry_points={
        'console_scripts': [
            'add_two_ints_server = py_srvcli.add_two_ints_server:main',
            'add_two_ints_client = py_srvcli.add_two_ints_client:main',
        ],
    },
)
