"""Install tf_demo as an ament_python package (colcon) or a plain pip package."""

from glob import glob

from setuptools import find_packages
from setuptools import setup

package_name = 'tf_demo'

NODES = [
    'static_tf_pub',
    'dynamic_tf_pub',
    'frame_broadcaster',
    'tf_listener',
    'odom_tf_broadcaster',
    'point_transformer',
    'robot_state_publisher',
    'joint_state_publisher',
]
TOOLS = [
    'tf_echo',
    'static_transform_publisher',
    'view_frames',
    'tf_monitor',
    'tf_doctor',
    'tf_saver',
    'tf_loader',
    'tf_demo_live',
    'tf_view',
    'tf_topic',
    'tf_record',
    'tf_plot',
    'tf_play',
]
# Upstream's names for the same tools (tf2_ros' tf2_echo and tf2_monitor).
ALIASES = {'tf2_echo': 'tf_echo', 'tf2_monitor': 'tf_monitor'}

setup(
    name=package_name,
    version='0.1.0',
    packages=find_packages(exclude=['test', 'test.*', 'bench']),
    data_files=[
        ('share/ament_index/resource_index/packages', ['resource/' + package_name]),
        ('share/' + package_name, ['package.xml']),
        ('share/' + package_name + '/launch', glob('launch/*.py')),
        ('share/' + package_name + '/config', glob('config/*')),
        ('share/' + package_name + '/urdf', glob('urdf/*')),
    ],
    package_data={'tf_demo': ['py.typed']},
    python_requires='>=3.10',
    install_requires=[
        'setuptools',
        'numpy>=1.24',
        'PyYAML>=5.4',
        'lxml',
        'yourdfpy>=0.0.56',
        'xacro',
    ],
    extras_require={
        'dds': ['cyclonedds==11.0.1'],
        # tf_view's live 3D view in the browser.
        'view': ['viser>=1.0', 'pycollada'],
        # tf_demo.bag: rosbag2 recordings (MCAP and SQLite3) without ROS; tf_plot's plots.
        'bag': ['rosbags>=0.10', 'matplotlib>=3.6', 'mcap>=1.1'],  # mcap: unfinished .mcap
        'test': [
            'cyclonedds==11.0.1',
            'pytest>=7',
            'pytest-timeout',
            'hypothesis>=6.80',
            'pin>=2.7',
            'ruff==0.17.5',
            'mypy>=1.10',
            'types-PyYAML',
            # tf_view's browser tests (with Debian's chromium and chromium-driver)
            'selenium>=4.10',
            'pillow',
            # tf_record's bags read back independently of rosbags
            'mcap',
        ],
    },
    zip_safe=True,
    maintainer='The tf_demo Authors',
    maintainer_email='tf_demo@example.com',
    description='A pure-Python tf2 that runs on rclpy or standalone over Cyclone DDS.',
    license='Apache-2.0',
    entry_points={
        'console_scripts': (
            [f'{name} = tf_demo.nodes.{name}:main' for name in NODES]
            + [f'{name} = tf_demo.cli.{name}:main' for name in TOOLS]
            + [f'{alias} = tf_demo.cli.{tool}:main' for alias, tool in ALIASES.items()]
        ),
    },
)
