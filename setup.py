"""
Install tf_demo as an ament_python package (colcon) or a plain pip package.

The hot modules (``tf_demo/build_info.py``'s ``COMPILED_MODULES``) are compiled to C extensions
by mypyc (part of mypy) when mypyc and a C compiler with Python's headers are there; otherwise,
or with ``TF_DEMO_INTERPRETED=1``, the same source installs interpreted and one line says so.
"""

from glob import glob
import os
import runpy
import shutil
import sys

from setuptools import Extension
from setuptools import find_packages
from setuptools import setup
from setuptools.command.build_ext import build_ext

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
    'tf_relay',
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

HERE = os.path.dirname(os.path.abspath(__file__))
BUILD_INFO = runpy.run_path(os.path.join(HERE, 'tf_demo', 'build_info.py'))
INTERPRETED_VARIABLE = BUILD_INFO['INTERPRETED_ENVIRONMENT_VARIABLE']
#: mypyc's group: its shared library is `tf_demo__mypyc` (one per interpreter and platform).
MYPYC_GROUP = 'tf_demo.compiled'


def _say(text: str) -> None:
    print(f'tf_demo: {text}', file=sys.stderr, flush=True)


def _interpreted_reason() -> str | None:
    """Return why this build is interpreted, or None when mypyc can compile it."""
    if os.environ.get(INTERPRETED_VARIABLE, '') not in ('', '0'):
        return f'{INTERPRETED_VARIABLE} is set'
    try:
        import mypyc.build  # noqa: F401
    except ImportError:
        return 'mypyc (pip install mypy) is not installed'
    import sysconfig

    compiler = (sysconfig.get_config_var('CC') or 'cc').split()[0]
    if shutil.which(compiler) is None:
        return f'no C compiler ({compiler}) on PATH'
    include = sysconfig.get_paths()['include']
    if not os.path.exists(os.path.join(include, 'Python.h')):
        return f"Python's C headers are missing ({include}/Python.h: install python3-dev)"
    return None


class BuildExt(build_ext):
    """build_ext that compiles the hot modules with mypyc, or installs them interpreted."""

    def finalize_options(self) -> None:
        # mypycify type-checks the package: do it only when extensions are really built.
        reason = _interpreted_reason()
        if reason is None:
            from mypyc.build import mypycify

            paths = [
                os.path.relpath(os.path.join(HERE, *name.split('.')) + '.py')
                for name in BUILD_INFO['COMPILED_MODULES']
            ]
            try:
                self.distribution.ext_modules = mypycify(
                    [
                        '--follow-imports=silent',
                        '--ignore-missing-imports',
                        '--no-warn-unused-configs',
                        *paths,
                    ],
                    opt_level='3',
                    group_name=MYPYC_GROUP,
                    # the generated C, beside the rest of this build's temporary files
                    target_dir=os.path.join(
                        self.get_finalized_command('build').build_base, 'mypyc'
                    ),
                )
            except SystemExit:  # mypyc printed the type errors it cannot compile
                reason = 'mypyc refused the package (its errors are above)'
            except Exception as error:
                reason = f'mypyc could not compile the package ({error})'
        if reason is not None:
            self.distribution.ext_modules = []
            self._interpreted = reason
        else:
            self._interpreted = None
        super().finalize_options()

    def run(self) -> None:
        if self.inplace:
            _remove_stray_extensions()
        if self._interpreted is not None:
            _say(f'installing interpreted: {self._interpreted}')
            return
        try:
            super().run()
        except Exception as error:  # compiler or linker failed: fall back, whole
            for output in self.get_outputs():
                if os.path.exists(output):
                    os.remove(output)
            _say(f'installing interpreted: the C build failed ({error})')
            return
        # Newer than the sources, even where the C did not change and nothing was recompiled
        # (tf_demo/build_info.py's stale_modules compares the times).
        for extension in self.extensions:
            path = self.get_ext_fullpath(extension.name)
            if os.path.exists(path):
                os.utime(path)
        _say(f'compiled {len(BUILD_INFO["COMPILED_MODULES"])} modules with mypyc')


def _remove_stray_extensions() -> None:
    """Delete in-place extensions of modules no longer compiled (they would shadow the source)."""
    compiled = {name.replace('.', os.sep) for name in BUILD_INFO['COMPILED_MODULES']}
    for path in glob(os.path.join(HERE, 'tf_demo', '**', '*.*.so'), recursive=True):
        module = os.path.relpath(path, HERE).split('.', 1)[0]
        if module not in compiled and not module.endswith('__mypyc'):
            os.remove(path)
            _say(f'removed {os.path.relpath(path, HERE)}: that module is no longer compiled')


def _ext_modules() -> list[Extension]:
    """A placeholder that makes setuptools run build_ext (and tag a platform wheel)."""
    if os.environ.get(INTERPRETED_VARIABLE, '') not in ('', '0'):
        return []
    return [Extension(f'{MYPYC_GROUP}__mypyc_placeholder', sources=[])]


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
    ext_modules=_ext_modules(),
    cmdclass={'build_ext': BuildExt},
    python_requires='>=3.10',
    # What tools/other_pythons.sh and the suite test (README, "Pythons and platforms").
    classifiers=[
        'Programming Language :: Python :: 3',
        'Programming Language :: Python :: 3 :: Only',
        'Programming Language :: Python :: 3.10',
        'Programming Language :: Python :: 3.11',
        'Programming Language :: Python :: 3.12',
        'Programming Language :: Python :: 3.13',
        'Programming Language :: Python :: Implementation :: CPython',
        'Operating System :: POSIX :: Linux',
        'Typing :: Typed',
    ],
    install_requires=[
        'setuptools',
        'numpy>=1.21',
        'PyYAML>=5.4',
        'lxml',
        'yourdfpy>=0.0.56',
        'xacro',
        # mypyc_attr: BufferCore stays open to subclasses when compiled (a no-op otherwise).
        'mypy_extensions>=1.0',
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
            # test_wheel: the sdist and the wheel, built as a user builds them
            'build',
            'wheel',
        ],
        # the documentation site (doc/conf.py), built by test/test_docs.py
        'docs': ['sphinx>=7.2', 'furo', 'myst-parser>=2'],
    },
    zip_safe=False,
    maintainer='The tf_demo Authors',
    maintainer_email='tf_demo@example.com',
    description='A typed-Python tf2 (mypyc-compiled where it can be) on rclpy or standalone DDS.',
    license='Apache-2.0',
    entry_points={
        'console_scripts': (
            [f'{name} = tf_demo.nodes.{name}:main' for name in NODES]
            + [f'{name} = tf_demo.cli.{name}:main' for name in TOOLS]
            + [f'{alias} = tf_demo.cli.{tool}:main' for alias, tool in ALIASES.items()]
        ),
    },
)
