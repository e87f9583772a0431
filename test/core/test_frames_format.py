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

"""allFramesAsString, allFramesAsYAML and the DOT dump in tf2's exact formats (spec §3.8)."""

from __future__ import annotations

from tf_demo.core import BufferCore

S = 1_000_000_000
IDENTITY = (0.0, 0.0, 0.0, 1.0)


def _rep105() -> BufferCore:
    core = BufferCore()
    core.set_transform('map', 'odom', 0, (0, 0, 0), IDENTITY, 'static_pub', True)
    core.set_transform('odom', 'base', 10 * S, (0, 0, 0), IDENTITY, 'odometry')
    core.set_transform('odom', 'base', 11 * S, (0, 0, 0), IDENTITY, 'odometry')
    core.set_transform('base', 'laser', 5 * S, (0, 0, 0), IDENTITY, 'driver')
    core.set_transform('base', 'laser', 12 * S, (0, 0, 0), IDENTITY, 'driver')
    return core


def test_empty_buffer_outputs():
    """An empty buffer gives '' as string, '[]' as YAML and the 'recieved' DOT graph."""
    core = BufferCore()
    assert core.all_frames_as_string() == ''
    assert core.all_frames_as_yaml() == '[]'
    assert core.all_frames_as_dot() == 'digraph G {\n"no tf data recieved"}'
    assert core.frames_info() == []


def test_all_frames_as_string():
    """One line per child frame in id order, parent from the newest entry."""
    assert _rep105().all_frames_as_string() == (
        'Frame odom exists with parent map.\n'
        'Frame base exists with parent odom.\n'
        'Frame laser exists with parent base.\n'
    )


def test_yaml_dump_exact_text():
    """The YAML text matches tf2's format, with transform_delay only when a time is given."""
    core = _rep105()
    expected = (
        'odom: \n'
        "  parent: 'map'\n"
        "  broadcaster: 'static_pub'\n"
        '  rate: 10000.000\n'
        '  most_recent_transform: 0.000000\n'
        '  oldest_transform: 0.000000\n'
        '  buffer_length: 0.000\n'
        'base: \n'
        "  parent: 'odom'\n"
        "  broadcaster: 'odometry'\n"
        '  rate: 2.000\n'
        '  most_recent_transform: 11.000000\n'
        '  oldest_transform: 10.000000\n'
        '  buffer_length: 1.000\n'
        'laser: \n'
        "  parent: 'base'\n"
        "  broadcaster: 'driver'\n"
        '  rate: 0.286\n'
        '  most_recent_transform: 12.000000\n'
        '  oldest_transform: 5.000000\n'
        '  buffer_length: 7.000\n'
    )
    assert core.all_frames_as_yaml() == expected
    with_delay = core.all_frames_as_yaml(13 * S + S // 2)
    assert '  transform_delay: 2.500\n  buffer_length: 1.000\n' in with_delay
    assert '  transform_delay: 13.500\n' in with_delay


def test_yaml_after_clear_keeps_static_frames_only():
    """After clear(), dynamic frames disappear from the YAML; a buffer of only those gives ''."""
    core = _rep105()
    core.clear()
    assert core.all_frames_as_yaml().startswith('odom: \n')
    assert 'base:' not in core.all_frames_as_yaml()
    dynamic_only = BufferCore()
    dynamic_only.set_transform('a', 'b', S, (0, 0, 0), IDENTITY)
    dynamic_only.clear()
    assert dynamic_only.all_frames_as_yaml() == ''


def test_dot_dump_exact_text():
    """The DOT graph has one edge per child and tf2's label layout."""
    assert _rep105().all_frames_as_dot() == (
        'digraph G {\n'
        '"map" -> "odom"[label="Broadcaster: static_pub\\nAverage rate: 10000.000 Hz\\n'
        'Most recent transform: 0.000000 \\nBuffer length: 0.000 sec\\n"];\n'
        '"odom" -> "base"[label="Broadcaster: odometry\\nAverage rate: 2.000 Hz\\n'
        'Most recent transform: 11.000000 \\nBuffer length: 1.000 sec\\n"];\n'
        '"base" -> "laser"[label="Broadcaster: driver\\nAverage rate: 0.286 Hz\\n'
        'Most recent transform: 12.000000 \\nBuffer length: 7.000 sec\\n"];\n'
        '}'
    )


def test_dot_dump_with_time_has_ages_and_root_legend():
    """With a current time, labels show the age and each root gets the legend block."""
    dot = _rep105().all_frames_as_dot(20 * S)
    assert 'Most recent transform: 11.000000 ( 9.000 sec old)\\nBuffer length' in dot
    assert dot.endswith(
        'edge [style=invis];\n'
        ' subgraph cluster_legend { style=bold; color=black; label ="view_frames Result";\n'
        '"Recorded at time: 20.000000"[ shape=plaintext ] ;\n'
        ' }->"map";\n'
        '}'
    )


def test_dot_dump_legend_for_emptied_cache():
    """A child whose cache was cleared gets the legend even without a time."""
    core = BufferCore()
    core.set_transform('a', 'b', S, (0, 0, 0), IDENTITY, 'x')
    core.clear()
    assert core.all_frames_as_dot() == (
        'digraph G {\n'
        'edge [style=invis];\n'
        ' subgraph cluster_legend { style=bold; color=black; label ="view_frames Result";\n'
        '}->"b";\n'
        '}'
    )


def test_rate_uses_100_microsecond_floor():
    """Two samples 50 us apart report 2 / 100 us = 20000 Hz."""
    core = BufferCore()
    core.set_transform('a', 'b', S, (0, 0, 0), IDENTITY)
    core.set_transform('a', 'b', S + 50_000, (1, 0, 0), IDENTITY)
    assert '  rate: 20000.000\n' in core.all_frames_as_yaml()


def test_frames_info_reports_children():
    """frames_info reports children with parent, kind, stamps and sample counts."""
    core = _rep105()
    infos = core.frames_info()
    assert [info.child for info in infos] == ['odom', 'base', 'laser']
    assert infos[1].parent == 'odom'
    assert infos[1].oldest_ns == 10 * S
    assert infos[1].newest_ns == 11 * S
    assert infos[1].sample_count == 2
    assert infos[0].is_static
