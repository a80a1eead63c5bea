from glob import glob

from setuptools import setup

package_name = 'course_pkg'
setup(
    name=package_name,
    packages=[package_name],
    data_files=[('share/ament_index/resource_index/packages', ['resource/' + package_name]),
                ('share/' + package_name, ['package.xml']),
                ('share/' + package_name + '/launch', glob('launch/*')),
                ('share/' + package_name + '/config', glob('config/*'))],
    entry_points={'console_scripts': [
        'mover = course_pkg.nodes:main',
        'square = course_pkg.nodes:main',
        'follower = course_pkg.nodes:main',
        'beacon_search = course_pkg.nodes:main',
        'figure_of_eight = course_pkg.nodes:main',
        'waypoints = course_pkg.nodes:main',
        'wall_follower = course_pkg.nodes:main',
        'talker = course_pkg.nodes:main',
        'listener = course_pkg.nodes:main',
    ]},
)
