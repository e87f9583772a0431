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

"""
tf_doctor's report: the findings in plain language or JSON, a summary line and the exit code.

Each finding is printed with its severity, kind, message and fix, wrapped at 99 columns; the
verdict counts errors and warnings (info findings do not make the exit code 1).
"""

from __future__ import annotations

from collections.abc import Sequence
import json
import textwrap

from tf_demo.cli._doctor_model import Finding
from tf_demo.cli._doctor_tree import islands_of
from tf_demo.cli._observations import Observation


def summarize(observations: Sequence[Observation]) -> dict[str, int]:
    """Count for the report's first line: messages, frames and trees."""
    parent_of: dict[str, str] = {}
    for observation in sorted(observations, key=lambda o: o.receive_ns):
        for transform in observation.transforms:
            parent_of[transform.child] = transform.parent
    return {
        'messages': len(observations),
        'frames': len(set(parent_of) | set(parent_of.values())),
        'trees': len(islands_of(parent_of)),
    }


def _wrapped(text: str, first: str, indent: str, width: int = 99) -> list[str]:
    lines: list[str] = []
    for index, paragraph in enumerate(text.split('\n')):
        lead = first if index == 0 else indent
        lines.extend(
            textwrap.wrap(
                paragraph,
                width=width,
                initial_indent=lead,
                subsequent_indent=indent,
                break_on_hyphens=False,
                break_long_words=False,
            )
            or [lead]
        )
    return lines


def bag_time(at_ns: int, start_ns: int) -> str:
    """Say when ``at_ns`` is: the bag time, and how far into the recording."""
    sec, nanosec = divmod(at_ns, 1_000_000_000)
    return f'bag time {sec}.{nanosec // 1_000_000:03d} s ({(at_ns - start_ns) / 1e9:.3f} s in)'


def format_report(
    findings: Sequence[Finding],
    summary: dict[str, int],
    source: str,
    start_ns: int | None = None,
) -> str:
    """
    Format the plain-language report: each finding with its fix, then the verdict.

    With ``start_ns`` (a recording's start) a finding with a time says when, in bag time.
    """
    lines = [
        f'tf_doctor: {source}: {summary["messages"]} messages, {summary["frames"]} frames, '
        f'{summary["trees"]} tree{"s" if summary["trees"] != 1 else ""}.'
    ]
    for finding in findings:
        lines.append('')
        lines.extend(
            _wrapped(finding.message, f'{finding.severity.upper()} [{finding.kind}] ', '    ')
        )
        if start_ns is not None and finding.at_ns is not None:
            lines.append(f'  At: {bag_time(finding.at_ns, start_ns)}')
        lines.extend(_wrapped(finding.fix, '  Fix: ', '    '))
    problems = [f for f in findings if f.severity != 'info']
    lines.append('')
    if problems:
        errors = sum(1 for f in problems if f.severity == 'error')
        warnings = len(problems) - errors
        lines.append(
            f'Found {errors} error{"s" if errors != 1 else ""} and '
            f'{warnings} warning{"s" if warnings != 1 else ""}.'
        )
    else:
        notes = len(findings)
        lines.append(
            'Healthy: no problems found'
            + (f' ({notes} note{"s" if notes != 1 else ""} above).' if notes else '.')
        )
    return '\n'.join(lines) + '\n'


def format_report_json(findings: Sequence[Finding], summary: dict[str, int], source: str) -> str:
    """Format the report as one JSON object (``--json``)."""
    return (
        json.dumps(
            {
                'source': source,
                'healthy': not any(f.severity != 'info' for f in findings),
                'summary': summary,
                'findings': [
                    {
                        'kind': f.kind,
                        'severity': f.severity,
                        'frames': list(f.frames),
                        'message': f.message,
                        'fix': f.fix,
                        'at_s': None if f.at_ns is None else f.at_ns / 1e9,
                    }
                    for f in findings
                ],
            },
            ensure_ascii=False,
        )
        + '\n'
    )


def exit_code(findings: Sequence[Finding]) -> int:
    """Return 0 when healthy, 1 when an error or a warning was found."""
    return 1 if any(f.severity != 'info' for f in findings) else 0
