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

"""Loading xacro files without ROS: arguments, $(find pkg), package:// includes, clear errors."""

from __future__ import annotations

import os
from pathlib import Path
import re

import pytest
from tf_demo.urdf import find_package_share
from tf_demo.urdf import parse_xacro_args
from tf_demo.urdf import resolve_resource
from tf_demo.urdf import RobotModel
from tf_demo.urdf import UrdfBrokenRefError
from tf_demo.urdf import UrdfError
from tf_demo.urdf import UrdfMalformedError

SAMPLES = Path(__file__).resolve().parents[2] / 'urdf'
XACRO_NS = 'xmlns:xacro="http://www.ros.org/wiki/xacro"'


def test_mobile_robot_has_rep105_frames_and_two_wheels() -> None:
    """The sample xacro expands to base_footprint -> base_link with wheels, lidar and camera."""
    model = RobotModel.from_file(SAMPLES / 'mobile_robot.urdf.xacro')
    assert model.root == 'base_footprint'
    assert model.movable_joints == ['left_wheel_joint', 'right_wheel_joint']
    assert all(model.joint(j).type == 'continuous' for j in model.movable_joints)
    children = {child: parent for parent, child, _, _ in model.static_transforms()}
    assert children == {
        'base_link': 'base_footprint',
        'lidar_link': 'base_link',
        'camera_link': 'base_link',
    }
    wheels = {c: t for _, c, t, _ in model.joint_transforms({'left_wheel_joint': 0.0})}
    assert wheels == {'left_wheel_link': (0.0, 0.15, 0.0)}


def test_xacro_mappings_change_the_robot() -> None:
    """Arguments as mappings: prefix renames every frame, wheel_radius lifts the base."""
    model = RobotModel.from_file(
        SAMPLES / 'mobile_robot.urdf.xacro', {'prefix': 'r1/', 'wheel_radius': '0.2'}
    )
    assert model.root == 'r1/base_footprint'
    base = [t for _, c, t, _ in model.static_transforms() if c == 'r1/base_link']
    assert base == [(0.0, 0.0, 0.2)]


def test_xacro_args_are_parsed_like_the_command_line() -> None:
    """'a:=1 b:=x' becomes a mapping; a word without := is refused with its text."""
    assert parse_xacro_args('prefix:=r1/ wheel_radius:=0.1') == {
        'prefix': 'r1/',
        'wheel_radius': '0.1',
    }
    with pytest.raises(ValueError, match="xacro argument 'oops' is not of the form name:=value"):
        parse_xacro_args('oops')


def write_xacro(path: Path, body: str) -> Path:
    """Write a xacro file: robot ``r`` (with the xacro namespace) holding ``body``."""
    path.write_text(f'<robot name="r" {XACRO_NS}>\n{body}\n</robot>\n', encoding='utf-8')
    return path


def write_package(root: Path, name: str, files: dict[str, str]) -> Path:
    share = root / name
    for relative, text in files.items():
        path = share / relative
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text)
    return share


PARTS = f"""<robot {XACRO_NS}>
  <xacro:macro name="arm" params="parent">
    <link name="arm_link"/>
    <joint name="arm_joint" type="fixed">
      <parent link="${{parent}}"/><child link="arm_link"/><origin xyz="0 0 0.5"/>
    </joint>
  </xacro:macro>
</robot>
"""
#: A robot that includes parts.xacro through $(find parts_pkg) and uses its arm macro.
USES_PARTS = (
    '<xacro:include filename="$(find parts_pkg)/urdf/parts.xacro"/>'
    '<link name="base"/><xacro:arm parent="base"/>'
)


def test_find_and_package_include_resolve_through_package_paths(tmp_path: Path) -> None:
    """$(find pkg) and package://pkg/... in xacro:include resolve via package_paths."""
    write_package(tmp_path / 'pkgs', 'parts_pkg', {'urdf/parts.xacro': PARTS})
    main = tmp_path / 'robot.urdf.xacro'
    main.write_text(
        f"""<robot name="r" {XACRO_NS}>
  <xacro:include filename="package://parts_pkg/urdf/parts.xacro"/>
  <xacro:property name="share" value="$(find parts_pkg)"/>
  <link name="base" type="${{share}}"/>
  <xacro:arm parent="base"/>
</robot>
"""
    )
    model = RobotModel.from_file(main, package_paths=[tmp_path / 'pkgs'])
    assert model.static_transforms() == [
        ('base', 'arm_link', (0.0, 0.0, 0.5), (0.0, 0.0, 0.0, 1.0))
    ]
    assert f'type="{tmp_path / "pkgs" / "parts_pkg"}"' in model.xml


def test_find_uses_the_ament_prefix_path(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """Without package_paths, a package installed under AMENT_PREFIX_PATH is found."""
    prefix = tmp_path / 'install'
    write_package(prefix / 'share', 'parts_pkg', {'urdf/parts.xacro': PARTS})
    marker = prefix / 'share' / 'ament_index' / 'resource_index' / 'packages' / 'parts_pkg'
    marker.parent.mkdir(parents=True)
    marker.touch()
    monkeypatch.setenv('AMENT_PREFIX_PATH', f'/nonexistent:{prefix}')
    monkeypatch.delenv('TF_DEMO_PACKAGE_PATH', raising=False)
    assert find_package_share('parts_pkg') == prefix / 'share' / 'parts_pkg'
    assert RobotModel.from_file(write_xacro(tmp_path / 'r.xacro', USES_PARTS)).root == 'base'


def test_find_of_unknown_package_names_it(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """A missing package is a broken reference that names the package and the file."""
    monkeypatch.setenv('AMENT_PREFIX_PATH', '')
    main = write_xacro(
        tmp_path / 'r.xacro',
        '<xacro:include filename="$(find no_such_pkg)/a.xacro"/><link name="base"/>',
    )
    with pytest.raises(UrdfBrokenRefError, match=r"r\.xacro: xacro: .*package 'no_such_pkg' not"):
        RobotModel.from_file(main)


def test_xacro_errors_name_the_file(tmp_path: Path) -> None:
    """Undefined arguments and broken XML in a xacro file are errors naming that file."""
    undefined = tmp_path / 'undefined.xacro'
    undefined.write_text(f'<robot name="$(arg name)" {XACRO_NS}><link name="a"/></robot>')
    with pytest.raises(UrdfMalformedError, match=r'undefined\.xacro: xacro: xacro failed: .*name'):
        RobotModel.from_file(undefined)
    broken = write_xacro(tmp_path / 'broken.xacro', '<link name="a">')
    with pytest.raises(UrdfMalformedError, match=r'broken\.xacro.*malformed XML'):
        RobotModel.from_file(broken)
    missing_include = write_xacro(tmp_path / 'inc.xacro', '<xacro:include filename="gone.xacro"/>')
    with pytest.raises(UrdfBrokenRefError, match=r'inc\.xacro: xacro: .*gone\.xacro'):
        RobotModel.from_file(missing_include)


def test_expanded_xacro_is_validated_like_urdf(tmp_path: Path) -> None:
    """xacro output goes through the same strict checks (here: a joint to a missing link)."""
    bad = write_xacro(
        tmp_path / 'bad.urdf.xacro',
        '<link name="a"/><joint name="j" type="fixed"><parent link="a"/><child link="ghost"/>'
        '</joint>',
    )
    with pytest.raises(UrdfBrokenRefError, match=r"bad\.urdf\.xacro:\d+: joint 'j': child link"):
        RobotModel.from_file(bad)


def test_package_path_variable_is_searched(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """Packages are also found through the TF_DEMO_PACKAGE_PATH search path."""
    write_package(tmp_path / 'elsewhere', 'parts_pkg', {'urdf/parts.xacro': PARTS})
    monkeypatch.setenv('TF_DEMO_PACKAGE_PATH', f'/nonexistent:{tmp_path / "elsewhere"}')
    monkeypatch.setenv('AMENT_PREFIX_PATH', '')
    model = RobotModel.from_file(write_xacro(tmp_path / 'r.xacro', USES_PARTS))
    assert [child for _, child, _, _ in model.static_transforms()] == ['arm_link']


# -- files the loader reads --------------------------------------------------------------------


def test_device_fifo_directory_huge_and_non_utf8_files_are_refused(tmp_path: Path) -> None:
    """Bounded reads: /dev/zero is not read until memory runs out; each error names the file."""
    with pytest.raises(UrdfError, match=r'^/dev/zero: file: not a regular file'):
        RobotModel.from_file('/dev/zero')
    fifo = tmp_path / 'fifo.urdf'
    os.mkfifo(fifo)
    with pytest.raises(UrdfError, match=rf'^{re.escape(str(fifo))}: file: not a regular file'):
        RobotModel.from_file(fifo)
    with pytest.raises(UrdfError, match=rf'^{re.escape(str(tmp_path))}: file: is a directory'):
        RobotModel.from_file(tmp_path)
    huge = tmp_path / 'huge.urdf'
    with huge.open('wb') as handle:
        handle.truncate(64 * 1024 * 1024)  # sparse: no disk used
    with pytest.raises(UrdfError, match=r'huge\.urdf: file: file is larger than \d+ bytes'):
        RobotModel.from_file(huge)
    latin = tmp_path / 'latin.urdf'
    latin.write_bytes(b'<robot name="r">\n<link name="caf\xe9"/>\n</robot>\n')
    with pytest.raises(UrdfError, match=r'latin\.urdf:2: file: not UTF-8 text$'):
        RobotModel.from_file(latin)
    with pytest.raises(UrdfBrokenRefError, match=r'nope\.urdf: file: no such file$'):
        RobotModel.from_file(tmp_path / 'nope.urdf')


def test_resources_resolve_as_resource_retriever_does(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """package:// through the package path, file:// as is, plain paths beside the description."""
    (tmp_path / 'pkg').mkdir()
    monkeypatch.setenv('TF_DEMO_PACKAGE_PATH', str(tmp_path))
    assert resolve_resource('package://pkg/meshes/a.stl') == tmp_path / 'pkg' / 'meshes' / 'a.stl'
    assert resolve_resource('file:///abs/b.dae') == Path('/abs/b.dae')
    assert resolve_resource('c.obj', tmp_path) == tmp_path / 'c.obj'
    assert resolve_resource('/abs/d.obj', tmp_path) == Path('/abs/d.obj')
    with pytest.raises(ValueError, match=r'only package://, file:// and plain paths'):
        resolve_resource('https://example.com/e.stl')
    with pytest.raises(ValueError, match='does not name a package and a file'):
        resolve_resource('package://pkg')
    with pytest.raises(LookupError, match="package 'nowhere' not found"):
        resolve_resource('package://nowhere/x.stl')
