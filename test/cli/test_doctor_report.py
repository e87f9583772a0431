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

"""Tests of tf_doctor's report: the plain-language text, JSON, the summary and the exit code."""

import json

from doctor_cases import static
from tf_demo.cli._doctor import diagnose
from tf_demo.cli._doctor_report import format_report
from tf_demo.cli._doctor_report import format_report_json
from tf_demo.cli._doctor_report import summarize


def test_json_report():
    """--json gives one object with healthy, summary and findings."""
    observations = [static('map', 'odom'), static('base_link', 'laser')]
    findings = diagnose(observations)
    record = json.loads(format_report_json(findings, summarize(observations), 'x'))
    assert record['healthy'] is False
    assert record['summary'] == {'messages': 2, 'frames': 4, 'trees': 2}
    assert record['findings'][0]['kind'] == 'disconnected'


def test_text_report_golden():
    """The text report wraps at 99 columns, lists each tree on its own line, and counts."""
    observations = [static('map', 'odom'), static('base_link', 'laser')]
    report = format_report(diagnose(observations), summarize(observations), 'file.yaml')
    assert report == (
        'tf_doctor: file.yaml: 2 messages, 4 frames, 2 trees.\n'
        '\n'
        'ERROR [disconnected] The frames form 2 separate trees; lookups between trees fail:\n'
        '    tree 1 (root base_link): base_link, laser\n'
        '    tree 2 (root map): map, odom\n'
        '  Fix: The likely missing link is odom→base_link, published by the odometry source '
        '(base driver,\n'
        '    diff-drive controller or robot_localization). Start that publisher, or for a fixed '
        'offset run\n'
        '    static_transform_publisher --frame-id odom --child-frame-id base_link\n'
        '\n'
        'Found 1 error and 0 warnings.\n'
    )
