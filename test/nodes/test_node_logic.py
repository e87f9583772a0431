# Copyright 2026 The tf_demo Authors
#
# Licensed under the Apache License, Version 2.0 (the "License");
# you may not use this file except in compliance with the License.
# You may obtain a copy of the License at
#
#     http://www.apache.org/licenses/LICENSE-2.0
#
# Unless required by applicable law or agreed to in writing, software
# distributed under the License is distributed on an "AS IS" BASIS,
# WITHOUT WARRANTIES OR CONDITIONS OF ANY KIND, either express or implied.
# See the License for the specific language governing permissions and
# limitations under the License.

"""Pure logic of the tutorial nodes: config parsing, the circle, formatters, launch files."""

from __future__ import annotations

import ast
import math
from pathlib import Path
import re

import pytest
from tf_demo.msgs import geometry_msgs
from tf_demo.msgs import nav_msgs
from tf_demo.nodes.dynamic_tf_pub import circle_transform
from tf_demo.nodes.odom_tf_broadcaster import transform_from_odometry
from tf_demo.nodes.point_transformer import format_point
from tf_demo.nodes.static_tf_pub import format_published
from tf_demo.nodes.static_tf_pub import load_specs_file
from tf_demo.nodes.static_tf_pub import spec_from_values
from tf_demo.nodes.static_tf_pub import specs_from_yaml
from tf_demo.nodes.static_tf_pub import StaticTransformSpec
from tf_demo.nodes.tf_listener import format_failure
from tf_demo.nodes.tf_listener import format_translation
from tf_demo.ros.node_helpers import make_transform_stamped
from tf_demo.ros.node_helpers import NodeConfigError
import yaml

REPO = Path(__file__).resolve().parents[2]


def test_rep105_example_file_parses_to_three_static_transforms() -> None:
    """config/rep105_static_transforms.yaml: base_footprint->base_link->{lidar,camera}."""
    specs = load_specs_file(str(REPO / 'config' / 'rep105_static_transforms.yaml'))
    assert [(s.parent, s.child) for s in specs] == [
        ('base_footprint', 'base_link'),
        ('base_link', 'lidar_link'),
        ('base_link', 'camera_link'),
    ]
    assert specs[2].translation == (0.5, 0.0, 0.2)
    assert specs[2].rotation == (0.0, 0.0, 0.0, 1.0)


def test_rotation_accepts_rpy_and_normalises_quaternions() -> None:
    """Three numbers are roll/pitch/yaw (tf2 setRPY); four are a quaternion, normalised."""
    rpy = spec_from_values('a', 'b', [0, 0, 0], [0.1, 0.2, 0.3])
    assert rpy.rotation == pytest.approx((0.034270799, 0.106020511, 0.143572175, 0.983347443))
    quat = spec_from_values('a', 'b', [0, 0, 0], [0.0, 0.0, 2.0, 2.0])
    assert quat.rotation == pytest.approx((0.0, 0.0, math.sqrt(0.5), math.sqrt(0.5)))


@pytest.mark.parametrize(
    ('text', 'message'),
    [
        ('transforms: [', r'<f>: line \d+ is not valid YAML'),
        ('frames: []', "<f>: expected a mapping with a 'transforms' list"),
        ('transforms: []', '<f>: the transforms list is empty'),
        (
            'transforms: [{parent: a, translation: [0, 0, 0]}]',
            r"transforms\[0\] is missing 'child'",
        ),
        (
            'transforms: [{parent: a, child: b, translation: [0, 0]}]',
            r'transforms\[0\] translation must be 3 numbers \[x, y, z\], got \[0, 0\]',
        ),
        (
            'transforms: [{parent: a, child: b, translation: [0, 0, 0], rotation: [1, 2]}]',
            r'transforms\[0\] rotation must be 3 numbers \[roll, pitch, yaw\] or 4',
        ),
        (
            'transforms: [{parent: a, child: b, translation: [0, 0, 0], rotation: [0, 0, 0, 0]}]',
            'quaternion .* must not be zero',
        ),
        ('transforms: [{parent: /a, child: b, translation: [0, 0, 0]}]', "cannot start with '/'"),
        ('transforms: [{parent: a, child: a, translation: [0, 0, 0]}]', "both 'a'"),
        (
            'transforms: [{parent: a, child: b, translation: [0, 0, 0]},'
            ' {parent: a, child: b, translation: [1, 0, 0]}]',
            r"transforms\[1\]: child frame 'b' appears twice",
        ),
        (
            'transforms: [{parent: a, child: b, translation: [0, 0, 0], scale: 2}]',
            r'transforms\[0\] has unknown key\(s\) scale',
        ),
        ('transforms: [{parent: a, child: b, translation: [.nan, 0, 0]}]', 'finite'),
    ],
)
def test_bad_transform_files_give_one_line_errors(text: str, message: str) -> None:
    """Every invalid file is refused with one line naming the file, entry and field."""
    with pytest.raises(NodeConfigError, match=message.replace('<f>', 'f.yaml')) as info:
        specs_from_yaml(text, 'f.yaml')
    assert '\n' not in str(info.value)


def test_format_published_lists_every_transform() -> None:
    """The start-up log line lists parent -> child with translation and rotation."""
    text = format_published([StaticTransformSpec('a', 'b', (0.5, 0.0, 0.2), (0, 0, 0, 1.0))])
    assert text == (
        'Publishing 1 static transform(s) on /tf_static:\n'
        '  a -> b: translation (0.5, 0, 0.2), rotation (0, 0, 0, 1)'
    )


def test_circle_transform_matches_the_course_formula() -> None:
    """x = r cos t, y = r sin t, rotation (0, 0, sin(t/2), cos(t/2)) with t the stamp in s."""
    translation, rotation = circle_transform(2.0, 1_500_000_000)
    assert translation == (2.0 * math.cos(1.5), 2.0 * math.sin(1.5), 0.0)
    assert rotation == (0.0, 0.0, math.sin(0.75), math.cos(0.75))


def test_listener_formatters() -> None:
    """The listener logs the translation, or the course's warning with the reason."""
    t = make_transform_stamped(
        'odom', 'camera_link', 1_250_000_000, (1.0, -2.0, 0.25), (0, 0, 0, 1)
    )
    assert format_translation('odom', 'camera_link', t) == (
        'Transform odom <- camera_link at 1.250000: translation x=1.000, y=-2.000, z=0.250'
    )
    assert format_failure('odom', 'camera_link', 'no frame') == (
        'Could not transform odom to camera_link: no frame'
    )


def test_point_formatter() -> None:
    """The point transformer logs the point in both frames."""
    a = geometry_msgs.PointStamped()
    a.point.x = 1.0
    b = geometry_msgs.PointStamped()
    b.point.x, b.point.y = 2.0, 3.5
    assert format_point('base_link', 'map', a, b) == (
        'Point (1.000, 0.000, 0.000) in base_link is (2.000, 3.500, 0.000) in map'
    )


def test_odometry_becomes_a_transform_with_its_own_stamp_and_frames() -> None:
    """Stamp, frames, position and orientation are copied; empty frames use the defaults."""
    odom = nav_msgs.Odometry()
    odom.header.stamp.sec, odom.header.stamp.nanosec = 12, 345
    odom.header.frame_id = 'odom'
    odom.child_frame_id = 'base_footprint'
    odom.pose.pose.position.x, odom.pose.pose.position.y = 1.0, 2.0
    q = odom.pose.pose.orientation
    q.z, q.w = math.sqrt(0.5), math.sqrt(0.5)
    t = transform_from_odometry(odom, geometry_msgs.TransformStamped, 'o', 'b')
    assert (t.header.stamp.sec, t.header.stamp.nanosec) == (12, 345)
    assert (t.header.frame_id, t.child_frame_id) == ('odom', 'base_footprint')
    assert (t.transform.translation.x, t.transform.translation.y) == (1.0, 2.0)
    assert t.transform.rotation.z == math.sqrt(0.5)
    odom.header.frame_id = odom.child_frame_id = ''
    t = transform_from_odometry(odom, geometry_msgs.TransformStamped, 'o', 'b')
    assert (t.header.frame_id, t.child_frame_id) == ('o', 'b')


@pytest.mark.parametrize('name', ['tf_demo.launch.py', 'rep105.launch.py'])
def test_launch_files_parse_and_define_generate_launch_description(name: str) -> None:
    """The launch files are valid Python with generate_launch_description() (run inside ROS)."""
    tree = ast.parse((REPO / 'launch' / name).read_text(encoding='utf-8'))
    functions = {n.name for n in tree.body if isinstance(n, ast.FunctionDef)}
    assert 'generate_launch_description' in functions
    executables = {
        kw.value.value
        for node in ast.walk(tree)
        if isinstance(node, ast.Call)
        for kw in node.keywords
        if kw.arg == 'executable' and isinstance(kw.value, ast.Constant)
    }
    assert {'static_tf_pub', 'dynamic_tf_pub', 'rviz2'} <= executables


def test_mobile_robot_launch_runs_rsp_on_the_xacro_with_jsp_and_odometry() -> None:
    """mobile_robot.launch.py: RSP on urdf/mobile_robot.urdf.xacro, JSP, odom -> base_footprint."""
    tree = ast.parse((REPO / 'launch' / 'mobile_robot.launch.py').read_text(encoding='utf-8'))
    functions = {n.name for n in tree.body if isinstance(n, ast.FunctionDef)}
    assert 'generate_launch_description' in functions
    keywords = {
        (kw.arg, kw.value.value)
        for node in ast.walk(tree)
        if isinstance(node, ast.Call)
        for kw in node.keywords
        if isinstance(kw.value, ast.Constant)
    }
    executables = {value for arg, value in keywords if arg == 'executable'}
    assert {'robot_state_publisher', 'joint_state_publisher', 'dynamic_tf_pub'} <= executables
    constants = {n.value for n in ast.walk(tree) if isinstance(n, ast.Constant)}
    assert {'mobile_robot.urdf.xacro', 'odom', 'base_footprint'} <= constants
    assert (REPO / 'urdf' / 'mobile_robot.urdf.xacro').is_file()


def test_rviz_config_shows_tf_with_fixed_frame_odom() -> None:
    """config/tf_demo.rviz: a TF display and the fixed frame odom."""
    config = yaml.safe_load((REPO / 'config' / 'tf_demo.rviz').read_text(encoding='utf-8'))
    manager = config['Visualization Manager']
    assert manager['Global Options']['Fixed Frame'] == 'odom'
    assert 'rviz_default_plugins/TF' in [d['Class'] for d in manager['Displays']]


@pytest.mark.parametrize(
    ('translation', 'shown'),
    [
        (f'[{"9" * 400}, 0, 0]', '<an integer of about 40'),
        (f'[1, {"9" * 5000}, 0]', 'a value cannot be converted (Exceeds the limit (4300 digits)'),
        ('[1.0e+400, 0, 0]', 'inf'),
        ('[.nan, 0, 0]', 'nan'),
    ],
)
def test_a_transforms_file_with_a_huge_or_non_finite_number_is_one_line(
    translation: str, shown: str
) -> None:
    """A 400-digit integer in a translation is refused like inf: the entry named, no traceback."""
    text = f'transforms: [{{parent: a, child: b, translation: {translation}}}]\n'
    with pytest.raises(NodeConfigError) as caught:
        specs_from_yaml(text, 'huge.yaml')
    message = str(caught.value)
    assert message.startswith('huge.yaml:'), message
    assert shown in message
    assert len(message) < 400
    assert '\n' not in message


@pytest.mark.parametrize(
    ('name', 'value', 'problem'),
    [
        ('rate', 1e-300, 'is too small: the period 1/rate must be at most 9223372036 s'),
        ('rate', 0.0, 'must be a positive finite number of Hz'),
        ('rate', math.inf, 'must be finite'),
        ('period', 1e300, 'must be at most 9223372036 s'),
        ('period', -1.0, 'must be > 0'),
    ],
)
def test_timer_rates_and_periods_a_timer_cannot_hold_are_one_line(
    name: str, value: float, problem: str
) -> None:
    """A rate of 1e-300 Hz (a period beyond int64 ns) is refused before a timer is made."""
    from tf_demo.ros.node_helpers import as_period_s
    from tf_demo.ros.node_helpers import as_rate_hz

    check = as_rate_hz if name == 'rate' else as_period_s
    with pytest.raises(NodeConfigError, match=re.escape(problem)):
        check(name, value)


@pytest.mark.parametrize('node', ['dynamic_tf_pub', 'tf_listener', 'joint_state_publisher'])
def test_a_node_given_a_timer_it_cannot_run_exits_1_with_one_line(
    node: str, world_env: dict[str, str]
) -> None:
    """``-p rate:=1e-300`` (or ``period:=1e300``): exit 1, one line naming it, no traceback."""
    import subprocess

    from conftest import executable_command

    parameter = 'period:=1e300' if node == 'tf_listener' else 'rate:=1e-300'
    completed = subprocess.run(
        executable_command(node, '--ros-args', '-p', parameter),
        env=world_env,
        capture_output=True,
        text=True,
        timeout=60,
        check=False,
    )
    assert completed.returncode == 1, completed.stderr
    assert 'Traceback' not in completed.stderr, completed.stderr
    assert completed.stderr.strip().count('\n') == 0, completed.stderr
    assert parameter.split(':=')[0] in completed.stderr
