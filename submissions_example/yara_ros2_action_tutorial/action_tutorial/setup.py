from setuptools import find_packages, setup

package_name = 'action_tutorial'

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
    description='The action tutorial server on its own interface',
    license='MIT',
    entry_points={
        'console_scripts': [
            'fibonacci_action_server = action_tutorial.fibonacci_action_server:main',
        ],
    },
)
