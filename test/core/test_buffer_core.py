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

"""BufferCore against the worked examples of spec/tf2.md §1-3 and tf2's simple_tf2_core tests."""

from __future__ import annotations

from collections.abc import Callable
import logging
import math
import random
from typing import Any

import numpy as np
import pytest
from tf_demo.core import BackwardExtrapolationException
from tf_demo.core import BufferCore
from tf_demo.core import ConnectivityException
from tf_demo.core import ExtrapolationException
from tf_demo.core import ForwardExtrapolationException
from tf_demo.core import InvalidArgumentException
from tf_demo.core import LookupException
from tf_demo.core import math3d
from tf_demo.core import NoDataForExtrapolationException
from tf_demo.core import TransformException

S = 1_000_000_000
IDENTITY = (0.0, 0.0, 0.0, 1.0)
SUFFIX_BAR_FOO = ', when looking up transform from frame [bar] to frame [foo]'


class Log:
    """Collects tf2's log lines."""

    def __init__(self) -> None:
        self.lines: list[tuple[int, str]] = []

    def __call__(self, level: int, text: str) -> None:
        self.lines.append((level, text))


#: A frame name that is not a str: the core's own TypeError, or (compiled) mypyc's check of the
#: argument's declared type.
NOT_A_STR = 'must be str|str object expected'


def error_text(error: type[Exception], function: Callable[..., object], *args: object) -> str:
    """Return the text of the ``error`` that ``function(*args)`` raises (failing if none)."""
    with pytest.raises(error) as info:
        function(*args)
    return str(info.value)


@pytest.fixture
def log():
    return Log()


#: The rep105 fixture's links: (parent, child, stamp_ns, translation, authority, is_static).
REP105_LINKS = (
    ('map', 'odom', 0, (1.0, 0.0, 0.0), 'a', True),
    ('odom', 'base', 10 * S, (1.0, 0.0, 0.0), 'b', False),
    ('odom', 'base', 11 * S, (2.0, 0.0, 0.0), 'b', False),
    ('base', 'laser', 5 * S, (0.0, 0.0, 1.0), 'c', False),
    ('base', 'laser', 12 * S, (0.0, 0.0, 2.0), 'c', False),
    ('base', 'cam', 0, (0.0, 1.0, 0.0), 'd', True),
)


@pytest.fixture
def rep105():
    """map->odom static, odom->base at {10,11}, base->laser at {5,12}, base->cam static."""
    core = BufferCore()
    for parent, child, stamp_ns, translation, authority, is_static in REP105_LINKS:
        core.set_transform(parent, child, stamp_ns, translation, IDENTITY, authority, is_static)
    return core


def test_lookup_direction_matches_tf2():
    """With a->b at x=+1, lookup(a, b) has x=+1 and lookup(b, a) has x=-1."""
    core = BufferCore()
    core.set_transform('a', 'b', S, (1.0, 0.0, 0.0), IDENTITY)
    assert core.lookup_transform('a', 'b', 0).translation == (1.0, 0.0, 0.0)
    assert core.lookup_transform('b', 'a', 0).translation == (-1.0, 0.0, 0.0)


def test_validation_log_texts(log):
    """Every failed check logs tf2's exact ERROR line, several per message when needed."""
    core = BufferCore(log=log)
    assert not core.set_transform('a', 'a', S, (0, 0, 0), IDENTITY, 'auth')
    assert log.lines[-1] == (
        logging.ERROR,
        'TF_SELF_TRANSFORM: Ignoring transform from authority "auth" with frame_id and  '
        'child_frame_id "a" because they are the same',
    )
    log.lines.clear()
    assert not core.set_transform('', '', S, (0, 0, 0), IDENTITY, 'auth')
    assert [text.split(':')[0] for _, text in log.lines] == [
        'TF_SELF_TRANSFORM',
        'TF_NO_CHILD_FRAME_ID',
        'TF_NO_FRAME_ID',
    ]
    assert log.lines[1][1] == (
        'TF_NO_CHILD_FRAME_ID: Ignoring transform from authority "auth" because child_frame_id '
        'not set '
    )
    assert log.lines[2][1] == (
        'TF_NO_FRAME_ID: Ignoring transform with child_frame_id ""  from authority "auth" '
        'because frame_id not set'
    )
    log.lines.clear()
    assert not core.set_transform('p', 'c', S, (math.nan, 0, 0), IDENTITY, 'auth')
    assert log.lines == [
        (
            logging.ERROR,
            'TF_NAN_INPUT: Ignoring transform for child_frame_id "c" from authority "auth" '
            'because of a nan value in the transform (nan 0.000000 0.000000) '
            '(0.000000 0.000000 0.000000 1.000000)',
        )
    ]
    log.lines.clear()
    assert not core.set_transform('p', 'c', S, (0, 0, 0), (0, 0, 0, 0), 'auth')
    assert [text.split(':')[0] for _, text in log.lines] == [
        'TF_NAN_INPUT',
        'TF_DENORMALIZED_QUATERNION',
    ]
    assert log.lines[1][1].startswith(
        'TF_DENORMALIZED_QUATERNION: Ignoring transform for child_frame_id "c" from authority '
        '"auth" because of an invalid quaternion in the transform ('
    )
    assert core.frame_ids() == []


def test_infinite_translation_is_accepted(log):
    """Inf in the translation is not rejected (only NaN is)."""
    core = BufferCore(log=log)
    assert core.set_transform('p', 'c', S, (math.inf, 0, 0), IDENTITY)
    assert log.lines == []


def test_old_data_warning(log):
    """Too-old data logs TF_OLD_DATA with a real newline and %20."""
    core = BufferCore(2 * S, log=log)
    assert core.set_transform('p', 'c', 10 * S, (0, 0, 0), IDENTITY, 'me')
    assert not core.set_transform('p', 'c', 7 * S, (0, 0, 0), IDENTITY, 'me')
    assert log.lines == [
        (
            logging.WARNING,
            'TF_OLD_DATA ignoring data from the past for frame c at time 7.000000 according to '
            'authority me\nPossible reasons are listed at '
            'http://wiki.ros.org/tf/Errors%20explained',
        )
    ]


def test_quaternion_normalised_and_canonicalised_on_insert():
    """(0,0,0,2) -> identity, (0,0,0,-1) -> identity, (0.1,0.2,0.3,-0.9) -> tf2's value."""
    core = BufferCore()
    core.set_transform('p', 'a', S, (0, 0, 0), (0, 0, 0, 2))
    core.set_transform('p', 'b', S, (0, 0, 0), (0, 0, 0, -1))
    core.set_transform('p', 'c', S, (0, 0, 0), (0.1, 0.2, 0.3, -0.9))
    assert core.lookup_transform('p', 'a', 0).rotation == (0.0, 0.0, 0.0, 1.0)
    assert core.lookup_transform('p', 'b', 0).rotation == (0.0, 0.0, 0.0, 1.0)
    assert core.lookup_transform('p', 'c', 0).rotation == pytest.approx(
        (-0.102598, -0.205196, -0.307794, 0.923381), abs=1e-6
    )


def test_leading_slash_stripped_once():
    """One leading slash is stripped; '//y' is stored as '/y'."""
    core = BufferCore()
    core.set_transform('/p', '/c', S, (1, 0, 0), IDENTITY)
    core.set_transform('p', '//y', S, (1, 0, 0), IDENTITY)
    assert core.frame_ids() == ['c', 'p', '/y']
    assert core.lookup_transform('p', 'c', 0).translation == (1.0, 0.0, 0.0)


def test_names_met_before_take_the_same_checks(log):
    """Frames known from earlier inserts (with or without their slash) are checked as new ones."""
    core = BufferCore(S, log=log)
    assert core.set_transform('/p', 'c', S, (1, 0, 0), IDENTITY, 'auth')
    assert core.set_transform('p', '/c', 2 * S, (2, 0, 0), IDENTITY, 'auth')  # the same link
    assert core.frame_ids() == ['c', 'p']
    assert core.lookup_transform('p', 'c', S + S // 2).translation == (1.5, 0.0, 0.0)
    assert not core.set_transform('/c', 'c', 3 * S, (0, 0, 0), IDENTITY, 'auth')
    assert log.lines[-1][1].startswith('TF_SELF_TRANSFORM')
    assert '"c"' in log.lines[-1][1]
    # tf2 refuses NaN only: an infinite translation is stored, even one whose sum is NaN.
    assert core.set_transform('p', 'c', 3 * S, (math.inf, -math.inf, 0), IDENTITY, 'auth')
    assert not core.set_transform('p', 'c', 3 * S, (math.nan, 0, 0), IDENTITY, 'auth')
    assert log.lines[-1][1].startswith('TF_NAN_INPUT')
    assert not core.set_transform('p', 'c', 4 * S, (0, 0, 0), (0, 0, 0, 0), 'auth')
    assert log.lines[-1][1].startswith('TF_DENORMALIZED_QUATERNION')
    assert not core.set_transform('p', 'c', 0, (0, 0, 0), IDENTITY, 'auth')
    assert log.lines[-1][1].startswith('TF_OLD_DATA ignoring data from the past for frame c ')
    assert core.set_transform('p', 'c', 5 * S, (0, 0, 0), (0, 0, 1e-60, 1e-60), 'auth')
    with pytest.raises(TypeError, match=NOT_A_STR):
        core.set_transform('p', ['c'], 6 * S, (0, 0, 0), IDENTITY)  # type: ignore[arg-type]
    with pytest.raises(TypeError, match='as numbers'):
        core.set_transform('p', 'c', 6 * S, ('1', 0, 0), IDENTITY)  # type: ignore[arg-type]
    assert core.frame_ids() == ['c', 'p']


def test_ids_child_first_and_kept_after_clear():
    """A new child gets its id before its parent; clear() keeps ids, authorities, statics."""
    core = BufferCore()
    core.set_transform('parent', 'child', S, (0, 0, 0), IDENTITY, 'x')
    core.set_transform('parent', 'fixed', 0, (0, 0, 1), IDENTITY, 'y', True)
    assert core.frame_ids() == ['child', 'parent', 'fixed']
    core.clear()
    assert core.frame_ids() == ['child', 'parent', 'fixed']
    assert core.lookup_transform('parent', 'fixed', 5 * S).translation == (0.0, 0.0, 1.0)
    assert core.all_frames_as_string() == (
        'Frame child exists with parent NO_PARENT.\nFrame fixed exists with parent parent.\n'
    )


def test_duplicates_and_same_stamp_entries():
    """Exact duplicates are dropped but succeed; same stamp with new data is kept."""
    core = BufferCore()
    assert core.set_transform('p', 'c', S, (1, 0, 0), IDENTITY, 'first')
    assert core.set_transform('p', 'c', S, (1, 0, 0), IDENTITY, 'second')
    assert core.frames_info()[0].sample_count == 1
    assert core.frames_info()[0].authority == 'second'
    assert core.set_transform('p', 'c', S, (2, 0, 0), IDENTITY)
    assert core.frames_info()[0].sample_count == 2
    # Newest-inserted wins at the newest stamp.
    assert core.lookup_transform('p', 'c', S).translation == (2.0, 0.0, 0.0)


def test_reparenting_and_static_overwrite():
    """A child may change parent over time; a static child is overwritten for all times."""
    core = BufferCore()
    core.set_transform('a', 'c', 1 * S, (1, 0, 0), IDENTITY)
    core.set_transform('b', 'c', 2 * S, (2, 0, 0), IDENTITY)
    assert core.parent_of('c', S + S // 2) == 'a'
    assert core.parent_of('c', 2 * S) == 'b'
    assert core.lookup_transform('a', 'c', S + S // 2).translation == (1.0, 0.0, 0.0)
    core.set_transform('a', 's', 0, (1, 0, 0), IDENTITY, '', True)
    core.set_transform('b', 's', 0, (3, 0, 0), IDENTITY, '', True)
    assert core.parent_of('s', 123) == 'b'
    assert core.lookup_transform('b', 's', 99 * S).translation == (3.0, 0.0, 0.0)


def test_static_dynamic_kind_switch_discards_history():
    """Switching a child between static and dynamic replaces its cache."""
    core = BufferCore()
    core.set_transform('p', 'c', 1 * S, (1, 0, 0), IDENTITY)
    core.set_transform('p', 'c', 2 * S, (2, 0, 0), IDENTITY)
    core.set_transform('p', 'c', 0, (5, 0, 0), IDENTITY, '', True)
    assert core.frames_info()[0].is_static
    assert core.lookup_transform('p', 'c', 77).translation == (5.0, 0.0, 0.0)
    core.set_transform('p', 'c', 3 * S, (3, 0, 0), IDENTITY)
    info = core.frames_info()[0]
    assert (info.is_static, info.sample_count, info.oldest_ns) == (False, 1, 3 * S)


def test_target_equals_source_shortcut():
    """Identity without validation; stamp is the frame's newest when time is 0."""
    core = BufferCore()
    assert core.lookup_transform('zz', 'zz', 0) == ((0, 0, 0), IDENTITY, 0)
    assert core.lookup_transform('', '', 7).stamp_ns == 7
    core.set_transform('foo', 'bar', 2 * S, (0, 0, 0), IDENTITY)
    core.set_transform('foo', 'bar', 3 * S, (0, 0, 0), IDENTITY)
    assert core.lookup_transform('bar', 'bar', 0).stamp_ns == 3 * S
    assert core.can_transform('nope', 'nope', 0)


def test_frame_validation_texts():
    """Empty, slash-prefixed and unknown frames raise tf2's exact errors."""
    core = BufferCore()
    core.set_transform('foo', 'bar', S, (0, 0, 0), IDENTITY)
    assert error_text(InvalidArgumentException, core.lookup_transform, '', 'bar', 0) == (
        'Invalid argument "" passed to lookupTransform argument target_frame - in tf2 '
        'frame_ids cannot be empty'
    )
    assert error_text(InvalidArgumentException, core.lookup_transform, 'foo', '/bar', 0) == (
        'Invalid argument "/bar" passed to lookupTransform argument source_frame - in tf2 '
        "frame_ids cannot start with a '/'"
    )
    assert (
        error_text(LookupException, core.lookup_transform, 'foo', 'baz', 0)
        == '"baz" passed to lookupTransform argument source_frame does not exist. '
    )
    assert not core.can_transform('foo', 'baz', 0)
    assert core.transform_error('foo', 'baz', 0) == (
        'Invalid frame ID "baz" passed to canTransform argument source_frame - frame does not '
        'exist'
    )
    assert not core.can_transform('', 'bar', 0)
    assert core.transform_error('', 'bar', 0) == (
        'Invalid frame ID "" passed to canTransform argument target_frame - in tf2 frame_ids '
        'cannot be empty'
    )


def test_latest_common_time_examples(rep105):
    """LCT(map,laser)=11, LCT(cam,laser)=12, LCT(cam,map)=11, LCT(odom,map)=0."""
    assert rep105.get_latest_common_time('map', 'laser') == 11 * S
    assert rep105.get_latest_common_time('cam', 'laser') == 12 * S
    assert rep105.get_latest_common_time('cam', 'map') == 11 * S
    assert rep105.get_latest_common_time('odom', 'map') == 0
    assert rep105.lookup_transform('odom', 'map', 0).stamp_ns == 0
    assert rep105.lookup_transform('odom', 'map', 123).stamp_ns == 123


def test_links_above_common_ancestor_do_not_count():
    """root->mid at [1,2], mid->c1/c2 at [5,6]: c1<-c2 works, root<-c2 at 0 fails at LCT 2."""
    core = BufferCore()
    for stamp in (1, 2):
        core.set_transform('root', 'mid', stamp * S, (0, 0, 0), IDENTITY)
    for stamp in (5, 6):
        core.set_transform('mid', 'c1', stamp * S, (1, 0, 0), IDENTITY)
        core.set_transform('mid', 'c2', stamp * S, (0, 1, 0), IDENTITY)
    assert core.lookup_transform('c1', 'c2', 0).stamp_ns == 6 * S
    assert core.lookup_transform('c1', 'c2', 5 * S + S // 2).translation == (-1.0, 1.0, 0.0)
    assert error_text(BackwardExtrapolationException, core.lookup_transform, 'root', 'c2', 0) == (
        'Lookup would require extrapolation into the past.  Requested time 2.000000 but the '
        'earliest data is at time 5.000000, when looking up transform from frame [c2] to frame '
        '[root]'
    )


def test_zero_stamped_dynamic_link_is_ignored_by_lct():
    """A dynamic link stamped 0 plus one at 5 gives LCT 5 and tf2's single-sample failure."""
    core = BufferCore()
    core.set_transform('a', 'b', 0, (0, 0, 0), IDENTITY)
    core.set_transform('b', 'c', 5 * S, (0, 0, 0), IDENTITY)
    assert core.get_latest_common_time('a', 'c') == 5 * S
    assert error_text(
        NoDataForExtrapolationException, core.lookup_transform, 'a', 'c', 0
    ).startswith(
        'Lookup would require extrapolation at time 5.000000, but only time 0.000000 is in the '
        'buffer'
    )


def test_walk_error_messages():
    """foo->bar at {2,3}: future, single-sample and post-clear texts and classes."""
    single_sample = (
        'Lookup would require extrapolation at time 4.000000, but only time 2.000000 is in the '
        'buffer'
    )
    future = (
        'Lookup would require extrapolation into the future.  Requested time 4.000000 but the '
        'latest data is at time 3.000000'
    )
    core = BufferCore()
    lookup = core.lookup_transform
    core.set_transform('foo', 'bar', 2 * S, (0, 0, 0), IDENTITY)
    text = error_text(NoDataForExtrapolationException, lookup, 'foo', 'bar', 4 * S)
    assert text == single_sample + SUFFIX_BAR_FOO
    core.set_transform('foo', 'bar', 3 * S, (0, 0, 0), IDENTITY)
    assert error_text(ForwardExtrapolationException, lookup, 'foo', 'bar', 4 * S) == (
        future + SUFFIX_BAR_FOO
    )
    # Target-side failure gives the same suffix (source and target as named in the call).
    assert error_text(
        ForwardExtrapolationException, core.lookup_transform, 'bar', 'foo', 4 * S
    ).endswith(', when looking up transform from frame [foo] to frame [bar]')
    core.clear()
    assert (
        error_text(NoDataForExtrapolationException, core.lookup_transform, 'foo', 'bar', 3 * S)
        == SUFFIX_BAR_FOO
    )
    with pytest.raises(ConnectivityException):
        core.lookup_transform('foo', 'bar', 0)
    assert issubclass(NoDataForExtrapolationException, ExtrapolationException)
    assert issubclass(ExtrapolationException, TransformException)


def test_connectivity_text():
    """Unconnected trees give tf2's text with no space after 'tree.'."""
    core = BufferCore()
    core.set_transform('a', 'b', S, (0, 0, 0), IDENTITY)
    core.set_transform('c', 'd', S, (0, 0, 0), IDENTITY)
    text = (
        "Could not find a connection between 'a' and 'd' because they are not part of the same "
        'tree.Tf has two or more unconnected trees.'
    )
    assert error_text(ConnectivityException, core.lookup_transform, 'a', 'd', 0) == text
    assert error_text(ConnectivityException, core.lookup_transform, 'a', 'd', S) == text
    assert not core.can_transform('a', 'd', S)
    assert core.transform_error('a', 'd', S) == text


def test_loop_is_reported():
    """A cycle raises LookupException with the loop text followed by the frame list."""
    core = BufferCore()
    core.set_transform('a', 'b', S, (0, 0, 0), IDENTITY)
    core.set_transform('c', 'a', S, (0, 0, 0), IDENTITY)
    core.set_transform('b', 'c', S, (0, 0, 0), IDENTITY)
    core.set_transform('x', 'y', S, (0, 0, 0), IDENTITY)
    assert error_text(LookupException, core.lookup_transform, 'x', 'b', S) == (
        'The tf tree is invalid because it contains a loop.\n'
        'Frame b exists with parent a.\nFrame a exists with parent c.\n'
        'Frame c exists with parent b.\nFrame y exists with parent x.\n\n'
    )


def test_harmless_failure_above_meeting_point():
    """c1<-c2 at 5.5 works although root->mid has no data at 5.5."""
    core = BufferCore()
    core.set_transform('root', 'mid', 1 * S, (0, 0, 0), IDENTITY)
    core.set_transform('root', 'mid', 2 * S, (0, 0, 0), IDENTITY)
    for stamp in (5, 6):
        core.set_transform('mid', 'c1', stamp * S, (1, 0, 0), IDENTITY)
        core.set_transform('mid', 'c2', stamp * S, (0, 1, 0), IDENTITY)
    assert core.can_transform('c1', 'c2', 5 * S + S // 2)
    assert core.lookup_transform('c2', 'c1', 5 * S + S // 2).translation == (1.0, -1.0, 0.0)


def test_full_lookup_example():
    """bar at x=2 at 2.5 s and x=3 at 3 s: lookup(bar@3, bar@2.5, fixed=foo) is x=-0.5 @3."""
    core = BufferCore()
    core.set_transform('foo', 'bar', 2 * S, (1.0, 0, 0), IDENTITY)
    core.set_transform('foo', 'bar', 3 * S, (3.0, 0, 0), IDENTITY)
    result = core.lookup_transform_full('bar', 3 * S, 'bar', 2 * S + S // 2, 'foo')
    assert result.translation == pytest.approx((-1.0, 0.0, 0.0))
    assert result.stamp_ns == 3 * S
    core.set_transform('foo', 'bar', 4 * S, (2.0, 0, 0), IDENTITY)
    assert core.can_transform_full('bar', 3 * S, 'bar', 2 * S + S // 2, 'foo')
    assert not core.can_transform_full('bar', 9 * S, 'bar', 2 * S, 'foo')
    assert 'into the future' in core.transform_error_full('bar', 9 * S, 'bar', 2 * S, 'foo')
    assert 'fixed_frame does not exist' in error_text(
        LookupException, core.lookup_transform_full, 'bar', 0, 'bar', 0, 'nope'
    )


def test_full_lookup_composes_with_rotation():
    """The fixed-frame result equals target@tt <- fixed composed with fixed <- source@st."""
    core = BufferCore()
    q1 = math3d.quat_from_rpy(0.1, 0.2, 0.3)
    q2 = math3d.quat_from_rpy(-0.4, 0.1, 1.3)
    core.set_transform('world', 'robot', 1 * S, (1.0, 2.0, 0.0), q1)
    core.set_transform('world', 'robot', 2 * S, (3.0, -1.0, 0.5), q2)
    result = core.lookup_transform_full('robot', 2 * S, 'robot', 1 * S, 'world')
    world_t_robot2 = core.lookup_transform('world', 'robot', 2 * S)
    world_t_robot1 = core.lookup_transform('world', 'robot', 1 * S)
    inv_t, inv_q = math3d.invert(world_t_robot2.translation, world_t_robot2.rotation)
    t, q = math3d.compose(inv_t, inv_q, world_t_robot1.translation, world_t_robot1.rotation)
    assert result.translation == pytest.approx(t, abs=1e-12)
    assert result.rotation == pytest.approx(q, abs=1e-12)


def test_lookup_result_rotation_is_canonical():
    """As in ROS 2 (tf2::Transform holds a matrix), the result quaternion has w >= 0 here."""
    core = BufferCore()
    half = math.radians(170) / 2
    q = (0.0, 0.0, math.sin(half), math.cos(half))
    core.set_transform('a', 'b', S, (0, 0, 0), q)
    core.set_transform('b', 'c', S, (0, 0, 0), q)
    rotation = core.lookup_transform('a', 'c', 0).rotation
    assert rotation == pytest.approx(
        (0.0, 0.0, -math.sin(math.radians(20) / 2), math.cos(math.radians(20) / 2))
    )


def test_chain_examples(rep105):
    """tf2's _chainAsVector quirks, the four verified outputs of spec §3.8."""
    assert rep105.chain('map', 0, 'laser', 0, 'map') == ['laser', 'base', 'odom']
    assert rep105.chain('laser', 0, 'map', 0, 'laser') == ['map', 'odom', 'base', 'laser']
    assert rep105.chain('laser', 0, 'cam', 0, 'laser') == ['laser']
    assert rep105.chain('laser', 11 * S, 'cam', 0, 'map') == [
        'cam',
        'map',
        'odom',
        'base',
        'laser',
    ]


def test_chain_prunes_the_two_walks_as_jazzy_does():
    """
    Two times: tf2 Jazzy's pruning of the source and target chains, quirks included.

    Found by the differential test against Jazzy's own tf2_py (these answers are Jazzy's): a
    source that is the fixed frame walks nothing, and nothing of the target's walk is kept; a
    source walk whose end equals the target walk's end keeps the target's first frame twice.
    """
    core = BufferCore()
    core.set_transform('yy', 'y1', 0, (1.0, 0.0, 0.0), (0.0, 0.0, 0.0, 1.0), 'a', True)
    core.set_transform('10', 'c1', 0, (1.0, 0.0, 0.0), (0.0, 0.0, 0.0, 1.0), 'a', True)
    core.set_transform('10', 'cy', 0, (0.0, 1.0, 0.0), (0.0, 0.0, 0.0, 1.0), 'a', True)
    assert core.chain('y1', 25 * S, 'yy', 0, 'yy') == []
    assert core.chain('10', 10 * S, 'c1', 9 * S, 'cy') == ['cy', 'cy']
    assert core.chain('10', 10 * S, 'c1', 10 * S, 'cy') == ['cy']
    assert core.chain('cy', 10 * S, 'c1', 9 * S, '10') == ['c1', '10', 'cy']


def test_introspection_helpers(rep105):
    """frame_exists, frame_ids, parent_of and frames_info report the buffer's contents."""
    assert rep105.frame_exists('map')
    assert rep105.frame_exists('NO_PARENT')
    assert not rep105.frame_exists('nope')
    assert rep105.frame_ids() == ['odom', 'map', 'base', 'laser', 'cam']
    assert rep105.parent_of('laser') == 'base'
    assert rep105.parent_of('map') is None
    assert rep105.parent_of('base', 99 * S) is None
    infos = {info.child: info for info in rep105.frames_info()}
    assert infos['laser'][1:] == ('base', 'c', False, 5 * S, 12 * S, 2)
    assert infos['odom'][1:] == ('map', 'a', True, 0, 0, 1)


def test_lookup_velocity_translation_and_rotation():
    """Pure translation at 2 m/s and pure yaw at 0.5 rad/s come back as that twist."""
    core = BufferCore()
    for step in range(11):
        t = step / 10
        q = math3d.quat_from_rpy(0.0, 0.0, 0.5 * t)
        core.set_transform('odom', 'mover', step * S // 10, (2.0 * t, 0.0, 0.0), IDENTITY)
        core.set_transform('odom', 'spinner', step * S // 10, (0.0, 0.0, 0.0), q)
    linear, angular = core.lookup_velocity('mover', 'odom', S // 2, S // 10)
    assert linear == pytest.approx((2.0, 0.0, 0.0), abs=1e-6)
    assert angular == pytest.approx((0.0, 0.0, 0.0), abs=1e-9)
    linear, angular = core.lookup_velocity('spinner', 'odom', S // 2, S // 10)
    assert linear == pytest.approx((0.0, 0.0, 0.0), abs=1e-9)
    assert angular == pytest.approx((0.0, 0.0, 0.5), abs=1e-6)


def test_lookup_velocity_times_and_divisions_are_tf2s():
    """
    Two cases the differential test against Jazzy's own core found (Jazzy's answers).

    tf2 turns the window's start into nanoseconds with ``std::round`` (halves away from zero):
    here it lands on the first sample, not half a nanosecond before it.  And a window that
    vanishes in double seconds at today's epoch makes tf2 divide by zero: NaN, not an error.
    """
    core = BufferCore()
    core.set_transform('bc', 'a0', 123_456_789, (0.0, 0.0, 0.0), IDENTITY)
    core.set_transform('bc', 'a0', 2_098_765_413, (1.0, 0.0, 0.0), IDENTITY)
    linear, _ = core.lookup_velocity('bc', 'a0', 185_185_183, 123_456_789)
    assert linear[0] == pytest.approx(-1.0 / 1.975308624, rel=1e-6)
    epoch = 1_764_000_000_123_456_789
    core.set_transform('by', 'c0', epoch, (1.0, 2.0, 3.0), IDENTITY)
    linear, angular = core.lookup_velocity('c0', 'c0', epoch, 2)
    assert all(math.isnan(value) for value in (*linear, *angular))


def test_insert_callbacks_run_after_each_insert():
    """Callbacks run once per stored transform and can be removed."""
    core = BufferCore()
    calls = []
    handle = core.add_insert_callback(lambda: calls.append(core.frame_ids()))
    core.set_transform('p', 'c', S, (0, 0, 0), IDENTITY)
    core.set_transform('p', 'p', S, (0, 0, 0), IDENTITY)
    assert calls == [['c', 'p']]
    core.remove_insert_callback(handle)
    core.set_transform('p', 'c', 2 * S, (0, 0, 0), IDENTITY)
    assert len(calls) == 1


def test_bad_argument_types_are_reported():
    """Wrong argument shapes raise TypeError naming the problem, not a crash inside the core."""
    core = BufferCore()
    with pytest.raises(TypeError, match='translation'):
        core.set_transform('p', 'c', S, (0, 0), IDENTITY)
    untyped_none: Any = None  # what an untyped caller may pass
    with pytest.raises(TypeError, match=NOT_A_STR):
        core.set_transform(untyped_none, 'c', S, (0, 0, 0), IDENTITY)
    with pytest.raises(ValueError, match='negative'):
        BufferCore(-1)


def test_batch_lookup_equals_single_lookups(rep105):
    """lookup_transforms equals N single lookups, including time 0 and interior stamps."""
    rep105.set_transform(
        'base', 'laser', 8 * S, (0.3, 0.1, 1.5), math3d.quat_from_rpy(0.1, 0.2, 0.3)
    )
    times = np.array([0, 10 * S, 10 * S + 123456789, 11 * S, 10 * S + S // 3], dtype=np.int64)
    for target, source in (('map', 'laser'), ('laser', 'cam'), ('cam', 'map'), ('laser', 'laser')):
        translations, rotations = rep105.lookup_transforms(target, source, times)
        for row, stamp in enumerate(times.tolist()):
            single = rep105.lookup_transform(target, source, stamp)
            assert translations[row] == pytest.approx(single.translation, abs=1e-9)
            assert rotations[row] == pytest.approx(single.rotation, abs=1e-9)


def test_batch_lookup_raises_first_failure(rep105):
    """The batch raises what the first failing single lookup raises."""
    times = np.array([10 * S, 13 * S, 1 * S], dtype=np.int64)
    assert error_text(
        ForwardExtrapolationException, rep105.lookup_transforms, 'map', 'laser', times
    ) == error_text(ForwardExtrapolationException, rep105.lookup_transform, 'map', 'laser', 13 * S)
    with pytest.raises(LookupException):
        rep105.lookup_transforms('map', 'nope', times)


def test_single_sample_answers_exactly_at_its_stamp():
    """One sample answers a lookup at exactly its stamp (and fails one nanosecond later)."""
    core = BufferCore()
    core.set_transform('a', 'b', 2 * S, (1.0, 0.0, 0.0), (1.0, 0.0, 0.0, 0.0), 'x')
    result = core.lookup_transform('a', 'b', 2 * S)
    assert result == ((1.0, 0.0, 0.0), (1.0, 0.0, 0.0, 0.0), 2 * S)
    translations, _ = core.lookup_transforms('a', 'b', np.array([2 * S]))
    assert translations.tolist() == [[1.0, 0.0, 0.0]]
    with pytest.raises(NoDataForExtrapolationException):
        core.lookup_transform('a', 'b', 2 * S + 1)


def test_deep_and_wide_trees_like_tf2_speed_test():
    """tf2's speed_test shapes: a 100-link chain and a 100-child star, at time 0 and inside."""
    core = BufferCore()
    for index in range(100):
        for stamp in (S, 2 * S):
            core.set_transform(
                f'chain{index}',
                f'chain{index + 1}',
                stamp,
                (0.01 * stamp / S, 0.0, 0.0),
                math3d.quat_from_rpy(0.0, 0.0, 0.001 * stamp / S),
            )
        core.set_transform('star', f'leaf{index}', 0, (1.0, 0.0, 0.0), IDENTITY, '', True)
    result = core.lookup_transform('chain0', 'chain100', S + S // 2)
    expected_t, expected_q = (0.0, 0.0, 0.0), IDENTITY
    link_t, link_q = (0.015, 0.0, 0.0), math3d.quat_from_rpy(0.0, 0.0, 0.0015)
    for _ in range(100):
        expected_t, expected_q = math3d.compose(expected_t, expected_q, link_t, link_q)
    assert result.translation == pytest.approx(expected_t, abs=1e-9)
    assert result.rotation == pytest.approx(expected_q, abs=1e-9)
    assert core.lookup_transform('chain0', 'chain100', 0).stamp_ns == 2 * S
    assert core.lookup_transform('leaf3', 'leaf97', 0).translation == (0.0, 0.0, 0.0)
    assert core.lookup_transform('leaf3', 'leaf97', 5 * S).stamp_ns == 5 * S


def _messy_inserts(seed: int, count: int) -> list[tuple[Any, ...]]:
    """Transforms as a busy, partly broken /tf brings them (every kind set_transform refuses)."""
    rng = random.Random(seed)
    frames = ['map', 'odom', '/odom', 'base', 'arm', 'hand', '', '/', '//x']
    inserts: list[tuple[Any, ...]] = []
    for _ in range(count):
        parent, child = rng.choice(frames), rng.choice(frames)
        stamp: Any = rng.choice([rng.randrange(1, 40) * S // 4, 0, 1, 30 * S])
        turn = rng.uniform(-math.pi, math.pi)
        rotation: Any = (0.0, 0.0, math.sin(turn / 2), math.cos(turn / 2))
        translation: Any = (rng.uniform(-5, 5), rng.uniform(-5, 5), 0.0)
        odd = rng.randrange(12)
        if odd == 0:
            translation = (math.nan, 0.0, 0.0)
        elif odd == 1:
            rotation = (0.0, 0.0, 0.0, 0.0)
        elif odd == 2:
            rotation = (0.0, 0.0, 2.0, 0.0)  # not normalised: tf2 normalises it
        elif odd == 3:
            translation = ('x', 0.0, 0.0)  # a TypeError
        elif odd == 4:
            stamp = 2.5e9  # a float stamp, as int() takes it
        elif odd == 5:
            rotation = (math.inf, 0.0, 0.0, 1.0)
        inserts.append((parent, child, stamp, translation, rotation))
    return inserts


def _nan_signless(lines: list[tuple[int, str]]) -> list[tuple[int, str]]:
    """Log lines with ``-nan`` written ``nan``."""
    return [(level, text.replace('-nan', 'nan')) for level, text in lines]


def _answers(core: BufferCore) -> list[object]:
    """Everything observable of a core: frames, parents, lookups or their errors."""
    answers: list[object] = [core.all_frames_as_string(), core.all_frames_as_yaml(40 * S)]
    names = core.frame_ids()
    for target in names:
        for source in names:
            for time_ns in (0, S, 3 * S + S // 3, 7 * S, 29 * S):
                try:
                    answers.append(core.lookup_transform(target, source, time_ns))
                except TransformException as error:
                    answers.append(f'{type(error).__name__}: {error}')
    return answers


@pytest.mark.parametrize('seed', range(6))
@pytest.mark.parametrize('is_static', [False, True])
def test_set_transforms_inserts_as_set_transform_one_by_one(seed: int, is_static: bool) -> None:
    """The many-at-once insert stores, refuses, logs and fails exactly as single inserts do."""
    inserts = _messy_inserts(seed, 400)
    one_log, many_log = Log(), Log()
    one, many = BufferCore(10 * S, log=one_log), BufferCore(10 * S, log=many_log)
    one_failures = []
    for parent, child, stamp, translation, rotation in inserts:
        try:
            one.set_transform(parent, child, stamp, translation, rotation, 'auth', is_static)
        except TypeError as error:
            one_failures.append((parent, child, str(error)))
    calls = []
    many.add_insert_callback(lambda: calls.append(1))
    failures = many.set_transforms(inserts, 'auth', is_static)
    assert [(parent, child, str(error)) for parent, child, error in failures] == one_failures
    assert one_failures  # the scenario has bad input
    # The sign of a NaN made from inf * 0 depends on CPython's code path (specialised or not).
    assert _nan_signless(many_log.lines) == _nan_signless(one_log.lines)
    assert any('TF_OLD_DATA' in text for _, text in one_log.lines) or is_static
    assert _answers(many) == _answers(one)
    assert calls
