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

"""Tests of tf_doctor's timing checks: stamps, rates, stopped streams and fixed mounts on /tf."""

from doctor_cases import kinds
from doctor_cases import REVOLUTE_ROBOT
from doctor_cases import S
from doctor_cases import static
from doctor_cases import stream
from doctor_cases import T0
from tf_demo.cli._doctor import diagnose
from tf_demo.cli._doctor_report import exit_code
from tf_demo.cli._doctor_robot import RobotInfo
from tf_demo.cli._observations import Observation
from tf_demo.cli._observations import ObservedTransform
from tf_demo.cli._observations import TF_TOPIC


def test_future_and_old_stamps():
    """Stamps ahead of or far behind the listener's clock point at the clocks."""
    future = stream('odom', 'base_link', delay_ns=-3 * S)
    finding = next(f for f in diagnose(future) if f.kind == 'future_stamps')
    assert '3.000 s in the future' in finding.message
    assert 'use_sim_time' in finding.fix
    sim = [
        Observation(
            TF_TOPIC, T0 + i * S // 10, (ObservedTransform('odom', 'base_link', i * S // 10),)
        )
        for i in range(1, 30)
    ]
    finding = next(f for f in diagnose(sim) if f.kind == 'old_stamps')
    assert 'simulation time' in finding.message


def test_zero_stamps():
    """Dynamic transforms stamped 0 are reported."""
    zero = [
        Observation(TF_TOPIC, T0 + i, (ObservedTransform('odom', 'base_link', 0),))
        for i in range(5)
    ]
    assert kinds(diagnose(zero)) == ['rep105_frame_missing', 'zero_stamps']  # no map


def test_sparse_data():
    """Slow or single-sample dynamic data is an extrapolation risk."""
    slow = stream('odom', 'base_link', rate_hz=1.0, seconds=4.0)
    finding = next(f for f in diagnose(slow) if f.kind == 'sparse_data')
    assert 'gaps up to 1.000 s' in finding.message
    once = stream('odom', 'base_link', rate_hz=1.0, seconds=1.0)
    finding = next(f for f in diagnose(once, listen_ns=3 * S) if f.kind == 'sparse_data')
    assert 'Only one stamp' in finding.message


def test_stopped_stream():
    """A stream that stops long before the recording ends is reported as stopped."""
    stopped = stream('odom', 'base_link', seconds=1.0)
    later = stream('map', 'odom', seconds=4.0)
    finding = next(f for f in diagnose(stopped + later) if f.kind == 'stopped')
    assert finding.frames == ('base_link',)
    assert 'stopped arriving 3.000 s' in finding.message


def test_timing_findings_say_when_they_happen():
    """Each timing finding carries the reception time where it shows first."""
    stopped = stream('odom', 'base_link', seconds=1.0)  # last at 0.95 s (+1 ms delay)
    finding = next(
        f for f in diagnose(stopped + stream('map', 'odom', seconds=4.0)) if f.kind == 'stopped'
    )
    assert finding.at_ns == T0 + 950_000_000 + 1_000_000
    slow = stream('odom', 'base_link', rate_hz=1.0, seconds=4.0)
    sparse = next(f for f in diagnose(slow) if f.kind == 'sparse_data')
    assert sparse.at_ns == T0 + 1_000_000  # the first of the equally wide gaps


def shifted(observations: list[Observation], back_ns: int) -> list[Observation]:
    """The same messages received later, their stamps ``back_ns`` earlier (a clock reset)."""
    result = []
    for observation in observations:
        (transform,) = observation.transforms
        moved = ObservedTransform(transform.parent, transform.child, transform.stamp_ns - back_ns,
                                  transform.translation)  # fmt: skip
        result.append(Observation(TF_TOPIC, observation.receive_ns + 2 * S, (moved,)))
    return result


def test_stamps_going_back_once_are_a_clock_jump_or_a_regression():
    """A reset by 5 s is a clock jump; a step back by 10 ms twice a stamp regression; with
    its time. Three or more steps back stay publishers fighting."""
    first = stream('odom', 'base_link', seconds=2.0)
    jumped = first + shifted(first, 5 * S)  # from 1.95 s back to -5 s
    (finding,) = [f for f in diagnose(jumped) if f.kind == 'clock_jump']
    assert 'jumped back by 6.950 s' in finding.message
    assert finding.at_ns == T0 + 2 * S + 1_000_000
    assert 'stamp_regression' not in kinds(diagnose(jumped))
    wobbly = stream('odom', 'base_link', seconds=2.0)
    for index in (10, 30):  # two messages stamped 10 ms before the one before them
        (transform,) = wobbly[index].transforms
        early = ObservedTransform(
            'odom',
            'base_link',
            wobbly[index - 1].transforms[0].stamp_ns - 10_000_000,
            transform.translation,
        )
        wobbly[index] = Observation(TF_TOPIC, wobbly[index].receive_ns, (early,))
    (finding,) = [f for f in diagnose(wobbly) if f.kind == 'stamp_regression']
    assert 'went backwards 2 times (by up to' in finding.message
    assert finding.at_ns == wobbly[10].receive_ns
    assert 'clock_jump' not in kinds(diagnose(wobbly))


def test_a_fixed_mount_sent_repeatedly_on_tf_belongs_on_tf_static():
    """Not 'publish faster': a transform that never changes is published once on /tf_static."""
    observations = [
        static('map', 'odom'),
        *stream('odom', 'base_link', seconds=5.0),
        *stream('base_link', 'laser', rate_hz=1.0, seconds=5.0, values=[(0.1, 0.0, 0.2)]),
    ]
    findings = diagnose(observations, listen_ns=5 * S)
    assert kinds(findings) == ['fixed_mount_on_tf']
    finding = findings[0]
    assert finding.severity == 'warning'
    assert 'base_link→laser arrived 5 times on /tf with the same value' in finding.message
    assert finding.fix.startswith('Publish a fixed mount once on /tf_static')
    assert 'faster' not in finding.fix
    fast = diagnose([*stream('base_link', 'laser', values=[(0.1, 0.0, 0.2)])], listen_ns=2 * S)
    assert [(f.kind, f.severity) for f in fast] == [
        ('rep105_frame_missing', 'info'),  # base_link without odom
        ('fixed_mount_on_tf', 'info'),
    ]
    assert exit_code(fast) == 0


def test_standing_still_is_not_a_fixed_mount():
    """Odometry of a robot at rest and a robot joint at rest keep the usual advice."""
    resting = stream('odom', 'base_link', rate_hz=1.0, seconds=4.0, values=[(1.0, 0.0, 0.0)])
    assert kinds(diagnose(resting)) == ['rep105_frame_missing', 'sparse_data']  # no map
    joint = stream('frame_1', 'frame_2', rate_hz=1.0, seconds=4.0, values=[(1.0, 0.0, 0.0)])
    robot = RobotInfo(REVOLUTE_ROBOT, 4, frozenset({'frame_1_to_frame_2'}))
    assert kinds(diagnose(joint, robot=robot)) == ['sparse_data']
