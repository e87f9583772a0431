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

"""Errors raised while loading a robot description: each names the file, element and reason."""

from __future__ import annotations

__all__ = [
    'UrdfBrokenRefError',
    'UrdfError',
    'UrdfMalformedError',
    'UrdfUnsupportedError',
]


class UrdfError(ValueError):
    """
    A robot description that cannot be used.

    The message has the form <source>:<line>: <element>: <reason> so that one line tells the
    user which file, which element and what is wrong.
    """

    def __init__(self, source: str, element: str, reason: str, line: int | None = None) -> None:
        self.source = source
        self.element = element
        self.reason = reason
        self.line = line
        location = source if line is None else f'{source}:{line}'
        super().__init__(f'{location}: {element}: {reason}')


class UrdfMalformedError(UrdfError):
    """The XML or the robot structure is invalid (syntax, missing or bad values, not a tree)."""


class UrdfUnsupportedError(UrdfError):
    """The description uses something the URDF format does not define (e.g. a joint type)."""


class UrdfBrokenRefError(UrdfError):
    """An element refers to a link, joint or file that does not exist."""
